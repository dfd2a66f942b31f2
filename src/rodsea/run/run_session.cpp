#include "rodsea/run/run_session.hpp"

#include <csignal>
#include <limits>
#include <ostream>

#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/progress_file.hpp"
#include "rodsea/run/plan_report.hpp"

namespace rodsea {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The time-series column of the first polar species' P, shown by the progress; past the end of
// the row (so P shows as 0) when there are no polar rods.
std::size_t polar_order_column(const EngineParameters& p) {
    for (size_t s = 0; s < p.species.size(); ++s)
        if (p.species[s].kind == BodyKind::polar_rod) return 2 * s;
    return std::numeric_limits<std::size_t>::max();
}

}  // namespace

std::uint64_t frames_due(const RunPlan& plan, std::uint64_t step) {
    const std::uint64_t per = plan.steps_per_output(), total = plan.total_steps();
    return step / per + 1 + (step == total && total % per != 0 ? 1 : 0);
}

RunSession::RunSession(RunPlan plan, TrajectoryFile trajectory, SeriesCsv csv,
                       std::filesystem::path dir, double wall_before,
                       std::unique_ptr<RunDirectoryLock> lock)
    : plan_(std::move(plan)),
      lock_(std::move(lock)),
      trajectory_(std::move(trajectory)),
      csv_(std::move(csv)),
      recorder_(plan_),
      steady_(plan_, recorder_.columns()),
      dir_(std::move(dir)),
      wall_before_(wall_before),
      polar_column_(polar_order_column(plan_.engine)),
      frame_reserve_bytes_(2 * estimate_resources(plan_).frame_bytes + kMetadataReserve),
      frames_written_(trajectory_.first_frame() + trajectory_.frames()) {}

void RunSession::name_in_messages() {
    who_ = dir_.string() + ": ";
}

void RunSession::set_aside() {
    trajectory_.close();
    write_progress("stopped", 0.0);
}

void RunSession::attach(const Ensemble& ensemble, std::size_t system) {
    ensemble_ = &ensemble;
    system_ = system;
}

double RunSession::wall_seconds() const {
    return wall_before_ + seconds_since(started_);
}

void RunSession::write_frame(double steps_per_second) {
    trajectory_.reserve(frame_reserve_bytes_);
    const BodyState& bodies = ensemble_->bodies(system_);
    const std::vector<double> row = recorder_.row(plan_.engine, bodies, steps_per_second);
    last_polar_order_ = polar_column_ < row.size() ? row[polar_column_] : 0.0;
    const double time = ensemble_->time(system_);
    trajectory_.append_frame(step_count(), time, bodies, row);
    csv_.append(step_count(), time, row);
    trajectory_.flush();
    csv_.flush();
    // The interval closes, and the frame counts, only once both files hold it: a failure part
    // way leaves both as a checkpoint must see them.
    recorder_.start_interval();
    ++frames_written_;
    if (steady_.active()) steady_.add_row(row);
    remember_good_state();
}

void RunSession::remember_good_state() {
    last_good_ = {step_count(), frames_written_, ensemble_->bodies(system_),
                  recorder_.interval_state()};
}

// A state the engine should never produce (a value not finite, a body outside the plates or the
// box) is a blow-up that the step's own bounds missed: it never reaches a frame.
std::optional<BlowUp> RunSession::invalid_state() const {
    const auto p = find_state_problem(plan_.engine, ensemble_->bodies(system_),
                                      ensemble_->time(system_), StateOrigin::resumed);
    if (!p) return std::nullopt;
    return BlowUp{"body " + std::to_string(p->body) + "'s " + p->field, p->value, p->allowed,
                  "a smaller time.dt, a smaller noise.epsilon or a less dense packing"};
}

// The frames it counts are first forced to disk, so that no crash can leave a checkpoint that
// refers to frames the files do not have.
void RunSession::checkpoint(bool complete) {
    sync_file(dir_ / kTrajectoryFile);
    sync_file(dir_ / kSeriesFile);
    Checkpoint c;
    c.config_toml = plan_.config_toml;
    c.run_id = trajectory_.run_id();
    c.step = step_count();
    c.frames_written = frames_written_;
    c.bodies = ensemble_->bodies(system_);
    // A run that ended off the output grid closed its interval early with the last row; an
    // extension (--duration) continues the interval as an uninterrupted run would.
    c.interval_accumulators =
        complete && open_interval_at_end_ ? *open_interval_at_end_ : recorder_.interval_state();
    c.wall_seconds = wall_seconds();
    c.complete = complete;
    write_checkpoint(dir_ / kCheckpointFile, c);
    last_checkpoint_ = Clock::now();
}

