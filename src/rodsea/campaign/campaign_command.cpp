#include "rodsea/campaign/campaign_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>

#include "rodsea/calibration/calibration_table.hpp"
#include "rodsea/campaign/campaign_collect.hpp"
#include "rodsea/campaign/campaign_cost.hpp"
#include "rodsea/campaign/campaign_figures.hpp"
#include "rodsea/campaign/ensemble_executor.hpp"
#include "rodsea/campaign/local_executor.hpp"
#include "rodsea/campaign/slurm_executor.hpp"
#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/error.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

namespace fs = std::filesystem;

const CommandSpec& campaign_command_spec() {
    static const CommandSpec spec{
        "campaign",
        "plan|run|status|collect|submit CAMPAIGN [--out DIR] [--scale F] [--duration T] "
        "[--extend] [--jobs N | --ensemble] [--threads T] [--backend cpu|gpu] [submit options]",
        "a figure's grid of runs: plan its cost, run it, follow it, collect its table",
        "CAMPAIGN is a TOML file (docs/campaigns.md: a base config, axes over config keys, "
        "replicates, the analysis): every point is built and checked, packing included, before "
        "anything runs.\n"
        "  plan     the points, their bodies, spheres and steps, and the cost in core-hours, "
        "measured on this machine (each point stepped for --measure-seconds in a small box), "
        "and in wall time with --jobs or --ensemble and --threads\n"
        "  run      runs every run not yet done, --jobs at a time on --threads each, in DIR "
        "(default out/<campaign name>); run it again to continue: done runs are skipped, "
        "interrupted ones resume from their checkpoints, failed ones are retried once; Ctrl-C "
        "stops every run with a checkpoint. With --ensemble the runs are stepped together in "
        "this process as one ensemble on --threads (on a GPU, in the same kernels), each "
        "writing its own directory exactly as alone\n"
        "  status   each run: pending, running, interrupted, done or failed, its progress and "
        "ETA (readable while a runner works)\n"
        "  collect  analyses every finished run ([analysis] of the campaign) and writes "
        "DIR/collected/points.csv (a row per point, replicates combined), runs.csv and the "
        "campaign's [[figure]]s in collected/figures/; names what is missing, and keeps a table "
        "that would shrink as <name>.previous.csv\n"
        "  submit   SLURM: the runs not done as one sbatch job array (a task per run, or --pack "
        "runs per task) in DIR/slurm/; SIGTERM --signal-seconds before the wall time makes "
        "every run checkpoint, and a follow-up job (afterany) submits what is left, --resubmit "
        "times at most",
        {{"--out", "DIR", "the campaign's directory (default out/<campaign name>)"},
         {"--scale", "F",
          "box side times F, in (0, 1], area fractions kept (counts given as counts times F^2): "
          "run a figure small first; fixed for a campaign directory, and taken from it when "
          "not given (but by plan)"},
         {"--duration", "T",
          "every run's time.duration, s; fixed for a campaign directory unless --extend, and "
          "taken from it when not given (but by plan)"},
         {"--extend", "",
          "run, submit: take the campaign directory to a longer --duration (the same --scale "
          "and points): runs done continue from their last checkpoints, bit for bit the runs "
          "that had been given it from the start"},
         {"--jobs", "N",
          "run, submit: runs at a time (in each array task) (default 1); plan: for the "
          "wall-time estimate"},
         {"--threads", "T",
          "run: threads per run, or of the ensemble (default 1); plan: for the wall-time "
          "estimate"},
         {"--ensemble", "",
          "run, submit: step the runs (of each array task) together as one ensemble in one "
          "process instead of --jobs processes: a GPU's way to run many small systems; plan: "
          "for the wall-time estimate"},
         {"--backend", "cpu|gpu",
          "run, submit: step every run on the host's cores or a CUDA device, replacing "
          "run.backend (for a run that started on the other, from here on)"},
         {"--partition", "P", "submit: the SLURM partition (default: the cluster's)"},
         {"--account", "A", "submit: the SLURM account to charge (default: yours)"},
         {"--time", "T",
          "submit: wall time per array task, as sbatch takes it: minutes, HH:MM:SS or "
          "D-HH:MM:SS (default 24:00:00)"},
         {"--signal-seconds", "S",
          "submit: SIGTERM this long before the wall time, for the checkpoint (default "
          "min(300, half the wall time))"},
         {"--cpus-per-task", "C",
          "submit: CPUs per array task, shared by its --jobs runs (default 1)"},
         {"--gpus-per-task", "G", "submit: GPUs per array task (default 0)"},
         {"--throttle", "K", "submit: array tasks running at a time (default: no limit)"},
         {"--pack", "K", "submit: runs per array task, run --jobs at a time (default 1)"},
         {"--resubmit", "N",
          "submit: follow-up submissions of what did not finish, at most (default 3; 0: none)"},
         {"--dry-run", "", "submit: write the script, submit nothing"},
         {"--tasks", "FILE", "run: only the runs of one task of a submission (the array script)"},
         {"--task", "N", "run: the line of --tasks (default $SLURM_ARRAY_TASK_ID)"},
         {"--retry-failed", "",
          "run: give runs that failed twice two more tries (not those that "
          "blew up: they would repeat the same steps)"},
         {"--measure-seconds", "S",
          "plan: seconds of stepping per point to measure its cost "
          "(default 0.3)"},
         {"--no-measure", "", "plan: skip the measurement (no core-hours)"},
         {"--reference", "", "print the campaign file's key reference (Markdown) and exit"},
         {"--quiet", "", "run, collect: no progress lines"},
         {"--reanalyse", "",
          "collect: analyse every finished run again (by default a run whose analysis is on "
          "disk for the same trajectory, [analysis] and rodsea version is reused)"}},
        "Files: DIR/campaign.toml, scaling.txt, runs/<point>/seed<k>.toml (config), "
        "runs/<point>/seed<k>/ (the run), .log, .failed, collected/. Exit codes: 0 done; 1 some "
        "run failed; 2 bad campaign or options (nothing run); 74 file error; 130/143 stopped by "
        "SIGINT/SIGTERM (every run checkpointed)."};
    return spec;
}

