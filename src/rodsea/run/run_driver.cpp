#include "rodsea/run/run_driver.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <thread>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/cli/free_cores.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/ensemble.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/progress_file.hpp"
#include "rodsea/io/run_lock.hpp"
#include "rodsea/io/series_csv.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/run/checkpoint_checks.hpp"
#include "rodsea/run/output_directory.hpp"
#include "rodsea/run/plan_report.hpp"
#include "rodsea/run/run_session.hpp"
#include "rodsea/run/series_recorder.hpp"
#include "rodsea/run/steady_stop.hpp"
#include "rodsea/text_file.hpp"

namespace rodsea {

namespace {

// One directory named twice would have two writers (the lock would refuse the second only
// after the first had started): refused before any work, as every other input problem.
void check_distinct(const std::vector<std::filesystem::path>& dirs) {
    std::set<std::filesystem::path> seen;
    for (const std::filesystem::path& dir : dirs) {
        if (!seen.insert(directory_key(dir)).second)
            throw InvalidParameter(
                "run directory", dir.string(), "each run's own directory",
                "two runs of one command would write the same directory "
                "(configs with the same file name go to the same directory: rename one)");
    }
}

// Steps the ensemble until every session's run has ended, each as its session decides.
// `codes[i]` receives session i's exit code. The progress follows the run with the most steps
// left; a run's messages end the bar's line first.
class EnsembleLoop {
  public:
    EnsembleLoop(Ensemble& ensemble, std::vector<RunSession*> sessions, int threads,
                 ProgressStyle style, std::ostream& out, std::ostream& err)
        : ensemble_(ensemble),
          active_(std::move(sessions)),
          requested_threads_(threads),
          threads_(threads),
          style_(style),
          out_(out),
          err_(err) {
        for (std::size_t m = 0; m < active_.size(); ++m)
            active_[m]->attach(ensemble_, m);
    }

