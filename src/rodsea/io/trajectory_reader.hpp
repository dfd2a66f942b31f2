#pragma once
// Reads what TrajectoryFile wrote: frame steps and times, one frame's bodies (single precision
// as stored), and any time-series column. Throws FileError for a file that is not a rodsea
// trajectory.
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
    TrajectoryReader(TrajectoryReader&&) noexcept;
    ~TrajectoryReader();

    std::uint64_t frames() const { return steps_.size(); }
    const std::vector<std::int64_t>& steps() const { return steps_; }
    const std::vector<double>& times() const { return times_; }
    BodyState frame(std::uint64_t index) const;
    std::vector<double> series(const std::string& column) const;
    bool has_series(const std::string& column) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::vector<std::int64_t> steps_;
    std::vector<double> times_;
};

}  // namespace rodsea