namespace {

struct Loaded {
    Campaign campaign;
    CampaignScaling scaling;
    CampaignGrid grid;
    CampaignPaths paths;
};

// A campaign directory remembers the --scale and --duration its runs were given (scaling.txt):
// every command but plan, which describes the file rather than a directory, takes from there
// what is not given again, so that `status`, `collect` and a `run` that continues need only the
// campaign and --out. What is given is checked against it as before.
Loaded load(const Arguments& a, bool remembered_scaling = true) {
    if (a.positional.size() != 2)
        throw InvalidParameter("CAMPAIGN", std::to_string(a.positional.size() - 1) + " given",
                               "one campaign file after the subcommand (rodsea campaign --help)");
    Loaded l;
    l.campaign = load_campaign_file(a.positional[1]);
    l.paths.dir = a.value("--out").value_or(default_campaign_dir(l.campaign).string());
    if (remembered_scaling)
        if (const std::optional<CampaignScaling> started = read_campaign_scaling(l.paths))
            l.scaling = *started;
    if (const auto f = a.value("--scale")) l.scaling.scale = parse_number("--scale", *f, 1e-3, 1.0);
    if (const auto t = a.value("--duration"))
        l.scaling.duration = parse_number("--duration", *t, 1e-6, 1e6, "s");
    l.grid = expand_campaign(l.campaign, l.scaling, calibration_table_lookup());
    return l;
}

// Every run's plan: what it runs, and what its stored config must be.
std::vector<RunPlan> plans_of(const Loaded& l) {
    std::vector<RunPlan> plans;
    plans.reserve(l.grid.runs.size());
    for (const CampaignRun& r : l.grid.runs)
        plans.push_back(run_plan(l.campaign, l.grid, r, l.scaling, calibration_table_lookup()));
    return plans;
}

// plan and run: the ensemble is one process, so --jobs has no meaning beside it.
void refuse_jobs_with_ensemble(const Arguments& a) {
    if (a.has("--ensemble") && a.value("--jobs"))
        throw InvalidParameter("--jobs", *a.value("--jobs"), "no --jobs with --ensemble",
                               "the ensemble is one process; give it --threads");
}

int plan(const Arguments& a, std::ostream& out) {
    const Loaded l = load(a, false);
    PlannedExecution how;
    how.jobs = static_cast<int>(parse_count("--jobs", a.value("--jobs").value_or("1"), 1, 4096));
    how.threads = static_cast<int>(
        parse_count("--threads", a.value("--threads").value_or("1"), 1, kMaxThreads));
    how.ensemble = a.has("--ensemble");
    refuse_jobs_with_ensemble(a);
    const double seconds =
        a.has("--no-measure")
            ? 0.0
            : parse_number("--measure-seconds", a.value("--measure-seconds").value_or("0.3"), 0.01,
                           60.0, "s");
    const std::vector<PointCost> costs =
        estimate_campaign_cost(l.campaign, l.grid, l.scaling, calibration_table_lookup(), seconds);
    describe_campaign(l.campaign, l.grid, l.scaling, costs, how, out);
    out << "  directory " << l.paths.dir.string() << "\n";
    return kExitOk;
}

// With --extend, every run's plan at the scaling the directory was started with, once it is
// checked that the directory holds a campaign and that only its runs' durations grow.
std::optional<std::vector<RunPlan>> plans_before_extension(const Arguments& a, const Loaded& l,
                                                           const std::vector<RunPlan>& plans,
                                                           bool quiet, std::ostream& out) {
    if (!a.has("--extend")) return std::nullopt;
    if (!a.value("--duration"))
        throw InvalidParameter("--extend", "without --duration",
                               "--extend with --duration T: every run continues to T s");
    const std::optional<CampaignScaling> before = read_campaign_scaling(l.paths);
    if (!before)
        throw InvalidParameter("--extend", l.paths.dir.string(),
                               "a campaign directory to extend (this one holds none yet)",
                               "start the campaign without --extend");
    if (before->scale != l.scaling.scale)
        throw InvalidParameter("--scale", exact_number(l.scaling.scale),
                               "the campaign's --scale " + exact_number(before->scale) +
                                   ": an extension changes the runs' duration only");
    const CampaignGrid grid = expand_campaign(l.campaign, *before, calibration_table_lookup());
    std::vector<RunPlan> before_plans;
    for (std::size_t i = 0; i < l.grid.runs.size(); ++i) {
        before_plans.push_back(
            run_plan(l.campaign, grid, grid.runs[i], *before, calibration_table_lookup()));
        const double was = before_plans.back().control.duration;
        if (was > plans[i].control.duration)
            throw InvalidParameter("--duration", exact_number(*l.scaling.duration),
                                   "at least every run's duration so far (" + l.grid.runs[i].id +
                                       ": " + exact_number(was) + " s)",
                                   "a campaign is extended, not shortened");
    }
    if (!quiet && before->duration != l.scaling.duration)
        out << "campaign " << l.paths.dir.string() << ": extended from "
            << (before->duration ? "--duration " + exact_number(*before->duration) + " s"
                                 : std::string("each point's duration"))
            << " to " << exact_number(*l.scaling.duration)
            << " s: runs done continue from their last checkpoints" << std::endl;
    return before_plans;
}

std::optional<BackendKind> backend_option(const Arguments& a) {
    if (const auto b = a.value("--backend")) return backend_flag("--backend", *b);
    return std::nullopt;
}

int run(const Arguments& a, std::ostream& out, std::ostream& err) {
    const Loaded l = load(a);
    LocalExecutorOptions o;
    o.jobs = static_cast<int>(parse_count("--jobs", a.value("--jobs").value_or("1"), 1, 4096));
    o.threads = static_cast<int>(
        parse_count("--threads", a.value("--threads").value_or("1"), 1, kMaxThreads));
    o.retry_failed = a.has("--retry-failed");
    o.quiet = a.has("--quiet");
    o.backend = backend_option(a);
    refuse_jobs_with_ensemble(a);
    if (o.backend) require_usable_backend(*o.backend, "--backend");
    if (const auto tasks = a.value("--tasks")) {
        const char* env = std::getenv("SLURM_ARRAY_TASK_ID");
        const std::optional<std::string> task = a.value("--task");
        if (!task && !env)
            throw InvalidParameter("--task", "missing",
                                   "the task's line of --tasks (or $SLURM_ARRAY_TASK_ID)");
        o.only =
            runs_of_task(*tasks, parse_count("--task", task ? *task : env, 0, 1'000'000), l.grid);
    } else if (a.value("--task")) {
        throw InvalidParameter("--task", *a.value("--task"), "--task together with --tasks");
    }
    const std::vector<RunPlan> plans = plans_of(l);
    const auto before = plans_before_extension(a, l, plans, o.quiet, out);
    prepare_campaign_dir(l.paths, l.campaign, l.scaling, l.grid, plans,
                         before ? &*before : nullptr);
    if (a.has("--ensemble")) return run_campaign_as_ensemble(l.paths, l.grid, o, out, err);
    return run_campaign_locally(l.paths, l.grid, o, out);
}

int submit(const Arguments& a, std::ostream& out) {
    const Loaded l = load(a);
    SlurmOptions o;
    o.campaign_file = fs::absolute(a.positional[1]);
    o.scaling = l.scaling;
    o.partition = a.value("--partition").value_or("");
    o.account = a.value("--account").value_or("");
    for (const auto& [flag, value] :
         {std::pair{"--partition", o.partition}, {"--account", o.account}})
        if (value.find_first_of(" \t\n'\"\\$`") != std::string::npos)
            throw InvalidParameter(flag, value, "a SLURM name (no spaces, quotes or $)");
    if (const auto t = a.value("--time")) o.time = *t;
    o.time_seconds = parse_slurm_time(o.time);
    if (const auto s = a.value("--signal-seconds"))
        o.signal_seconds = parse_count("--signal-seconds", *s, 10, 65'535);  // sbatch's limit
    const auto count = [&](const char* flag, long fallback, long lo, long hi) {
        const auto v = a.value(flag);
        return static_cast<int>(v ? parse_count(flag, *v, lo, hi) : fallback);
    };
    o.cpus_per_task = count("--cpus-per-task", 1, 1, 4096);
    o.gpus_per_task = count("--gpus-per-task", 0, 0, 64);
    o.throttle = count("--throttle", 0, 0, 100'000);
    o.pack = count("--pack", 1, 1, 10'000);
    o.jobs = count("--jobs", 1, 1, 4096);
    o.resubmit = count("--resubmit", 3, 0, 100);
    o.ensemble = a.has("--ensemble");
    o.backend = backend_option(a);
    if (o.ensemble && a.value("--jobs"))
        throw InvalidParameter("--jobs", *a.value("--jobs"), "no --jobs with --ensemble",
                               "each array task steps its runs as one ensemble on "
                               "--cpus-per-task threads");
    if (o.jobs > o.pack)
        throw InvalidParameter(
            "--jobs", std::to_string(o.jobs),
            "at most --pack (" + std::to_string(o.pack) + "): the runs of one array task");
    if (o.jobs > o.cpus_per_task)
        throw InvalidParameter("--jobs", std::to_string(o.jobs),
                               "at most --cpus-per-task (" + std::to_string(o.cpus_per_task) + ")");
    o.retry_failed = a.has("--retry-failed");
    o.dry_run = a.has("--dry-run");
    check_slurm_options(o);
    // The scripts name the directory in #SBATCH lines, which sbatch splits at spaces.
    const std::string dir = fs::absolute(l.paths.dir).string();
    if (dir.find_first_of(" \t\n'\"\\$`%") != std::string::npos)
        throw InvalidParameter("--out", dir,
                               "a directory whose path has no spaces, quotes, $ or % (it is "
                               "written into #SBATCH lines)");
    const std::vector<RunPlan> plans = plans_of(l);
    const auto before = plans_before_extension(a, l, plans, false, out);
    prepare_campaign_dir(l.paths, l.campaign, l.scaling, l.grid, plans,
                         before ? &*before : nullptr);
    return submit_campaign_to_slurm(l.paths, l.campaign, l.grid, o, out);
}

int status(const Arguments& a, std::ostream& out) {
    const Loaded l = load(a);
    check_campaign_dir(l.paths, l.scaling, l.grid, plans_of(l));
    std::size_t counts[5] = {};
    std::size_t width = 3;
    for (const CampaignRun& r : l.grid.runs)
        width = std::max(width, r.id.size());
    width = std::min<std::size_t>(width, kNameColumnWidth);
    const int w = static_cast<int>(width);
    char line[512];
    std::snprintf(line, sizeof line, "%-*s %-11s %7s %18s %10s %9s\n", w, "run", "state", "done",
                  "t / duration (s)", "steps/s", "ETA");
    out << line;
    for (const CampaignRun& r : l.grid.runs) {
        const RunStatus s = run_status(l.paths, r);
        ++counts[static_cast<int>(s.state)];
        std::string done = "-", time = "-", rate = "-", eta = "-";
        if (s.progress) {
            const RunProgress& p = *s.progress;
            // A run of an extended campaign that has not continued yet: its way to the new end.
            const bool extended = ends_before(p, r.duration);
            const double fraction = extended ? p.time / r.duration : p.fraction();
            done = format_number(std::floor(fraction * 1000) / 10) + " %";
            time =
                format_number(p.time) + " / " + format_number(extended ? r.duration : p.duration);
            if (s.state == RunState::running) {
                rate = format_number(std::round(p.steps_per_second));
                if (p.eta_seconds() >= 0) eta = format_duration(p.eta_seconds());
            }
        }
        const std::string id = name_in_column(r.id, width);
        std::snprintf(line, sizeof line, "%-*s %-11s %7s %18s %10s %9s\n", w, id.c_str(),
                      to_string(s.state), done.c_str(), time.c_str(), rate.c_str(), eta.c_str());
        out << line;
        if (s.state == RunState::failed)
            out << (s.blew_up ? "    blew up (a resume would repeat the same steps: change the "
                                "config): "
                              : "    failed " + std::to_string(s.failures) + " times: ")
                << s.last_failure << "\n";
    }
    out << "\n" << l.grid.runs.size() << " runs: ";
    for (int k = 0; k < 5; ++k)
        out << (k ? ", " : "") << counts[k] << " " << to_string(static_cast<RunState>(k));
    out << "\n";
    return kExitOk;
}

int collect(const Arguments& a, std::ostream& out) {
    const Loaded l = load(a);
    check_campaign_dir(l.paths, l.scaling, l.grid, plans_of(l));
    const CollectResult r =
        collect_campaign(l.paths, l.campaign, l.grid, out, a.has("--quiet"), a.has("--reanalyse"));
    out << "collect: " << r.runs_analysed << " runs of " << r.points_with_runs << " points ("
        << r.runs_reused << " unchanged since their analysis) -> " << r.points_table.string()
        << ", " << r.runs_table.string() << "\n";
    for (const std::string& s : r.shrunk)
        out << "collect: " << s << "\n";
    if (!r.missing.empty()) {
        out << "collect: " << r.missing.size() << " runs not finished (rodsea campaign run "
            << "continues them):";
        for (const std::string& id : r.missing)
            out << " " << id;
        out << "\n";
    }
    if (l.campaign.figures.empty()) return kExitOk;
    const FiguresDrawn drawn = draw_campaign_figures(l.paths, l.campaign, l.grid, out);
    out << "collect: " << drawn.files.size() << " figure files in "
        << (l.paths.collected() / "figures").string() << "\n";
    if (!a.has("--quiet"))
        for (const fs::path& f : drawn.files)
            out << "  " << f.string() << "\n";
    for (const std::string& u : drawn.unfinished)
        out << "collect: " << u << "\n";
    for (const std::string& p : drawn.problems)
        out << "collect: FAILED " << p << "\n";
    return drawn.problems.empty() ? kExitOk : kExitFailure;
}

// Each subcommand's options: one given to another subcommand is refused, not ignored.
void check_options_of(const std::string& sub, const Arguments& a) {
    static const std::vector<std::pair<std::string, std::vector<std::string>>> options{
        {"plan", {"--jobs", "--threads", "--ensemble", "--measure-seconds", "--no-measure"}},
        {"run",
         {"--jobs", "--threads", "--retry-failed", "--quiet", "--tasks", "--task", "--ensemble",
          "--backend", "--extend"}},
        {"status", {}},
        {"collect", {"--quiet", "--reanalyse"}},
        {"submit",
         {"--jobs", "--partition", "--account", "--time", "--signal-seconds", "--cpus-per-task",
          "--gpus-per-task", "--throttle", "--pack", "--resubmit", "--retry-failed", "--dry-run",
          "--ensemble", "--backend", "--extend"}}};
    const auto own =
        std::find_if(options.begin(), options.end(), [&](const auto& o) { return o.first == sub; });
    if (own == options.end()) return;  // an unknown subcommand is named below
    std::vector<std::string> allowed{"--out", "--scale", "--duration"};
    allowed.insert(allowed.end(), own->second.begin(), own->second.end());
    std::vector<std::string> given = a.switches;
    for (const auto& [flag, value] : a.values)
        given.push_back(flag);
    for (const std::string& flag : given) {
        if (std::find(allowed.begin(), allowed.end(), flag) != allowed.end()) continue;
        std::string list;
        for (const std::string& f : allowed)
            list += (list.empty() ? "" : ", ") + f;
        throw InvalidParameter(flag, "with campaign " + sub,
                               "an option of campaign " + sub + ": " + list);
    }
}

}  // namespace

int campaign_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const std::optional<Arguments> parsed = arguments_or_help(args, campaign_command_spec(), out);
    if (!parsed) return kExitOk;
    const Arguments& a = *parsed;
    if (a.has("--reference")) {
        out << campaign_reference_markdown();
        return kExitOk;
    }
    const std::vector<std::string> subcommands{"plan", "run", "status", "collect", "submit"};
    const std::string sub = a.positional.empty() ? "" : a.positional[0];
    check_options_of(sub, a);
    if (sub == "plan") return plan(a, out);
    if (sub == "run") return run(a, out, err);
    if (sub == "status") return status(a, out);
    if (sub == "collect") return collect(a, out);
    if (sub == "submit") return submit(a, out);
    const auto guess = config::closest_match(sub, subcommands);
    throw InvalidParameter("SUBCOMMAND", sub.empty() ? "none" : quoted(sub),
                           "plan, run, status, collect or submit",
                           guess ? "did you mean '" + *guess + "'?" : "rodsea campaign --help");
}

}  // namespace rodsea