    // Session i's exit code by its place in the sessions given.
    std::vector<int> run() {
        std::vector<int> codes(active_.size(), kExitOk);
        for (std::size_t m = 0; m < active_.size(); ++m)
            order_.push_back(m);
        follow_lead();
        for (RunSession* s : active_)
            s->write_progress("running", 0.0);
        if (const int signal = stop_signal_received(); signal != 0)  // during the build
            return stop_all(signal, codes);
        if (requested_threads_ > 1) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));  // a first measure
            adapt_threads();
        }
        // Read only when a frame, an end or a progress file needs it: it reads the clock.
        const std::function<double()> rate = [this] { return progress_->steps_per_second(); };
        const RunSession::BeforePrinting settle = [this] { settle_progress(); };
        while (!active_.empty()) {
            const std::uint64_t steps = steps_this_time();
            const auto started = std::chrono::steady_clock::now();
            try {
                ensemble_.run(steps);
            } catch (const BlowUpError&) {
                // Each system's blow-up is read below; the others stepped as usual.
            }
            pace(steps, seconds_since(started));
            std::vector<std::size_t> ended;
            for (std::size_t m = 0; m < active_.size(); ++m) {
                RunSession& s = *active_[m];
                std::optional<int> code;
                if (const std::optional<BlowUp>& b = ensemble_.blow_up(m)) {
                    settle_progress();
                    code = s.stop_after_blow_up(*b, s.step_count(), rate(), out_, err_);
                } else {
                    code = s.after_step(rate, out_, err_, style_, settle);
                }
                if (code) {
                    codes[order_[m]] = *code;
                    ended.push_back(m);
                }
            }
            if (!settled_) progress_->update(lead_->step_count(), lead_->polar_order());
            if (const int signal = stop_signal_received(); signal != 0) {
                retire(ended);
                return stop_all(signal, codes);
            }
            for (std::size_t m = 0; m < active_.size(); ++m) {
                if (std::find(ended.begin(), ended.end(), m) != ended.end()) continue;
                if (const auto code = active_[m]->between_steps(rate(), err_, settle)) {
                    codes[order_[m]] = *code;
                    ended.push_back(m);
                }
            }
            if (seconds_since(last_threads_check_) >= kThreadsCheckSeconds) adapt_threads();
            if (!ended.empty()) retire(ended);
        }
        return codes;
    }

  private:
    static double seconds_since(std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    }

    // The ensemble steps in runs (a device reads its statistics once per run): up to the next
    // step at which some session has a frame to write or ends, no more than 1 % of the lead
    // run's steps (the progress moves by at most that), and short enough in wall time that a
    // signal, a checkpoint or the progress waits at most about kRunSeconds.
    std::uint64_t steps_this_time() const {
        std::uint64_t steps =
            std::min(steps_per_run_, std::max<std::uint64_t>(1, lead_->plan().total_steps() / 100));
        for (const RunSession* s : active_)
            steps = std::min(steps, s->steps_to_next_output());
        return steps;
    }
    // Runs grow while they take well under kRunSeconds and shrink when they take more.
    void pace(std::uint64_t steps, double seconds) {
        if (steps < steps_per_run_) return;  // cut short by an output: says nothing
        if (seconds < 0.25 * kRunSeconds && steps_per_run_ < kMostStepsPerRun)
            steps_per_run_ *= 2;
        else if (seconds > kRunSeconds && steps_per_run_ > 1)
            steps_per_run_ /= 2;
    }

    // The progress follows the run with the most steps left (the first of them), from here.
    void follow_lead() {
        if (active_.empty()) return;
        lead_ = active_.front();
        for (RunSession* s : active_)
            if (s->steps_left() > lead_->steps_left()) lead_ = s;
        progress_ = std::make_unique<ProgressReporter>(out_, style_, lead_->step_count(),
                                                       lead_->plan().total_steps(),
                                                       lead_->plan().engine.dt);
        settled_ = false;
        if (active_.size() > 1 && style_ != ProgressStyle::quiet)
            out_ << "progress: " << lead_->dir().string()
                 << ", the run with the most steps left of " << active_.size() << std::endl;
    }

    // Ends the progress line before a message; a new one starts after the step.
    void settle_progress() {
        if (settled_) return;
        progress_->finish(lead_->step_count(), lead_->polar_order());
        settled_ = true;
    }

    // Drops the runs that ended from the ensemble; the others step on, bit for bit.
    void retire(std::vector<std::size_t> ended) {
        if (ended.empty()) return;
        std::sort(ended.begin(), ended.end());
        ensemble_.retire(ended);
        for (std::size_t k = ended.size(); k-- > 0;) {
            active_.erase(active_.begin() + static_cast<std::ptrdiff_t>(ended[k]));
            order_.erase(order_.begin() + static_cast<std::ptrdiff_t>(ended[k]));
        }
        for (std::size_t m = 0; m < active_.size(); ++m)
            active_[m]->attach(ensemble_, m);
        if (settled_) follow_lead();
    }

    std::vector<int> stop_all(int signal, std::vector<int>& codes) {
        settle_progress();
        const double rate = progress_->steps_per_second();
        for (std::size_t m = 0; m < active_.size(); ++m)
            codes[order_[m]] = active_[m]->stop_on_signal(signal, rate, out_, err_);
        return codes;
    }

    // Steps on as many of the threads asked for as other processes leave cores free
    // (FreeCoreMonitor): more threads than free cores spin against each other. Said once when
    // it first differs.
    void adapt_threads() {
        last_threads_check_ = std::chrono::steady_clock::now();
        if (requested_threads_ <= 1) return;
        const int use = threads_for_free_cores(requested_threads_, cores_.sample());
        if (use == threads_) return;
        ensemble_.set_threads(use);
        threads_ = use;
        if (style_ != ProgressStyle::quiet && !told_threads_) {
            out_ << "\nthreads: stepping on " << use << " of run.threads = " << requested_threads_
                 << ", as other processes leave " << use << " core" << (use == 1 ? "" : "s")
                 << " free (rechecked every " << kThreadsCheckSeconds
                 << " s; the trajectory does not depend on it)\n"
                 << std::flush;
            told_threads_ = true;
        }
    }

    Ensemble& ensemble_;
    std::vector<RunSession*> active_;
    std::vector<std::size_t> order_;  // each active session's place in the sessions given
    RunSession* lead_ = nullptr;
    std::unique_ptr<ProgressReporter> progress_;
    bool settled_ = true;
    int requested_threads_, threads_;
    ProgressStyle style_;
    std::ostream& out_;
    std::ostream& err_;
    FreeCoreMonitor cores_;
    bool told_threads_ = false;
    std::chrono::steady_clock::time_point last_threads_check_ = std::chrono::steady_clock::now();
    static constexpr double kThreadsCheckSeconds = 2.0;
    static constexpr double kRunSeconds = 0.5;
    static constexpr std::uint64_t kMostStepsPerRun = std::uint64_t{1} << 20;
    std::uint64_t steps_per_run_ = 1;
};

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
    // A continuation's file holds the run's frames from its first_frame on.
    const TrajectoryReader reader(trajectory);
    if (reader.species() != c.bodies.species)
        throw FileError(trajectory.string(),
                        "holds other bodies (/particles/bodies/species) than the checkpoint: a "
                        "run resumes with the bodies it started with");
    const std::uint64_t first = read_first_frame(trajectory);
    if (first > c.frames_written || reader.frames() < c.frames_written - first) {
        const std::string held = first == 0
                                     ? std::to_string(reader.frames()) + " frames"
                                     : "the run's frames " + std::to_string(first) + " to " +
                                           std::to_string(first + reader.frames()) + " (exclusive)";
        throw FileError(trajectory.string(), "holds " + held + " but the checkpoint counts " +
                                                 std::to_string(c.frames_written) +
                                                 " (the file was replaced or damaged)");
    }
    if (c.frames_written > first) {
        const std::uint64_t k = c.frames_written - 1;
        const std::uint64_t expected = std::min(k * plan.steps_per_output(), plan.total_steps());
        const std::int64_t stored = reader.steps()[k - first];
        if (stored != static_cast<std::int64_t>(expected))
            throw FileError(trajectory.string(),
                            "frame " + std::to_string(k) + " is at step " + std::to_string(stored) +
                                " where the checkpoint's config puts it at step " +
                                std::to_string(expected));
    }
    check_checkpoint_state(c, plan, checkpoint);
}

