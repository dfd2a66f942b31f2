#pragma once
// Random sequential insertion: each body in turn at a uniformly random position and angle,
// retried until it overlaps nothing. Below ~0.45 total area fraction it is the best start there
// is (uniform and isotropic at once, no lattice to forget); toward the jamming of random
// insertion (~0.55 for rods) the retries explode, and the lattice start takes over.
#include <cstdint>
#include <vector>

#include "rodsea/builder/builder_options.hpp"
#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/planar_bodies.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/random.hpp"

namespace rodsea {

struct InsertionResult {
    bool complete = false;       // every body placed within the budget
    std::uint64_t attempts = 0;  // trial placements made
};

// Inserts the bodies of the largest footprint first (the hardest to fit later). Gives up, with
// `bodies` partly filled, once the attempts exceed `attempts_per_body` times the body count.
// Orientation as place_lattice: isotropic, polar rods +x and other rods ±x (aligned), or polar
// rods +x and the others at random (polar_aligned).
InsertionResult insert_randomly(const std::vector<Species>& species,
                                const std::vector<Footprint>& feet,
                                const std::vector<long long>& counts, const Box& box,
                                double clearance, InitialOrientation orientation,
                                double attempts_per_body, SplitMix64& rng, PlanarBodies& bodies);

}  // namespace rodsea
