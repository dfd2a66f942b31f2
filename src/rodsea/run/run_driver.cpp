#include "rodsea/run/run_driver.hpp"

#include <chrono>
#include <csignal>
#include <functional>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <thread>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/cli/free_cores.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/series_csv.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/run/plan_report.hpp"
#include "rodsea/run/progress_file.hpp"
#include "rodsea/run/run_lock.hpp"
#include "rodsea/run/series_recorder.hpp"
#include "rodsea/run/steady_stop.hpp"
#include "rodsea/text_file.hpp"

namespace rodsea {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// The time-series column of the first polar species' P, shown by the progress; past the end of
// the row (so P shows as 0) when there are no polar rods.
std::size_t polar_order_column(const EngineParameters& p) {
    for (size_t s = 0; s < p.species.size(); ++s)
        if (p.species[s].kind == BodyKind::polar_rod) return 2 * s;
    return std::numeric_limits<std::size_t>::max();
}

// Everything one session of a run holds: the simulation and its open output files.
class Session {
  public:
    Session(const RunPlan& plan, Simulation sim, TrajectoryFile trajectory, SeriesCsv csv,
            std::filesystem::path dir, double wall_before)
        : plan_(plan),
          sim_(std::move(sim)),
          trajectory_(std::move(trajectory)),
          csv_(std::move(csv)),
          recorder_(plan),
          steady_(plan, recorder_.columns()),
          dir_(std::move(dir)),
          wall_before_(wall_before),
          polar_column_(polar_order_column(plan.engine)),
          frame_reserve_bytes_(2 * estimate_resources(plan).frame_bytes + kMetadataReserve),
          frames_written_(trajectory_.frames()) {}

    SeriesRecorder& recorder() { return recorder_; }
    SteadyStop& steady() { return steady_; }

    // A frame counts (and its interval closes) only once the trajectory and the CSV both hold
    // it: a failure part way leaves the count, and the interval, as a checkpoint must see them.
    void write_frame(double steps_per_second) {
        trajectory_.reserve(frame_reserve_bytes_);
        const std::vector<double> row = recorder_.row(sim_, steps_per_second);
        last_polar_order_ = polar_column_ < row.size() ? row[polar_column_] : 0.0;
        trajectory_.append_frame(sim_.step_count(), sim_.time(), sim_.bodies(), row);
        csv_.append(sim_.step_count(), sim_.time(), row);
        trajectory_.flush();
        csv_.flush();
        recorder_.start_interval();
        ++frames_written_;
        if (steady_.active()) steady_.add_row(row);
        remember_good_state();
    }

    // The state a checkpoint after a blow-up holds: the last frame's, or the resumed
    // checkpoint's until a frame is written.
    void remember_good_state() {
        last_good_ = {sim_.step_count(), frames_written_, sim_.bodies(),
                      recorder_.interval_state()};
    }

    // A state the engine should never produce (a value not finite, a body outside the plates or
    // the box) is a blow-up that the step's own bounds missed: it never reaches a frame.
    std::optional<BlowUp> invalid_state() const {
        const auto p =
            find_state_problem(plan_.engine, sim_.bodies(), sim_.time(), StateOrigin::resumed);
        if (!p) return std::nullopt;
        return BlowUp{"body " + std::to_string(p->body) + "'s " + p->field, p->value, p->allowed,
                      "a smaller time.dt, a smaller noise.epsilon or a less dense packing"};
    }

    // The frames it counts are first forced to disk, so that no crash can leave a checkpoint
    // that refers to frames the files do not have.
    void checkpoint(bool complete) {
        sync_file(dir_ / kTrajectoryFile);
        sync_file(dir_ / kSeriesFile);
        Checkpoint c;
        c.config_toml = plan_.config_toml;
        c.run_id = trajectory_.run_id();
        c.step = sim_.step_count();
        c.frames_written = frames_written_;
        c.bodies = sim_.bodies();
        // A run that ended off the output grid closed its interval early with the last row; an
        // extension (--duration) continues the interval as an uninterrupted run would.
        c.interval_accumulators =
            complete && open_interval_at_end_ ? *open_interval_at_end_ : recorder_.interval_state();
        c.wall_seconds = wall_before_ + seconds_since(started_);
        c.complete = complete;
        write_checkpoint(dir_ / kCheckpointFile, c);
        last_checkpoint_ = Clock::now();
    }