// Makes the checkpoint and config.toml those of the extended run. A complete run that ended off
// the output grid wrote a last frame that an uninterrupted longer run does not have: it is
// dropped (the files are truncated to the frames the checkpoint counts when they are reopened),
// so that the extension is bit for bit the longer run. The checkpoint is written before any file
// changes: a crash in between resumes the extension, never a run whose checkpoint counts frames
// that are gone.
void commit_extension(const std::filesystem::path& dir, const RunPlan& plan, Checkpoint& c) {
    const std::uint64_t due = frames_due(plan, c.step);
    if (c.complete && c.frames_written == due + 1) c.frames_written = due;
    c.complete = false;
    if (c.config_toml != plan.config_toml) c.extending_from = config_fingerprint(c.config_toml);
    c.config_toml = plan.config_toml;
    write_checkpoint(dir / kCheckpointFile, c);
    write_file_atomically(dir / kConfigFile, plan.config_toml);
}

// A run directory read back and checked, ready to continue.
struct ResumedRun {
    std::filesystem::path dir;
    std::unique_ptr<RunDirectoryLock> lock;
    Checkpoint checkpoint;
    RunPlan plan;
    bool extending = false;
    bool complete = false;          // nothing to do
    std::uint64_t first_frame = 0;  // of the run, in trajectory.h5 (a continuation's is not 0)
};

