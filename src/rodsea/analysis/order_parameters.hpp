#pragma once
// In-plane orientation of rods and the order parameters of MODEL.md §4. θ is the angle of the
// body x axis in the x-y plane: thick → thin for polar rods.
#include <cmath>
#include <cstdint>
#include <vector>

#include "rodsea/engine/body_state.hpp"

namespace rodsea {

inline double in_plane_angle(const Quat& q) {
    const Vec3 axis = rotate(q, Vec3{1.0, 0.0, 0.0});
    return std::atan2(axis.y, axis.x);
}

// |⟨(cos mθ, sin mθ)⟩| over the bodies of one species: m = 1 gives P, m = 2 gives S.
// Returns 0 when the species has no bodies.
inline double orientational_order(const BodyState& bodies, std::uint32_t species, int m) {
    double c = 0.0, s = 0.0;
    std::size_t n = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (bodies.species[b] != species) continue;
        const double theta = in_plane_angle(bodies.orientation[b]);
        c += std::cos(m * theta);
        s += std::sin(m * theta);
        ++n;
    }
    return n == 0 ? 0.0 : std::hypot(c, s) / static_cast<double>(n);
}

}  // namespace rodsea
