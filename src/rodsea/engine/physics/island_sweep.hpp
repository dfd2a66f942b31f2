#pragma once
// The impulses of one island of contacts (bodies joined by body–body contacts; a plate joins
// nothing), swept Gauss–Seidel style in list order until a sweep gives none or the sweep cap is
// reached (docs/model.md §3, docs/architecture.md "The step"). After the first sweep a contact is
// looked at again only if one of its bodies got an impulse since it was last looked at.
//
// Islands share no body, so every executor sweeps them independently and gets the same bits:
// the CPU backend on its threads, the GPU backend one island per thread.
#include <cstdint>

#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/engine/physics/impulse.hpp"
#include "rodsea/math/hostdevice.hpp"

namespace rodsea::physics {

struct IslandSweep {
    int sweeps = 0;
    std::uint32_t impulses = 0;
    std::uint32_t body_collisions = 0;   // impulses approaching faster than kCollisionSpeed
    std::uint32_t plate_collisions = 0;  // the same with a plate
    std::uint32_t unresolved = 0;        // contacts still approaching at the sweep cap
};

// The relative velocity (a − b) at a contact's point; a plate moves at `plate_velocity`.
// `bodies` gives velocity(b) and spin(b).
template <class Bodies>
RODSEA_HD Vec3 contact_velocity(const Contact& c, const Bodies& bodies,
                                const Vec3& plate_velocity) {
    const Vec3 va = point_velocity(bodies.velocity(c.a), bodies.spin(c.a), c.arm_a);
    return c.with_plate() ? va - plate_velocity
                          : va - point_velocity(bodies.velocity(c.b), bodies.spin(c.b), c.arm_b);
}

// Sweeps the contacts contacts[order[0]], ..., contacts[order[count − 1]]. `bodies` gives
// velocity(b) and spin(b) (writable), inv_mass(b) and inv_inertia(b) (world frame);
// `last_changed[b]` is 0 for every body of the island on entry. on_plate_impulse(k, approach)
// is called for each impulse on a plate contact k, with its approach speed before the impulse.
template <class Bodies, class OnPlateImpulse>
RODSEA_HD IslandSweep sweep_island(const Contact* contacts, const std::uint32_t* order,
                                   std::uint32_t count, Bodies& bodies, int* last_changed,
                                   const Vec3& plate_velocity, double approach_tolerance,
                                   int max_sweeps, OnPlateImpulse&& on_plate_impulse) {
    IslandSweep stats;
    const Mat3 zero = Mat3::zero();
    bool any_impulse = true;
    while (any_impulse && stats.sweeps < max_sweeps) {
        ++stats.sweeps;
        const int sweep = stats.sweeps;
        any_impulse = false;
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::uint32_t k = order[i];
            const Contact& c = contacts[k];
            const bool plate = c.with_plate();
            const int changed = plate ? last_changed[c.a]
                                      : (last_changed[c.a] > last_changed[c.b] ? last_changed[c.a]
                                                                               : last_changed[c.b]);
            if (sweep > 1 && changed < sweep - 1) continue;  // nothing moved since last check

            const Vec3 u = contact_velocity(c, bodies, plate_velocity);
            const double un = dot(u, c.normal);
            if (un >= -approach_tolerance) continue;

            const Mat3 k_matrix =
                plate ? collision_matrix(bodies.inv_mass(c.a), bodies.inv_inertia(c.a), c.arm_a,
                                         0.0, zero, {})
                      : collision_matrix(bodies.inv_mass(c.a), bodies.inv_inertia(c.a), c.arm_a,
                                         bodies.inv_mass(c.b), bodies.inv_inertia(c.b), c.arm_b);
            const Impulse impulse =
                stronge_impulse(u, c.normal, k_matrix, c.friction, c.restitution);

            bodies.velocity(c.a) += bodies.inv_mass(c.a) * impulse.p;
            bodies.spin(c.a) += bodies.inv_inertia(c.a) * cross(c.arm_a, impulse.p);
            last_changed[c.a] = sweep;
            if (plate) {
                on_plate_impulse(k, -un);
            } else {
                bodies.velocity(c.b) -= bodies.inv_mass(c.b) * impulse.p;
                bodies.spin(c.b) -= bodies.inv_inertia(c.b) * cross(c.arm_b, impulse.p);
                last_changed[c.b] = sweep;
            }
            ++stats.impulses;
            if (-un > kCollisionSpeed) ++(plate ? stats.plate_collisions : stats.body_collisions);
            any_impulse = true;
        }
    }
    if (any_impulse) {
        for (std::uint32_t i = 0; i < count; ++i) {
            const Contact& c = contacts[order[i]];
            if (dot(contact_velocity(c, bodies, plate_velocity), c.normal) < -approach_tolerance)
                ++stats.unresolved;
        }
    }
    return stats;
}

}  // namespace rodsea::physics