    // progress.txt is for people and monitors: a failure to write it never stops the run (a
    // full disk shows up at the next frame, which handles it).
    void write_progress(const char* state, double steps_per_second) {
        RunProgress p;
        p.state = state;
        p.step = sim_.step_count();
        p.total_steps = plan_.total_steps();
        p.time = sim_.time();
        p.duration = plan_.control.duration;
        p.steps_per_second = steps_per_second;
        p.wall_seconds = wall_before_ + seconds_since(started_);
        p.updated = unix_time_now();
        try {
            write_progress_file(dir_, p);
        } catch (const FileError&) {
        }
        last_progress_ = Clock::now();
    }

    // Steps on as many of run.threads as other processes leave cores free (FreeCoreMonitor):
    // more threads than free cores spin against each other. Said once when it first differs.
    void adapt_threads(std::ostream& out, ProgressStyle style) {
        const int requested = plan_.control.threads;
        if (requested <= 1) return;
        const int use = threads_for_free_cores(requested, cores_.sample());
        if (use == sim_.options().threads) return;
        sim_.set_threads(use);
        if (style != ProgressStyle::quiet && !told_threads_) {
            out << "\nthreads: stepping on " << use << " of run.threads = " << requested
                << ", as other processes leave " << use << " core" << (use == 1 ? "" : "s")
                << " free (rechecked every " << kProgressSeconds
                << " s; the trajectory does not depend on it)\n"
                << std::flush;
            told_threads_ = true;
        }
    }

