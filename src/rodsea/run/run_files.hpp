#pragma once
// The files of a run directory, as `rodsea run` writes them (run_driver.hpp says what each holds).
namespace rodsea {

inline const char* const kConfigFile = "config.toml";
inline const char* const kTrajectoryFile = "trajectory.h5";
inline const char* const kSeriesFile = "timeseries.csv";
inline const char* const kCheckpointFile = "checkpoint.h5";

}  // namespace rodsea