ResumedRun read_run(const std::filesystem::path& dir, const RunOptions& options) {
    const std::filesystem::path checkpoint_path = dir / kCheckpointFile;
    if (!std::filesystem::exists(checkpoint_path))
        throw FileError(checkpoint_path.string(),
                        std::filesystem::exists(dir / kConfigFile)
                            ? "no checkpoint here: the run stopped before its first checkpoint, "
                              "so there is nothing to resume; start it again with rodsea run " +
                                  (dir / kConfigFile).string() + " --out " + dir.string() +
                                  " --overwrite"
                            : "no checkpoint here: is this a directory made by rodsea run?");
    ResumedRun run{
        dir, std::make_unique<RunDirectoryLock>(dir), read_checkpoint(checkpoint_path), {}};
    const Checkpoint& c = run.checkpoint;
    RunPlan stored = load_config_string(c.config_toml, checkpoint_path.string() + " [config]");
    check_checkpoint(c, stored, checkpoint_path);
    check_belongs_here(dir, c, stored);
    run.extending = options.duration || options.steady_samples;
    run.plan = run.extending
                   ? extended_plan(c, options.duration, options.steady_samples, checkpoint_path)
                   : std::move(stored);
    run.complete = c.complete && (!run.extending || run.plan.total_steps() == c.step);
    if (!run.complete) check_frames_counted(c, run.plan, run.extending, checkpoint_path);
    run.first_frame = read_first_frame(dir / kTrajectoryFile);
    if (run.first_frame > 0 && !run.complete) refuse_steady_stop(run.plan, dir.string());
    // Checked and locked: what a killed writer of this directory left half-written goes.
    remove_stale_temporaries(dir);
    return run;
}

// Steps every system of the ensemble whose session started (`by_system[m]`, not null) to its
// run's end; the systems of the others leave first. `run_of[m]` is system m's place in
// `codes`, which receives each run's exit code.
void step_to_the_end(Ensemble& ensemble, const std::vector<RunSession*>& by_system,
                     const std::vector<std::size_t>& run_of, std::vector<int>& codes,
                     const BackendOptions& stepping, const RunOptions& options, std::ostream& out,
                     std::ostream& err, bool progress_is_terminal) {
    std::vector<std::size_t> never_started;
    std::vector<RunSession*> sessions;
    std::vector<std::size_t> runs;
    for (std::size_t m = 0; m < by_system.size(); ++m) {
        if (by_system[m] == nullptr) {
            never_started.push_back(m);
            continue;
        }
        sessions.push_back(by_system[m]);
        runs.push_back(run_of[m]);
    }
    if (by_system.size() > 1 || options.name_runs_in_messages)
        for (RunSession* session : sessions)
            session->name_in_messages();
    if (!sessions.empty()) {
        ensemble.retire(never_started);
        EnsembleLoop loop(ensemble, sessions, stepping.threads,
                          choose_progress_style(options.quiet, progress_is_terminal), out, err);
        const std::vector<int> ended = loop.run();
        for (std::size_t k = 0; k < runs.size(); ++k)
            codes[runs[k]] = ended[k];
    }
}

int first_failure(const std::vector<int>& codes) {
    for (int code : codes)
        if (code != kExitOk) return code;
    return kExitOk;
}

