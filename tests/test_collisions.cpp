// Two-body collisions through the whole engine (contact search, arms, impulse, resolution):
// momentum and angular momentum conserved to round-off, the normal relative velocity reversed
// by e when frictionless, and kinetic energy never gained.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "each_backend.hpp"
#include "rodsea/engine/cpu/free_flight.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"
#include "two_body.hpp"

namespace rodsea {
namespace {

using testing::BodySpec;
using testing::normal_relative_velocity;
using testing::two_body_simulation;

const Vec3 kCentre{20.0, 20.0, 10.0};

class TwoBodyCollision : public testing::EachBackend {};  // middle of the box and of the 20 mm gap

struct Outcome {
    size_t contacts = 0;
    size_t impulses = 0;
    double un_before = 0.0, un_after = 0.0;  // of the first contact, when there is exactly one
};

// One step; checks the conservation laws and returns what happened.
Outcome collide(const Species& a, const Species& b, const BodySpec& sa, const BodySpec& sb,
                ContactCoefficients coefficients, const BackendOptions& options) {
    Simulation sim = two_body_simulation(a, b, sa, sb, coefficients, options);
    const Vec3 fixed_point{3.0, -7.0, 1.0};
    const Vec3 p0 = sim.linear_momentum(), l0 = sim.angular_momentum(fixed_point);
    const double e0 = sim.kinetic_energy();
    // Scales for round-off: momentum ~ m v, angular momentum ~ m v |x|.
    const double p_scale = a.shape.mass * norm(sa.velocity) + b.shape.mass * norm(sb.velocity);
    const double l_scale = p_scale * 40.0;

    // The state the contact search saw: the same free flight the step does.
    BodyState flown = sim.bodies();
    const EngineParameters& prm = sim.parameters();
    cpu::advance_free_flight(flown.view(), SpeciesTable::from(prm), step_context(prm, 1), 1);
    sim.step();
    Outcome out;
    out.contacts = sim.contacts().size();
    out.impulses = sim.last_step().impulses;
    EXPECT_EQ(sim.last_step().unresolved, 0u);
    EXPECT_NEAR(norm(sim.linear_momentum() - p0), 0.0, 1e-13 * p_scale);
    EXPECT_NEAR(norm(sim.angular_momentum(fixed_point) - l0), 0.0, 1e-13 * l_scale);
    EXPECT_LE(sim.kinetic_energy(), e0 * (1 + 1e-13));
    if (out.contacts == 1) {
        const Contact& c = sim.contacts()[0];
        const BodyState& s = flown;
        const Vec3 u = (s.velocity[c.a] + cross(s.spin[c.a], c.arm_a)) -
                       (s.velocity[c.b] + cross(s.spin[c.b], c.arm_b));
        out.un_before = dot(u, c.normal);
        out.un_after = normal_relative_velocity(sim, c);
    }
    return out;
}

// Largest overlap between any sphere of a and any of b, as a fraction of the smaller radius.
double deepest_overlap(const Shape& a, const Vec3& xa, const Quat& qa, const Shape& b,
                       const Vec3& xb, const Quat& qb) {
    double deepest = 0.0;
    for (size_t i = 0; i < a.sphere_count(); ++i)
        for (size_t j = 0; j < b.sphere_count(); ++j) {
            const double d =
                norm((xa + rotate(qa, a.offsets[i])) - (xb + rotate(qb, b.offsets[j])));
            deepest =
                std::max(deepest, (a.radii[i] + b.radii[j] - d) / std::min(a.radii[i], b.radii[j]));
        }
    return deepest;
}

TEST_P(TwoBodyCollision, HeadOnSpheresFrictionless) {
    const Species bead = bead_species();
    const double gap = 0.8 - 1e-4;  // centres: overlapping by 0.1 µm
    const Outcome o =
        collide(bead, bead, {kCentre, {}, {30, 0, 0}, {}},
                {kCentre + Vec3{gap, 0, 0}, {}, {-10, 0, 0}, {}}, {0.0, 0.3}, options());
    ASSERT_EQ(o.contacts, 1u);
    EXPECT_NEAR(o.un_before, -40.0, 1e-6);
    EXPECT_NEAR(o.un_after / o.un_before, -0.3, 1e-12);
}

TEST_P(TwoBodyCollision, ObliqueSpinningSpheresWithFriction) {
    const Species bead = bead_species();
    const Vec3 n = normalized(Vec3{1.0, 0.6, 0.3});
    const Outcome o =
        collide(bead, bead, {kCentre, {}, {30, 5, -3}, {40, -10, 25}},
                {kCentre + (0.8 - 1e-4) * n, {}, {-10, 2, 4}, {-5, 60, 0}}, {0.05, 0.3}, options());
    ASSERT_EQ(o.contacts, 1u);
    EXPECT_EQ(o.impulses, 1u);
    // With friction the normal ratio is still e when the contact sticks; in the slide it is
    // e exactly too (P = j(n − μt̂) is built so): check the normal part of Stronge's law.
    EXPECT_NEAR(o.un_after / o.un_before, -0.3, 1e-9);
}

TEST_P(TwoBodyCollision, HeadOnRodsEndToEndFrictionless) {
    const Species rod = apolar_rod_species(2.5);
    const Quat along_x = flat_orientation(0.0);
    // End spheres (radius 0.2 mm, centres 1.05 mm from the centre) overlap by 0.1 µm.
    const double separation = 2 * 1.05 + 0.4 - 1e-4;
    const Outcome o = collide(rod, rod, {kCentre, along_x, {25, 0, 0}, {}},
                              {kCentre + Vec3{separation, 0, 0}, along_x, {-25, 0, 0}, {}},
                              {0.0, 0.3}, options());
    ASSERT_EQ(o.contacts, 1u);
    EXPECT_NEAR(o.un_after / o.un_before, -0.3, 1e-12);
}

TEST_P(TwoBodyCollision, ObliqueRodsWithFriction) {
    const Species polar = polar_rod_species();
    const Species apolar = apolar_rod_species(4.5);
    // The polar rod's thin end (+x) meets the side of a tilted apolar rod crossing in front.
    const Quat qa = flat_orientation(0.3);
    const Quat qb =
        flat_orientation(0.3 + std::numbers::pi / 2) * Quat::from_axis_angle({1, 0, 0}, 0.2);
    const Shape& sa = polar.shape;
    const Vec3 tip = kCentre + rotate(qa, sa.offsets.back());
    const Vec3 n = rotate(qa, Vec3{1, 0, 0});
    const double reach = sa.radii.back() + 0.4 - 1e-4;  // apolar centre sphere radius 0.4 mm
    const Vec3 xb = tip + reach * n;  // apolar rod's centre sphere is at its centre of mass
    const Outcome o = collide(polar, apolar, {kCentre, qa, 40.0 * n, {0, 0, 5}},
                              {xb, qb, {0, -3, 1}, {2, 0, -8}}, {0.05, 0.3}, options());
    EXPECT_GE(o.contacts, 1u);
    EXPECT_GE(o.impulses, 1u);
}

// Random rod pairs in random 3D orientations, touching at one sphere pair, with random
// velocities and spins: the conservation laws hold in every trial (checked inside collide),
// and the frictionless single-contact trials reverse the normal velocity by e.
TEST_P(TwoBodyCollision, RandomRodPairsConserveMomentumAndNeverGainEnergy) {
    SplitMix64 rng(2024);
    const Species rods[] = {polar_rod_species(), apolar_rod_species(2.5), apolar_rod_species(1.0),
                            bead_species()};
    int single_frictionless = 0, with_impulse = 0;
    const int trials = 400;
    for (int trial = 0; trial < trials; ++trial) {
        const Species& a = rods[rng.next() % 4];
        const Species& b = rods[rng.next() % 4];
        const auto random_q = [&] {
            return normalized(Quat{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1),
                                   rng.uniform(-1, 1)});
        };
        const Quat qa = random_q(), qb = random_q();
        const size_t ia = rng.next() % a.shape.sphere_count();
        const size_t ib = rng.next() % b.shape.sphere_count();
        const Vec3 n = normalized(Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)});
        const Vec3 ca = kCentre + rotate(qa, a.shape.offsets[ia]);
        const double reach = a.shape.radii[ia] + b.shape.radii[ib] - 1e-4;
        // Sphere ib of b sits along −n from sphere ia of a, so n points from b into a.
        const Vec3 xb = ca - reach * n - rotate(qb, b.shape.offsets[ib]);
        const Vec3 va{rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20)};
        // Touching, not interpenetrating: a random placement can push the rods through each
        // other, where contact normals contradict and no impulse sequence can settle them.
        if (deepest_overlap(a.shape, kCentre, qa, b.shape, xb, qb) > 0.05) {
            --trial;
            continue;
        }
        const Vec3 vb = va + rng.uniform(5, 60) * n;  // b moves toward a along n
        const Vec3 wa{rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)};
        const Vec3 wb{rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)};
        const ContactCoefficients k =
            trial % 2 ? ContactCoefficients{0.0, 0.3} : ContactCoefficients{0.05, 0.3};
        const Outcome o = collide(a, b, {kCentre, qa, va, wa}, {xb, qb, vb, wb}, k, options());
        if (o.impulses > 0) ++with_impulse;
        if (k.friction == 0.0 && o.contacts == 1 && o.impulses == 1) {
            ++single_frictionless;
            EXPECT_NEAR(o.un_after / o.un_before, -0.3, 1e-9);
        }
    }
    EXPECT_GT(with_impulse, trials / 2);
    EXPECT_GT(single_frictionless, trials / 10);
}

