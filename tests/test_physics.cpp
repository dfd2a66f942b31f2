// The per-element physics of engine/physics/, function by function, against answers fixed by
// geometry or mechanics. These are the functions both executors call (RODSEA_HD); the engine
// tests check them again through the CPU backend.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "rodsea/engine/physics/contact_geometry.hpp"
#include "rodsea/engine/physics/free_flight.hpp"
#include "rodsea/engine/physics/impulse.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/engine/physics/rigid_rotation.hpp"
#include "rodsea/engine/physics/sphere_placement.hpp"
#include "rodsea/random.hpp"

namespace rodsea::physics {
namespace {

constexpr double kPi = std::numbers::pi;

// cos h and sin h / h to the last bits over the whole range the series serves (|h| ≤ 0.02):
// the first omitted terms are below 1e-17 of the result, so a few ulps at most.
TEST(Physics, HalfAngleSeriesIsCosAndSincToRoundOff) {
    for (double h = 1e-6; h <= 0.02; h *= 1.7) {
        const HalfAngle a = half_angle_series(h * h);
        EXPECT_NEAR(a.cos, std::cos(h), 2e-16);
        EXPECT_NEAR(a.sinc, std::sin(h) / h, 2e-16);
    }
}

// Both branches of axis_angle (series below h² = 4e-4, library above) are the rotation by the
// angle: a quarter turn about z takes x to y, and the series branch agrees with
// Quat::from_axis_angle.
TEST(Physics, AxisAngleRotatesByTheAngleOnBothBranches) {
    const Vec3 y = rotate(axis_angle({0, 0, 1}, 0.5 * kPi), Vec3{1, 0, 0});
    EXPECT_NEAR(norm(y - Vec3{0, 1, 0}), 0.0, 1e-15);
    const Vec3 axis = normalized(Vec3{0.2, -0.7, 0.4});
    const Quat series = axis_angle(axis, 0.03), library = Quat::from_axis_angle(axis, 0.03);
    EXPECT_NEAR(series.w, library.w, 1e-16);
    EXPECT_NEAR(norm(series.vec() - library.vec()), 0.0, 1e-16);
}

// A symmetric top keeps |ω| and its angular momentum; the bound for it is |ω|² itself. An
// asymmetric body's bound (|L| / I_min)² is never below |ω|².
TEST(Physics, SpinBoundIsExactForSymmetricAndAnUpperBoundForAsymmetricBodies) {
    const Rotor symmetric = make_rotor({0.5, 2.0, 2.0});
    EXPECT_EQ(symmetric.axis, 0);
    const Quat q = Quat::from_axis_angle(normalized(Vec3{1, 2, 3}), 0.8);
    const Vec3 w{3.0, -4.0, 12.0};
    EXPECT_EQ(spin_bound2(symmetric, q, w), norm2(w));
    const Rotor asymmetric = make_rotor({1.0, 2.0, 3.5});
    EXPECT_EQ(asymmetric.axis, -1);
    SplitMix64 rng(3);
    for (int k = 0; k < 100; ++k) {
        const Vec3 spin{rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
        EXPECT_GE(spin_bound2(asymmetric, q, spin), norm2(spin) * (1 - 1e-15));
    }
}

// Torque-free rotation conserves the world angular momentum L = R I Rᵀ ω and the kinetic energy
// exactly (to round-off) on both the fast symmetric path and the general splitting.
TEST(Physics, RotateFreeKeepsAngularMomentumAndEnergy) {
    for (const Vec3& inertia : {Vec3{0.3, 1.1, 1.1}, Vec3{0.7, 1.3, 2.2}}) {
        const Rotor rotor = make_rotor(inertia);
        Quat q = Quat::from_axis_angle(normalized(Vec3{0.3, -1, 0.5}), 1.2);
        Vec3 w{40.0, -25.0, 60.0};
        const auto momentum = [&] {
            const Vec3 wb = rotate(conjugate(q), w);
            return rotate(q, Vec3{inertia.x * wb.x, inertia.y * wb.y, inertia.z * wb.z});
        };
        const auto energy = [&] {
            const Vec3 wb = rotate(conjugate(q), w);
            return 0.5 *
                   (inertia.x * wb.x * wb.x + inertia.y * wb.y * wb.y + inertia.z * wb.z * wb.z);
        };
        const Vec3 l0 = momentum();
        const double e0 = energy();
        for (int k = 0; k < 1000; ++k)
            rotate_free(q, w, rotor, 1.25e-6);
        EXPECT_NEAR(norm(momentum() - l0), 0.0, 1e-12 * norm(l0));
        // The splitting of an asymmetric body keeps E to O(dt²): (|ω| dt)² ~ 1e-8 per step.
        EXPECT_NEAR(energy(), e0, 1e-9 * e0);
    }
}

// One step of free flight is the exact parabola: x + v dt − ½ g dt² ẑ, v − g dt ẑ; x and y
// wrapped into the box; its speeds in the plane are v_x² + v_y² and |ω|² reach².
TEST(Physics, FreeFlightIsTheParabolaWrappedIntoTheBox) {
    StepContext step;
    step.dt = 1e-3;
    step.gravity = 9810.0;
    step.box = {10.0, 10.0};
    Vec3 x{9.99, 0.005, 1.0}, v{30.0, -20.0, 5.0}, w{0.0, 0.0, 2.0};
    Quat q;
    const Rotor rotor = make_rotor({0.1, 1.0, 1.0});
    const PlanarSpeed2 speed = planar_speed2(v, q, w, rotor, 4.0);
    fly_freely(x, v, q, w, rotor, step.dt, step.gravity, step.drop(), step.box);
    EXPECT_NEAR(x.x, 9.99 + 0.03 - 10.0, 1e-14);
    EXPECT_NEAR(x.y, 0.005 - 0.02 + 10.0, 1e-14);
    EXPECT_NEAR(x.z, 1.0 + 5e-3 - 0.5 * 9810.0 * 1e-6, 1e-14);
    EXPECT_NEAR(v.z, 5.0 - 9.81, 1e-13);
    EXPECT_EQ(speed.drift2, 30.0 * 30.0 + 20.0 * 20.0);
    EXPECT_EQ(speed.turn2, 4.0 * 4.0);
    // A turn about z by ω dt.
    EXPECT_NEAR(std::atan2(rotated_axis(q, 0).y, rotated_axis(q, 0).x), 2e-3, 1e-15);
}

// Spheres on the body's x axis land at x + s u for any orientation; the general path (axis
// −1) puts them at x + R · offset: both are the same points.
TEST(Physics, SpherePlacementPutsOffsetsWhereTheRotationDoes) {
    const Vec3 offsets[3] = {{-1.5, 0, 0}, {0.25, 0, 0}, {2.0, 0, 0}};
    const Quat q = Quat::from_axis_angle(normalized(Vec3{0.4, 0.1, -1}), 2.1);
    const Vec3 x{3.0, -2.0, 0.7};
    Vec3 fast[3], general[3];
    place_spheres(fast, offsets, 3, x, q, 0);
    place_spheres(general, offsets, 3, x, q, -1);
    for (int s = 0; s < 3; ++s) {
        EXPECT_NEAR(norm(fast[s] - (x + rotate(q, offsets[s]))), 0.0, 1e-15);
        EXPECT_NEAR(norm(general[s] - fast[s]), 0.0, 1e-15);
    }
}

// Two spheres overlapping by δ along x: the normal points from b into a, the overlap is δ and
// both arms reach the middle of the overlap. Apart or coincident: no contact.
TEST(Physics, SphereContactSitsInTheMiddleOfTheOverlap) {
    const Vec3 pa{1.0, 0.0, 0.5}, pb{0.3, 0.0, 0.5};  // radii 0.4 + 0.4 at 0.7: δ = 0.1
    const Vec3 xa{1.5, 0.2, 0.5}, xb{0.0, -0.1, 0.5};
    Contact c;
    ASSERT_TRUE(sphere_sphere_contact(pa - pb, 3, pa, 0.4, xa, 8, pb, 0.4, xb, c));
    EXPECT_EQ(c.a, 3u);
    EXPECT_EQ(c.b, 8u);
    EXPECT_NEAR(norm(c.normal - Vec3{1, 0, 0}), 0.0, 1e-15);
    EXPECT_NEAR(c.overlap, 0.1, 1e-15);
    const Vec3 middle{0.65, 0.0, 0.5};
    EXPECT_NEAR(norm(xa + c.arm_a - middle), 0.0, 1e-15);
    EXPECT_NEAR(norm(xb + c.arm_b - middle), 0.0, 1e-15);
    EXPECT_FALSE(sphere_sphere_contact({0.81, 0, 0}, 3, pa, 0.4, xa, 8, pb, 0.4, xb, c));
    EXPECT_FALSE(sphere_sphere_contact({0, 0, 0}, 3, pa, 0.4, xa, 8, pb, 0.4, xb, c));
}

// A sphere 0.01 mm into the base: overlap 0.01 with the base, none with the lid, normal +z, and
// the contact point halfway through the overlap.
TEST(Physics, PlateContactSitsInTheMiddleOfTheOverlap) {
    const PlateState plates{0.1, 1.5, -3.0};
    const Vec3 p{2.0, 3.0, 0.1 + 0.4 - 0.01};
    const PlateOverlaps o = plate_overlaps(p.z, 0.4, plates);
    EXPECT_NEAR(o.base, 0.01, 1e-15);
    EXPECT_LT(o.lid, 0.0);
    const Vec3 x{2.5, 3.0, 0.49};
    const Contact c = plate_contact(7, p, 0.4, x, true, o.base, {0.03, 0.1});
    EXPECT_TRUE(c.with_plate());
    EXPECT_EQ(c.b, kBasePlate);
    EXPECT_EQ(c.normal, (Vec3{0, 0, 1}));
    EXPECT_NEAR((x + c.arm_a).z, 0.1 - 0.005, 1e-15);
    EXPECT_EQ(plate_contact(7, p, 0.4, x, false, 0.02, {}).normal, (Vec3{0, 0, -1}));
}

// The base moves as A cos Ωt with velocity −AΩ sin Ωt (its derivative), the lid w above it.
TEST(Physics, PlatesMoveAsTheDriveSays) {
    const PlateMotion m{0.0435, 400 * kPi, 1.4};
    for (double t : {0.0, 1e-3, 2.6e-3, 0.0123}) {
        const PlateState s = plate_state(m, t);
        EXPECT_NEAR(s.base_z, 0.0435 * std::cos(400 * kPi * t), 1e-16);
        EXPECT_NEAR(s.lid_z - s.base_z, 1.4, 1e-15);
        const double h = 1e-8;
        const double slope =
            (plate_state(m, t + h).base_z - plate_state(m, t - h).base_z) / (2 * h);
        EXPECT_NEAR(s.velocity_z, slope, 1e-6);
    }
}

// R I⁻¹ Rᵀ has the body axes as eigenvectors with the inverse moments as eigenvalues.
TEST(Physics, WorldInverseInertiaHasTheBodyAxesAsEigenvectors) {
    const Quat q = Quat::from_axis_angle(normalized(Vec3{1, -2, 0.5}), 0.9);
    const Vec3 inverse{2.0, 0.5, 0.25};
    const Mat3 m = world_inverse_inertia(q, inverse);
    for (int k = 0; k < 3; ++k) {
        const Vec3 axis = rotated_axis(q, k);
        EXPECT_NEAR(norm(m * axis - inverse[k] * axis), 0.0, 1e-15);
    }
    EXPECT_NEAR(norm(point_velocity({1, 2, 3}, {0, 0, 2}, {1, 0, 0}) - Vec3{1, 4, 3}), 0.0, 0.0);
}

// η = ±1, equally likely over keys, and a function of each of seed, step, body and plate.
TEST(Physics, NoiseSignIsFairAndDependsOnEveryKey) {
    int plus = 0;
    const int n = 20000;
    for (int b = 0; b < n; ++b) {
        const double s = noise_sign(5, 77, static_cast<std::uint32_t>(b), kBasePlate);
        ASSERT_TRUE(s == 1.0 || s == -1.0);
        plus += s > 0 ? 1 : 0;
    }
    // Binomial(n, ½): the standard deviation of the count is √n / 2 ≈ 71; 4σ.
    EXPECT_NEAR(plus, n / 2, 4 * std::sqrt(n) / 2);
    const auto differs = [](auto change) {
        int changed = 0;
        for (std::uint32_t b = 0; b < 64; ++b)
            changed += noise_sign(5, 77, b, kBasePlate) != change(b) ? 1 : 0;
        return changed;
    };
    // Each key changed alone flips about half of 64 signs; none flips none.
    EXPECT_GT(differs([](std::uint32_t b) { return noise_sign(6, 77, b, kBasePlate); }), 10);
    EXPECT_GT(differs([](std::uint32_t b) { return noise_sign(5, 78, b, kBasePlate); }), 10);
    EXPECT_GT(differs([](std::uint32_t b) { return noise_sign(5, 77, b + 64, kBasePlate); }), 10);
    EXPECT_GT(differs([](std::uint32_t b) { return noise_sign(5, 77, b, kLidPlate); }), 10);
}

}  // namespace
}  // namespace rodsea::physics

namespace rodsea {
namespace {

// A speed or an overlap that is NaN reaches the blow-up check as +∞: a NaN compares false, so
// std::max drops it while a device's reduction may keep it; as +∞ every executor keeps it.
TEST(Physics, ANaNSpeedCountsAsInfinite) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(nan_as_infinity(nan), HUGE_VAL);
    EXPECT_EQ(nan_as_infinity(2.5), 2.5);
    const physics::Rotor rotor = physics::make_rotor({0.2, 1.1, 1.1});
    const physics::PlanarSpeed2 s =
        physics::planar_speed2({nan, 0.0, 0.0}, Quat{}, {0.0, 0.0, nan}, rotor, 4.0);
    EXPECT_EQ(s.drift2, HUGE_VAL);
    EXPECT_EQ(s.turn2, HUGE_VAL);
    const physics::PlanarSpeed2 finite =
        physics::planar_speed2({3.0, 4.0, 9.0}, Quat{}, {0.0, 0.0, 2.0}, rotor, 4.0);
    EXPECT_EQ(finite.drift2, 25.0);  // the vertical speed does not count
    EXPECT_EQ(finite.turn2, 16.0);   // |ω|² reach²
}

}  // namespace
}  // namespace rodsea
