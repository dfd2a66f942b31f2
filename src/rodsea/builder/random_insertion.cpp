#include "rodsea/builder/random_insertion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "rodsea/builder/disc_grid.hpp"

namespace rodsea {

InsertionResult insert_randomly(const std::vector<Species>& species,
                                const std::vector<Footprint>& feet,
                                const std::vector<long long>& counts, const Box& box,
                                double clearance, InitialOrientation orientation,
                                double attempts_per_body, SplitMix64& rng, PlanarBodies& bodies) {
    std::vector<std::uint32_t> order(species.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return species[a].shape.projected_area > species[b].shape.projected_area;
    });
    std::vector<std::uint32_t> body_species;
    for (const std::uint32_t s : order)
        body_species.insert(body_species.end(), static_cast<size_t>(std::max(0LL, counts[s])), s);

    InsertionResult result;
    const double budget = attempts_per_body * static_cast<double>(body_species.size());
    const bool aligned = orientation == InitialOrientation::aligned;
    DiscGrid grid(body_species, feet, box, clearance);
    bodies = {};
    for (std::uint32_t b = 0; b < body_species.size(); ++b) {
        const std::uint32_t s = body_species[b];
        const bool plus_x_only =
            orientation != InitialOrientation::isotropic && species[s].kind == BodyKind::polar_rod;
        for (;;) {
            if (static_cast<double>(result.attempts) >= budget) return result;
            ++result.attempts;
            const double x = rng.uniform(0.0, box.lx), y = rng.uniform(0.0, box.ly);
            double angle = 0.0;
            if (!aligned && !plus_x_only)
                angle = rng.uniform(-std::numbers::pi, std::numbers::pi);
            else if (feet[s].rotatable && !plus_x_only && rng.uniform() < 0.5)
                angle = std::numbers::pi;
            if (!grid.trial(b, x, y, angle)) continue;
            grid.insert_body(b, x, y, angle);
            bodies.add(s, x, y, angle);
            break;
        }
    }
    result.complete = true;
    return result;
}

}  // namespace rodsea
