#include "rodsea/engine/cpu/sphere_table.hpp"

#include <algorithm>
#include <limits>

#include "rodsea/engine/physics/sphere_placement.hpp"

namespace rodsea::cpu {

void SphereTable::assign(std::span<const std::uint32_t> body_species, const SpeciesTable& species) {
    body.clear();
    radius.clear();
    first_of.assign(1, 0);
    for (std::size_t b = 0; b < body_species.size(); ++b) {
        const std::uint32_t k = body_species[b];
        for (std::uint32_t s = species.first_sphere[k]; s < species.first_sphere[k + 1]; ++s) {
            body.push_back(static_cast<std::uint32_t>(b));
            radius.push_back(species.sphere_radius[s]);
        }
        first_of.push_back(static_cast<std::uint32_t>(body.size()));
    }
    position.resize(body.size());
    lowest.resize(body_species.size());
    highest.resize(body_species.size());
}

void SphereTable::update_positions(BodyView bodies, const SpeciesTable& species, int threads) {
    const auto n = static_cast<std::ptrdiff_t>(bodies.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::ptrdiff_t b = 0; b < n; ++b) {
        const std::uint32_t k = bodies.species[b];
        const std::uint32_t first = first_of[b];
        const std::uint32_t end = first_of[b + 1];
        physics::place_spheres(position.data() + first,
                               species.sphere_offset.data() + species.first_sphere[k], end - first,
                               bodies.position[b], bodies.orientation[b], species.sphere_axis[k]);
        // Written the way plate_overlaps writes them, so that a skipped body has no overlap.
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (std::uint32_t s = first; s < end; ++s) {
            low = std::min(low, position[s].z - radius[s]);
            high = std::max(high, position[s].z + radius[s]);
        }
        lowest[b] = low;
        highest[b] = high;
    }
}

}  // namespace rodsea::cpu
