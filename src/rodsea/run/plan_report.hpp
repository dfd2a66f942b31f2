#pragma once
// What `rodsea info` prints and `rodsea run` shows before it starts: the system, the drive, the
// run's length, the expected memory and output size, and every docs/model.md CHOICE in force.
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/config/run_plan.hpp"

namespace rodsea {

struct ResourceEstimate {
    std::uint64_t bodies = 0;
    std::uint64_t spheres = 0;
    std::uint64_t memory_bytes = 0;      // engine state and per-step scratch, approximate
    std::uint64_t frame_bytes = 0;       // one trajectory frame (float32 per-body arrays)
    std::uint64_t frames = 0;            // frames the run writes, the initial one included
    std::uint64_t trajectory_bytes = 0;  // frames × frame_bytes plus the series
    std::uint64_t checkpoint_bytes = 0;  // one checkpoint (double precision)
};
ResourceEstimate estimate_resources(const RunPlan& plan);

// Throws InvalidParameter (naming the system's size, what it needs and what the machine has)
// when the run's memory exceeds what this machine has available (cli/machine_memory.hpp).
void check_fits_in_memory(const RunPlan& plan);
// The same for the runs of an ensemble together: they share the machine's memory.
void check_fits_in_memory(const std::vector<RunPlan>& plans);

// The full report (`rodsea info`); `brief` drops the CHOICE list (the header of `rodsea run`).
void describe_plan(const RunPlan& plan, std::ostream& out, bool brief = false);

// What `rodsea run` with several configs shows before it starts: one line per run (size,
// length, output, directory), then the ensemble's backend (`stepping`: its backend and threads),
// memory and output in all; `point_to_info`: a last line saying where each run's plan is in full.
void describe_ensemble(const std::vector<RunPlan>& plans,
                       const std::vector<std::filesystem::path>& dirs, const RunControl& stepping,
                       std::ostream& out, bool point_to_info = true);

std::string format_bytes(std::uint64_t bytes);  // "5.3 MB"

}  // namespace rodsea
