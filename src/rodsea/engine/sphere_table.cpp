#include "rodsea/engine/sphere_table.hpp"

#include <algorithm>

namespace rodsea {

namespace {

// The world centres of `count` spheres on body axis K: x + s u, s their offsets along it.
template <int K>
void place_along(Vec3* out, const Vec3* offsets, std::uint32_t count, const Vec3& x,
                 const Vec3& u) {
    for (std::uint32_t s = 0; s < count; ++s) {
        const double along = K == 0 ? offsets[s].x : (K == 1 ? offsets[s].y : offsets[s].z);
        out[s] = {x.x + along * u.x, x.y + along * u.y, x.z + along * u.z};
    }
}

}  // namespace

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

    species_axis_.assign(species.size(), -1);
    for (size_t k = 0; k < species.size(); ++k) {
        for (int axis = 0; axis < 3 && species_axis_[k] < 0; ++axis) {
            const bool on_axis =
                std::all_of(species[k].shape.offsets.begin(), species[k].shape.offsets.end(),
                            [axis](const Vec3& o) {
                                return o[(axis + 1) % 3] == 0.0 && o[(axis + 2) % 3] == 0.0;
                            });
            if (on_axis) species_axis_[k] = axis;
        }
    }
}

void SphereTable::update_positions(const BodyState& bodies, const std::vector<Species>& species,
                                   int threads) {
    const auto n = static_cast<std::ptrdiff_t>(bodies.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::ptrdiff_t b = 0; b < n; ++b) {
        const std::uint32_t k = bodies.species[b];
        const Shape& shape = species[k].shape;
        const Vec3 x = bodies.position[b];
        const std::uint32_t first = first_of[b];
        const int axis = species_axis_[k];
        if (axis >= 0) {
            // r · (s e_axis) is s times column `axis` of r to the last bit (the other terms add
            // ±0). One template per axis keeps the offset's component a plain load.
            const Vec3 u = rotated_axis(bodies.orientation[b], axis);
            Vec3* out = position.data() + first;
            const Vec3* offsets = shape.offsets.data();
            const std::uint32_t count = first_of[b + 1] - first;
            switch (axis) {
                case 0:
                    place_along<0>(out, offsets, count, x, u);
                    break;
                case 1:
                    place_along<1>(out, offsets, count, x, u);
                    break;
                default:
                    place_along<2>(out, offsets, count, x, u);
                    break;
            }
        } else {
            const Mat3 r = to_matrix(bodies.orientation[b]);
            for (std::uint32_t s = first; s < first_of[b + 1]; ++s)
                position[s] = x + r * shape.offsets[s - first];
        }
    }
}

}  // namespace rodsea