// progress.txt is for people and monitors: a failure to write it never stops the run (a full
// disk shows up at the next frame, which handles it).
void RunSession::write_progress(const char* state, double steps_per_second) {
    RunProgress p;
    p.state = state;
    p.step = step_count();
    p.total_steps = plan_.total_steps();
    p.time = ensemble_->time(system_);
    p.duration = plan_.control.duration;
    p.steps_per_second = steps_per_second;
    p.wall_seconds = wall_seconds();
    p.updated = unix_time_now();
    try {
        write_progress_file(dir_, p);
    } catch (const FileError&) {
    }
    last_progress_ = Clock::now();
}

std::uint64_t RunSession::steps_to_next_output() const {
    const std::uint64_t step = step_count(), every = plan_.steps_per_output();
    const std::uint64_t next = std::min((step / every + 1) * every, plan_.total_steps());
    return next > step ? next - step : 1;
}

std::optional<int> RunSession::after_step(const std::function<double()>& rate, std::ostream& out,
                                          std::ostream& err, ProgressStyle style,
                                          const BeforePrinting& before_printing) {
    recorder_.accumulate(ensemble_->last_run(system_));
    const std::uint64_t step = step_count(), total = plan_.total_steps();
    const bool on_grid = step % plan_.steps_per_output() == 0;
    if (!on_grid && step != total) return std::nullopt;  // most steps: nothing more to do
    const double steps_per_second = rate();
    if (const std::optional<BlowUp> b = invalid_state()) {
        before_printing();
        return stop_after_blow_up(*b, step, steps_per_second, out, err);
    }
    try {
        if (step == total && !on_grid) open_interval_at_end_ = recorder_.interval_state();
        write_frame(steps_per_second);
    } catch (const FileError& e) {
        before_printing();
        return stop_after_write_failure(e, steps_per_second, out, err);
    }
    if (on_grid) {
        if (const std::optional<SteadyVerdict> v = steady_.verdict()) {
            before_printing();
            return finish(out, err, style, v, steps_per_second);
        }
    }
    if (step == total) {
        before_printing();
        return finish(out, err, style, std::nullopt, steps_per_second);
    }
    return std::nullopt;
}

std::optional<int> RunSession::between_steps(double steps_per_second, std::ostream& err,
                                             const BeforePrinting& before_printing) {
    if (seconds_since(last_progress_) >= kProgressSeconds)
        write_progress("running", steps_per_second);
    if (seconds_since(last_checkpoint_) < plan_.control.checkpoint_interval * 60.0)
        return std::nullopt;
    try {
        checkpoint(false);
    } catch (const FileError& e) {
        before_printing();
        err << "rodsea: " << who_ << "cannot write the checkpoint: " << e.what()
            << "\n  the previous checkpoint is intact; stopping. Continue with: rodsea run "
               "--resume "
            << dir_.string() << "\n";
        return kExitIoError;
    }
    return std::nullopt;
}

// The run's end: at its duration, or earlier once steady (`verdict`).
int RunSession::finish(std::ostream& out, std::ostream& err, ProgressStyle style,
                       const std::optional<SteadyVerdict>& verdict, double steps_per_second) {
    try {
        // Closed first: a run is marked complete only with its trajectory whole.
        trajectory_.close();
        checkpoint(true);
        write_progress(verdict ? "steady" : "done", steps_per_second);
    } catch (const FileError& e) {
        err << "rodsea: " << who_
            << "the run reached its end but its files could not be closed: " << e.what()
            << "\n  the last checkpoint is intact; continue with: rodsea run "
            << "--resume " << dir_.string() << "\n";
        return kExitIoError;
    }
    if (style == ProgressStyle::quiet) return kExitOk;
    if (verdict) {
        const double frame_time = plan_.frame_interval();
        out << who_ << "steady: the window from "
            << format_number(frame_time * static_cast<double>(verdict->first_frame))
            << " s (decided by " << verdict->decided_by
            << ") holds n_eff = " << format_number(verdict->n_eff) << " independent samples of "
            << verdict->counted << " >= time.steady_samples = " << plan_.control.steady_samples
            << "; stopped at t = " << ensemble_->time(system_) << " s of at most "
            << plan_.control.duration << " s\n";
    }
    report_end(out);
    return kExitOk;
}

