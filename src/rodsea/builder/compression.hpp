#pragma once
// The random start for dense packings below jamming: every body shrunk about its geometric centre
// until random insertion is easy (area fraction `start_fraction`), inserted at uniformly random
// positions and angles, then restored to full size at once and the overlaps that makes pushed
// apart (overlap_relaxation.hpp). The result is a random packing: uniform, isotropic, and never
// on a lattice, so there is nothing of a lattice to forget. Above the jamming fraction of this
// quench (measured in docs/builder.md) the overlaps cannot all be removed and it fails.
#include <cstdint>
#include <vector>

#include "rodsea/builder/builder_options.hpp"
#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/overlap_relaxation.hpp"
#include "rodsea/builder/planar_bodies.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/random.hpp"

namespace rodsea {

struct CompressionOptions {
    double clearance = 0.0025;     // smallest disc–disc gap at the end, mm
    double start_fraction = 0.30;  // area fraction of the shrunk bodies at insertion
    int max_iterations = 4000;     // of the overlap relaxation
    double probe_side = 40.0;      // mm, of the probe box (compression_probe_succeeds)
};

struct CompressionResult {
    bool complete = false;       // every overlap removed
    double start_scale = 1.0;    // the shrinking at insertion
    std::uint64_t attempts = 0;  // random placements tried
    OverlapRelaxationResult relaxation;
};

// Whether compression is worth trying in a large box: the same area fractions in a small square
// box (side `probe_side`, counts scaled and rounded) compressed first, which costs a few percent of
// the full attempt, because a jammed attempt runs a thousand iterations before it stalls. True
// without a probe when the box is not much larger than the probe.
bool compression_probe_succeeds(const std::vector<Species>& species,
                                const std::vector<Footprint>& feet,
                                const std::vector<long long>& counts, const Box& box,
                                InitialOrientation orientation, const CompressionOptions& options,
                                SplitMix64& rng);

// A footprint shrunk about the geometric centre: discs at s times their offsets, s times their
// radii.
Footprint scaled(const Footprint& f, double s);

// Fills `bodies` (replacing what they held) with the counts of each species. Orientation as
// insert_randomly; aligned bodies never turn. Incomplete when the insertion or the relaxation
// fails; `bodies` then overlap and must not be used.
CompressionResult compress_from_random(const std::vector<Species>& species,
                                       const std::vector<Footprint>& feet,
                                       const std::vector<long long>& counts, const Box& box,
                                       InitialOrientation orientation,
                                       const CompressionOptions& options, SplitMix64& rng,
                                       PlanarBodies& bodies);

}  // namespace rodsea