    // Steps to the end, or until a signal or a write failure. Returns an ExitCode.
    int run(std::ostream& out, std::ostream& err, ProgressStyle style) {
        const std::uint64_t total = plan_.total_steps();
        const std::uint64_t per_output = plan_.steps_per_output();
        const double checkpoint_seconds = plan_.control.checkpoint_interval * 60.0;
        ProgressReporter progress(out, style, sim_.step_count(), total, plan_.engine.dt);
        last_checkpoint_ = Clock::now();
        rate_ = [&progress] { return progress.steps_per_second(); };
        write_progress("running", 0.0);
        if (const int signal = stop_signal_received(); signal != 0)  // during the build
            return stop_on_signal(signal, out, err);
        if (plan_.control.threads > 1) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));  // a first measure
            adapt_threads(out, style);
        }
        while (sim_.step_count() < total) {
            try {
                sim_.step();
            } catch (const BlowUpError& e) {
                progress.finish(e.step(), last_polar_order_);
                return stop_after_blow_up(e.blow_up(), e.step(), out, err);
            }
            recorder_.accumulate(sim_.last_step());
            const std::uint64_t step = sim_.step_count();
            const bool on_grid = step % per_output == 0;
            if (on_grid || step == total) {
                if (const std::optional<BlowUp> b = invalid_state()) {
                    progress.finish(step, last_polar_order_);
                    return stop_after_blow_up(*b, step, out, err);
                }
            }
            try {
                if (step == total && !on_grid) open_interval_at_end_ = recorder_.interval_state();
                if (on_grid || step == total) write_frame(progress.steps_per_second());
            } catch (const FileError& e) {
                progress.finish(step, last_polar_order_);
                return stop_after_write_failure(e, out, err);
            }
            progress.update(step, last_polar_order_);
            if (on_grid) {
                if (const std::optional<SteadyVerdict> v = steady_.verdict()) {
                    progress.finish(step, last_polar_order_);
                    return finish(out, err, style, v);
                }
            }
            if (const int signal = stop_signal_received(); signal != 0) {
                progress.finish(step, last_polar_order_);
                return stop_on_signal(signal, out, err);
            }
            if ((step & 63u) == 0 && seconds_since(last_progress_) >= kProgressSeconds) {
                write_progress("running", progress.steps_per_second());
                adapt_threads(out, style);
            }
            if ((step & 63u) == 0 && seconds_since(last_checkpoint_) >= checkpoint_seconds) {
                try {
                    checkpoint(false);
                } catch (const FileError& e) {
                    err << "rodsea: cannot write the checkpoint: " << e.what()
                        << "\n  the previous checkpoint is intact; stopping. Continue with: "
                           "rodsea run --resume "
                        << dir_.string() << "\n";
                    return kExitIoError;
                }
            }
        }
        progress.finish(sim_.step_count(), last_polar_order_);
        return finish(out, err, style, std::nullopt);
    }

  private:
    // The run's end: at its duration, or earlier once steady (`verdict`).
    int finish(std::ostream& out, std::ostream& err, ProgressStyle style,
               const std::optional<SteadyVerdict>& verdict) {
        try {
            // Closed first: a run is marked complete only with its trajectory whole.
            trajectory_.close();
            checkpoint(true);
            write_progress(verdict ? "steady" : "done", rate_());
        } catch (const FileError& e) {
            err << "rodsea: the run reached its end but its files could not be closed: " << e.what()
                << "\n  the last checkpoint is intact; continue with: rodsea run "
                << "--resume " << dir_.string() << "\n";
            return kExitIoError;
        }
        if (style == ProgressStyle::quiet) return kExitOk;
        if (verdict) {
            const double frame_time =
                static_cast<double>(plan_.steps_per_output()) * plan_.engine.dt;
            out << "steady: the window from "
                << format_number(frame_time * static_cast<double>(verdict->first_frame))
                << " s (decided by " << verdict->decided_by
                << ") holds n_eff = " << format_number(verdict->n_eff) << " independent samples of "
                << verdict->counted << " >= time.steady_samples = " << plan_.control.steady_samples
                << "; stopped at t = " << sim_.time() << " s of at most " << plan_.control.duration
                << " s\n";
        }
        report_end(out);
        return kExitOk;
    }

    int stop_on_signal(int signal, std::ostream& out, std::ostream& err) {
        const char* what = signal == SIGINT   ? "interrupted (SIGINT)"
                           : signal == SIGHUP ? "hung up (SIGHUP)"
                                              : "terminated (SIGTERM)";
        try {
            checkpoint(false);
            trajectory_.close();
            write_progress("stopped", rate_());
            err << "rodsea: " << what << " at step " << sim_.step_count() << " (t = " << sim_.time()
                << " s); checkpoint written.\n  continue with: rodsea run --resume "
                << dir_.string() << "\n";
        } catch (const FileError& e) {
            err << "rodsea: " << what << ", but the checkpoint could not be written: " << e.what()
                << "\n  the previous checkpoint is intact; continue from it with: rodsea run "
                   "--resume "
                << dir_.string() << "\n";
            out.flush();
            return kExitIoError;
        }
        out.flush();
        return signal == SIGINT ? kExitInterrupted : kExitTerminated;
    }

    // The state after a blow-up is meaningless: the checkpoint holds the last frame's state,
    // which passed every check, and the files end with that frame.
    int stop_after_blow_up(const BlowUp& b, std::uint64_t step, std::ostream& out,
                           std::ostream& err) {
        const double dt = plan_.engine.dt;
        err << "rodsea: the simulation blew up at step " << step
            << " (t = " << format_number(static_cast<double>(step) * dt) << " s): " << b.what
            << " is " << b.value << ", beyond " << b.bound << ".\n  what to change: " << b.advice
            << ".\n";
        try {
            trajectory_.close();
            Checkpoint c;
            c.config_toml = plan_.config_toml;
            c.step = last_good_.step;
            c.frames_written = last_good_.frames;
            c.bodies = last_good_.bodies;
            c.interval_accumulators = last_good_.interval;
            c.wall_seconds = wall_before_ + seconds_since(started_);
            c.run_id = trajectory_.run_id();
            write_checkpoint(dir_ / kCheckpointFile, c);
            write_progress("blown_up", rate_());
            err << "  the last good state (frame " << last_good_.frames - 1
                << ", t = " << format_number(static_cast<double>(last_good_.step) * dt)
                << " s) is checkpointed and the trajectory ends there; resuming would repeat the "
                   "same steps: change the config and start again with --overwrite\n";
        } catch (const FileError& e) {
            err << "  and the last good state could not be checkpointed: " << e.what() << "\n";
        }
        out.flush();
        return kExitBlownUp;
    }

    int stop_after_write_failure(const FileError& e, std::ostream& out, std::ostream& err) {
        // HDF5 cannot be trusted to close a file whose writes failed: it is left as it is. The
        // room claimed for the frame goes back, for the checkpoint.
        trajectory_.abandon();
        trajectory_.release_reserve();
        write_progress("stopped", rate_());
        err << "rodsea: cannot write output at step " << sim_.step_count()
            << " (t = " << sim_.time() << " s): " << e.what() << "\n";
        try {
            checkpoint(false);
            err << "  checkpoint written (" << frames_written_
                << " complete frames are kept); make room (disk space, quota or file-size "
                   "limit) and continue with: rodsea run --resume "
                << dir_.string() << "\n";
        } catch (const FileError& again) {
            err << "  the checkpoint could not be written either (" << again.what()
                << "); the previous checkpoint is intact: make room and resume from it with: "
                   "rodsea run --resume "
                << dir_.string() << "\n";
        }
        out.flush();
        return kExitIoError;
    }

    void report_end(std::ostream& out) const {
        const RunTotals& t = sim_.totals();
        out << "done: " << sim_.step_count() << " steps, t = " << sim_.time() << " s, "
            << frames_written_ << " frames in " << (dir_ / kTrajectoryFile).string()
            << "\n      this session: largest overlap " << t.max_overlap_fraction * 100
            << " % of a radius, unresolved contacts " << t.unresolved << ", most sweeps "
            << t.max_sweeps << "; wall time of the whole run "
            << format_duration(wall_before_ + seconds_since(started_)) << "\n      state hash "
            << std::hex << sim_.state_hash() << std::dec << "\n";
    }

    const RunPlan& plan_;
    Simulation sim_;
    TrajectoryFile trajectory_;
    SeriesCsv csv_;
    SeriesRecorder recorder_;
    SteadyStop steady_;
    std::filesystem::path dir_;
    double wall_before_;
    std::size_t polar_column_;
    // Room for two frames and HDF5's growing chunk indexes (a few kB per frame at most): a frame
    // must never run out of space half-way (see TrajectoryFile::reserve).
    static constexpr std::uint64_t kMetadataReserve = 64 * 1024;
    std::uint64_t frame_reserve_bytes_;
    std::uint64_t frames_written_;
    double last_polar_order_ = 0.0;
    std::optional<std::vector<double>> open_interval_at_end_;  // before the off-grid last row
    // The state at the last frame written, for a checkpoint after a blow-up.
    struct GoodState {
        std::uint64_t step = 0, frames = 0;
        BodyState bodies;
        std::vector<double> interval;
    } last_good_;
    Clock::time_point started_ = Clock::now();
    Clock::time_point last_checkpoint_ = Clock::now();
    Clock::time_point last_progress_ = Clock::now();
    FreeCoreMonitor cores_;
    bool told_threads_ = false;
    static constexpr double kProgressSeconds = 2.0;      // wall time between progress.txt updates
    std::function<double()> rate_ = [] { return 0.0; };  // this session's steps/s
};

