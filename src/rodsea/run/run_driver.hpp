#pragma once
// `rodsea run`: builds the initial state, steps it, writes the trajectory, the time series and
// checkpoints, and stops cleanly (with a checkpoint) on SIGINT, SIGTERM or a failing disk.
//
// A run directory holds:
//   config.toml       the full resolved config (every key), for people to read
//   trajectory.h5     H5MD trajectory and time series (io/trajectory_file.hpp)
//   timeseries.csv    the same time series as CSV
//   checkpoint.h5     the latest checkpoint (io/checkpoint.hpp), replaced atomically
#include <filesystem>
#include <iosfwd>
#include <optional>

#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/config/run_plan.hpp"

namespace rodsea {

struct RunOptions {
    std::filesystem::path out_dir;
    bool overwrite = false;  // replace the run files of an existing directory
    bool quiet = false;      // no plan, no progress; errors still go to the error stream
    // Resume only: extend (or shorten, not below the time done) the run to this duration, s,
    // and/or change its stop-when-steady sample count; the stored config says the new values.
    std::optional<double> duration;
    std::optional<long long> steady_samples;
    // Resume only: continue on this backend instead of the stored run.backend, for this session
    // (the stored config keeps saying how the run started).
    std::optional<BackendKind> backend;
};

inline const char* const kConfigFile = "config.toml";
inline const char* const kTrajectoryFile = "trajectory.h5";
inline const char* const kSeriesFile = "timeseries.csv";
inline const char* const kCheckpointFile = "checkpoint.h5";

// Starts a new run of `plan` in options.out_dir. Everything about the input (packing, output
// directory) is checked before any work; problems throw InvalidParameter or FileError.
// Returns an ExitCode; messages go to `out` (plan, progress) and `err` (what went wrong).
int start_run(const RunPlan& plan, const RunOptions& options, std::ostream& out, std::ostream& err,
              bool progress_is_terminal = false);

// Continues the run in `dir` from its checkpoint, bit for bit as if it had never stopped; with
// options.duration or options.steady_samples, with that run length (also when it had completed),
// bit for bit the run that had been given it from the start.
int resume_run(const std::filesystem::path& dir, const RunOptions& options, std::ostream& out,
               std::ostream& err, bool progress_is_terminal = false);

}  // namespace rodsea
