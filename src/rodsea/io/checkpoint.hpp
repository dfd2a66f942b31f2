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
    // What identifies the run it belongs to: the trajectory's run id (TrajectoryFile::run_id),
    // and, during an extension (--duration) whose files are not all rewritten yet, the
    // fingerprint of the config the trajectory and config.toml may still hold. Resume refuses
    // a checkpoint whose run id or config is not its directory's.
    std::string run_id;
    std::string extending_from;
    std::uint64_t step = 0;
    std::uint64_t frames_written = 0;  // trajectory frames and time-series rows on disk
    BodyState bodies;
    std::vector<double> interval_accumulators;  // the driver's running sums since the last row
    double wall_seconds = 0.0;                  // wall time spent so far, over all sessions
    bool complete = false;                      // the run reached its last step
};

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);
// Throws FileError for a missing, truncated, foreign or edited file (the config's fingerprint is
// stored with it), or a state that is not finite. Checkpoints of format 1 (before run ids) are
// read with an empty run_id.
Checkpoint read_checkpoint(const std::filesystem::path& path);

// A fingerprint of a config's text (FNV-1a, 16 hex digits): equal texts, equal fingerprints.
std::string config_fingerprint(const std::string& config_toml);

}  // namespace rodsea