// Frames a run has written once it has done `step` steps: frame 0, one per output interval,
// and the last step's.
std::uint64_t frames_due(const RunPlan& plan, std::uint64_t step) {
    const std::uint64_t per = plan.steps_per_output(), total = plan.total_steps();
    return step / per + 1 + (step == total && total % per != 0 ? 1 : 0);
}

bool is_empty_directory(const std::filesystem::path& dir) {
    return std::filesystem::is_directory(dir) && std::filesystem::is_empty(dir);
}

// Refuses a directory that holds anything unless --overwrite, and creates it. True when it
// did not exist.
bool prepare_output_directory(const std::filesystem::path& dir, bool overwrite) {
    std::error_code ec;
    const bool existed = std::filesystem::exists(dir, ec);
    if (existed) {
        if (!std::filesystem::is_directory(dir, ec))
            throw FileError(dir.string(), "exists and is not a directory");
        if (!is_empty_directory(dir) && !overwrite) {
            // Without a checkpoint there is nothing --resume could continue.
            const bool resumable = std::filesystem::exists(dir / kCheckpointFile, ec);
            throw InvalidParameter(
                "--out", dir.string(), "a new or empty directory",
                resumable ? "it exists and is not empty: choose another --out, add --overwrite "
                            "to replace its run files, or continue it with rodsea run --resume " +
                                dir.string()
                          : "it exists and is not empty, and has no checkpoint to resume (a run "
                            "stopped before its first checkpoint?): choose another --out, or add "
                            "--overwrite to start again there");
        }
    }
    std::filesystem::create_directories(dir, ec);
    if (ec) throw FileError(dir.string(), "cannot create the output directory: " + ec.message());
    return !existed;
}

