#pragma once
// Contacts from sphere positions: the contact point sits in the middle of the overlap.
#include <cmath>
#include <cstdint>

#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/math/hostdevice.hpp"

namespace rodsea::physics {

// Sphere i of body a at p_i (centre of mass x_a) and sphere j of body b at p_j, d = p_i − p_j
// (minimum image): fills `c` but for its coefficients and returns true when the spheres overlap.
// (Most listed pairs do not touch: the caller looks the coefficients up only for those that do.)
RODSEA_HD inline bool sphere_sphere_contact(const Vec3& d, std::uint32_t a, const Vec3& p_i,
                                            double r_i, const Vec3& x_a, std::uint32_t b,
                                            const Vec3& p_j, double r_j, const Vec3& x_b,
                                            Contact& c) {
    const double reach = r_i + r_j;
    const double d2 = norm2(d);
    if (d2 >= reach * reach || d2 == 0.0) return false;
    const double dist = std::sqrt(d2);
    c.a = a;
    c.b = b;
    c.normal = d / dist;
    c.overlap = reach - dist;
    c.arm_a = (p_i - x_a) - (r_i - 0.5 * c.overlap) * c.normal;
    c.arm_b = (p_j - x_b) + (r_j - 0.5 * c.overlap) * c.normal;
    return true;
}

// How far a sphere at height z with radius r pokes below the base and above the lid (mm);
// positive means a contact.
struct PlateOverlaps {
    double base, lid;
};
RODSEA_HD inline PlateOverlaps plate_overlaps(double z, double r, const PlateState& plates) {
    return {plates.base_z - (z - r), (z + r) - plates.lid_z};
}

// How far a body moves along z to leave the plates after the impulses (mm), from its spheres'
// deepest overlap with the base and with the lid (0 where none overlaps): up by the one, down by
// the other, and not at all when it overlaps neither or both (no vertical move frees a body
// wedged between the plates).
//
// Why at all: time-driven stepping lets a sphere pressed against an accelerating plate sink by
// about ½ (a + g) dt² each step; the impulses stop the approach but nothing undoes the depth, so
// over a contact lasting a few milliseconds it adds up to ~(a + g) T dt / 2 (≈ 0.1 µm at
// dt = 1.25 µs). Small, but the polar rod's ratchet speed near the default gap changes by
// 0.23 mm/s per µm of gap, and without the push its speed never converged in dt (docs/model.md).
// Moving by the deepest overlap, along the plate's normal, leaves every plate contact just
// touching.
RODSEA_HD inline double plate_push(double base_depth, double lid_depth) {
    if ((base_depth > 0.0) == (lid_depth > 0.0)) return 0.0;
    return base_depth > 0.0 ? base_depth : -lid_depth;
}

// The contact of sphere p (radius r) of body a (centre of mass x_a) with the base or the lid,
// `overlap` deep.
RODSEA_HD inline Contact plate_contact(std::uint32_t a, const Vec3& p, double r, const Vec3& x_a,
                                       bool base, double overlap, const ContactCoefficients& k) {
    Contact c;
    c.a = a;
    c.b = base ? kBasePlate : kLidPlate;
    c.normal = {0.0, 0.0, base ? 1.0 : -1.0};
    c.overlap = overlap;
    c.arm_a = (p - x_a) - (r - 0.5 * overlap) * c.normal;
    c.friction = k.friction;
    c.restitution = k.restitution;
    return c;
}

}  // namespace rodsea::physics
