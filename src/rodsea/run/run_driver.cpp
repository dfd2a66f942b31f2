#include "rodsea/run/run_driver.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <numeric>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/ensemble.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/run_lock.hpp"
#include "rodsea/io/series_csv.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/run/checkpoint_checks.hpp"
#include "rodsea/run/ensemble_loop.hpp"
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
    check_checkpoint_belongs(dir, c, stored);
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

int first_failure(const std::vector<int>& codes) {
    for (int code : codes)
        if (code != kExitOk) return code;
    return kExitOk;
}

// The sessions of an ensemble's runs, system by system, opened the same way for new runs and
// resumed ones: `open(m)` makes system m's session from its run's files (a failure there is the
// command's), the session is attached to its system, and `begin(m, session)` writes what must
// come before its steps. A FileError in `begin` ends that run alone, told by `failed(m, error)`:
// its system is left out of the stepping (by_system[m] null).
struct OpenedSessions {
    std::vector<std::unique_ptr<RunSession>> owned;
    std::vector<RunSession*> by_system;
};

OpenedSessions open_sessions(Ensemble& ensemble, std::size_t systems,
                             const std::function<std::unique_ptr<RunSession>(std::size_t)>& open,
                             const std::function<void(std::size_t, RunSession&)>& begin,
                             const std::function<void(std::size_t, const FileError&)>& failed) {
    OpenedSessions opened;
    opened.by_system.assign(systems, nullptr);
    for (std::size_t m = 0; m < systems; ++m) {
        opened.owned.push_back(open(m));
        RunSession& session = *opened.owned.back();
        session.attach(ensemble, m);
        try {
            begin(m, session);
            opened.by_system[m] = &session;
        } catch (const FileError& e) {
            failed(m, e);
        }
    }
    return opened;
}

