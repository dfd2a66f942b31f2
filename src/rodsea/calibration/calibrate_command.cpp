#include "rodsea/calibration/calibrate_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <numbers>
#include <optional>
#include <ostream>
#include <sstream>
#include <thread>

#include "rodsea/calibration/calibration_grid.hpp"
#include "rodsea/cli/arguments.hpp"
#include "rodsea/cli/count_progress.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

const CommandSpec& calibrate_command_spec() {
    static const CommandSpec spec{
        "calibrate",
        "CONFIG [--out DIR] [--threads N] [--backend cpu|gpu] [--quiet]",
        "single-body speed and D_r over ε, gap and dt",
        "Single-body experiments (docs/validation.md): for every combination of the ε, gaps and "
        "time steps in CONFIG's [calibrate] table, `copies` independent bodies of one kind are "
        "each shaken alone for `warmup` + `duration` seconds. Each point gives the mean speed "
        "along the body's axis (+: toward body +x, thick → thin for a polar rod) and the "
        "fraction of copies going that way, the speed distribution (per drive period), and D_r "
        "from C(t) = exp(−D_r t) with a jackknife error. The points run in parallel: on the "
        "CPU one copy per thread, on the GPU (--backend gpu) every copy of the points that "
        "share dt in the same kernels, each copy's trace the one it has alone on the GPU. DIR "
        "(default out/<CONFIG name>) receives:\n"
        "calibration.csv: one row per point: gap, dt, ε, D_r ± err, speed ± err, ...\n"
        "speed_distribution.csv: the per-period axial speeds of each point as a histogram\n"
        "calibrate.toml: CONFIG as given",
        {{"--out", "DIR",
          "output directory (replaced files: calibration.csv, speed_distribution.csv, "
          "calibrate.toml)"},
         {"--threads", "N", "worker threads, [1, 256] (default: the machine's cores, at most 256)"},
         {"--backend", "cpu|gpu",
          "what steps the copies (default cpu); gpu needs a build with CUDA and a device, and is "
          "refused before any work where there is none"},
         {"--quiet", "", "no plan and no progress"}},
        std::string("CONFIG keys (units and ranges):\n") + kCalibrationKeysHelp};
    return spec;
}

namespace {

struct PointResult {
    SingleBodyExperiment experiment;
    SingleBodyResult result;
};

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return std::nan("");
    const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
}

std::string calibration_csv(const std::vector<PointResult>& points) {
    std::ostringstream out;
    out << "# rodsea " << RODSEA_VERSION
        << " calibration: single bodies in the vibrated cell, one row per point; units: gap [mm], "
           "dt [s], epsilon [1/mm], D_r [rad^2/s], speeds [mm/s], duration [s]\n";
    out << "species,gap,dt,noise_mode,epsilon,D_r,D_r_err,speed,speed_err,transverse_speed,"
           "transverse_speed_err,forward_fraction,speed_p10,speed_p50,speed_p90,copies,duration,"
           "unresolved\n";
    for (const PointResult& p : points) {
        const SingleBodyExperiment& e = p.experiment;
        const SingleBodyResult& r = p.result;
        out << to_string(e.species.kind) << ',' << exact_number(e.drive.gap) << ','
            << exact_number(e.dt) << ',' << to_string(e.noise_mode) << ','
            << exact_number(e.epsilon) << ',' << exact_number(r.rotational_diffusion.mean) << ','
            << exact_number(r.rotational_diffusion.error) << ',' << exact_number(r.axial_speed.mean)
            << ',' << exact_number(r.axial_speed.error) << ','
            << exact_number(r.transverse_speed.mean) << ','
            << exact_number(r.transverse_speed.error) << ',' << exact_number(r.forward_fraction)
            << ',' << exact_number(percentile(r.period_speeds, 0.1)) << ','
            << exact_number(percentile(r.period_speeds, 0.5)) << ','
            << exact_number(percentile(r.period_speeds, 0.9)) << ',' << e.copies << ','
            << exact_number(e.duration) << ',' << r.unresolved << '\n';
    }
    return out.str();
}