// New runs to their first frame and checkpoint, then (with `step`) to their ends.
std::vector<int> start_each(const std::vector<NewRun>& runs, const RunOptions& options,
                            std::ostream& out, std::ostream& err, bool progress_is_terminal,
                            bool step) {
    if (runs.empty()) throw InvalidParameter("CONFIG", "none", "at least one config");
    // From here on a signal asks for a clean stop, and a file-size limit fails a write instead
    // of killing the process.
    StopSignalGuard signals;
    std::vector<RunPlan> plans;
    std::vector<std::filesystem::path> dirs;
    for (const NewRun& run : runs) {
        const PackingCheck packing = check_packing(run.plan.engine, run.plan.counts);
        if (!packing.ok)
            throw InvalidParameter(
                "species", "these counts", "a packing that fits",
                packing.message +
                    (runs.size() > 1 ? " (the run into " + run.dir.string() + ")" : std::string()));
        check_steady_series(run.plan);
        check_output_directory(run.dir, options.overwrite);
        plans.push_back(run.plan);
        dirs.push_back(run.dir);
    }
    check_distinct(dirs);
    check_fits_in_memory(plans);
    // A new run's backend is its config's (rodsea run --backend rewrites the config), so that its
    // stored config says what stepped it; options.backend is for resumed runs.
    RunOptions given = options;
    given.backend.reset();
    const BackendOptions stepping = ensemble_options(plans, dirs, given);
    require_usable_backend(stepping.backend, "run.backend");

    std::vector<std::unique_ptr<RemoveUnlessStarted>> cleanups;
    std::vector<std::unique_ptr<RunDirectoryLock>> locks;
    for (const std::filesystem::path& dir : dirs) {
        const bool created = create_output_directory(dir);
        cleanups.push_back(std::make_unique<RemoveUnlessStarted>(dir, created));
        locks.push_back(std::make_unique<RunDirectoryLock>(dir));
    }
    // Only once every directory is this process's: a run still going in one of them refuses
    // the command before any old run is removed.
    if (options.overwrite)
        for (const std::filesystem::path& dir : dirs)
            remove_run_files(dir);
    // Flushed at once: with stdout going to a file, the plan and the start would otherwise
    // appear only with the first progress line, minutes later.
    if (!options.quiet) {
        if (plans.size() == 1) {
            out << "rodsea run -> " << dirs.front().string() << "\n";
            describe_plan(plans.front(), out, true);
        } else {
            RunControl control = plans.front().control;
            control.threads = stepping.threads;
            control.backend = stepping.backend;
            describe_ensemble(plans, dirs, control, out);
        }
        out << std::flush;
    }

    std::vector<Simulation> systems;
    for (std::size_t r = 0; r < plans.size(); ++r) {
        const RunPlan& plan = plans[r];
        BuildReport built;
        BodyState bodies =
            build_initial_state(plan.engine, plan.counts, plan.builder, plan.engine.seed, &built);
        if (!options.quiet) {
            // Dense starts keep some order (docs/builder.md): say how they were built and how
            // much.
            std::ostringstream line;
            line.precision(3);
            if (plans.size() > 1) line << dirs[r].string() << ": ";
            line << "initial state built in " << built.seconds << " s: " << describe_start(built)
                 << ", then " << built.sweeps << " Monte Carlo sweeps; order at the start:";
            for (size_t s = 0; s < plan.engine.species.size(); ++s)
                if (plan.engine.species[s].kind != BodyKind::bead)
                    line << " " << plan.engine.species[s].name << " P = " << built.polar_order.at(s)
                         << ", S = " << built.nematic_order.at(s) << ";";
            out << line.str() << std::endl;
        }
        systems.emplace_back(plan.engine, std::move(bodies));
    }
    Ensemble ensemble(std::move(systems), stepping);

    std::vector<std::unique_ptr<RunSession>> sessions;
    std::vector<int> codes(plans.size(), kExitOk);
    std::vector<RunSession*> by_system(plans.size(), nullptr);
    std::vector<std::size_t> run_of(plans.size());
    for (std::size_t r = 0; r < plans.size(); ++r) {
        run_of[r] = r;
        const RunPlan& plan = plans[r];
        const std::filesystem::path& dir = dirs[r];
        write_file_atomically(dir / kConfigFile, plan.config_toml);
        const SeriesRecorder columns(plan);
        TrajectoryFile trajectory =
            TrajectoryFile::create(dir / kTrajectoryFile, plan.engine, ensemble.bodies(r).species,
                                   plan.config_toml, columns.columns());
        SeriesCsv csv = SeriesCsv::create(dir / kSeriesFile, columns.columns());
        sessions.push_back(std::make_unique<RunSession>(plan, std::move(trajectory), std::move(csv),
                                                        dir, 0.0, std::move(locks[r])));
        RunSession& session = *sessions.back();
        session.attach(ensemble, r);
        try {
            session.write_frame(0.0);
            session.checkpoint(false);
            if (!step) session.set_aside();
            cleanups[r]->started();
            by_system[r] = &session;
        } catch (const FileError& e) {
            err << "rodsea: cannot write the first frame and checkpoint of " << dir.string() << ": "
                << e.what()
                << "\n  there is nothing to resume: make room and start again with --overwrite\n";
            codes[r] = kExitIoError;
        }
    }
    if (step)
        step_to_the_end(ensemble, by_system, run_of, codes, stepping, options, out, err,
                        progress_is_terminal);
    return codes;
}

}  // namespace