int RunSession::stop_on_signal(int signal, double steps_per_second, std::ostream& out,
                               std::ostream& err) {
    const char* what = signal == SIGINT   ? "interrupted (SIGINT)"
                       : signal == SIGHUP ? "hung up (SIGHUP)"
                                          : "terminated (SIGTERM)";
    try {
        checkpoint(false);
        trajectory_.close();
        write_progress("stopped", steps_per_second);
        err << "rodsea: " << who_ << "" << what << " at step " << step_count()
            << " (t = " << ensemble_->time(system_)
            << " s); checkpoint written.\n  continue with: rodsea run --resume " << dir_.string()
            << "\n";
    } catch (const FileError& e) {
        err << "rodsea: " << who_ << "" << what
            << ", but the checkpoint could not be written: " << e.what()
            << "\n  the previous checkpoint is intact; continue from it with: rodsea run "
               "--resume "
            << dir_.string() << "\n";
        out.flush();
        return kExitIoError;
    }
    out.flush();
    return signal == SIGINT ? kExitInterrupted : kExitTerminated;
}

// The state after a blow-up is meaningless: the checkpoint holds the last frame's state, which
// passed every check, and the files end with that frame.
int RunSession::stop_after_blow_up(const BlowUp& b, std::uint64_t step, double steps_per_second,
                                   std::ostream& out, std::ostream& err) {
    const double dt = plan_.engine.dt;
    err << "rodsea: " << who_ << "the simulation blew up at step " << step
        << " (t = " << format_number(static_cast<double>(step) * dt) << " s): " << b.what << " is "
        << b.value << ", beyond " << b.bound << ".\n  what to change: " << b.advice << ".\n";
    try {
        trajectory_.close();
        Checkpoint c;
        c.config_toml = plan_.config_toml;
        c.step = last_good_.step;
        c.frames_written = last_good_.frames;
        c.bodies = last_good_.bodies;
        c.interval_accumulators = last_good_.interval;
        c.wall_seconds = wall_seconds();
        c.run_id = trajectory_.run_id();
        write_checkpoint(dir_ / kCheckpointFile, c);
        write_progress("blown_up", steps_per_second);
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

int RunSession::stop_after_write_failure(const FileError& e, double steps_per_second,
                                         std::ostream& out, std::ostream& err) {
    // HDF5 cannot be trusted to close a file whose writes failed: it is left as it is. The room
    // claimed for the frame goes back, for the checkpoint.
    trajectory_.abandon();
    trajectory_.release_reserve();
    write_progress("stopped", steps_per_second);
    err << "rodsea: " << who_ << "cannot write output at step " << step_count()
        << " (t = " << ensemble_->time(system_) << " s): " << e.what() << "\n";
    try {
        checkpoint(false);
        err << "  checkpoint written (" << frames_written_ - trajectory_.first_frame()
            << " complete frames are kept); make room (disk space, quota or file-size limit) and "
               "continue with: rodsea run --resume "
            << dir_.string() << "\n";
    } catch (const FileError& again) {
        err << "  the checkpoint could not be written either (" << again.what()
            << "); the previous checkpoint is intact: make room and resume from it with: rodsea "
               "run --resume "
            << dir_.string() << "\n";
    }
    out.flush();
    return kExitIoError;
}

void RunSession::report_end(std::ostream& out) const {
    const RunTotals& t = ensemble_->totals(system_);
    const std::uint64_t first = trajectory_.first_frame();
    out << who_ << "done: " << step_count() << " steps, t = " << ensemble_->time(system_) << " s, "
        << frames_written_ - first << " frames in " << (dir_ / kTrajectoryFile).string()
        << (first > 0 ? " (the run's frames " + std::to_string(first) + "-" +
                            std::to_string(frames_written_ - 1) + ": a continuation)"
                      : "")
        << "\n      this session: largest overlap " << t.max_overlap_fraction * 100
        << " % of a radius, unresolved contacts " << t.unresolved << ", most sweeps "
        << t.max_sweeps << "; wall time of the whole run " << format_duration(wall_seconds())
        << "\n      state hash " << std::hex << ensemble_->state_hash(system_) << std::dec << "\n";
}

}  // namespace rodsea