// 41 bins from the smallest to the largest per-period axial speed over all points, so that
// every point's distribution is on the same axis.
std::string distribution_csv(const std::vector<PointResult>& points) {
    double lo = 1e300, hi = -1e300;
    for (const PointResult& p : points)
        for (double v : p.result.period_speeds) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    constexpr int kBins = 41;
    if (!(hi > lo)) hi = lo + 1.0;
    const double width = (hi - lo) / kBins;
    std::ostringstream out;
    out << "# rodsea " << RODSEA_VERSION
        << " speed_distribution: per-period axial speed of every copy, probability density per "
           "point; units: speed [mm/s], density [s/mm]\n";
    out << "point,gap,dt,epsilon,speed_low,speed_high,density\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::vector<double>& v = points[i].result.period_speeds;
        std::vector<double> counts(kBins, 0.0);
        for (double s : v)
            counts[std::min<std::size_t>(kBins - 1, static_cast<std::size_t>((s - lo) / width))] +=
                1.0;
        const SingleBodyExperiment& e = points[i].experiment;
        for (int b = 0; b < kBins; ++b)
            out << i << ',' << exact_number(e.drive.gap) << ',' << exact_number(e.dt) << ','
                << exact_number(e.epsilon) << ',' << exact_number(lo + b * width) << ','
                << exact_number(lo + (b + 1) * width) << ','
                << exact_number(v.empty() ? 0.0
                                          : counts[b] / (static_cast<double>(v.size()) * width))
                << '\n';
    }
    return out.str();
}

