#pragma once
// One run directory during one session of `rodsea run`: its open trajectory and CSV, the time
// series it records, its stop-when-steady judge, its checkpoints and its progress.txt. The state
// it records is one system of an Ensemble (engine/ensemble.hpp): a lone run is an ensemble of
// one, and `rodsea run A.toml B.toml` steps several, each writing its own directory exactly as
// it would alone. The loop that steps the ensemble (ensemble_loop.cpp) calls after_step() for each
// system after each step; the session says when its run has ended and with which exit code.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rodsea/cli/progress.hpp"
#include "rodsea/config/run_plan.hpp"
#include "rodsea/engine/ensemble.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/run_lock.hpp"
#include "rodsea/io/series_csv.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/run/run_files.hpp"
#include "rodsea/run/series_recorder.hpp"
#include "rodsea/run/steady_stop.hpp"

namespace rodsea {

// Frames a run has written once it has done `step` steps: frame 0, one per output interval,
// and the last step's.
std::uint64_t frames_due(const RunPlan& plan, std::uint64_t step);

class RunSession {
  public:
    // `wall_before`: the wall seconds of the run's earlier sessions. `lock` is held for the life
    // of the session.
    RunSession(RunPlan plan, TrajectoryFile trajectory, SeriesCsv csv, std::filesystem::path dir,
               double wall_before, std::unique_ptr<RunDirectoryLock> lock);

    // Its messages begin with its directory: with several runs on one stream, each names its own.
    void name_in_messages();

    // The system of `ensemble` this session records; again after the ensemble retires others.
    void attach(const Ensemble& ensemble, std::size_t system);

    const RunPlan& plan() const { return plan_; }
    const std::filesystem::path& dir() const { return dir_; }
    std::uint64_t step_count() const { return ensemble_->step_count(system_); }
    std::uint64_t steps_left() const { return plan_.total_steps() - step_count(); }
    // Steps until this run next has something to do after a step (a frame and series row, or
    // its end): the ensemble may take that many in one go.
    std::uint64_t steps_to_next_output() const;
    double polar_order() const { return last_polar_order_; }  // in the last frame's row
    SeriesRecorder& recorder() { return recorder_; }
    SteadyStop& steady() { return steady_; }

    // Throws FileError; a frame counts only once the trajectory and the CSV both hold it.
    void write_frame(double steps_per_second);
    // The state a checkpoint after a blow-up holds: the last frame's, or the resumed
    // checkpoint's until a frame is written.
    void remember_good_state();
    // Throws FileError; the frames it counts are forced to disk first.
    void checkpoint(bool complete);

    // Called before any message of this session is printed: a progress bar on the same stream
    // must end its line first.
    using BeforePrinting = std::function<void()>;

    // After each run of steps of the ensemble (not after a blow-up of this system; a run ends at
    // the latest where steps_to_next_output() said): records its steps, writes the frame due, and
    // judges the end (the duration, a steady window, a state the engine should never produce, a
    // failed write). Returns the run's exit code once it ended. `rate`, this session's steps/s, is
    // read only for a frame or an end (it reads the clock).
    std::optional<int> after_step(const std::function<double()>& rate, std::ostream& out,
                                  std::ostream& err, ProgressStyle style,
                                  const BeforePrinting& before_printing);
    // Every few seconds: progress.txt, and a checkpoint when output.checkpoint_interval has
    // passed. Returns kExitIoError once a checkpoint cannot be written.
    std::optional<int> between_steps(double steps_per_second, std::ostream& err,
                                     const BeforePrinting& before_printing);
    int stop_after_blow_up(const BlowUp& blow_up, std::uint64_t step, double steps_per_second,
                           std::ostream& out, std::ostream& err);
    int stop_on_signal(int signal, double steps_per_second, std::ostream& out, std::ostream& err);
    // A run created but not stepped (create_runs): its files closed and progress.txt saying
    // stopped, as a signal would have left them right after the first checkpoint. Throws
    // FileError.
    void set_aside();
    void write_progress(const char* state, double steps_per_second);

  private:
    std::optional<BlowUp> invalid_state() const;
    int finish(std::ostream& out, std::ostream& err, ProgressStyle style,
               const std::optional<SteadyVerdict>& verdict, double steps_per_second);
    int stop_after_write_failure(const FileError& e, double steps_per_second, std::ostream& out,
                                 std::ostream& err);
    void report_end(std::ostream& out) const;
    double wall_seconds() const;

    RunPlan plan_;
    std::unique_ptr<RunDirectoryLock> lock_;
    TrajectoryFile trajectory_;
    SeriesCsv csv_;
    SeriesRecorder recorder_;
    SteadyStop steady_;
    std::filesystem::path dir_;
    std::string who_;  // before its messages: "" alone, "<dir>: " among several
    double wall_before_;
    const Ensemble* ensemble_ = nullptr;
    std::size_t system_ = 0;
    std::size_t polar_column_;
    // Room for two frames and HDF5's growing chunk indexes (a few kB per frame at most): a frame
    // must never run out of space half-way (see TrajectoryFile::reserve).
    static constexpr std::uint64_t kMetadataReserve = 64 * 1024;
    std::uint64_t frame_reserve_bytes_;
    std::uint64_t frames_written_;  // by the run, in this directory and before it (first_frame)
    double last_polar_order_ = 0.0;
    std::optional<std::vector<double>> open_interval_at_end_;  // before the off-grid last row
    // The state at the last frame written, for a checkpoint after a blow-up.
    struct GoodState {
        std::uint64_t step = 0, frames = 0;
        BodyState bodies;
        std::vector<double> interval;
    } last_good_;
    using Clock = std::chrono::steady_clock;
    Clock::time_point started_ = Clock::now();
    Clock::time_point last_checkpoint_ = Clock::now();
    Clock::time_point last_progress_ = Clock::now();
    static constexpr double kProgressSeconds = 2.0;  // wall time between progress.txt updates
};

}  // namespace rodsea
