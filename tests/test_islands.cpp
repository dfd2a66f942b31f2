// The island-parallel resolver against the plain Gauss–Seidel sweep over the whole contact list
// that it replaced (kept here as the reference): the same impulses, so the same velocities and
// spins bit for bit, on 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "rodsea/engine/cpu/contact_resolution.hpp"
#include "rodsea/engine/cpu/contact_search.hpp"
#include "rodsea/engine/physics/impulse.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

// The whole list swept in order until no impulse, the resolver before islands.
size_t sweep_whole_list(const std::vector<Contact>& contacts, BodyState& bodies,
                        const cpu::InverseInertia& inertia, double plate_velocity_z,
                        const EngineParameters& params) {
    std::vector<int> last_changed(bodies.size(), 0);
    const Vec3 plate_velocity{0.0, 0.0, plate_velocity_z};
    const auto point_velocity = [&](std::uint32_t b, const Vec3& arm) {
        return bodies.velocity[b] + cross(bodies.spin[b], arm);
    };
    size_t impulses = 0;
    bool any = true;
    for (int sweep = 1; any && sweep <= params.max_sweeps; ++sweep) {
        any = false;
        for (const Contact& c : contacts) {
            const bool plate = c.with_plate();
            const int changed =
                plate ? last_changed[c.a] : std::max(last_changed[c.a], last_changed[c.b]);
            if (sweep > 1 && changed < sweep - 1) continue;
            const Vec3 u = point_velocity(c.a, c.arm_a) -
                           (plate ? plate_velocity : point_velocity(c.b, c.arm_b));
            if (dot(u, c.normal) >= -params.approach_tolerance) continue;
            const Mat3 k =
                plate ? physics::collision_matrix(inertia.inv_mass(c.a), inertia.inv_inertia(c.a),
                                                  c.arm_a, 0.0, Mat3::zero(), {})
                      : physics::collision_matrix(inertia.inv_mass(c.a), inertia.inv_inertia(c.a),
                                                  c.arm_a, inertia.inv_mass(c.b),
                                                  inertia.inv_inertia(c.b), c.arm_b);
            const physics::Impulse p =
                physics::stronge_impulse(u, c.normal, k, c.friction, c.restitution);
            bodies.velocity[c.a] += inertia.inv_mass(c.a) * p.p;
            bodies.spin[c.a] += inertia.inv_inertia(c.a) * cross(c.arm_a, p.p);
            last_changed[c.a] = sweep;
            if (!plate) {
                bodies.velocity[c.b] -= inertia.inv_mass(c.b) * p.p;
                bodies.spin[c.b] -= inertia.inv_inertia(c.b) * cross(c.arm_b, p.p);
                last_changed[c.b] = sweep;
            }
            ++impulses;
            any = true;
        }
    }
    return impulses;
}

// Six chains of eight touching beads lying on the base, thrown together and down at random: the
// chains are six islands, and each needs many sweeps to settle.
TEST(IslandResolver, AppliesExactlyTheImpulsesOfOneSweepOverTheWholeList) {
    EngineParameters params;
    params.box = {40.0, 40.0};
    params.species = {bead_species()};
    const double r = 0.4;
    const StepContext step = step_context(params, 0);  // the plates at t = 0
    const physics::PlateState& plates = step.plates;
    BodyState start;
    SplitMix64 rng(8);
    for (int chain = 0; chain < 6; ++chain) {
        for (int k = 0; k < 8; ++k) {
            const Vec3 x{5.0 + k * (2.0 * r - 1e-4), 5.0 + 5.0 * chain, plates.base_z + r - 1e-5};
            const Vec3 v{rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, -1)};
            const Vec3 w{rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)};
            start.add(0, x, Quat{}, v, w);
        }
    }
    const SpeciesTable species = SpeciesTable::from(params);
    cpu::SphereTable spheres;
    spheres.assign(start.species, species);
    spheres.update_positions(start.view(), species, 1);
    cpu::ContactFinder finder;
    std::vector<Contact> contacts;
    finder.find(spheres, start.view(), species, step, contacts, 1);
    ASSERT_EQ(contacts.size(), 6u * (7 + 8));  // 7 neighbours and 8 base contacts per chain
    cpu::InverseInertia inertia;
    inertia.update_for(contacts, start.view(), species);

    BodyState reference = start;
    const size_t reference_impulses =
        sweep_whole_list(contacts, reference, inertia, plates.velocity_z, params);
    ASSERT_GT(reference_impulses, 200u);  // many sweeps, not one impulse per contact
    for (int threads = 1; threads <= 2; ++threads) {
        BodyState bodies = start;
        cpu::ContactResolver resolver;
        std::vector<cpu::PlateHit> hits;
        const cpu::ResolutionStats stats =
            resolver.resolve(contacts, bodies.view(), inertia, step, hits, threads);
        EXPECT_EQ(resolver.islands(), 6u);
        EXPECT_EQ(stats.impulses, reference_impulses);
        EXPECT_EQ(stats.unresolved, 0u);
        for (size_t b = 0; b < start.size(); ++b) {
            EXPECT_EQ(bodies.velocity[b], reference.velocity[b]) << "body " << b;
            EXPECT_EQ(bodies.spin[b], reference.spin[b]) << "body " << b;
        }
    }
}

}  // namespace
}  // namespace rodsea
