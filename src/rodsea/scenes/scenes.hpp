#pragma once
// The scenario library: the scenes that tests, benchmarks and the executable share, so that
// "a dense monolayer" means the same bodies everywhere.
#include <cstdint>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

struct Scene {
    EngineParameters params;
    BodyState bodies;
};

// N = round(φ L² / A), MODEL.md §2 (the paper's Table S1).
long long count_for_area_fraction(double area_fraction, const Box& box, const Shape& shape);

// Orientation of a body lying flat with its axis at angle (rad) to x.
Quat flat_orientation(double angle);

// Height of the centre of mass that puts the lowest sphere `clearance` mm above the base at
// t = 0 for the given orientation.
double resting_height(const Shape& shape, const Quat& orientation, const DriveParameters& drive,
                      double clearance = 1e-3);

// One body of `species` in a square box of side `box_side`, on the base, axis along x, tipped by
// `tilt` rad about its y axis (thin end up for a polar rod when tilt > 0).
Scene single_body(const Species& species, double box_side, double tilt = 0.0);

struct Population {
    Species species;
    long long count = 0;
};

// Bodies flat on the base in rows along x (each row one species, rows of the species
// interleaved), spread evenly over the box, each pointing along +x or −x at random. A lattice
// start: dense packings that random insertion cannot reach, with no overlap by construction.
// Each body gets a small random velocity (in-plane, up to kStartSpeed) and spin (up to
// kStartSpin about each axis): a perfectly still lattice is mirror-symmetric and the vibration
// alone would never move it sideways.
// Throws InvalidParameter when the rows do not fit in the box.
inline constexpr double kStartSpeed = 5.0;  // mm/s
inline constexpr double kStartSpin = 10.0;  // rad/s
Scene row_packed_monolayer(const std::vector<Population>& populations, const Box& box,
                           std::uint64_t seed);

// The benchmark and demo mixture: polar rods at φ_p in apolar rods of length ℓ_a at φ_a, in a
// square box of `box_side` mm, with MODEL.md defaults for everything else.
Scene polar_in_apolar_mixture(double phi_polar, double apolar_length, double phi_apolar,
                              double box_side, std::uint64_t seed);

}  // namespace rodsea
