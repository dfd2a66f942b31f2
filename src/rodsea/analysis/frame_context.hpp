#pragma once
// One frame plus the neighbour layer every observable of that frame shares: the grid of each
// body group is built on first use and reused by the next observable that asks for it.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "rodsea/analysis/analysis_frame.hpp"
#include "rodsea/analysis/body_grid.hpp"

namespace rodsea {

// Polar rods, and the medium (every body that is not a polar rod).
enum class BodyGroup { polar, medium, all };

class FrameContext {
  public:
    // `steady`: whether the frame is inside the steady-state window being averaged.
    FrameContext(const AnalysisFrame& frame, std::span<const SpeciesInfo> species, bool steady,
                 double cell_side = kDefaultCellSide);

    // 2.5 mm: a few bodies per cell at the paper's densities, small against every radius asked.
    static constexpr double kDefaultCellSide = 2.5;

    const AnalysisFrame& frame() const { return frame_; }
    std::span<const SpeciesInfo> species() const { return species_; }
    bool steady() const { return steady_; }
    bool is_polar(std::uint32_t body) const {
        return species_[frame_.species[body]].kind == BodyKind::polar_rod;
    }

    const std::vector<std::uint32_t>& members(BodyGroup group) const {
        return grid(group).members();
    }
    const BodyGrid& grid(BodyGroup group) const;

  private:
    const AnalysisFrame& frame_;
    std::span<const SpeciesInfo> species_;
    bool steady_;
    double cell_side_;
    mutable std::array<std::unique_ptr<BodyGrid>, 3> grids_;
};

}  // namespace rodsea
