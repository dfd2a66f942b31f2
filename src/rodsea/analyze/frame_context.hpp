#pragma once
// One frame plus what every observable of that frame shares: the arrays of each group of bodies
// and their neighbour grid, built on first use and reused by the next observable that asks.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "rodsea/analysis/coarse_grained_fields.hpp"
#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/analysis/nematic_defects.hpp"
#include "rodsea/analyze/analysis_frame.hpp"
#include "rodsea/neighbors/periodic_grid.hpp"

namespace rodsea {

// Polar rods; the medium (every body that is not a polar rod); the medium's rods (apolar rods
// only: beads have no axis); every body.
enum class BodyGroup { polar, medium, medium_rods, all };

// The bodies of one group, in frame order, as arrays, with their grid.
struct GroupArrays {
    std::vector<std::uint32_t> members;  // frame indices
    std::vector<Vec3> position;          // mm, wrapped
    std::vector<double> angle;           // rad
    std::vector<Vec3> velocity;          // mm/s
    PeriodicGrid2D grid;
};

// The coarse-grained fields of a frame on one grid: each species' own, and the medium's rods
// together (every apolar rod), whose director field carries the nematic defects.
struct FrameFields {
    FieldGrid grid;
    std::vector<GroupFields> species;        // in the run's species order
    std::optional<GroupFields> medium_rods;  // none when the run has no apolar rods
};

class FrameContext {
  public:
    // `steady`: whether the frame is inside the steady-state window being averaged; `block`:
    // which time block of that window it falls in.
    FrameContext(const AnalysisFrame& frame, std::span<const SpeciesInfo> species, bool steady,
                 int block = 0);

    const AnalysisFrame& frame() const { return frame_; }
    std::span<const SpeciesInfo> species() const { return species_; }
    bool steady() const { return steady_; }
    int block() const { return block_; }
    bool is_polar(std::uint32_t body) const {
        return species_[frame_.species[body]].kind == BodyKind::polar_rod;
    }
    const GroupArrays& group(BodyGroup group) const;
    // Built on first use; every observable of a run asks with the same cell (fields.cell).
    const FrameFields& fields(double cell) const;
    // The defects of the medium rods' director field on that grid (empty without apolar rods).
    const std::vector<NematicDefect>& defects(double cell) const;
    // DBSCAN labels of the polar rods, in the order of group(BodyGroup::polar); every observable
    // of a run asks with the same parameters (flocks.eps, flocks.min_samples).
    const std::vector<int>& flock_labels(const DbscanParameters& parameters) const;

  private:
    bool in(BodyGroup group, std::uint32_t body) const;

    const AnalysisFrame& frame_;
    std::span<const SpeciesInfo> species_;
    bool steady_;
    int block_;
    mutable std::array<std::unique_ptr<GroupArrays>, 4> groups_;
    mutable std::unique_ptr<FrameFields> fields_;
    mutable std::optional<std::vector<NematicDefect>> defects_;
    mutable std::optional<std::vector<int>> flock_labels_;
    mutable DbscanParameters flock_parameters_;
};

}  // namespace rodsea