// Each resumed run's state from its checkpoint, its extension committed first (a run given a
// longer --duration); unless `quiet`, where each goes on from, on what.
std::vector<Simulation> resumed_systems(std::vector<ResumedRun>& runs,
                                        const BackendOptions& stepping, bool quiet,
                                        std::ostream& out) {
    std::vector<Simulation> systems;
    for (ResumedRun& run : runs) {
        if (run.complete) continue;
        if (run.extending) commit_extension(run.dir, run.plan, run.checkpoint);
        const Checkpoint& c = run.checkpoint;
        const RunPlan& plan = run.plan;
        if (!quiet) {
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
    if (!quiet && systems.size() > 1)
        out << "stepping " << systems.size() << " runs together as one ensemble on "
            << to_string(stepping.backend) << ", " << stepping.threads
            << (stepping.threads == 1 ? " thread" : " threads") << std::endl;
    return systems;
}

// New runs' configs and directories, checked before anything is written: each packing, each
// steady-state series, each directory (free, or --overwrite), no directory twice, and the memory
// they need together. Their plans and directories, in order, go to `plans` and `dirs`.
void check_new_runs(const std::vector<NewRun>& runs, const RunOptions& options,
                    std::vector<RunPlan>& plans, std::vector<std::filesystem::path>& dirs) {
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
}

// What the new runs will do, flushed at once: with stdout going to a file, the plan and the
// start would otherwise appear only with the first progress line, minutes later.
void describe_new_runs(const std::vector<RunPlan>& plans,
                       const std::vector<std::filesystem::path>& dirs,
                       const BackendOptions& stepping, std::ostream& out) {
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

// Each new run's initial state, built from its config; unless `quiet`, how it was built and how
// much order it kept (dense starts keep some: docs/builder.md).
std::vector<Simulation> built_systems(const std::vector<RunPlan>& plans,
                                      const std::vector<std::filesystem::path>& dirs, bool quiet,
                                      std::ostream& out) {
    std::vector<Simulation> systems;
    for (std::size_t r = 0; r < plans.size(); ++r) {
        const RunPlan& plan = plans[r];
        BuildReport built;
        BodyState bodies =
            build_initial_state(plan.engine, plan.counts, plan.builder, plan.engine.seed, &built);
        if (!quiet) {
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
    return systems;
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
    check_new_runs(runs, options, plans, dirs);
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
    if (!options.quiet) describe_new_runs(plans, dirs, stepping, out);
    Ensemble ensemble(built_systems(plans, dirs, options.quiet, out), stepping);

    std::vector<int> codes(plans.size(), kExitOk);
    std::vector<std::size_t> run_of(plans.size());
    std::iota(run_of.begin(), run_of.end(), std::size_t{0});
    const OpenedSessions opened = open_sessions(
        ensemble, plans.size(),
        [&](std::size_t r) {
            const RunPlan& plan = plans[r];
            const std::filesystem::path& dir = dirs[r];
            write_file_atomically(dir / kConfigFile, plan.config_toml);
            const SeriesRecorder columns(plan);
            TrajectoryFile trajectory = TrajectoryFile::create(dir / kTrajectoryFile, plan.engine,
                                                               ensemble.bodies(r).species,
                                                               plan.config_toml, columns.columns());
            SeriesCsv csv = SeriesCsv::create(dir / kSeriesFile, columns.columns());
            return std::make_unique<RunSession>(plan, std::move(trajectory), std::move(csv), dir,
                                                0.0, std::move(locks[r]));
        },
        [&](std::size_t r, RunSession& session) {
            session.write_frame(0.0);
            session.checkpoint(false);
            if (!step) session.set_aside();
            cleanups[r]->started();
        },
        [&](std::size_t r, const FileError& e) {
            err << "rodsea: cannot write the first frame and checkpoint of " << dirs[r].string()
                << ": " << e.what()
                << "\n  there is nothing to resume: make room and start again with --overwrite\n";
            codes[r] = kExitIoError;
        });
    if (step)
        step_to_the_end(ensemble, opened.by_system, run_of, codes, stepping.threads,
                        plans.size() > 1 || options.name_runs_in_messages,
                        choose_progress_style(options.quiet, progress_is_terminal), out, err);
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

    Ensemble ensemble(resumed_systems(runs, stepping, options.quiet, out), stepping);

    std::vector<std::size_t> run_of;  // system m steps runs[run_of[m]]
    for (std::size_t r = 0; r < runs.size(); ++r)
        if (!runs[r].complete) run_of.push_back(r);
    std::vector<std::optional<SteadyStop>> histories(run_of.size());
    const OpenedSessions opened = open_sessions(
        ensemble, run_of.size(),
        [&](std::size_t m) {
            ResumedRun& run = runs[run_of[m]];
            const RunPlan& plan = run.plan;
            const Checkpoint& c = run.checkpoint;
            const std::filesystem::path& dir = run.dir;
            const SeriesRecorder columns(plan);
            const std::uint64_t frames_here = c.frames_written - run.first_frame;
            SeriesCsv csv = SeriesCsv::reopen(dir / kSeriesFile, frames_here);
            if (plan.control.steady_samples > 0) {
                histories[m].emplace(plan, columns.columns());
                histories[m]->restore(TrajectoryReader(dir / kTrajectoryFile), c.frames_written);
            }
            TrajectoryFile trajectory = TrajectoryFile::reopen(dir / kTrajectoryFile, frames_here,
                                                               plan.engine, columns.columns());
            // An extension interrupted before every file said its new length is finished here.
            if (read_stored_config(dir / kTrajectoryFile) != plan.config_toml)
                trajectory.replace_config(plan.config_toml);
            if (!run.extending && (!std::filesystem::exists(dir / kConfigFile) ||
                                   read_text_file(dir / kConfigFile) != plan.config_toml))
                write_file_atomically(dir / kConfigFile, plan.config_toml);
            return std::make_unique<RunSession>(plan, std::move(trajectory), std::move(csv), dir,
                                                c.wall_seconds, std::move(run.lock));
        },
        [&](std::size_t m, RunSession& session) {
            const ResumedRun& run = runs[run_of[m]];
            const Checkpoint& c = run.checkpoint;
            session.recorder().restore_interval(c.interval_accumulators);
            session.remember_good_state();
            if (histories[m]) session.steady() = std::move(*histories[m]);
            // A run stopped by a failed write has its checkpoint at the step whose frame failed:
            // that frame comes first, from the same state and interval, as the uninterrupted run
            // wrote it.
            if (c.frames_written + 1 == frames_due(run.plan, c.step)) session.write_frame(0.0);
        },
        [&](std::size_t m, const FileError& e) {
            err << "rodsea: still cannot write " << runs[run_of[m]].dir.string() << ": " << e.what()
                << "\n  the checkpoint is intact; make room and resume again\n";
            codes[run_of[m]] = kExitIoError;
        });
    step_to_the_end(ensemble, opened.by_system, run_of, codes, stepping.threads,
                    run_of.size() > 1 || options.name_runs_in_messages,
                    choose_progress_style(options.quiet, progress_is_terminal), out, err);
    return codes;
}

}  // namespace rodsea
