// The Stronge impulse alone, and a sphere meeting a fixed plate through the whole engine.
#include <gtest/gtest.h>

#include <cmath>

#include "rodsea/engine/physics/impulse.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

// Collision matrix of one rod touching a fixed wall at a random point of its surface.
struct RodOnWall {
    Mat3 k;
    Vec3 n;
    Vec3 u;
};

RodOnWall random_rod_on_wall(SplitMix64& rng) {
    const Shape shape = polar_rod_species().shape;
    const Quat q = normalized(
        Quat{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)});
    const Mat3 r = to_matrix(q);
    const Vec3& i = shape.principal_inertia;
    const Mat3 inv_i = r * Mat3::diagonal({1 / i.x, 1 / i.y, 1 / i.z}) * transpose(r);
    const size_t s = static_cast<size_t>(rng.next() % shape.sphere_count());
    const Vec3 n{0, 0, 1};
    const Vec3 arm = r * shape.offsets[s] - shape.radii[s] * n;
    RodOnWall c;
    c.n = n;
    c.k = physics::collision_matrix(1 / shape.mass, inv_i, arm, 0.0, Mat3::zero(), {});
    c.u = {rng.uniform(-50, 50), rng.uniform(-50, 50), -rng.uniform(1, 100)};
    return c;
}

TEST(StrongeImpulse, FrictionlessReversesNormalVelocityByE) {
    SplitMix64 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        const RodOnWall c = random_rod_on_wall(rng);
        const physics::Impulse p = physics::stronge_impulse(c.u, c.n, c.k, 0.0, 0.3);
        const Vec3 after = c.u + c.k * p.p;
        EXPECT_NEAR(dot(after, c.n), -0.3 * dot(c.u, c.n), 1e-12 * norm(c.u));
        EXPECT_NEAR(norm(p.p - dot(p.p, c.n) * c.n), 0.0, 1e-12 * norm(p.p));
    }
}

// Over random rods, contact points and velocities: the impulse stays in the Coulomb cone, a
// sticking contact ends with zero slip, and a body hitting a fixed wall never gains energy
// (ΔKE = P·(u + u')/2 in the wall's frame).
TEST(StrongeImpulse, StaysInFrictionConeSticksExactlyAndDissipates) {
    SplitMix64 rng(11);
    int sticking = 0, sliding = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const RodOnWall c = random_rod_on_wall(rng);
        const double mu = trial % 2 ? 0.03 : 0.6, e = trial % 3 ? 0.1 : 0.3;
        const physics::Impulse p = physics::stronge_impulse(c.u, c.n, c.k, mu, e);
        const double pn = dot(p.p, c.n);
        const double pt = norm(p.p - pn * c.n);
        ASSERT_GT(pn, 0.0);
        EXPECT_LE(pt, mu * pn * (1 + 1e-12));
        const Vec3 after = c.u + c.k * p.p;
        if (p.sticking) {
            ++sticking;
            EXPECT_NEAR(norm(after - dot(after, c.n) * c.n), 0.0, 1e-11 * norm(c.u));
            EXPECT_NEAR(dot(after, c.n), -e * dot(c.u, c.n), 1e-11 * norm(c.u));
        } else {
            ++sliding;
            EXPECT_NEAR(pt, mu * pn, 1e-12 * pn);
        }
        EXPECT_LE(dot(p.p, c.u + after), 1e-12 * norm(p.p) * norm(c.u));
    }
    EXPECT_GT(sticking, 100);  // both branches must have been exercised
    EXPECT_GT(sliding, 100);
}

// A bead falls onto a fixed base: the step in which it meets the plate turns its incoming
// velocity −v into +e v exactly (a sphere's contact arm is parallel to the normal, so the
// impulse is purely normal and K = 1/m).
TEST(PlateCollision, DroppedSphereReboundsWithRatioE) {
    for (double e : {0.1, 0.3, 0.9}) {
        Scene scene = single_body(bead_species(), 10.0);
        scene.params.drive.gamma = 0.0;  // fixed plates
        scene.params.species[0].plate = {0.0, e};
        scene.bodies.position[0].z = scene.params.species[0].shape.radii[0] + 0.2;  // base at 0
        Simulation sim(scene.params, scene.bodies);
        double incoming = 0.0;
        while (sim.totals().impulses == 0) {
            incoming = sim.bodies().velocity[0].z - scene.params.drive.gravity * scene.params.dt;
            sim.step();
            ASSERT_LT(sim.step_count(), 100000u);
        }
        EXPECT_LT(incoming, -1.0);  // it fell ~0.2 mm: v ≈ −sqrt(2 g h) ≈ −63 mm/s
        EXPECT_NEAR(sim.bodies().velocity[0].z / incoming, -e, 1e-12) << "e = " << e;
    }
}

// A spinning, sliding sphere hits the base: with a large μ it ends sticking (no slip at the
// contact point); with μ = 0.03 it slides and the tangential impulse is exactly μ times the
// normal one.
TEST(PlateCollision, SpinningSphereSticksOrSlidesWithinTheCone) {
    for (double mu : {0.03, 2.0}) {
        Scene scene = single_body(bead_species(), 10.0);
        scene.params.drive.gamma = 0.0;
        scene.params.drive.gravity = 0.0;
        scene.params.species[0].plate = {mu, 0.3};
        // Half a step's fall above the fixed base at z = 0: it touches in the first step.
        scene.bodies.velocity[0] = {20.0, 5.0, -30.0};
        scene.bodies.position[0].z =
            scene.params.species[0].shape.radii[0] + 0.5 * 30.0 * scene.params.dt;
        scene.bodies.spin[0] = {10.0, -40.0, 3.0};
        Simulation sim(scene.params, scene.bodies);
        const double m = scene.params.species[0].shape.mass;
        const Vec3 v0 = scene.bodies.velocity[0];
        sim.step();
        ASSERT_EQ(sim.totals().impulses, 1u);
        const Vec3 dp = m * (sim.bodies().velocity[0] - v0);
        const double pn = dp.z, pt = std::hypot(dp.x, dp.y);
        EXPECT_LE(pt, mu * pn * (1 + 1e-12));
        const Contact& c = sim.contacts().at(0);
        const Vec3 u = sim.bodies().velocity[0] + cross(sim.bodies().spin[0], c.arm_a);
        if (mu > 1.0) {
            EXPECT_NEAR(std::hypot(u.x, u.y), 0.0, 1e-12);
            EXPECT_NEAR(u.z, 0.3 * 30.0, 1e-11);
        } else {
            EXPECT_NEAR(pt, mu * pn, 1e-12 * pn);
        }
    }
}

}  // namespace
}  // namespace rodsea
