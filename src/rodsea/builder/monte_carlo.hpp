#pragma once
// Randomisation of a packing by hard-body Monte Carlo in the plane: trial translations and
// rotations about z, each rejected if any disc of the moved body would come closer than the
// clearance to a disc of another body. The steps adapt per species and move type toward 30–50 %
// acceptance: at low density they grow to jumps across half the box and turns of up to ±π, so
// the lattice is forgotten within a few sweeps; at high density they shrink to rattling in the
// free volume the lattice leaves.
#include <cstdint>
#include <vector>

#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/planar_bodies.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/random.hpp"

namespace rodsea {

struct MonteCarloOptions {
    double clearance = 0.0025;  // smallest disc–disc gap allowed, mm
    int sweeps = 50;            // each sweep tries one move per body
    bool rotate = true;         // false keeps every angle (the aligned start)
};

struct MonteCarloResult {
    int sweeps = 0;
    std::uint64_t attempted = 0;
    std::uint64_t accepted = 0;
    std::vector<double> translation_step;  // per species at the end, mm (largest |Δx|, |Δy|)
    std::vector<double> rotation_step;     // per species at the end, rad (largest |Δθ|)
};

// Throws std::logic_error if the start is not overlap-free: the lattice guarantees it, so an
// overlap here is a bug, not bad input.
MonteCarloResult randomise(PlanarBodies& bodies, const std::vector<Footprint>& feet, const Box& box,
                           const MonteCarloOptions& options, SplitMix64& rng);

}  // namespace rodsea
