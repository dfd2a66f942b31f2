#pragma once
// The flow of the medium around polar rods (docs/model.md §4; paper Fig. 5b): for every polar rod i
// and medium body j at distance r, the medium's in-plane velocity in the rod's corotating axes
// (along its axis, thick → thin, and across it), its speed, and the same relative to the rod
// (the comoving frame), averaged per distance bin over rods and frames.
#include <cstddef>
#include <span>
#include <vector>

#include "rodsea/analysis/neighbor_query.hpp"

namespace rodsea {

struct MediumVelocityParameters {
    double d = 100.0;      // mm, the distance reported on its own (the paper's d)
    double r_max = 100.0;  // mm, the profile's range, at most half the box
    double bin = 1.0;      // mm
};

// The medium at distance d from the polar rods in one frame, averaged over its pairs.
struct MediumAtDistance {
    double pairs = 0.0;
    double along = 0.0;           // mm/s, lab frame, along the rod's axis
    double speed = 0.0;           // mm/s, lab frame
    double relative_speed = 0.0;  // mm/s, relative to the rod
};

class MediumVelocity {
  public:
    explicit MediumVelocity(const MediumVelocityParameters& p);

    // One frame: the medium's grid and velocities (mm/s), the polar rods' positions, angles (rad)
    // and velocities. Returns that frame's values at d (pairs 0 when no medium body is there).
    MediumAtDistance compute(const PeriodicGrid2D& medium, std::span<const Vec3> medium_velocity,
                             std::span<const Vec3> rods, std::span<const double> rod_angle,
                             std::span<const Vec3> rod_velocity);

    std::vector<double> bin_centres() const;  // mm
    // Per bin: pairs, and the means over them (NaN where no pair): velocity along and across
    // the rod's axis, speed, velocity relative to the rod along its axis, relative speed.
    std::vector<double> pairs() const;
    std::vector<double> along() const;
    std::vector<double> across() const;
    std::vector<double> speed() const;
    std::vector<double> relative_along() const;
    std::vector<double> relative_speed() const;

  private:
    enum Column { kPairs, kAlong, kAcross, kSpeed, kRelativeAlong, kRelativeSpeed, kColumns };
    std::vector<double> mean_of(Column c) const;

    MediumVelocityParameters p_;
    std::size_t bins_;
    std::vector<double> sums_;  // [bin][column]
};

}  // namespace rodsea
