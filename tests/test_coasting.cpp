// The coasting step (cpu/coasting_backend.hpp) against the step that flies every body: the same
// contacts at the same steps, the same path to round-off, and bounds that never let a contact
// slip, tested where they are tight (bodies aimed at the plates and at each other).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "rodsea/engine/cpu/coasting_backend.hpp"
#include "rodsea/engine/cpu/cpu_backend.hpp"
#include "rodsea/engine/physics/coasting.hpp"
#include "rodsea/engine/physics/contact_geometry.hpp"
#include "rodsea/engine/physics/sphere_placement.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

// The contacts of one step as (a, b) pairs: the same contacts in the same order.
std::vector<std::pair<std::uint32_t, std::uint32_t>> contact_pairs(const std::vector<Contact>& cs) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (const Contact& c : cs)
        out.emplace_back(c.a, c.b);
    return out;
}

// The angle between two orientations, rad: from the vector part of the turn between them (an
// arccosine of their dot product would lose half the digits near zero).
double angle_between(const Quat& p, const Quat& q) {
    const Quat turn = conjugate(p) * q;
    return 2.0 *
           std::asin(std::min(1.0, std::sqrt(turn.x * turn.x + turn.y * turn.y + turn.z * turn.z)));
}

struct Comparison {
    std::uint64_t steps_with_contacts = 0;  // in the reference
    double largest_distance = 0.0;          // mm, over all bodies and steps
    double largest_angle = 0.0;             // rad
    cpu::CoastingCounts counts;
};

// Steps both backends from the same state and checks after every step that they found the same
// contacts; returns how far apart the states came.
Comparison compare_with_reference(const Scene& scene, std::uint64_t steps) {
    const SpeciesTable species = SpeciesTable::from(scene.params);
    cpu::CpuBackend reference(species, scene.bodies, 1);
    cpu::CoastingBackend coasting(species, scene.bodies, 1);
    Comparison result;
    StepStatistics stats;
    StageProfile profile;
    for (std::uint64_t k = 1; k <= steps; ++k) {
        const StepContext context = step_context(scene.params, k);
        reference.step(context, stats, profile);
        coasting.step(context, stats, profile);
        const auto expected = contact_pairs(reference.contacts());
        EXPECT_EQ(contact_pairs(coasting.contacts()), expected) << "step " << k;
        if (contact_pairs(coasting.contacts()) != expected) break;
        result.steps_with_contacts += expected.empty() ? 0 : 1;
        const BodyState& a = reference.bodies();
        const BodyState& b = coasting.bodies();
        for (std::size_t i = 0; i < a.size(); ++i) {
            const Vec3 d = PeriodicBox2D{scene.params.box.lx, scene.params.box.ly}.minimum_image(
                a.position[i] - b.position[i]);
            result.largest_distance = std::max(result.largest_distance, norm(d));
            result.largest_angle =
                std::max(result.largest_angle, angle_between(a.orientation[i], b.orientation[i]));
        }
    }
    result.counts = coasting.counts();
    return result;
}

