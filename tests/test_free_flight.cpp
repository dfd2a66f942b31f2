// Free flight: the parabola under gravity, and torque-free rotation checked against the exact
// precession of a symmetric body, the exact turn of a sphere, and a fine reference integration of
// Euler's equations.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "each_backend.hpp"
#include "rodsea/engine/physics/rigid_rotation.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

// A body alone in a 50 mm gap between fixed plates: it never touches anything.
Scene free_body(const Species& species) {
    Scene scene = single_body(species, 40.0);
    scene.params.drive.gamma = 0.0;
    scene.params.drive.gap = 50.0;
    scene.bodies.position[0].z = 25.0;
    return scene;
}

class FreeFlight : public testing::EachBackend {};

TEST_P(FreeFlight, BallisticBodyFollowsTheParabola) {
    Scene scene = free_body(polar_rod_species());
    const Vec3 x0 = scene.bodies.position[0], v0{3.0, -2.0, 60.0};
    scene.bodies.velocity[0] = v0;
    Simulation sim(scene.params, scene.bodies, options());
    const double g = scene.params.drive.gravity;
    for (int block = 0; block < 4; ++block) {
        sim.run(500);
        const double t = sim.time();
        // Round-off only: ~2000 additions of O(10) mm numbers.
        EXPECT_NEAR(sim.bodies().position[0].z, x0.z + v0.z * t - 0.5 * g * t * t, 1e-10);
        EXPECT_NEAR(sim.bodies().position[0].x, x0.x + v0.x * t, 1e-10);
        EXPECT_NEAR(sim.bodies().velocity[0].z, v0.z - g * t, 1e-10);
        EXPECT_EQ(sim.totals().impulses, 0u);
    }
}

// Round-off bound for 10⁴ steps: each step converts ω ↔ L and renormalises q, a few ulps
// (~1e-15 relative); accumulated linearly over 10⁴ steps that stays below 1e-10.
constexpr double kRoundOff = 1e-10;

// A symmetric top precesses regularly: its axis turns about the fixed L at |L|/I_⊥.
TEST_P(FreeFlight, SymmetricRodPrecessesExactly) {
    Scene scene = free_body(polar_rod_species());
    scene.params.drive.gravity = 0.0;
    const Quat q0 = Quat::from_axis_angle(normalized(Vec3{0.3, 1.0, -0.2}), 0.7);
    scene.bodies.orientation[0] = q0;
    scene.bodies.spin[0] = {35.0, -20.0, 80.0};
    Simulation sim(scene.params, scene.bodies, options());
    const Vec3 l0 = sim.angular_momentum(sim.bodies().position[0]);
    const double e0 = sim.kinetic_energy();
    sim.run(10000);
    const Vec3& i = scene.params.species[0].shape.principal_inertia;
    const Vec3 axis = rotate(sim.bodies().orientation[0], Vec3{1, 0, 0});
    const Vec3 expected = rotate(Quat::from_axis_angle(normalized(l0), norm(l0) * sim.time() / i.y),
                                 rotate(q0, Vec3{1, 0, 0}));
    EXPECT_NEAR(norm(axis - expected), 0.0, 1e-11);
    // The whole attitude, the spin about the rod's own axis included: q(t) = P(L̂, |L| t / I_t)
    // q0 S(x̂, L_a (1/I_a − 1/I_t) t), the two exact commuting rotations.
    const double l_axial = dot(l0, rotate(q0, Vec3{1, 0, 0}));
    const Quat exact =
        Quat::from_axis_angle(normalized(l0), norm(l0) * sim.time() / i.y) * q0 *
        Quat::from_axis_angle(Vec3{1, 0, 0}, l_axial * (1.0 / i.x - 1.0 / i.y) * sim.time());
    for (const Vec3& e : {Vec3{0, 1, 0}, Vec3{0, 0, 1}})
        EXPECT_NEAR(norm(rotate(sim.bodies().orientation[0], e) - rotate(exact, e)), 0.0, 1e-11);
    EXPECT_NEAR(norm(sim.angular_momentum(sim.bodies().position[0]) - l0), 0.0,
                kRoundOff * norm(l0));
    EXPECT_NEAR(sim.kinetic_energy(), e0, kRoundOff * e0);
}

