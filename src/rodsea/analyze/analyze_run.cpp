#include "rodsea/analyze/analyze_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <ostream>
#include <sstream>

#include "rodsea/analyze/fields_observable.hpp"
#include "rodsea/analyze/frame_context.hpp"
#include "rodsea/analyze/observable_registry.hpp"
#include "rodsea/analyze/structure_series.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/progress_file.hpp"
#include "rodsea/io/run_lock.hpp"
#include "rodsea/io/stored_run.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

namespace {

namespace fs = std::filesystem;

// The order series of the run that it recorded (runs from before Σ and N_m were recorded
// have only P and S).
std::vector<NamedSeries> recorded_order_series(const TrajectoryReader& reader,
                                               const AnalysisSetup& setup, std::size_t frames) {
    std::vector<NamedSeries> series;
    for (const std::string& column : steady_series_columns(setup)) {
        if (!reader.has_series(column)) continue;
        series.push_back({column, reader.series(column)});
        series.back().values.resize(frames);  // series() checked that it has every frame
    }
    return series;
}

// What a run still going says (its lock held; progress.txt for where it is), or "" for a run
// that no process writes.
std::string still_running(const fs::path& run_dir, double last_time) {
    if (!run_directory_in_use(run_dir)) return "";
    std::string where;
    if (const std::optional<RunProgress> p = read_progress_file(run_dir))
        where = " (t = " + format_number(p->time) + " of " + format_number(p->duration) + " s)";
    return "the run is still going" + where +
           ": this analysis covers its frames to t = " + format_number(last_time) +
           " s; analyse it again once its progress.txt says state = done";
}

}  // namespace

PreparedRun prepare_run(const fs::path& run, const AnalyzeRequest& request) {
    return prepare_run(std::vector<fs::path>{run}, request);
}

PreparedRun prepare_run(const std::vector<fs::path>& parts, const AnalyzeRequest& request) {
    PreparedRun p;
    const StoredRun stored = open_stored_run(parts);
    const TrajectoryReader& reader = stored.reader;
    p.run_dir = stored.run_dir;
    p.trajectory = stored.trajectory;
    p.parts = stored.parts;
    p.plan = stored.plan;
    p.setup = analysis_setup(p.plan);
    p.setup.blocks = request.options.blocks;
    p.times = reader.times();
    // A run whose duration is not a whole number of output intervals ends with a frame off the
    // grid: the averages and correlations need equally spaced frames, so it is left out.
    std::size_t frames = stored.grid_frames();
    if (frames < p.times.size())
        p.skipped.push_back("the last frame (t = " + format_number(p.times.back()) +
                            " s): the run ended there, off the " +
                            format_number(p.plan.control.output_interval) +
                            " s output grid, so it is not equally spaced with the others");
    p.times.resize(frames);
    p.stored_frames = frames;
    p.stored_last_time = p.times.back();
    p.setup.frame_interval = p.plan.frame_interval();
    for (std::size_t k = 1; k < frames; ++k)
        // Times are multiples of the output step: anything beyond rounding is not a rodsea run.
        if (std::abs(p.times[k] - p.times[k - 1] - p.setup.frame_interval) >
            1e-6 * p.setup.frame_interval)
            throw FileError(p.trajectory.string(),
                            "frames are not equally spaced in time: frame " + std::to_string(k) +
                                " at " + format_number(p.times[k]) + " s follows frame " +
                                std::to_string(k - 1) + " at " + format_number(p.times[k - 1]) +
                                " s, where the output interval is " +
                                format_number(p.setup.frame_interval) + " s");

    // Every frame must be complete before any work starts: the last one is read in full (a
    // file cut short fails here, not halfway through a multi-run analysis), and its body count
    // must be the config's.
    const BodyState last = stored.frame(frames - 1);
    if (static_cast<long long>(last.size()) != p.setup.total_count())
        throw FileError(p.trajectory.string(), "frames hold " + std::to_string(last.size()) +
                                                   " bodies, the stored config " +
                                                   std::to_string(p.setup.total_count()));

    SteadyWindow& w = p.window;
    const FrameSpan span =
        select_frame_span(p.times, p.setup.frame_interval, request.from, request.to);
    if (request.to) {
        // The run analysed as if it had ended at --to: the automatic start, the averages and the
        // correlations all see only the frames up to it, so a late window of a long run (or an
        // early one, to compare) needs no copy of the trajectory.
        if (span.end < frames)
            p.skipped.push_back(std::to_string(frames - span.end) + " frames after --to " +
                                format_number(*request.to) + " s (" +
                                format_number(p.times[span.end]) + " to " +
                                format_number(p.times[frames - 1]) + " s)");
        frames = span.end;
        p.times.resize(frames);
        w.to_given = true;
    }
    // A run still being written matters only where the analysis reaches its last frame.
    if (frames == p.stored_frames) p.still_running = still_running(p.run_dir, p.times.back());
    if (request.from) {
        w.first_frame = span.first;
    } else {
        w.automatic = true;
        const SteadyChoice choice =
            latest_steady_start(recorded_order_series(reader, p.setup, frames));
        w.first_frame = choice.first;
        w.basis = choice.decided_by;
        w.series = choice.series;
    }
    w.from = p.times[w.first_frame];
    p.setup.steady_frames = frames - w.first_frame;
    p.setup.frames = frames;
    // Blocks need at least one frame each; fewer than two blocks leave no error bar (NaN).
    p.setup.blocks = static_cast<int>(std::max<std::size_t>(
        1, std::min<std::size_t>(static_cast<std::size_t>(p.setup.blocks), p.setup.steady_frames)));
    p.options = resolve_analysis_options(request.options, p.setup);
    p.observables = select_observables(request.observables, p.setup, &p.skipped);
    if (std::find(p.observables.begin(), p.observables.end(), "fields") != p.observables.end())
        check_field_series_memory(p.setup, p.options);
    const std::string run_id = read_run_id(p.trajectory);
    if (!run_id.empty()) {
        // (A stream, not string +: GCC 12 warns falsely on the concatenation, -Werror=restrict.)
        std::ostringstream key;
        key << "rodsea " << RODSEA_VERSION << "|run " << run_id << "|frames " << frames
            << "|first step " << reader.steps()[0] << "|last step " << reader.steps()[frames - 1]
            << "|window "
            << (w.automatic ? std::string("automatic") : exact_number(w.from))
            // The record says whether --to ended the window, even where it is the run's end.
            << (w.to_given ? "|to" : "") << "|observables";
        for (const std::string& o : p.observables)
            key << " " << o;
        key << "|" << analysis_options_text(p.options);
        p.cache_key = key.str();
    }
    return p;
}

