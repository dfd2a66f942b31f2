#pragma once
// The scenario library: the scenes that tests, benchmarks and the executable share, so that
// "a dense monolayer" means the same bodies everywhere.
#include <cstdint>
#include <vector>

#include "rodsea/builder/placement.hpp"
#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

struct Scene {
    EngineParameters params;
    BodyState bodies;
};

// One body of `species` in a square box of side `box_side`, on the base, axis along x, tipped by
// `tilt` rad about its y axis (thin end up for a polar rod when tilt > 0).
Scene single_body(const Species& species, double box_side, double tilt = 0.0);

struct Population {
    Species species;
    long long count = 0;
};

// The bodies of each population flat on the base as `rodsea run` starts them
// (builder/initial_state.hpp, default options): random insertion when dilute, else the lattice,
// randomised by Monte Carlo; small random velocities and spins. Throws InvalidParameter when they
// do not fit in the box.
Scene monolayer(const std::vector<Population>& populations, const Box& box, std::uint64_t seed);

// The benchmark and demo mixture: polar rods at φ_p in apolar rods of length ℓ_a at φ_a, in a
// square box of `box_side` mm, with docs/model.md defaults for everything else.
Scene polar_in_apolar_mixture(double phi_polar, double apolar_length, double phi_apolar,
                              double box_side, std::uint64_t seed);

}  // namespace rodsea
