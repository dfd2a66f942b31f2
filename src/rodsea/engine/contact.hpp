#pragma once
#include <cstdint>
#include <limits>

#include "rodsea/math/vec3.hpp"

namespace rodsea {

inline constexpr std::uint32_t kBasePlate = std::numeric_limits<std::uint32_t>::max();
inline constexpr std::uint32_t kLidPlate = kBasePlate - 1;

// One touching pair of spheres (or a sphere and a plate) found in this step.
struct Contact {
    std::uint32_t a = 0;  // body
    std::uint32_t b = 0;  // body, or kBasePlate / kLidPlate
    Vec3 normal;          // unit, from b into a
    Vec3 arm_a;           // contact point − centre of mass of a (mm)
    Vec3 arm_b;           // contact point − centre of mass of b (mm); unused for plates
    double friction = 0.0;
    double restitution = 0.0;
    double overlap = 0.0;  // mm

    bool with_plate() const { return b >= kLidPlate; }
};

}  // namespace rodsea