// A sphere's spin is kept to the bit (its own path: ω is never converted to L and back) while
// its attitude turns about the fixed ω at |ω|: q(t) = R(ω̂, |ω| t) q0.
TEST_P(FreeFlight, SpinningBeadTurnsAboutItsFixedSpin) {
    Scene scene = free_body(bead_species());
    scene.params.drive.gravity = 0.0;
    const Quat q0 = Quat::from_axis_angle(normalized(Vec3{0.3, 1.0, -0.2}), 0.7);
    const Vec3 w0{350.0, -200.0, 800.0};  // a bead just after a frictional collision
    scene.bodies.orientation[0] = q0;
    scene.bodies.spin[0] = w0;
    Simulation sim(scene.params, scene.bodies, options());
    sim.run(10000);
    const Vec3& w = sim.bodies().spin[0];
    EXPECT_EQ(w.x, w0.x);
    EXPECT_EQ(w.y, w0.y);
    EXPECT_EQ(w.z, w0.z);
    const Quat exact = Quat::from_axis_angle(normalized(w0), norm(w0) * sim.time()) * q0;
    for (const Vec3& e : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
        EXPECT_NEAR(norm(rotate(sim.bodies().orientation[0], e) - rotate(exact, e)), 0.0,
                    kRoundOff);
}

RODSEA_ON_EACH_STEP(FreeFlight);

// One large step of torque-free rotation and 200 small ones from the same start, as
// (attitude, spin) after each: a half-angle of 0.09 rad per large step (above the series' 0.02),
// 4.5e-4 per small one.
struct LargeAndSmall {
    Quat q_large, q_small;
    Vec3 w_large, w_small;
};
LargeAndSmall one_large_step_and_many_small(const physics::Rotor& rotor, const Vec3& w0) {
    const Quat q0 = Quat::from_axis_angle(normalized(Vec3{0.3, 1.0, -0.2}), 0.7);
    const double dt = 2e-3;
    LargeAndSmall r{q0, q0, w0, w0};
    physics::rotate_free(r.q_large, r.w_large, rotor, dt);
    for (int k = 0; k < 200; ++k)
        physics::rotate_free(r.q_small, r.w_small, rotor, dt / 200);
    return r;
}

// A symmetric body takes small steps through power series and large ones (a half-angle above
// 0.02 rad) through the library's sin and cos. Both follow the exact flow, so one large step
// equals 200 small ones to round-off (~200 steps × a few ulps ≈ 1e-13).
TEST(FreeFlight, SymmetricPrecessionIsTheSameInOneLargeStepAndManySmallOnes) {
    const Vec3 w0{35.0, -20.0, 80.0};
    const LargeAndSmall r = one_large_step_and_many_small(
        physics::make_rotor(polar_rod_species().shape.principal_inertia), w0);
    for (const Vec3& e : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
        EXPECT_NEAR(norm(rotate(r.q_large, e) - rotate(r.q_small, e)), 0.0, 1e-13);
    EXPECT_NEAR(norm(r.w_large - r.w_small), 0.0, 1e-13 * norm(w0));
}

// The same for a sphere: its large steps go the symmetric body's general way, its small ones its
// own series, and the two agree to round-off; the small ones keep ω to the bit.
TEST(FreeFlight, SphereRotationIsTheSameInOneLargeStepAndManySmallOnes) {
    const physics::Rotor rotor = physics::make_rotor(bead_species().shape.principal_inertia);
    ASSERT_TRUE(rotor.isotropic);
    const Vec3 w0{35.0, -20.0, 80.0};
    const LargeAndSmall r = one_large_step_and_many_small(rotor, w0);
    for (const Vec3& e : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
        EXPECT_NEAR(norm(rotate(r.q_large, e) - rotate(r.q_small, e)), 0.0, 1e-13);
    EXPECT_NEAR(norm(r.w_large - w0), 0.0, 1e-13 * norm(w0));
    EXPECT_EQ(norm(r.w_small - w0), 0.0);
}

// Reference: Euler's equations and q̇ = ½ q ⊗ (0, ω_body) by classical RK4 at dt/20.
struct Reference {
    Quat q;
    Vec3 wb;
    Vec3 i;
    void derivative(const Quat& qq, const Vec3& w, Quat& dq, Vec3& dw) const {
        const Quat wq{0, w.x, w.y, w.z};
        const Quat d = qq * wq;
        dq = {0.5 * d.w, 0.5 * d.x, 0.5 * d.y, 0.5 * d.z};
        dw = {(i.y - i.z) * w.y * w.z / i.x, (i.z - i.x) * w.z * w.x / i.y,
              (i.x - i.y) * w.x * w.y / i.z};
    }
    void step(double h) {
        const auto add = [](const Quat& a, const Quat& b, double s) {
            return Quat{a.w + s * b.w, a.x + s * b.x, a.y + s * b.y, a.z + s * b.z};
        };
        Quat k1q, k2q, k3q, k4q;
        Vec3 k1w, k2w, k3w, k4w;
        derivative(q, wb, k1q, k1w);
        derivative(add(q, k1q, h / 2), wb + (h / 2) * k1w, k2q, k2w);
        derivative(add(q, k2q, h / 2), wb + (h / 2) * k2w, k3q, k3w);
        derivative(add(q, k3q, h), wb + h * k3w, k4q, k4w);
        q = normalized(Quat{q.w + h / 6 * (k1q.w + 2 * k2q.w + 2 * k3q.w + k4q.w),
                            q.x + h / 6 * (k1q.x + 2 * k2q.x + 2 * k3q.x + k4q.x),
                            q.y + h / 6 * (k1q.y + 2 * k2q.y + 2 * k3q.y + k4q.y),
                            q.z + h / 6 * (k1q.z + 2 * k2q.z + 2 * k3q.z + k4q.z)});
        wb = wb + (h / 6) * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
    }
};

// An asymmetric body (three unequal, separate spheres) spinning near its unstable middle axis,
// so that it tumbles: L is kept to round-off (2·10⁴ steps: 2 kRoundOff), energy to the splitting's
// bounded O((ω dt)²) error (here (50 rad/s · 5 µs)² ≈ 6e-8), and the attitude follows the
// reference.
TEST(FreeFlight, AsymmetricBodyKeepsEnergyAndAngularMomentum) {
    Species body{"tumbler",
                 BodyKind::bead,
                 make_shape({{{0, 0, 0}, 0.3}, {{1.0, 0.2, 0}, 0.2}, {{0.1, 0.9, 0.3}, 0.25}}, 1.0),
                 {0.0, 0.3}};
    const Vec3 i = body.shape.principal_inertia;
    ASSERT_GT(std::abs(i.x - i.y), 0.05 * i.x);
    ASSERT_GT(std::abs(i.y - i.z), 0.05 * i.y);
    Scene scene = free_body(body);
    scene.params.drive.gravity = 0.0;
    const Quat q0 = Quat::from_axis_angle(normalized(Vec3{1, 2, 3}), 0.4);
    const Vec3 wb0{0.5, 50.0, 0.8};
    scene.bodies.orientation[0] = q0;
    scene.bodies.spin[0] = rotate(q0, wb0);
    Simulation sim(scene.params, scene.bodies);
    const Vec3 l0 = sim.angular_momentum(sim.bodies().position[0]);
    const double e0 = sim.kinetic_energy();

    Reference ref{q0, wb0, i};
    const int steps = 20000;  // 0.1 s: several tumbles
    for (int s = 0; s < steps; ++s) {
        sim.step();
        for (int k = 0; k < 20; ++k)
            ref.step(scene.params.dt / 20);
        EXPECT_NEAR(sim.kinetic_energy(), e0, 1e-6 * e0);
    }
    EXPECT_NEAR(norm(sim.angular_momentum(sim.bodies().position[0]) - l0), 0.0,
                2 * kRoundOff * norm(l0));
    // Attitude: the splitting's phase error grows like t (ω dt)² ω ~ 1e-5 rad here.
    for (const Vec3& e : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
        EXPECT_NEAR(norm(rotate(sim.bodies().orientation[0], e) - rotate(ref.q, e)), 0.0, 1e-4);
    }
}

}  // namespace
}  // namespace rodsea
