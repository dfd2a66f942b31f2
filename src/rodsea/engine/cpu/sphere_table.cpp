#include "rodsea/engine/cpu/sphere_table.hpp"

#include <algorithm>
#include <cmath>

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

namespace {

// Body b's spheres from its pose, and its height bounds (sphere_table.hpp).
void update_body(SphereTable& t, std::size_t b, BodyView bodies, const SpeciesTable& species) {
    const std::uint32_t k = bodies.species[b];
    const std::uint32_t first = t.first_of[b];
    physics::place_spheres(t.position.data() + first,
                           species.sphere_offset.data() + species.first_sphere[k],
                           t.first_of[b + 1] - first, bodies.position[b], bodies.orientation[b],
                           species.sphere_axis[k]);
    // The body's lowest sphere bottom and highest top from its centre, its tilt and the
    // species' outline (species_table.hpp): a look at two or three spheres instead of all.
    // The margin (10⁻¹² of the heights, where x + s u and these sums round at 10⁻¹⁶) keeps
    // them bounds on the spheres as rounded. A lone sphere (a bead) is its own bound: the
    // plate search reads it directly, and its bounds are not set.
    if (t.first_of[b + 1] - first == 1) return;
    const double z = bodies.position[b].z;
    const int axis = species.sphere_axis[k];
    const double u = axis >= 0 ? rotated_axis(bodies.orientation[b], axis).z : 0.0;
    double down = 0.0, up = 0.0;
    for (std::uint32_t o = species.first_outline[k]; o < species.first_outline[k + 1]; ++o) {
        down = std::max(down, species.outline_radius[o] - species.outline_along[o] * u);
        up = std::max(up, species.outline_radius[o] + species.outline_along[o] * u);
    }
    const double margin = 1e-12 * (std::abs(z) + down + up);
    t.lowest[b] = z - down - margin;
    t.highest[b] = z + up + margin;
}

}  // namespace

void SphereTable::update_positions(BodyView bodies, const SpeciesTable& species, int threads) {
    const auto n = static_cast<std::ptrdiff_t>(bodies.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::ptrdiff_t b = 0; b < n; ++b)
        update_body(*this, static_cast<std::size_t>(b), bodies, species);
}

void SphereTable::update_positions_of(std::span<const std::uint32_t> list, BodyView bodies,
                                      const SpeciesTable& species, int threads) {
    const auto n = static_cast<std::ptrdiff_t>(list.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::ptrdiff_t i = 0; i < n; ++i)
        update_body(*this, list[static_cast<std::size_t>(i)], bodies, species);
}

void SphereTable::place(std::uint32_t b, std::uint32_t species_index, const Vec3& x, const Quat& q,
                        const SpeciesTable& species) {
    const std::uint32_t first = first_of[b];
    physics::place_spheres(position.data() + first,
                           species.sphere_offset.data() + species.first_sphere[species_index],
                           first_of[b + 1] - first, x, q, species.sphere_axis[species_index]);
}

}  // namespace rodsea::cpu
