#include "rodsea/run/run_command.hpp"

#include <unistd.h>

#include <filesystem>
#include <optional>
#include <ostream>

#include "rodsea/calibration/calibration_table.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/error.hpp"
#include "rodsea/run/plan_report.hpp"
#include "rodsea/run/run_continuation.hpp"
#include "rodsea/run/run_driver.hpp"
#include "rodsea/run/steady_stop.hpp"

namespace rodsea {

const CommandSpec& run_command_spec() {
    static const CommandSpec spec{
        "run",
        "CONFIG... [--out DIR] [--overwrite] [--threads N] [--backend cpu|gpu] [--quiet]  |  "
        "rodsea run --resume DIR... [--duration T] [--steady-samples N] [--threads N] "
        "[--backend cpu|gpu] [--quiet]  |  rodsea run --continue CHECKPOINT --out DIR "
        "[--overwrite] [--duration T] [--steady-samples N] [--threads N] [--backend cpu|gpu] "
        "[--quiet]",
        "start a simulation, or continue one from its checkpoint",
        "Reads CONFIG (TOML; every key in docs/config.md), checks all of it and the packing, "
        "prints the plan, builds the initial state (every body flat on the base, no overlaps) "
        "and runs it, writing into DIR (default: out/<config name>):\n"
        "  config.toml      the full resolved config        trajectory.h5   H5MD trajectory + "
        "time series\n"
        "  timeseries.csv   the time series as CSV          checkpoint.h5   the latest "
        "checkpoint\n"
        "On a terminal a progress bar shows simulated time, ETA, steps/s and P; otherwise a log "
        "line every 5 %. Checkpoints are written every output.checkpoint_interval minutes of wall "
        "time and on SIGINT/SIGTERM (Ctrl-C stops cleanly); --resume continues bit for bit where "
        "it stopped. --resume with --duration extends a run, finished or not, to a longer "
        "duration (bit for bit the run given that duration from the start; config.toml and the "
        "stored config say the new one); --steady-samples changes time.steady_samples (stop when "
        "steady) likewise, 0 to run to the duration.\n"
        "--continue goes on from a checkpoint alone, into a new directory, when the run's own "
        "directory is not at hand (a checkpoint copied off a cluster's scratch or kept from a "
        "machine given back): the same run, bit for bit on the same backend, whose new "
        "trajectory.h5 holds its frames from the checkpoint on (the earlier ones stay with the "
        "first directory; docs/running.md). It then resumes like any run directory.\n"
        "Several configs (or run directories after --resume) are stepped together as one "
        "ensemble, on a GPU in the same kernels: each run writes its own directory "
        "(out/<config name>, or DIR/<config name> with --out DIR) exactly as it would alone, "
        "and resumes alone or with others. All are checked before any starts; they share "
        "run.backend; a run that ends leaves the others going (docs/running.md).",
        {{"--out", "DIR",
          "output directory, refused if it exists and is not empty (with several configs, the "
          "parent of each run's, and those are refused)"},
         {"--overwrite", "", "replace the run files in an existing DIR"},
         {"--threads", "N",
          "run on N threads, replacing run.threads (the stored config says N); with --resume "
          "for this session only (threads change the speed, never the trajectory)"},
         {"--backend", "cpu|gpu",
          "step on the host's cores or a CUDA device, replacing run.backend; with --resume for "
          "this session only (a run started on the GPU goes on on the CPU, and the other way)"},
         {"--resume", "DIR",
          "continue the run in DIR from its checkpoint.h5 (more directories may follow)"},
         {"--continue", "CHECKPOINT",
          "continue the run of CHECKPOINT (a checkpoint.h5, or a run directory holding one) into "
          "the new directory --out DIR"},
         {"--duration", "T",
          "with --resume or --continue: the run's new duration, s (at least the time done)"},
         {"--steady-samples", "N",
          "with --resume or --continue: the run's new time.steady_samples (0: no stop when "
          "steady; a continuation must have 0)"},
         {"--quiet", "", "no plan and no progress (errors are still printed)"}},
        ""};
    return spec;
}

const CommandSpec& info_command_spec() {
    static const CommandSpec spec{
        "info",
        "CONFIG...",
        "what CONFIG would simulate",
        "Prints what CONFIG would simulate, without running it: the box and drive (amplitude A, "
        "peak plate speed), counts per species with spheres, projected areas and actual area "
        "fractions, the number of steps, the expected memory and output size, whether the "
        "packing is possible, the backend and device, and every docs/model.md CHOICE in force. "
        "With "
        "several configs, first what `rodsea run` with all of them would step as one ensemble "
        "(a line per run, the backend, the memory and output in all), then each plan in full.",
        {},
        ""};
    return spec;
}

namespace {

bool stdout_is_terminal() {
    return ::isatty(STDOUT_FILENO) == 1;
}

// Where `rodsea run` writes the run of `config` given among `count` configs and --out `out_flag`.
std::filesystem::path run_directory(const std::filesystem::path& config, std::size_t count,
                                    const std::optional<std::string>& out_flag) {
    if (!out_flag) return std::filesystem::path("out") / config.stem();
    return count == 1 ? std::filesystem::path(*out_flag)
                      : std::filesystem::path(*out_flag) / config.stem();
}

// What --resume and --continue share: the run's new length, and this session's backend and threads.
void read_length_flags(const Arguments& a, RunOptions& options) {
    if (const auto t = a.value("--duration"))
        options.duration = parse_number("--duration", *t, 0.0, 1e6, "s");
    if (const auto n = a.value("--steady-samples"))
        options.steady_samples = parse_count("--steady-samples", *n, 0, 1'000'000'000);
    if (const auto b = a.value("--backend")) options.backend = backend_flag("--backend", *b);
    if (const auto n = a.value("--threads"))
        options.threads = static_cast<int>(parse_count("--threads", *n, 1, kMaxThreads));
}

}  // namespace

int run_command(const std::vector<std::string>& words, std::ostream& out, std::ostream& err) {
    const std::optional<Arguments> parsed = arguments_or_help(words, run_command_spec(), out);
    if (!parsed) return kExitOk;
    const Arguments& a = *parsed;
    RunOptions options;
    options.quiet = a.has("--quiet");
    options.overwrite = a.has("--overwrite");
    if (const auto checkpoint = a.value("--continue")) {
        if (a.value("--resume") || !a.positional.empty())
            throw InvalidParameter("--continue", *checkpoint,
                                   "one checkpoint, with --out DIR (and --overwrite, --duration, "
                                   "--steady-samples, --threads, --backend, --quiet at most)",
                                   "the config comes from the checkpoint");
        const auto out_dir = a.value("--out");
        if (!out_dir)
            throw InvalidParameter("--out", "none given", "the new directory of the continuation",
                                   "rodsea run --continue CHECKPOINT --out DIR");
        options.out_dir = *out_dir;
        read_length_flags(a, options);
        return continue_run(*checkpoint, options, out, err, stdout_is_terminal());
    }
    if (const auto dir = a.value("--resume")) {
        if (a.value("--out") || options.overwrite)
            throw InvalidParameter("--resume", *dir,
                                   "run directories only (with --duration, --steady-samples, "
                                   "--threads, --backend, --quiet at most)",
                                   "the config and output directory come from each DIR");
        // Further directories after the first (a shell glob) are resumed together with it.
        std::vector<std::filesystem::path> dirs{*dir};
        dirs.insert(dirs.end(), a.positional.begin(), a.positional.end());
        read_length_flags(a, options);
        return resume_runs(dirs, options, out, err, stdout_is_terminal());
    }
    for (const char* flag : {"--duration", "--steady-samples"})
        if (a.value(flag))
            throw InvalidParameter(flag, *a.value(flag), "only with --resume DIR or --continue",
                                   "a new run takes its length from CONFIG ([time])");
    if (a.positional.empty())
        throw InvalidParameter("CONFIG", "none given",
                               "one config file or more (see rodsea run --help)");
    const std::optional<std::string> out_flag = a.value("--out");
    std::vector<NewRun> runs;
    for (const std::string& name : a.positional) {
        const std::filesystem::path config = name;
        RunPlan plan = load_config_file(name, calibration_table_lookup());
        if (const auto n = a.value("--threads"))
            plan = with_threads(plan.config_toml, name,
                                static_cast<int>(parse_count("--threads", *n, 1, kMaxThreads)));
        if (const auto b = a.value("--backend"))
            plan = with_backend(plan.config_toml, name, backend_flag("--backend", *b));
        // One config writes DIR itself; several write DIR/<config name> each.
        runs.push_back({std::move(plan), run_directory(config, a.positional.size(), out_flag)});
    }
    return start_runs(runs, options, out, err, stdout_is_terminal());
}

int info_command(const std::vector<std::string>& words, std::ostream& out, std::ostream&) {
    const std::optional<Arguments> parsed = arguments_or_help(words, info_command_spec(), out);
    if (!parsed) return kExitOk;
    const Arguments& a = *parsed;
    if (a.positional.empty())
        throw InvalidParameter("CONFIG", "none given",
                               "one config file or more (see rodsea info --help)");
    std::vector<RunPlan> plans;
    std::vector<std::filesystem::path> dirs;
    for (const std::string& name : a.positional) {
        plans.push_back(load_config_file(name, calibration_table_lookup()));
        check_steady_series(plans.back());
        dirs.push_back(run_directory(name, a.positional.size(), std::nullopt));
    }
    if (plans.size() > 1) {
        out << "rodsea info: " << plans.size() << " configs; `rodsea run` with all of them:\n";
        try {
            const BackendOptions stepping = ensemble_options(plans, dirs, RunOptions{});
            RunControl control = plans.front().control;
            control.threads = stepping.threads;
            control.backend = stepping.backend;
            describe_ensemble(plans, dirs, control, out, false);
        } catch (const InvalidParameter& e) {
            out << "  refused together: " << e.what() << "\n";
        }
    }
    for (std::size_t r = 0; r < plans.size(); ++r) {
        out << (r > 0 || plans.size() > 1 ? "\n" : "") << "rodsea info " << a.positional[r] << "\n";
        describe_plan(plans[r], out);
    }
    return kExitOk;
}

}  // namespace rodsea
