#pragma once
// Reads what TrajectoryFile wrote: frame steps and times, one frame's bodies (single precision
// as stored), and any time-series column. Everything read is checked before it is returned, as
// a config value would be: opening checks the frame steps and times (finite, increasing,
// as many as frames), the body count of every per-body dataset and the species indices
// (against the species stored in the file), and every time-series value (series() below), so
// that no reader (analyze, render, export, --resume, Python) uses or extends a NaN or a negative
// energy. Values within a frame are checked against the run's config by StoredRun::frame
// (engine/state_check.hpp). Every failure is a FileError naming the file, the dataset, and the
// frame, body or row with its value.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "rodsea/engine/body_state.hpp"

namespace rodsea {

class TrajectoryReader {
  public:
    explicit TrajectoryReader(const std::filesystem::path& path);
    // One run kept in several files, read as one: a run's first directory and its
    // continuations (rodsea run --continue), in the run's order, the first `keep[k]` frames of
    // `parts[k]` (a file may hold frames the next one holds again). Throws FileError naming the
    // later file when its frames do not follow the earlier ones' (steps not increasing) or the
    // files hold different bodies.
    static TrajectoryReader joined(std::vector<TrajectoryReader> parts,
                                   const std::vector<std::uint64_t>& keep);
    TrajectoryReader(TrajectoryReader&&) noexcept;
    ~TrajectoryReader();

    std::uint64_t frames() const { return steps_.size(); }
    const std::vector<std::int64_t>& steps() const { return steps_; }
    const std::vector<double>& times() const { return times_; }
    BodyState frame(std::uint64_t index) const;
    // Each body's species index, as stored (/particles/bodies/species).
    const std::vector<std::uint32_t>& species() const { return species_; }
    // Where frame `index` is stored: the file (one of a joined run's parts) and its index there,
    // for messages about a frame to name the file that holds it.
    struct FrameSource {
        std::filesystem::path file;
        std::uint64_t index;
    };
    FrameSource source_of(std::uint64_t index) const;
    // One column, one value per frame: finite; order parameters in [0, 1]; every column but the
    // signed mean velocities >= 0.
    std::vector<double> series(const std::string& column) const;
    bool has_series(const std::string& column) const;
    // The time-series columns the file holds, in the file's (alphabetical) order.
    std::vector<std::string> series_names() const;

  private:
    TrajectoryReader() = default;
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::vector<std::int64_t> steps_;
    std::vector<double> times_;
    std::vector<std::uint32_t> species_;
};

}  // namespace rodsea