BackendOptions ensemble_options(const std::vector<RunPlan>& plans,
                                const std::vector<std::filesystem::path>& dirs,
                                const RunOptions& given) {
    const std::optional<BackendKind>& backend = given.backend;
    BackendOptions options{.threads = 1, .backend = plans.front().control.backend};
    for (std::size_t r = 0; r < plans.size(); ++r) {
        options.threads = std::max(options.threads, plans[r].control.threads);
        if (!backend && plans[r].control.backend != options.backend)
            throw InvalidParameter(
                "run.backend",
                std::string(to_string(plans[r].control.backend)) + " for " + dirs[r].string() +
                    ", " + to_string(options.backend) + " for " + dirs.front().string(),
                "one backend for every run stepped together",
                "runs on different backends go in different commands, or give --backend");
    }
    if (backend) options.backend = *backend;
    if (given.threads) options.threads = *given.threads;
    return options;
}

int start_run(const RunPlan& plan, const RunOptions& options, std::ostream& out, std::ostream& err,
              bool progress_is_terminal) {
    return start_runs({{plan, options.out_dir}}, options, out, err, progress_is_terminal);
}

int resume_run(const std::filesystem::path& dir, const RunOptions& options, std::ostream& out,
               std::ostream& err, bool progress_is_terminal) {
    return resume_runs({dir}, options, out, err, progress_is_terminal);
}

int start_runs(const std::vector<NewRun>& runs, const RunOptions& options, std::ostream& out,
               std::ostream& err, bool progress_is_terminal) {
    return first_failure(start_each(runs, options, out, err, progress_is_terminal, true));
}

std::vector<int> create_runs(const std::vector<NewRun>& runs, const RunOptions& options,
                             std::ostream& out, std::ostream& err) {
    return start_each(runs, options, out, err, false, false);
}

int resume_runs(const std::vector<std::filesystem::path>& dirs, const RunOptions& options,
                std::ostream& out, std::ostream& err, bool progress_is_terminal) {
    return first_failure(resume_each(dirs, options, out, err, progress_is_terminal));
}