// --overwrite removes only the files a run writes and the analysis of them (rodsea analyze's
// RUN_DIR/analysis/, which would otherwise describe the old run); anything else stays.
void remove_run_files(const std::filesystem::path& dir) {
    std::error_code ec;
    for (const char* name :
         {kConfigFile, kTrajectoryFile, kSeriesFile, kCheckpointFile, kProgressFile})
        std::filesystem::remove(dir / name, ec);
    std::filesystem::remove_all(dir / "analysis", ec);
}

}  // namespace

int start_run(const RunPlan& plan, const RunOptions& options, std::ostream& out, std::ostream& err,
              bool progress_is_terminal) {
    // From here on a signal asks for a clean stop, and a file-size limit fails a write instead
    // of killing the process.
    StopSignalGuard signals;
    const PackingCheck packing = check_packing(plan.engine, plan.counts);
    if (!packing.ok)
        throw InvalidParameter("species", "these counts", "a packing that fits", packing.message);
    check_steady_series(plan);
    check_fits_in_memory(plan);
    require_usable_backend(plan.control.backend, "run.backend");
    const bool created = prepare_output_directory(options.out_dir, options.overwrite);
    const std::filesystem::path& dir = options.out_dir;
    const RunDirectoryLock lock(dir);
    if (options.overwrite) remove_run_files(dir);
    // A start that fails before its first checkpoint (the build runs out of memory, a signal
    // during the build) leaves nothing to resume: a directory it created goes with it.
    struct RemoveUnlessStarted {
        const std::filesystem::path& dir;
        bool armed;
        ~RemoveUnlessStarted() {
            std::error_code ignored;
            if (armed) std::filesystem::remove_all(dir, ignored);
        }
    } cleanup{dir, created};
    // Flushed at once: with stdout going to a file, the plan and the start would otherwise
    // appear only with the first progress line, minutes later.
    if (!options.quiet) {
        out << "rodsea run -> " << dir.string() << "\n";
        describe_plan(plan, out, true);
        out << std::flush;
    }

    BuildReport built;
    BodyState bodies =
        build_initial_state(plan.engine, plan.counts, plan.builder, plan.engine.seed, &built);
    if (!options.quiet) {
        // Dense starts keep some order (docs/builder.md): say how they were built and how much.
        std::ostringstream line;
        line.precision(3);
        line << "initial state built in " << built.seconds << " s: " << describe_start(built)
             << ", then " << built.sweeps << " Monte Carlo sweeps; order at the start:";
        for (size_t s = 0; s < plan.engine.species.size(); ++s)
            if (plan.engine.species[s].kind != BodyKind::bead)
                line << " " << plan.engine.species[s].name << " P = " << built.polar_order.at(s)
                     << ", S = " << built.nematic_order.at(s) << ";";
        out << line.str() << std::endl;
    }
    Simulation sim(plan.engine, std::move(bodies),
                   {.threads = plan.control.threads, .backend = plan.control.backend});
    write_file_atomically(dir / kConfigFile, plan.config_toml);
    const SeriesRecorder columns(plan);
    TrajectoryFile trajectory =
        TrajectoryFile::create(dir / kTrajectoryFile, plan.engine, sim.bodies().species,
                               plan.config_toml, columns.columns());
    SeriesCsv csv = SeriesCsv::create(dir / kSeriesFile, columns.columns());
    Session session(plan, std::move(sim), std::move(trajectory), std::move(csv), dir, 0.0);
    try {
        session.write_frame(0.0);
        session.checkpoint(false);
        cleanup.armed = false;
    } catch (const FileError& e) {
        err << "rodsea: cannot write the run's first frame and checkpoint: " << e.what()
            << "\n  there is nothing to resume: make room and start again with --overwrite\n";
        return kExitIoError;
    }
    return session.run(out, err, choose_progress_style(options.quiet, progress_is_terminal));
}