// Runs every copy of every point on `threads` worker threads, with a progress bar. Every copy
// is a task; results land in fixed slots, so the table does not depend on the thread count or on
// which thread ran what. Returns none when a stop signal came first; rethrows a copy's failure.
std::optional<std::vector<std::vector<SingleBodyTrace>>> run_copies(
    const std::vector<SingleBodyExperiment>& experiments, int copies, int threads,
    CountProgress& progress) {
    const std::size_t tasks = experiments.size() * static_cast<std::size_t>(copies);
    std::vector<std::vector<SingleBodyTrace>> traces(experiments.size(),
                                                     std::vector<SingleBodyTrace>(copies));
    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> failed{false};
    std::exception_ptr failure;  // written once, before `failed` is set
    std::mutex failure_lock;
    const auto worker = [&] {
        for (std::size_t task = next++; task < tasks; task = next++) {
            if (failed || stop_signal_received()) return;
            try {
                const std::size_t point = task / static_cast<std::size_t>(copies);
                const int copy = static_cast<int>(task % static_cast<std::size_t>(copies));
                traces[point][static_cast<std::size_t>(copy)] =
                    run_single_body_copy(experiments[point], copy);
                ++done;
            } catch (...) {
                const std::lock_guard lock(failure_lock);
                if (!failure) failure = std::current_exception();
                failed = true;
                return;
            }
        }
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back(worker);
    while (done < tasks && !failed && !stop_signal_received()) {
        progress.update(done);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    for (std::thread& t : pool)
        t.join();
    if (failure) std::rethrow_exception(failure);
    if (stop_signal_received()) return std::nullopt;
    return traces;
}

// The same on the GPU: the points grouped by dt (copies of a group step in lockstep), each group
// one ensemble of all its copies.
std::optional<std::vector<std::vector<SingleBodyTrace>>> run_copies_together(
    const std::vector<SingleBodyExperiment>& experiments, int copies, const BackendOptions& options,
    CountProgress& progress) {
    std::vector<std::vector<SingleBodyTrace>> traces(experiments.size());
    std::vector<char> done(experiments.size(), 0);
    std::size_t finished = 0;  // copies
    for (std::size_t first = 0; first < experiments.size(); ++first) {
        if (done[first]) continue;
        std::vector<std::size_t> group;
        std::vector<SingleBodyExperiment> members;
        for (std::size_t i = first; i < experiments.size(); ++i)
            if (!done[i] && experiments[i].dt == experiments[first].dt) {
                group.push_back(i);
                members.push_back(experiments[i]);
                done[i] = 1;
            }
        const double copies_in_group = static_cast<double>(group.size() * copies);
        const auto result =
            run_single_body_copies_together(members, copies, options, [&](double fraction) {
                progress.update(finished + static_cast<std::size_t>(fraction * copies_in_group));
            });
        if (!result) return std::nullopt;
        for (std::size_t k = 0; k < group.size(); ++k)
            traces[group[k]] = (*result)[k];
        finished += group.size() * static_cast<std::size_t>(copies);
    }
    return traces;
}

void print_points(const std::vector<PointResult>& points, std::ostream& out) {
    out << "  gap/mm  dt/s      ε/(1/mm)  D_r/(rad²/s)        speed/(mm/s)\n";
    for (const PointResult& p : points) {
        char line[160];
        std::snprintf(line, sizeof line,
                      "  %-6.3g  %-8.3g  %-8.4g  %8.4g ± %-8.2g  %+7.3f ± %.3f\n",
                      p.experiment.drive.gap, p.experiment.dt, p.experiment.epsilon,
                      p.result.rotational_diffusion.mean, p.result.rotational_diffusion.error,
                      p.result.axial_speed.mean, p.result.axial_speed.error);
        out << line;
    }
}

std::string read_config(const std::filesystem::path& config) {
    std::ifstream in(config);
    if (!in) throw FileError(config.string(), "cannot be read");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

int calibrate_command(const std::vector<std::string>& words, std::ostream& out, std::ostream&) {
    const std::optional<Arguments> parsed = arguments_or_help(words, calibrate_command_spec(), out);
    if (!parsed) return 0;
    const Arguments& args = *parsed;
    if (args.positional.size() != 1)
        throw InvalidParameter("CONFIG", std::to_string(args.positional.size()) + " given",
                               "exactly one config file (see rodsea calibrate --help)");
    const std::filesystem::path config = args.positional[0];
    const std::string text = read_config(config);
    const CalibrationGrid grid = parse_calibration_grid(text, config.string());
    // The machine's cores by default, within the range every --threads takes.
    const unsigned cores =
        std::clamp(std::thread::hardware_concurrency(), 1u, static_cast<unsigned>(kMaxThreads));
    const int threads = static_cast<int>(parse_count(
        "--threads", args.value("--threads").value_or(std::to_string(cores)), 1, kMaxThreads));
    BackendOptions backend;
    if (const auto b = args.value("--backend")) {
        backend.backend = backend_flag("--backend", *b);
        require_usable_backend(backend.backend, "--backend");
    }
    const std::filesystem::path dir =
        args.value("--out").value_or((std::filesystem::path("out") / config.stem()).string());
    if (std::filesystem::exists(dir) && !std::filesystem::is_directory(dir))
        throw FileError(dir.string(), "exists and is not a directory");
    std::filesystem::create_directories(dir);

    const std::vector<SingleBodyExperiment> experiments = grid.experiments();
    const bool quiet = args.has("--quiet");
    if (!quiet)
        out << "rodsea calibrate " << config.string() << ": " << experiments.size() << " points ("
            << grid.gap.size() << " gaps × " << grid.dt.size() << " dt × " << grid.epsilon.size()
            << " ε) × " << grid.copies << " copies of one " << to_string(grid.species.kind) << ", "
            << format_number(grid.warmup) << " + " << format_number(grid.duration) << " s each, "
            << (backend.backend == BackendKind::gpu ? std::string("on the GPU")
                                                    : "on " + std::to_string(threads) + " threads")
            << " → " << dir.string() << "\n";

    const StopSignalGuard stop_guard;
    CountProgress progress(out, choose_progress_style(quiet, ::isatty(STDOUT_FILENO) == 1),
                           experiments.size() * static_cast<std::size_t>(grid.copies), "copies");
    const auto traces = backend.backend == BackendKind::gpu
                            ? run_copies_together(experiments, grid.copies, backend, progress)
                            : run_copies(experiments, grid.copies, threads, progress);
    if (!traces) {
        const int signal = stop_signal_received();
        out << "\nrodsea calibrate: stopped by signal " << signal << "; nothing written\n";
        return StopRequested{signal}.exit_code();
    }
    progress.finish();

    std::vector<PointResult> points;
    for (std::size_t i = 0; i < experiments.size(); ++i) {
        const double period = 2.0 * std::numbers::pi / experiments[i].drive.angular_frequency;
        points.push_back({experiments[i], combine_single_body_traces((*traces)[i], period)});
    }
    write_file_atomically(dir / "calibration.csv", calibration_csv(points));
    write_file_atomically(dir / "speed_distribution.csv", distribution_csv(points));
    write_file_atomically(dir / "calibrate.toml", text);
    if (!quiet) {
        print_points(points, out);
        out << "wrote " << (dir / "calibration.csv").string() << ", speed_distribution.csv, "
            << "calibrate.toml\n";
    }
    return 0;
}

}  // namespace rodsea