// A 2.5 mm rod of the medium bouncing between the plates: 0.6 mm of room, so it flies free for
// thousands of steps between its plate collisions.
TEST(Coasting, ALoneRodMeetsThePlatesAtTheSameStepsWithinRoundOff) {
    Scene scene = single_body(apolar_rod_species(2.5), 20.0, 0.05);
    scene.bodies.position[0].z += 0.3;
    scene.bodies.velocity[0] = {4.0, -3.0, 250.0};  // up to the lid, 0.3 mm above
    scene.bodies.spin[0] = {1.5, -2.0, 6.0};
    // 3×10⁴ steps (37.5 ms): a handful of plate collisions. Free flight is linear in the state,
    // so between collisions the two paths' difference (the jump's round-off, ~10⁻¹⁵ mm) does not
    // grow; each collision multiplies it by a factor of order one. Far longer, the bounces' chaos
    // would amplify it past any fixed tolerance, as it would a change of compiler.
    const Comparison c = compare_with_reference(scene, 30'000);
    EXPECT_GE(c.steps_with_contacts, 3u);
    EXPECT_LT(c.largest_distance, 1e-9);
    EXPECT_LT(c.largest_angle, 1e-9);
    // It did coast: most steps it was left alone, and woke for the plates.
    EXPECT_LT(c.counts.awake_body_steps, 30'000u / 4);
    EXPECT_GE(c.counts.wakes_by_plate, 2u);
    std::printf(
        "[ measured ] lone rod: %llu contact steps, %llu of 30000 steps awake, %llu "
        "coasts, %.2g mm, %.2g rad\n",
        static_cast<unsigned long long>(c.steps_with_contacts),
        static_cast<unsigned long long>(c.counts.awake_body_steps),
        static_cast<unsigned long long>(c.counts.coasts), c.largest_distance, c.largest_angle);
}

// Two rods of the medium sliding at each other along x on the vibrating base.
TEST(Coasting, APairCollidesAtTheSameStepWithinRoundOff) {
    Scene scene = single_body(apolar_rod_species(2.5), 20.0, 0.0);
    Vec3 other = scene.bodies.position[0];
    other.x += 2.5 + 0.3;  // end to end, 0.3 mm apart
    scene.bodies.add(0, other, scene.bodies.orientation[0], {-12.0, 0.0, 20.0}, {0.0, 0.0, 3.0});
    scene.bodies.velocity[0] = {12.0, 0.5, 25.0};
    const Comparison c = compare_with_reference(scene, 10'000);
    EXPECT_GE(c.steps_with_contacts, 3u);
    EXPECT_LT(c.largest_distance, 1e-9);
    EXPECT_LT(c.largest_angle, 1e-9);
    EXPECT_GT(c.counts.wakes_by_travel, 0u);
    EXPECT_LT(c.counts.awake_body_steps, 2u * 10'000u / 2);
}

// Head-on, with no gravity and still plates, at random gaps and speeds: each coast relies on
// the other rod's promise, and the contact lands at the reference's step whatever the two.
TEST(Coasting, BodiesAimedAtEachOtherAtTheBoundMeetAtTheSameStep) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> gap(0.01, 0.4), speed(5.0, 60.0);
    for (int trial = 0; trial < 12; ++trial) {
        Scene scene = single_body(apolar_rod_species(2.5), 20.0, 0.0);
        scene.params.drive.gamma = 0.0;
        scene.params.drive.gravity = 0.0;
        scene.bodies.position[0].z += 0.3;  // mid-gap
        const double g = gap(random);
        // They meet within 6000 steps, between two steps' ends (not tied at one).
        const double v = std::max(speed(random), g / 0.0143717);
        Vec3 other = scene.bodies.position[0];
        other.x += 2.5 + g;
        scene.bodies.add(0, other, scene.bodies.orientation[0], {-v, 0.0, 0.0});
        scene.bodies.velocity[0] = {v, 0.0, 0.0};
        const Comparison c = compare_with_reference(scene, 8'000);
        EXPECT_GE(c.steps_with_contacts, 1u) << "trial " << trial;
        EXPECT_LT(c.largest_distance, 1e-9) << "trial " << trial;
        EXPECT_GT(c.counts.coasts, 0u) << "trial " << trial;
    }
}

// A neighbour's flight ends: rod A rests beside rod B, 0.04 mm away, and coasts relying on B
// (on its free flight once B has been calm for kCalmSteps, on its promised speed before); rod C
// hits B from the other side at 150 mm/s and sends it at A. A must wake the step after B's
// contact, and meet B when the reference does.
TEST(Coasting, ABrokenPromiseWakesTheCoastsThatReliedOnIt) {
    Scene scene = single_body(apolar_rod_species(2.5), 30.0, 0.0);
    scene.params.drive.gamma = 0.0;
    scene.params.drive.gravity = 0.0;
    scene.bodies.position[0].z += 0.3;
    scene.bodies.position[0].x = 8.0;
    Vec3 b = scene.bodies.position[0], c = b;
    b.x += 2.5 + 0.04;  // nearer than the far bound reaches: A relies on B's promise
    c.x = b.x + 2.5 + 0.3;
    scene.bodies.add(0, b, scene.bodies.orientation[0]);
    scene.bodies.add(0, c, scene.bodies.orientation[0], {-150.0, 0.0, 0.0});
    const Comparison result = compare_with_reference(scene, 6'000);
    EXPECT_GE(result.steps_with_contacts, 2u);  // C on B, then B on A
    EXPECT_LT(result.largest_distance, 1e-9);
    EXPECT_GT(result.counts.wakes_by_promise, 0u);
}

// The plate bound against the flight itself: for random rods (heights, vertical speeds, tilts,
// spins), the first step at which any sphere of the per-step flight overlaps a plate is never
// before first_plate_step; and for a rod that does not turn the bound is the step itself (it
// only gives away the 10⁻⁹ mm margin).
TEST(Coasting, ThePlateBoundIsNeverLateAndTightWithoutSpin) {
    const Scene scene = single_body(apolar_rod_species(2.5), 20.0, 0.0);
    const EngineParameters& params = scene.params;
    const SpeciesTable species = SpeciesTable::from(params);
    const physics::PlateMotion plates = params.drive.motion();
    const std::uint32_t first = species.first_sphere[0], count = species.sphere_count(0);
    const double reach = std::sqrt(species.reach2[0]);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int exact = 0, spinless = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const bool spins = trial % 2 == 0;
        const double tilt = 0.25 * unit(random);
        Vec3 x = scene.bodies.position[0];
        x.z += 0.25 + 0.25 * unit(random);
        Vec3 v{0.0, 0.0, 70.0 * unit(random)};
        Quat q = normalized(Quat::from_axis_angle({0.0, 1.0, 0.0}, tilt));
        Vec3 w = spins ? Vec3{8.0 * unit(random), 8.0 * unit(random), 20.0 * unit(random)} : Vec3{};
        const std::uint64_t start = 1000 + static_cast<std::uint64_t>(trial) * 37;
        // The start must be clear of both plates.
        std::vector<Vec3> at(count);
        const auto lowest_highest = [&](double& lo, double& hi) {
            physics::place_spheres(at.data(), species.sphere_offset.data() + first, count, x, q,
                                   species.sphere_axis[0]);
            lo = 1e300;
            hi = -1e300;
            for (std::uint32_t s = 0; s < count; ++s) {
                lo = std::min(lo, at[s].z - species.sphere_radius[first + s]);
                hi = std::max(hi, at[s].z + species.sphere_radius[first + s]);
            }
        };
        double lo = 0, hi = 0;
        lowest_highest(lo, hi);
        const physics::PlateState p0 =
            physics::plate_state(plates, static_cast<double>(start) * params.dt);
        if (lo <= p0.base_z || hi >= p0.lid_z) continue;
        physics::CoastStart c{x.z, v.z, x.z - lo, hi - x.z,
                              reach * norm(cross(w, rotated_axis(q, species.sphere_axis[0])))};
        const std::uint64_t bound =
            physics::first_plate_step(c, start, 1 << 16, params.dt, params.drive.gravity, plates);
        // The per-step flight until its spheres first cross a plate.
        std::uint64_t k = start;
        for (;;) {
            ++k;
            physics::fly_freely(x, v, q, w, species.rotor[0], params.dt, params.drive.gravity,
                                0.5 * params.drive.gravity * params.dt * params.dt,
                                {params.box.lx, params.box.ly});
            lowest_highest(lo, hi);
            const physics::PlateState p =
                physics::plate_state(plates, static_cast<double>(k) * params.dt);
            if (lo < p.base_z || hi > p.lid_z) break;
        }
        EXPECT_LE(bound, k) << "trial " << trial;
        if (!spins) {
            ++spinless;
            exact += bound == k ? 1 : 0;
        }
    }
    EXPECT_GT(spinless, 150);
    EXPECT_EQ(exact, spinless);
}

// A mixture: the coasting step's trajectory does not depend on the threads nor on anyone
// looking at the state, and in its first steps it is the reference's to round-off.
Simulation mixture(bool coasting, int threads) {
    Scene scene = polar_in_apolar_mixture(0.05, 2.5, 0.5, 20.0, 3);
    scene.params.noise_epsilon = 0.05;
    return Simulation(scene.params, scene.bodies, {.threads = threads, .coasting = coasting});
}

TEST(Coasting, AnyNumberOfThreadsAndAnyLookGiveTheSameBits) {
    std::uint64_t hash[3] = {};
    for (int threads = 1; threads <= 3; ++threads) {
        Simulation sim = mixture(true, threads);
        for (int block = 0; block < 30; ++block) {
            sim.run(50);
            if (threads == 2) (void)sim.bodies();  // a frame's look: flies coasting copies
        }
        EXPECT_GT(sim.totals().noise_kicks, 0u);
        hash[threads - 1] = sim.state_hash();
    }
    EXPECT_EQ(hash[0], hash[1]);
    EXPECT_EQ(hash[0], hash[2]);
}

}  // namespace
}  // namespace rodsea