namespace {

// Everything about a checkpoint is checked against its plan before any file is touched.
void check_checkpoint(const Checkpoint& c, const RunPlan& plan, const std::filesystem::path& path) {
    std::uint64_t expected = 0;
    for (long long n : plan.counts)
        expected += static_cast<std::uint64_t>(n);
    if (c.bodies.size() != expected)
        throw FileError(path.string(), "holds " + std::to_string(c.bodies.size()) +
                                           " bodies but its config asks for " +
                                           std::to_string(expected));
    const std::string interval = SeriesRecorder(plan).interval_problem(c.interval_accumulators);
    if (!interval.empty())
        throw FileError(
            path.string(),
            "damaged: dataset interval_accumulators (the time series' open interval): " + interval);
}

// The first line where two config texts differ, as "`a` here, `b` there".
std::string first_difference(const std::string& here, const std::string& there) {
    std::istringstream a(here), b(there);
    std::string la, lb;
    while (true) {
        const bool more_a = static_cast<bool>(std::getline(a, la));
        const bool more_b = static_cast<bool>(std::getline(b, lb));
        if (!more_a && !more_b) return "they differ";
        if (!more_a) la = "(nothing)";
        if (!more_b) lb = "(nothing)";
        if (la != lb || !more_a || !more_b) return "`" + la + "` against `" + lb + "`";
    }
}

// A checkpoint resumes only the run it was written by: the trajectory's run id, the config
// stored in the trajectory and in config.toml (or, during an extension not yet written to
// every file, the config it extends), the frames it counts, and a state that the engine could
// have produced. Checked before any file is touched; every refusal names the file and what
// differs.
void check_belongs_here(const std::filesystem::path& dir, const Checkpoint& c,
                        const RunPlan& plan) {
    const std::filesystem::path checkpoint = dir / kCheckpointFile,
                                trajectory = dir / kTrajectoryFile, config = dir / kConfigFile;
    if (!std::filesystem::exists(trajectory))
        throw FileError(trajectory.string(),
                        "missing: the checkpoint continues the frames it holds (start the run "
                        "again with rodsea run CONFIG --out DIR --overwrite)");
    const std::string id = read_run_id(trajectory);
    if (id != c.run_id)
        throw FileError(checkpoint.string(),
                        "belongs to another run: its run id is " +
                            (c.run_id.empty() ? std::string("none (an older rodsea)") : c.run_id) +
                            ", trajectory.h5's is " + (id.empty() ? std::string("none") : id) +
                            " (copied from another run directory?); nothing was changed");
    const std::string mine = config_fingerprint(c.config_toml);
    const auto check_config = [&](const std::filesystem::path& file, const std::string& text) {
        const std::string theirs = config_fingerprint(text);
        if (theirs == mine || (!c.extending_from.empty() && theirs == c.extending_from)) return;
        throw FileError(file.string(),
                        "holds another config than the checkpoint (" +
                            first_difference(text, c.config_toml) +
                            "): a run resumes with the config it started with (extend it with "
                            "--duration T); restore the file or start again with --overwrite");
    };
    check_config(trajectory.string() + ":/parameters/rodsea/config",
                 read_stored_config(trajectory));
    if (std::filesystem::exists(config)) check_config(config, read_text_file(config));
    const TrajectoryReader reader(trajectory);
    if (reader.frames() < c.frames_written)
        throw FileError(trajectory.string(), "holds " + std::to_string(reader.frames()) +
                                                 " frames but the checkpoint " + "counts " +
                                                 std::to_string(c.frames_written) +
                                                 " (the file was replaced or damaged)");
    if (c.frames_written > 0) {
        const std::uint64_t k = c.frames_written - 1;
        const std::uint64_t expected = std::min(k * plan.steps_per_output(), plan.total_steps());
        const std::int64_t stored = reader.steps()[k];
        if (stored != static_cast<std::int64_t>(expected))
            throw FileError(trajectory.string(),
                            "frame " + std::to_string(k) + " is at step " + std::to_string(stored) +
                                " where the checkpoint's config puts it at step " +
                                std::to_string(expected));
    }
    const double time = static_cast<double>(c.step) * plan.engine.dt;
    std::optional<StateProblem> problem =
        find_state_problem(plan.engine, c.bodies, time, StateOrigin::resumed);
    if (!problem) problem = find_gross_overlap(plan.engine, c.bodies);
    if (problem) {
        const std::string dataset = problem->field.substr(0, problem->field.find('.'));
        throw FileError(checkpoint.string(),
                        "impossible state: dataset " + dataset + ", body " +
                            std::to_string(problem->body) + " at step " + std::to_string(c.step) +
                            ": " + problem->field + " " + problem->value +
                            "; allowed: " + problem->allowed +
                            (problem->detail.empty() ? "" : " (" + problem->detail + ")"));
    }
}

// The plan of a run given a new length (--duration, --steady-samples), checked against what the
// run has done.
RunPlan extended_plan(const Checkpoint& c, const RunOptions& options,
                      const std::filesystem::path& path) {
    RunPlan plan = with_run_length(c.config_toml, path.string() + " [config]", options.duration,
                                   options.steady_samples);
    check_steady_series(plan);
    if (plan.total_steps() < c.step)
        throw InvalidParameter("--duration", format_number(plan.control.duration) + " s",
                               "at least the " +
                                   format_number(static_cast<double>(c.step) * plan.engine.dt) +
                                   " s already simulated");
    return plan;
}

// Makes the checkpoint and config.toml those of the extended run. A complete run that ended off
// the output grid wrote a last frame that an uninterrupted longer run does not have: it is
// dropped (the files are truncated to the frames the checkpoint counts when they are reopened),
// so that the extension is bit for bit the longer run. The checkpoint is written before any file
// changes: a crash in between resumes the extension, never a run whose checkpoint counts frames
// that are gone.
void commit_extension(const std::filesystem::path& dir, const RunPlan& plan, Checkpoint& c) {
    const std::filesystem::path path = dir / kCheckpointFile;
    const std::uint64_t due = frames_due(plan, c.step);
    const bool extra_last_frame = c.complete && c.frames_written == due + 1;
    if (c.frames_written != due && c.frames_written + 1 != due && !extra_last_frame)
        throw FileError(path.string(), "counts " + std::to_string(c.frames_written) +
                                           " frames at step " + std::to_string(c.step) +
                                           ": not a checkpoint of this run's config");
    if (extra_last_frame) c.frames_written = due;
    c.complete = false;
    if (c.config_toml != plan.config_toml) c.extending_from = config_fingerprint(c.config_toml);
    c.config_toml = plan.config_toml;
    write_checkpoint(path, c);
    write_file_atomically(dir / kConfigFile, plan.config_toml);
}

}  // namespace

