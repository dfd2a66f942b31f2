#pragma once
// `rodsea run --continue CHECKPOINT --out DIR`: a run continued from its checkpoint alone, in a
// new directory, when the directory it ran in (the trajectory the checkpoint continues) is not at
// hand: a checkpoint copied off a cluster's scratch, or kept when the machine that ran the run
// went away. The new directory continues the same run (its run id, step counter and open
// time-series interval): its frames are those the run would have written from the checkpoint on,
// bit for bit on the same backend, and its trajectory.h5 holds them from the run's frame
// first_frame on (io/trajectory_file.hpp: TrajectorySegment). From then on it is a run directory
// like any other: --resume continues it, rodsea analyze reads it.
#include <filesystem>
#include <iosfwd>

#include "rodsea/run/run_driver.hpp"

namespace rodsea {

// Continues the run of `checkpoint` (a checkpoint file, or a run directory holding one) into
// options.out_dir, with options.duration / options.steady_samples as --resume takes them. Every
// check (the checkpoint, its state, the new length, the output directory, the backend) comes
// before anything is written: problems throw InvalidParameter or FileError and leave no
// directory behind. Returns an ExitCode, as resume_run does.
int continue_run(const std::filesystem::path& checkpoint, const RunOptions& options,
                 std::ostream& out, std::ostream& err, bool progress_is_terminal = false);

}  // namespace rodsea