RunAnalysis analyze_run(const PreparedRun& run, std::ostream& log, bool quiet) {
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    RunAnalysis out;
    out.run = run;
    const std::size_t frames = run.times.size();
    if (!quiet) {
        log << "analyze " << run.run_dir.string() << ": " << frames << " frames, "
            << format_number(run.times.front()) << " to " << format_number(run.times.back())
            << " s\n";
        if (run.parts.size() > 1) {
            log << "  one run in " << run.parts.size() << " directories, joined in order:";
            for (const fs::path& part : run.parts)
                log << " " << (part.has_parent_path() ? part.parent_path() : part).string();
            log << "\n";
        }
        log << "  steady window from " << format_number(run.window.from) << " s";
        if (run.window.to_given) log << " to " << format_number(run.times.back()) << " s, --to,";
        log << " (frame " << run.window.first_frame << ", " << run.setup.steady_frames
            << " frames; ";
        if (run.window.automatic && !run.window.basis.empty()) {
            log << "automatic: the latest steady start of the order series, decided by "
                << run.window.basis << ")\n";
            for (const SeriesStart& s : run.window.series)
                log << "    " << s.name << ": steady from " << format_number(run.times[s.start])
                    << " s, n_eff = " << format_number(s.n_eff) << " in the window"
                    << (s.drifting ? "; DRIFTING: its two halves differ by > 3 errors" : "")
                    << "\n";
        } else if (run.window.automatic) {
            log << "automatic: no order-parameter series, whole run)\n";
        } else {
            log << "--from)\n";
        }
        log << "  observables:";
        for (const std::string& n : run.observables)
            log << " " << n;
        log << "\n";
        for (const std::string& s : run.skipped)
            log << "  skipped " << s << "\n";
        if (!run.still_running.empty()) log << "  NOTE: " << run.still_running << "\n";
    }
    std::vector<std::unique_ptr<Observable>> observables;
    bool any_transient = false;
    for (const std::string& name : run.observables) {
        observables.push_back(make_observable(name, run.setup, run.options));
        any_transient = any_transient || observables.back()->wants_transient();
    }
    std::vector<double> seconds(observables.size(), 0.0);
    std::vector<std::size_t> computed(observables.size(), 0);
    const StoredRun stored = open_stored_run(run.parts);
    const TrajectoryReader& reader = stored.reader;
    const std::size_t first = any_transient ? 0 : run.window.first_frame;
    std::size_t next_report = 1;
    for (std::size_t k = first; k < frames; ++k) {
        const bool steady = k >= run.window.first_frame;
        const AnalysisFrame frame =
            make_analysis_frame(stored.frame(k), run.setup.box, k, run.times[k], reader.steps()[k]);
        const int block = steady ? run.setup.block_of(k - run.window.first_frame) : 0;
        const FrameContext context(frame, run.setup.species, steady, block);
        for (std::size_t o = 0; o < observables.size(); ++o) {
            if (!steady && !observables[o]->wants_transient()) continue;
            const auto t0 = clock::now();
            observables[o]->compute(context);
            seconds[o] += std::chrono::duration<double>(clock::now() - t0).count();
            ++computed[o];
        }
        const std::size_t done = k - first + 1, total = frames - first;
        const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
        // Short analyses stay silent: a progress line only helps when there is time to wait.
        if (!quiet && done * 10 >= next_report * total && elapsed > 2.0) {
            log << "  " << done << "/" << total << " frames, " << format_duration(elapsed)
                << " elapsed, ETA "
                << format_duration(elapsed * static_cast<double>(total - done) /
                                   static_cast<double>(done))
                << "\n";
            while (next_report * total <= done * 10)
                ++next_report;
        }
    }
    for (std::size_t o = 0; o < observables.size(); ++o) {
        ObservableResults r = observables[o]->finish();
        r.frames = computed[o];
        r.seconds = seconds[o];
        out.results.push_back(std::move(r));
    }
    out.seconds = std::chrono::duration<double>(clock::now() - start).count();
    return out;
}

}  // namespace rodsea