int resume_run(const std::filesystem::path& dir, const RunOptions& options, std::ostream& out,
               std::ostream& err, bool progress_is_terminal) {
    StopSignalGuard signals;
    const std::filesystem::path checkpoint_path = dir / kCheckpointFile;
    if (!std::filesystem::exists(checkpoint_path))
        throw FileError(checkpoint_path.string(),
                        std::filesystem::exists(dir / kConfigFile)
                            ? "no checkpoint here: the run stopped before its first checkpoint, "
                              "so there is nothing to resume; start it again with rodsea run " +
                                  (dir / kConfigFile).string() + " --out " + dir.string() +
                                  " --overwrite"
                            : "no checkpoint here: is this a directory made by rodsea run?");
    const RunDirectoryLock lock(dir);
    Checkpoint c = read_checkpoint(checkpoint_path);
    const RunPlan stored =
        load_config_string(c.config_toml, checkpoint_path.string() + " [config]");
    check_checkpoint(c, stored, checkpoint_path);
    check_belongs_here(dir, c, stored);
    const bool extending = options.duration || options.steady_samples;
    const RunPlan plan = extending ? extended_plan(c, options, checkpoint_path) : stored;
    check_fits_in_memory(plan);
    const BackendKind backend = options.backend.value_or(plan.control.backend);
    require_usable_backend(backend, options.backend ? "--backend" : "run.backend");
    if (c.complete && (!extending || plan.total_steps() == c.step)) {
        if (!options.quiet)
            out << "rodsea: the run in " << dir.string() << " is already complete (step " << c.step
                << ", t = " << static_cast<double>(c.step) * plan.engine.dt
                << " s); nothing to do. Extend it with --duration T.\n";
        return kExitOk;
    }
    if (extending) commit_extension(dir, plan, c);
    // A run stopped by a failed write has its checkpoint at the step whose frame failed: that
    // frame comes first, from the same state and interval, as the uninterrupted run wrote it.
    const std::uint64_t due = frames_due(plan, c.step);
    if (c.step > plan.total_steps() || (c.frames_written != due && c.frames_written + 1 != due))
        throw FileError(checkpoint_path.string(),
                        "counts " + std::to_string(c.frames_written) + " frames at step " +
                            std::to_string(c.step) + ", where the run writes " +
                            std::to_string(due) + ": not a checkpoint of this run's config");
    if (!options.quiet) {
        out << "rodsea run --resume " << dir.string() << ": from step " << c.step << " of "
            << plan.total_steps() << " (t = " << static_cast<double>(c.step) * plan.engine.dt
            << " s of " << plan.control.duration << " s), " << c.frames_written << " frames kept"
            << (extending ? "; extended, config.toml updated" : "") << std::endl;
        if (backend != plan.control.backend)
            out << "backend: " << to_string(backend) << " for this session (the run's config "
                << "says " << to_string(plan.control.backend)
                << "): the trajectory goes on statistically, not bit for bit, as the run would "
                   "have"
                << std::endl;
    }
    const SeriesRecorder columns(plan);
    Simulation sim = Simulation::resume(plan.engine, std::move(c.bodies), c.step,
                                        {.threads = plan.control.threads, .backend = backend});
    SeriesCsv csv = SeriesCsv::reopen(dir / kSeriesFile, c.frames_written);
    std::optional<SteadyStop> history;
    if (plan.control.steady_samples > 0) {
        history.emplace(plan, columns.columns());
        history->restore(TrajectoryReader(dir / kTrajectoryFile), c.frames_written);
    }
    TrajectoryFile trajectory =
        TrajectoryFile::reopen(dir / kTrajectoryFile, c.frames_written, columns.columns());
    // An extension interrupted before every file said its new length is finished here.
    if (read_stored_config(dir / kTrajectoryFile) != plan.config_toml)
        trajectory.replace_config(plan.config_toml);
    if (!extending && (!std::filesystem::exists(dir / kConfigFile) ||
                       read_text_file(dir / kConfigFile) != plan.config_toml))
        write_file_atomically(dir / kConfigFile, plan.config_toml);
    Session session(plan, std::move(sim), std::move(trajectory), std::move(csv), dir,
                    c.wall_seconds);
    session.recorder().restore_interval(c.interval_accumulators);
    session.remember_good_state();
    if (history) session.steady() = std::move(*history);
    if (c.frames_written + 1 == due) {
        try {
            session.write_frame(0.0);
        } catch (const FileError& e) {
            err << "rodsea: still cannot write: " << e.what()
                << "\n  the checkpoint is intact; make room and resume again\n";
            return kExitIoError;
        }
    }
    return session.run(out, err, choose_progress_style(options.quiet, progress_is_terminal));
}

}  // namespace rodsea