RODSEA_ON_EACH_STEP(TwoBodyCollision);

}  // namespace
}  // namespace rodsea

namespace rodsea {
namespace {

class CollisionCount : public testing::EachBackend {};

// A bead dropped 0.5 mm onto a still base hits it at v₀ = √(2gh) = 99.0 mm/s and bounces with
// e = 0.3: 99.0, 29.7, 8.9, 2.7, then 0.80 mm/s and less, until it lies on the base and gets an
// impulse every step against gravity's g·dt. The collision count (approach above
// kCollisionSpeed = 1 mm/s) is the 4 bounces faster than that, at any dt (the next, 0.80 mm/s,
// is 20 % below the threshold, far more than the g·dt ≤ 0.04 mm/s that stepping adds), while
// the impulses of the resting steps grow as 1/dt.
TEST_P(CollisionCount, ABouncingBeadCountsItsBouncesNotItsRestingSteps) {
    const auto drop = [this](double dt) {
        EngineParameters p;
        p.box = {10.0, 10.0};
        p.drive.gamma = 0.0;  // the base stays at z = 0
        p.dt = dt;
        p.species = {bead_species()};
        BodyState bodies;
        const double radius = 0.4;
        bodies.add(0, {5.0, 5.0, radius + 0.5}, Quat{}, {}, {});
        Simulation sim(p, bodies, options());
        std::size_t body = 0, plate = 0;
        const auto steps = static_cast<std::uint64_t>(std::llround(0.03 / dt));  // 30 ms
        for (std::uint64_t i = 0; i < steps; ++i) {
            sim.step();
            body += sim.last_step().body_collisions;
            plate += sim.last_step().plate_collisions;
        }
        return std::array<double, 3>{static_cast<double>(body), static_cast<double>(plate),
                                     static_cast<double>(sim.totals().impulses)};
    };
    const auto coarse = drop(4e-6), fine = drop(1e-6);
    EXPECT_EQ(coarse[0], 0.0);
    EXPECT_EQ(fine[0], 0.0);
    EXPECT_EQ(coarse[1], 4.0);
    EXPECT_EQ(fine[1], 4.0);
    // ~11 ms of rest at the end: ~2700 impulses at 4 µs, ~4 times as many at 1 µs.
    EXPECT_GT(coarse[2], 1000.0);
    EXPECT_NEAR(fine[2] / coarse[2], 4.0, 0.2);
}

RODSEA_ON_EACH_STEP(CollisionCount);

}  // namespace
}  // namespace rodsea

