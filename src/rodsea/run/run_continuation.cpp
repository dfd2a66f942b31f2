#include "rodsea/run/run_continuation.hpp"

#include <ostream>

#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/run_lock.hpp"
#include "rodsea/io/series_csv.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/run/checkpoint_checks.hpp"
#include "rodsea/run/output_directory.hpp"
#include "rodsea/run/plan_report.hpp"
#include "rodsea/run/run_session.hpp"
#include "rodsea/run/series_recorder.hpp"

namespace rodsea {

namespace {

std::filesystem::path checkpoint_file(const std::filesystem::path& given) {
    std::error_code ec;
    return std::filesystem::is_directory(given, ec) ? given / kCheckpointFile : given;
}

std::string seconds(std::uint64_t step, double dt) {
    return format_number(static_cast<double>(step) * dt) + " s";
}

// Writes DIR's files for the continuation of `c` under `plan`: config.toml, a trajectory and a
// CSV holding no frame yet, and the checkpoint last. A failure removes what it wrote (without its
// checkpoint the directory could only start again from t = 0, as a new run); the directory goes
// too when this command made it (the caller's RemoveUnlessStarted).
void write_continuation(const std::filesystem::path& dir, const RunPlan& plan, const Checkpoint& c,
                        bool created, bool overwrite) {
    try {
        if (overwrite) remove_run_files(dir);
        const SeriesRecorder recorder(plan);
        write_file_atomically(dir / kConfigFile, plan.config_toml);
        TrajectoryFile::create(dir / kTrajectoryFile, plan.engine, c.bodies.species,
                               plan.config_toml, recorder.columns(),
                               TrajectorySegment{c.run_id, c.frames_written})
            .close();
        SeriesCsv::create(dir / kSeriesFile, recorder.columns()).flush();
        sync_file(dir / kTrajectoryFile);
        sync_file(dir / kSeriesFile);
        write_checkpoint(dir / kCheckpointFile, c);
    } catch (...) {
        if (!created) remove_run_files(dir);
        throw;
    }
}

}  // namespace

int continue_run(const std::filesystem::path& given, const RunOptions& options, std::ostream& out,
                 std::ostream& err, bool progress_is_terminal) {
    // A signal while the directory is being set up waits for it: the run then stops at once,
    // with the checkpoint written here.
    const StopSignalGuard signals;
    const std::filesystem::path path = checkpoint_file(given);
    const std::filesystem::path& dir = options.out_dir;
    if (!std::filesystem::exists(path)) throw FileError(path.string(), "no such checkpoint");
    // --overwrite there would delete the frames the checkpoint continues.
    if (directory_key(dir) == directory_key(path.parent_path().empty() ? "." : path.parent_path()))
        throw InvalidParameter(
            "--out", dir.string(), "a directory other than the checkpoint's",
            "the run goes on in its own directory with rodsea run --resume " + dir.string());
    Checkpoint c = read_checkpoint(path);
    if (c.run_id.empty())
        throw FileError(path.string(),
                        "written by a rodsea before run ids (checkpoint format 1): it resumes "
                        "only in its own directory, with rodsea run --resume");
    const RunPlan stored = load_config_string(c.config_toml, path.string() + " [config]");
    check_checkpoint(c, stored, path);
    check_checkpoint_state(c, stored, path);
    const bool extending = options.duration || options.steady_samples;
    const RunPlan plan =
        extending ? extended_plan(c, options.duration, options.steady_samples, path) : stored;
    const double dt = plan.engine.dt;
    if (c.complete && plan.total_steps() == c.step)
        throw InvalidParameter("--continue", path.string(),
                               "the checkpoint of a run not yet at its end, or --duration T "
                               "beyond that end",
                               "this run is complete at t = " + seconds(c.step, dt) +
                                   ": give --duration T to continue it to T");
    check_frames_counted(c, plan, extending, path);
    refuse_steady_stop(plan, path.string());
    check_output_directory(dir, options.overwrite);
    check_fits_in_memory(plan);
    require_usable_backend(options.backend.value_or(plan.control.backend),
                           options.backend ? "--backend" : "run.backend");

    // As an extension in place (run_driver.cpp: commit_extension): a complete run that ended off
    // the output grid wrote a last frame that the longer run does not have.
    if (extending && c.complete && c.frames_written == frames_due(plan, c.step) + 1)
        --c.frames_written;
    c.complete = false;
    c.config_toml = plan.config_toml;
    c.extending_from.clear();

    const bool created = create_output_directory(dir);
    RemoveUnlessStarted cleanup(dir, created);
    {
        // Taken before anything is removed: a run still going in DIR refuses this, untouched.
        const RunDirectoryLock lock(dir);
        write_continuation(dir, plan, c, created, options.overwrite);
    }
    cleanup.started();
    if (!options.quiet)
        out << "rodsea run --continue " << path.string() << " -> " << dir.string() << ": run "
            << c.run_id << " from step " << c.step << " (t = " << seconds(c.step, dt)
            << "); this directory holds its frames from frame " << c.frames_written
            << " on, the earlier ones stay with the run's first directory" << std::endl;
    RunOptions resumed = options;
    resumed.duration.reset();
    resumed.steady_samples.reset();
    return resume_run(dir, resumed, out, err, progress_is_terminal);
}

}  // namespace rodsea
