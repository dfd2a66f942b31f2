#pragma once
// Where a body goes: how many fit an area fraction, how one lies flat or tipped on the base.
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

// N = round(φ L² / A), docs/model.md §2 (the paper's Table S1).
long long count_for_area_fraction(double area_fraction, const Box& box, const Shape& shape);

// Orientation of a body lying flat with its axis at `angle` (rad) to x.
Quat flat_orientation(double angle);

// Lying at `angle`, then tipped by `tilt` (rad) about its own y axis: thin end up for a polar rod
// when tilt > 0.
Quat tipped_orientation(double angle, double tilt);

// How far above the base (mm) a built body's lowest sphere starts at t = 0: clear of the plate,
// so that the fresh state is strictly between the plates (engine/state_check.hpp).
inline constexpr double kRestingClearance = 1e-3;

// Height of the centre of mass that puts the lowest sphere `clearance` mm above the base at
// t = 0 for the given orientation.
double resting_height(const Shape& shape, const Quat& orientation, const DriveParameters& drive,
                      double clearance = kRestingClearance);

// Each body of a built state gets a small random velocity (in-plane, up to kStartSpeed) and spin
// (up to kStartSpin about each axis): a perfectly still packing is mirror-symmetric and the
// vibration alone would never move it sideways.
inline constexpr double kStartSpeed = 5.0;  // mm/s
inline constexpr double kStartSpin = 10.0;  // rad/s

}  // namespace rodsea
