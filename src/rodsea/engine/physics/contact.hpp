#pragma once
// A contact found in a step: two touching spheres of different bodies, or a sphere poking
// through a plate, with what its impulse needs.
#include <cstdint>
#include <limits>

#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

// Coefficients of one kind of collision (docs/model.md §3, paper Table S2).
struct ContactCoefficients {
    double friction = 0.05;     // μ, Coulomb, [0, 10]
    double restitution = 0.30;  // e, normal, [0, 1]
};

inline constexpr std::uint32_t kBasePlate = std::numeric_limits<std::uint32_t>::max();
inline constexpr std::uint32_t kLidPlate = kBasePlate - 1;

// A collision, as opposed to a contact that merely persists: an impulse on a contact approaching
// faster than this. Bodies resting on or pressed against each other or a plate approach at about
// (Γ + 1) g dt per step (0.09 mm/s at 1.25 µs, 0.4 mm/s at 5 µs) and get an impulse every step,
// so impulses grow as 1/dt; real impacts in the vibrated cell come at mm/s to tens of mm/s, and
// their count per second does not depend on dt.
inline constexpr double kCollisionSpeed = 1.0;  // mm/s

struct Contact {
    std::uint32_t a = 0;  // body
    std::uint32_t b = 0;  // body, or kBasePlate / kLidPlate
    Vec3 normal;          // unit, from b into a
    Vec3 arm_a;           // contact point − centre of mass of a (mm)
    Vec3 arm_b;           // contact point − centre of mass of b (mm); unused for plates
    double friction = 0.0;
    double restitution = 0.0;
    double overlap = 0.0;  // mm

    RODSEA_HD bool with_plate() const { return b >= kLidPlate; }
};

}  // namespace rodsea
