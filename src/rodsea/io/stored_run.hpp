#pragma once
// A finished or running simulation as the read-side commands (analyze, render, movie, export)
// see it: the trajectory, the config it was run with, and its frame times. Opening checks that
// the file is a rodsea trajectory with at least one complete frame.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "rodsea/config/run_plan.hpp"
#include "rodsea/io/trajectory_reader.hpp"

namespace rodsea {

struct StoredRun {
    std::filesystem::path run_dir, trajectory;
    // Every trajectory the frames come from, in the run's order (more than one for a run read
    // with its continuations); `trajectory` is the last.
    std::vector<std::filesystem::path> parts;
    RunPlan plan;
    TrajectoryReader reader;

    std::size_t frames() const { return reader.times().size(); }
    // The frames on the output grid (t = k × output interval): all of them, or all but the
    // last when the run's duration is not a whole number of intervals and its last frame was
    // written at its end. Analyses that need equally spaced frames use these.
    std::size_t grid_frames() const;
    const std::vector<double>& times() const { return reader.times(); }
    long long total_bodies() const;
    // Frame k, checked against the stored config (body count, species indices): a damaged
    // file fails here with FileError rather than drawing or exporting nonsense.
    BodyState frame(std::size_t k) const;
};

// Accepts a run directory or its trajectory.h5. Throws FileError for a missing file, one that
// is not a rodsea trajectory, or one without frames.
StoredRun open_stored_run(const std::filesystem::path& run_or_trajectory);
// One run kept in several directories (its first and its continuations, rodsea run --continue,
// in any order) read as one: its frames in order, each once, under the latest part's config
// (run_dir and trajectory are the latest part's, where the run goes on). Throws FileError when
// the parts are not of one run (run ids, configs other than in their length), when frames are
// missing between two of them, or when two start at the same frame.
StoredRun open_stored_run(const std::vector<std::filesystem::path>& parts);

// `runs` (directories or trajectories) grouped into runs: those of one run id (a run's first
// directory and its continuations) form one group, the others one each, in the order each group's
// first appears. Directories of one run that start at the same frame (a copy, two continuations
// of one checkpoint) go to different groups.
std::vector<std::vector<std::filesystem::path>> group_run_parts(
    const std::vector<std::filesystem::path>& runs);

// The frame a user asked for: --frame N (0-based; negative counts from the end, -1 the last)
// or --time T (the frame nearest T, s), or the last frame when neither is given. Throws
// InvalidParameter naming the flag and the run's range.
std::size_t select_frame(const StoredRun& run, std::optional<long long> frame,
                         std::optional<double> time);

// The frames of `times` (frame times `interval` s apart) with from − slack <= t <= to + slack
// (rounding slack only; none given: the run's ends), as [first, end). The one reading of a
// user's --from/--to for every read-side command: --from in [0, last frame], --to in [first
// frame, last frame]; a value outside, a reversed window or one between two frames throws
// InvalidParameter naming the flag and the run's range.
struct FrameSpan {
    std::size_t first = 0, end = 0;
};
FrameSpan select_frame_span(const std::vector<double>& times, double interval,
                            std::optional<double> from, std::optional<double> to);

// select_frame_span's frames, then every `every`-th of them.
std::vector<std::size_t> select_frame_window(const StoredRun& run, std::optional<double> from,
                                             std::optional<double> to, long long every);

}  // namespace rodsea
