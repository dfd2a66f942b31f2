#include "rodsea/builder/compression.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/builder/random_insertion.hpp"

namespace rodsea {

namespace {

// At an area fraction of 0.3 random insertion needs a few attempts per body: a budget of 1000
// fails only for bodies that cannot fit the box at all.
constexpr double kInsertionAttemptsPerBody = 1000.0;

}  // namespace

Footprint scaled(const Footprint& f, double s) {
    Footprint g = f;
    for (size_t k = 0; k < g.size(); ++k) {
        g.along[k] *= s;
        g.across[k] *= s;
        g.radius[k] *= s;
    }
    g.centre_offset *= s;
    g.half_length *= s;
    g.half_width *= s;
    g.max_radius *= s;
    return g;
}

CompressionResult compress_from_random(const std::vector<Species>& species,
                                       const std::vector<Footprint>& feet,
                                       const std::vector<long long>& counts, const Box& box,
                                       InitialOrientation orientation,
                                       const CompressionOptions& options, SplitMix64& rng,
                                       PlanarBodies& bodies) {
    CompressionResult result;
    double area = 0.0;
    for (size_t s = 0; s < species.size(); ++s)
        area += static_cast<double>(std::max(0LL, counts[s])) * species[s].shape.projected_area;
    const double fraction = area / (box.lx * box.ly);
    result.start_scale =
        fraction > options.start_fraction ? std::sqrt(options.start_fraction / fraction) : 1.0;
    std::vector<Footprint> shrunk;
    for (const Footprint& f : feet)
        shrunk.push_back(scaled(f, result.start_scale));
    const InsertionResult inserted =
        insert_randomly(species, shrunk, counts, box, options.clearance, orientation,
                        kInsertionAttemptsPerBody, rng, bodies);
    result.attempts = inserted.attempts;
    if (!inserted.complete) return result;

    OverlapRelaxationOptions relax;
    relax.clearance = options.clearance;
    relax.max_iterations = options.max_iterations;
    relax.rotate = orientation != InitialOrientation::aligned;  // polar_aligned: feet frozen
    result.relaxation = relax_overlaps(bodies, feet, box, relax);
    result.complete = result.relaxation.converged;
    return result;
}

bool compression_probe_succeeds(const std::vector<Species>& species,
                                const std::vector<Footprint>& feet,
                                const std::vector<long long>& counts, const Box& box,
                                InitialOrientation orientation, const CompressionOptions& options,
                                SplitMix64& rng) {
    // Below twice the probe's area the probe would save little.
    const double area = box.lx * box.ly, probe_area = options.probe_side * options.probe_side;
    if (area < 2.0 * probe_area) return true;
    std::vector<long long> probe_counts;
    for (const long long n : counts)
        probe_counts.push_back(std::llround(static_cast<double>(n) * probe_area / area));
    PlanarBodies probe;
    return compress_from_random(species, feet, probe_counts,
                                {options.probe_side, options.probe_side}, orientation, options, rng,
                                probe)
        .complete;
}

}  // namespace rodsea
