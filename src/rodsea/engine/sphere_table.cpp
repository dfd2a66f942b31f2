#include "rodsea/engine/sphere_table.hpp"

namespace rodsea {

void SphereTable::assign(const BodyState& bodies, const std::vector<Species>& species) {
    body.clear();
    radius.clear();
    first_of.assign(1, 0);
    for (size_t b = 0; b < bodies.size(); ++b) {
        const Shape& shape = species[bodies.species[b]].shape;
        for (size_t s = 0; s < shape.sphere_count(); ++s) {
            body.push_back(static_cast<std::uint32_t>(b));
            radius.push_back(shape.radii[s]);
        }
        first_of.push_back(static_cast<std::uint32_t>(body.size()));
    }
    position.resize(body.size());
}

void SphereTable::update_positions(const BodyState& bodies, const std::vector<Species>& species,
                                   int threads) {
    const auto n = static_cast<std::ptrdiff_t>(bodies.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::ptrdiff_t b = 0; b < n; ++b) {
        const Shape& shape = species[bodies.species[b]].shape;
        const Mat3 r = to_matrix(bodies.orientation[b]);
        const Vec3 x = bodies.position[b];
        const std::uint32_t first = first_of[b];
        for (std::uint32_t s = first; s < first_of[b + 1]; ++s)
            position[s] = x + r * shape.offsets[s - first];
    }
}

}  // namespace rodsea
