#include "rodsea/engine/contact_resolution.hpp"

#include <algorithm>

#include "rodsea/engine/impulse.hpp"

namespace rodsea {

void InverseInertia::update(const BodyState& bodies, const std::vector<Species>& species) {
    inv_mass.resize(bodies.size());
    inv_inertia.resize(bodies.size());
    for (size_t b = 0; b < bodies.size(); ++b) {
        const Shape& shape = species[bodies.species[b]].shape;
        const Mat3 r = to_matrix(bodies.orientation[b]);
        const Vec3& i = shape.principal_inertia;
        inv_mass[b] = 1.0 / shape.mass;
        inv_inertia[b] = r * Mat3::diagonal({1.0 / i.x, 1.0 / i.y, 1.0 / i.z}) * transpose(r);
    }
}

namespace {

Vec3 contact_point_velocity(const BodyState& bodies, std::uint32_t b, const Vec3& arm) {
    return bodies.velocity[b] + cross(bodies.spin[b], arm);
}

}  // namespace

ResolutionStats ContactResolver::resolve(const std::vector<Contact>& contacts, BodyState& bodies,
                                         const InverseInertia& inertia, double plate_velocity_z,
                                         const EngineParameters& params,
                                         std::vector<PlateHit>& hits) {
    ResolutionStats stats;
    last_changed_.assign(bodies.size(), 0);
    const Vec3 plate_velocity{0.0, 0.0, plate_velocity_z};
    const Mat3 zero = Mat3::zero();

    const auto relative_velocity = [&](const Contact& c) {
        const Vec3 va = contact_point_velocity(bodies, c.a, c.arm_a);
        return c.with_plate() ? va - plate_velocity
                              : va - contact_point_velocity(bodies, c.b, c.arm_b);
    };

    bool any_impulse = true;
    while (any_impulse && stats.sweeps < params.max_sweeps) {
        ++stats.sweeps;
        const int sweep = stats.sweeps;
        any_impulse = false;
        for (const Contact& c : contacts) {
            const bool plate = c.with_plate();
            const int changed =
                plate ? last_changed_[c.a] : std::max(last_changed_[c.a], last_changed_[c.b]);
            if (sweep > 1 && changed < sweep - 1) continue;  // nothing moved since last check

            const Vec3 u = relative_velocity(c);
            const double un = dot(u, c.normal);
            if (un >= -params.approach_tolerance) continue;

            const Mat3 k =
                plate ? collision_matrix(inertia.inv_mass[c.a], inertia.inv_inertia[c.a], c.arm_a,
                                         0.0, zero, {})
                      : collision_matrix(inertia.inv_mass[c.a], inertia.inv_inertia[c.a], c.arm_a,
                                         inertia.inv_mass[c.b], inertia.inv_inertia[c.b], c.arm_b);
            const Impulse impulse = stronge_impulse(u, c.normal, k, c.friction, c.restitution);

            bodies.velocity[c.a] += inertia.inv_mass[c.a] * impulse.p;
            bodies.spin[c.a] += inertia.inv_inertia[c.a] * cross(c.arm_a, impulse.p);
            last_changed_[c.a] = sweep;
            if (plate) {
                hits.push_back({c.a, c.b, -un});
            } else {
                bodies.velocity[c.b] -= inertia.inv_mass[c.b] * impulse.p;
                bodies.spin[c.b] -= inertia.inv_inertia[c.b] * cross(c.arm_b, impulse.p);
                last_changed_[c.b] = sweep;
            }
            ++stats.impulses;
            if (-un > kCollisionSpeed) ++(plate ? stats.plate_collisions : stats.body_collisions);
            any_impulse = true;
        }
    }
    if (any_impulse) {
        for (const Contact& c : contacts)
            if (dot(relative_velocity(c), c.normal) < -params.approach_tolerance)
                ++stats.unresolved;
    }
    return stats;
}

}  // namespace rodsea