namespace rodsea {
namespace {

class PlateProjection : public testing::EachBackend {};

// A bead on a base shaken at Γ = 0.8 never leaves it (the base never accelerates downward faster
// than g). Each step, free flight lets it sink by about ½ (a + g) dt² relative to the base, and the
// resting impulse (with e = 0.3 on an approach of (a + g) dt) adds at most e (a + g) dt² more. The
// projection out of the plate undoes that depth every step, so the deepest overlap contact search
// ever sees is bounded by one step's (1 + e)(Γ + 1) g dt². Without it the depth would add up over
// the 4 periods to ~½ g T dt ≈ 1e-4 mm, thousands of times that bound.
TEST_P(PlateProjection, ABeadRestingOnTheShakenBaseSinksAtMostOneStepsWorth) {
    EngineParameters p;
    p.box = {10.0, 10.0};
    p.drive.gamma = 0.8;
    p.species = {bead_species()};
    const double radius = 0.4;
    const double e = p.species[0].plate.restitution;
    BodyState bodies;
    // At t = 0 the base is at its top, z = A, and at rest.
    bodies.add(0, {5.0, 5.0, p.drive.amplitude() + radius}, Quat{}, {}, {});
    Simulation sim(p, bodies, options());
    const double period = 2.0 * std::numbers::pi / p.drive.angular_frequency;
    const auto steps = static_cast<std::uint64_t>(std::llround(4.0 * period / p.dt));
    double deepest = 0.0, highest = 0.0;
    for (std::uint64_t i = 0; i < steps; ++i) {
        sim.step();
        deepest = std::max(deepest, sim.last_step().max_overlap_fraction * radius);
        highest = std::max(highest, sim.bodies().position[0].z - radius - sim.plates().base_z);
    }
    const double one_step = (1.0 + e) * (p.drive.gamma + 1.0) * p.drive.gravity * p.dt * p.dt;
    EXPECT_GT(deepest, 0.0);  // it did press on the base
    EXPECT_LT(deepest, one_step);
    EXPECT_LT(highest, one_step);  // and stayed on it
}

RODSEA_ON_EACH_STEP(PlateProjection);

}  // namespace
}  // namespace rodsea
