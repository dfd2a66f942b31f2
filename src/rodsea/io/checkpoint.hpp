#pragma once
// A checkpoint is everything needed to continue a run bit for bit: the resolved config, the step
// counter (time and plate phase are step × dt; the noise signs hash the seed and step, so there
// is no other random-number state), every body's full double-precision state, how many
// trajectory frames were durable when it was written, and the run driver's partly filled
// time-series interval. Written as HDF5 through a temporary file renamed into place, so a crash
// at any moment leaves either the old checkpoint or the new one, never half of one.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "rodsea/engine/body_state.hpp"

namespace rodsea {

struct Checkpoint {
    std::string config_toml;
    std::uint64_t step = 0;
    std::uint64_t frames_written = 0;  // trajectory frames and time-series rows on disk
    BodyState bodies;
    std::vector<double> interval_accumulators;  // the driver's running sums since the last row
    double wall_seconds = 0.0;                  // wall time spent so far, over all sessions
    bool complete = false;                      // the run reached its last step
};

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);
// Throws FileError for a missing, truncated or foreign file.
Checkpoint read_checkpoint(const std::filesystem::path& path);

}  // namespace rodsea
