#pragma once
// Stage 1 of the step: every body moves freely for dt — an exact parabola under gravity and
// torque-free rotation about its centre of mass.
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

// Torque-free rotation of one body with principal moments `inertia` for time dt. World angular
// momentum is conserved exactly. Axisymmetric and spherical bodies (every rod and bead) follow
// the exact solution (regular precession); asymmetric bodies use the symmetric splitting into
// the exact rotations about the three principal axes (energy error O(dt²), bounded).
void rotate_free(Quat& orientation, Vec3& spin, const Vec3& inertia, double dt);

// Bodies are independent: split over `threads` OpenMP threads, with the same result for any count.
// Returns an upper bound on the speed in the plane (mm/s) of any sphere centre during the step,
// which tells the Verlet list when its spheres may have moved far enough to need a check.
double advance_free_flight(BodyState& bodies, const std::vector<Species>& species, const Box& box,
                           double gravity, double dt, int threads = 1);

}  // namespace rodsea
