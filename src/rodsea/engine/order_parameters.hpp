#pragma once
// In-plane orientation of rods and the order parameters of docs/model.md §4. θ is the angle of the
// body x axis in the x-y plane: thick → thin for polar rods.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "rodsea/engine/body_state.hpp"

namespace rodsea {

inline double in_plane_angle(const Quat& q) {
    const Vec3 axis = rotate(q, Vec3{1.0, 0.0, 0.0});
    return std::atan2(axis.y, axis.x);
}

// |⟨(cos mθ, sin mθ)⟩| over `angles`: m = 1 gives P, m = 2 gives S. 0 for no angles.
inline double orientational_order(std::span<const double> angles, int m) {
    double c = 0.0, s = 0.0;
    for (double theta : angles) {
        c += std::cos(m * theta);
        s += std::sin(m * theta);
    }
    return angles.empty() ? 0.0 : std::hypot(c, s) / static_cast<double>(angles.size());
}

// The same over the bodies of one species.
inline double orientational_order(const BodyState& bodies, std::uint32_t species, int m) {
    std::vector<double> angles;
    for (std::size_t b = 0; b < bodies.size(); ++b)
        if (bodies.species[b] == species) angles.push_back(in_plane_angle(bodies.orientation[b]));
    return orientational_order(angles, m);
}

}  // namespace rodsea
