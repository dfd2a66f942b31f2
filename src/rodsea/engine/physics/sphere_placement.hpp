#pragma once
// World centres of a body's spheres from its centre of mass x and orientation q.
#include <cstdint>

#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/quat.hpp"

namespace rodsea::physics {

// The world centres of `count` spheres on body axis K: x + s u, s their offsets along it and u
// the axis in the world (a column of the rotation). r · (s e_K) is s times that column to the
// last bit (the other terms add ±0), and costs a third of the matrix product.
template <int K>
RODSEA_HD void place_along(Vec3* out, const Vec3* offsets, std::uint32_t count, Vec3 x, Vec3 u) {
    for (std::uint32_t s = 0; s < count; ++s) {
        const double along = K == 0 ? offsets[s].x : (K == 1 ? offsets[s].y : offsets[s].z);
        out[s] = {x.x + along * u.x, x.y + along * u.y, x.z + along * u.z};
    }
}

// Every body: `axis` is the body axis all its sphere centres lie on (every rod and bead), or
// -1 for any other shape. x comes by value: the stores to `out` cannot alias it.
RODSEA_HD inline void place_spheres(Vec3* out, const Vec3* offsets, std::uint32_t count, Vec3 x,
                                    const Quat& q, int axis) {
    switch (axis) {
        case 0:
            place_along<0>(out, offsets, count, x, rotated_axis(q, 0));
            return;
        case 1:
            place_along<1>(out, offsets, count, x, rotated_axis(q, 1));
            return;
        case 2:
            place_along<2>(out, offsets, count, x, rotated_axis(q, 2));
            return;
        default: {
            const Mat3 r = to_matrix(q);
            for (std::uint32_t s = 0; s < count; ++s)
                out[s] = x + r * offsets[s];
        }
    }
}

}  // namespace rodsea::physics