std::vector<int> resume_each(const std::vector<std::filesystem::path>& dirs,
                             const RunOptions& options, std::ostream& out, std::ostream& err,
                             bool progress_is_terminal) {
    if (dirs.empty()) throw InvalidParameter("--resume", "none", "at least one run directory");
    StopSignalGuard signals;
    check_distinct(dirs);
    std::vector<ResumedRun> runs;
    for (const std::filesystem::path& dir : dirs)
        runs.push_back(read_run(dir, options));
    std::vector<RunPlan> plans;
    std::vector<std::filesystem::path> going_dirs;
    for (const ResumedRun& run : runs) {
        if (run.complete) continue;
        plans.push_back(run.plan);
        going_dirs.push_back(run.dir);
    }
    for (const ResumedRun& run : runs) {
        if (!run.complete || options.quiet) continue;
        out << "rodsea: the run in " << run.dir.string() << " is already complete (step "
            << run.checkpoint.step
            << ", t = " << static_cast<double>(run.checkpoint.step) * run.plan.engine.dt
            << " s); nothing to do. Extend it with --duration T.\n";
    }
    std::vector<int> codes(runs.size(), kExitOk);
    if (plans.empty()) return codes;
    check_fits_in_memory(plans);
    const BackendOptions stepping = ensemble_options(plans, going_dirs, options);
    require_usable_backend(stepping.backend, options.backend ? "--backend" : "run.backend");

    std::vector<Simulation> systems;
    for (ResumedRun& run : runs) {
        if (run.complete) continue;
        if (run.extending) commit_extension(run.dir, run.plan, run.checkpoint);
        const Checkpoint& c = run.checkpoint;
        const RunPlan& plan = run.plan;
        if (!options.quiet) {
            out << "rodsea run --resume " << run.dir.string() << ": from step " << c.step << " of "
                << plan.total_steps() << " (t = " << static_cast<double>(c.step) * plan.engine.dt
                << " s of " << plan.control.duration << " s), "
                << c.frames_written - run.first_frame << " frames kept"
                << (run.extending ? "; extended, config.toml updated" : "") << std::endl;
            if (stepping.backend != plan.control.backend)
                out << "backend: " << to_string(stepping.backend)
                    << " for this session (the run's config says "
                    << to_string(plan.control.backend)
                    << "): the trajectory goes on statistically, not bit for bit, as the run "
                       "would have"
                    << std::endl;
        }
        systems.push_back(Simulation::resume(plan.engine, c.bodies, c.step));
    }
    if (!options.quiet && systems.size() > 1)
        out << "stepping " << systems.size() << " runs together as one ensemble on "
            << to_string(stepping.backend) << ", " << stepping.threads
            << (stepping.threads == 1 ? " thread" : " threads") << std::endl;
    Ensemble ensemble(std::move(systems), stepping);

    std::vector<std::unique_ptr<RunSession>> sessions;
    std::vector<RunSession*> by_system;
    std::vector<std::size_t> run_of;
    for (std::size_t r = 0; r < runs.size(); ++r) {
        ResumedRun& run = runs[r];
        if (run.complete) continue;
        const RunPlan& plan = run.plan;
        const Checkpoint& c = run.checkpoint;
        const std::filesystem::path& dir = run.dir;
        const SeriesRecorder columns(plan);
        const std::uint64_t frames_here = c.frames_written - run.first_frame;
        SeriesCsv csv = SeriesCsv::reopen(dir / kSeriesFile, frames_here);
        std::optional<SteadyStop> history;
        if (plan.control.steady_samples > 0) {
            history.emplace(plan, columns.columns());
            history->restore(TrajectoryReader(dir / kTrajectoryFile), c.frames_written);
        }
        TrajectoryFile trajectory = TrajectoryFile::reopen(dir / kTrajectoryFile, frames_here,
                                                           plan.engine, columns.columns());
        // An extension interrupted before every file said its new length is finished here.
        if (read_stored_config(dir / kTrajectoryFile) != plan.config_toml)
            trajectory.replace_config(plan.config_toml);
        if (!run.extending && (!std::filesystem::exists(dir / kConfigFile) ||
                               read_text_file(dir / kConfigFile) != plan.config_toml))
            write_file_atomically(dir / kConfigFile, plan.config_toml);
        sessions.push_back(std::make_unique<RunSession>(plan, std::move(trajectory), std::move(csv),
                                                        dir, c.wall_seconds, std::move(run.lock)));
        RunSession& session = *sessions.back();
        session.attach(ensemble, by_system.size());
        by_system.push_back(nullptr);
        run_of.push_back(r);
        session.recorder().restore_interval(c.interval_accumulators);
        session.remember_good_state();
        if (history) session.steady() = std::move(*history);
        // A run stopped by a failed write has its checkpoint at the step whose frame failed:
        // that frame comes first, from the same state and interval, as the uninterrupted run
        // wrote it.
        if (c.frames_written + 1 == frames_due(plan, c.step)) {
            try {
                session.write_frame(0.0);
            } catch (const FileError& e) {
                err << "rodsea: still cannot write " << dir.string() << ": " << e.what()
                    << "\n  the checkpoint is intact; make room and resume again\n";
                codes[r] = kExitIoError;
                continue;
            }
        }
        by_system.back() = &session;
    }
    step_to_the_end(ensemble, by_system, run_of, codes, stepping, options, out, err,
                    progress_is_terminal);
    return codes;
}

}  // namespace rodsea
