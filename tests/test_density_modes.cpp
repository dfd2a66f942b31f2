// Bands as density modes (analysis/density_modes.hpp, the `bands` observable): uniform bands and
// discs against their Fourier transforms, random positions against the Rayleigh mean, and the
// split into transverse and longitudinal bands against the rods' axis.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "analysis_frames.hpp"
#include "rodsea/analysis/density_modes.hpp"
#include "rodsea/analyze/observable_registry.hpp"

namespace rodsea::testing {
namespace {

constexpr double kPi = std::numbers::pi;

// `rows` × `columns` rods evenly spaced over a stripe of width w centred on y0 that spans the box
// in x, all with angle `theta` (the rods in odd columns turned by π: either heading along one
// axis). Exactly periodic in x, so every mode with m_x ≠ 0 sums to zero.
std::vector<Body> stripe(double side, double y0, double w, int rows, int columns, double theta) {
    std::vector<Body> bodies;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i)
            bodies.push_back({side * (i + 0.5) / columns, y0 - 0.5 * w + w * (j + 0.5) / rows,
                              theta + (i % 2) * kPi});
    return bodies;
}

// |(1/n) Σ_j exp(i k y_j)| over n evenly spaced y_j, spacing δ: the geometric sum
// |sin(n k δ / 2) / (n sin(k δ / 2))|, which tends to the continuum band's sinc(k w / 2).
double stripe_amplitude(double k, double w, int n) {
    const double delta = w / n;
    return std::abs(std::sin(n * k * delta / 2) / (n * std::sin(k * delta / 2)));
}

std::vector<Vec3> positions(const AnalysisFrame& f) {
    return f.position;
}

TEST(DensityModes, AStripeAcrossTheBoxHasTheTransformOfItsWidthInOneModeOnly) {
    const double side = 88.0, w = 20.0;
    const int rows = 7, columns = 14;
    const auto frame = make_frame(side, stripe(side, 30.0, w, rows, columns, 0.0));
    const double k = 2 * kPi / side;
    const double expected = stripe_amplitude(k, w, rows);
    ASSERT_GT(expected, 0.8);  // a band a quarter of the box wide: far from the random 0.09
    const auto p = positions(frame);
    EXPECT_NEAR(density_mode_amplitude(frame.box, p, {0, 1}), expected, 1e-12);
    // Columns span the box evenly: Σ_i exp(2πi (i + ½) / columns) = 0 for the modes with m_x ≠ 0.
    EXPECT_NEAR(density_mode_amplitude(frame.box, p, {1, 0}), 0.0, 1e-12);
    EXPECT_NEAR(density_mode_amplitude(frame.box, p, {1, 1}), 0.0, 1e-12);
    EXPECT_NEAR(density_mode_amplitude(frame.box, p, {1, -1}), 0.0, 1e-12);
    // The phase of ρ_k places the stripe: its centre line, y = 30 mm along k = (0, 2π/L).
    EXPECT_NEAR(density_mode_position(frame.box, density_mode(frame.box, p, {0, 1}), {0, 1}), 30.0,
                1e-9);
    // Moving the stripe moves that phase, not the amplitude, across the periodic edge too (its
    // rows run from y = 70 to 90, i.e. 2 mm past the edge).
    const auto moved = make_frame(side, stripe(side, 80.0, w, rows, columns, 0.0));
    const auto rho = density_mode(moved.box, positions(moved), {0, 1});
    EXPECT_NEAR(std::abs(rho), expected, 1e-12);
    EXPECT_NEAR(density_mode_position(moved.box, rho, {0, 1}), 80.0, 1e-9);
}

TEST(DensityModes, UniformBoxAndRandomPositionsHaveTheirKnownAmplitudes) {
    const double side = 50.0;
    // The stripe as wide as the box: a uniform lattice, no mode at all.
    const auto uniform = make_frame(side, stripe(side, side / 2, side, 10, 10, 0.0));
    for (const DensityMode m : kLongestModes)
        EXPECT_NEAR(density_mode_amplitude(uniform.box, positions(uniform), m), 0.0, 1e-12);
    // N independent uniform positions: E|ρ_k|² = 1/N exactly; for N this large |ρ_k| is
    // Rayleigh, mean √(π/4N), relative spread √((4 − π)/π) = 0.52 per sample. 400 frames × 4
    // modes give the mean to 1.3 %; 5 % is four of those.
    const int n = 200, frames = 400;
    SplitMix64 rng(7);
    double sum = 0.0, sum2 = 0.0;
    for (int f = 0; f < frames; ++f) {
        std::vector<Vec3> p;
        for (int i = 0; i < n; ++i)
            p.push_back({rng.uniform(0, side), rng.uniform(0, side), 0.0});
        for (const DensityMode m : kLongestModes) {
            const double a = density_mode_amplitude({side, side}, p, m);
            sum += a;
            sum2 += a * a;
        }
    }
    const double samples = frames * 4.0;
    EXPECT_NEAR(sum / samples, std::sqrt(kPi / (4.0 * n)), 0.05 * std::sqrt(kPi / (4.0 * n)));
    EXPECT_NEAR(sum2 / samples, 1.0 / n, 0.05 / n);  // E|ρ|² = 1/N: relative spread 1/40 here
}

TEST(DensityModes, ACompactFlockRaisesEveryModeAsADiscDoes) {
    // A uniform disc of radius R: ρ_k = 2 J₁(kR) / (kR) in every direction, so a round flock
    // raises the transverse and the longitudinal amplitude alike, where a band raises one.
    const double side = 80.0, radius = 10.0, spacing = 0.1;
    std::vector<Body> disc;
    for (double x = -radius; x <= radius; x += spacing)
        for (double y = -radius; y <= radius; y += spacing)
            if (x * x + y * y < radius * radius) disc.push_back({40.0 + x, 40.0 + y, 0.3});
    const auto frame = make_frame(side, disc);
    const auto expected = [&](double k) {
        return 2.0 * std::cyl_bessel_j(1.0, k * radius) / (k * radius);
    };
    const double k = 2 * kPi / side;
    // The lattice disc's rim departs from the circle by a spacing: relative error ~ spacing / R.
    const double tolerance = 2.0 * spacing / radius * expected(k);
    const BandAmplitudes b = band_amplitudes(frame.box, positions(frame), 0.3);
    EXPECT_NEAR(b.modes[0], expected(k), tolerance);
    EXPECT_NEAR(b.modes[1], expected(k), tolerance);
    EXPECT_NEAR(b.modes[2], expected(std::sqrt(2.0) * k), tolerance);
    EXPECT_NEAR(b.transverse, b.modes[0], 0.0);  // axis at 0.3 rad: nearest k = (1, 0)
    EXPECT_NEAR(b.longitudinal, b.modes[1], 0.0);
}

TEST(DensityModes, TheAxisIsTheRodsDirectorEitherHeading) {
    const std::vector<double> one_way{kPi / 6, kPi / 6};
    const std::vector<double> both_ways{kPi / 6, kPi / 6 - kPi, kPi / 6 + kPi};
    EXPECT_NEAR(director_angle(one_way), kPi / 6, 1e-12);
    EXPECT_NEAR(director_angle(both_ways), kPi / 6, 1e-12);
    EXPECT_NEAR(director_angle(std::vector<double>{-kPi / 3}), 2 * kPi / 3, 1e-12);
    // Crossed rods have no axis.
    EXPECT_TRUE(std::isnan(director_angle(std::vector<double>{0.0, kPi / 2})));
    EXPECT_TRUE(std::isnan(director_angle(std::vector<double>{})));
}

TEST(Bands, AStripeOfRodsMovingAlongItIsLongitudinalAndAcrossItTransverse) {
    const double side = 88.0, w = 20.0;
    const int rows = 7, columns = 14;
    const double expected = stripe_amplitude(2 * kPi / side, w, rows);
    const auto band_of = [&](double theta) {
        const auto bodies = stripe(side, 30.0, w, rows, columns, theta);
        const auto setup = make_setup(side, bodies, 1);
        const auto observable = make_observable("bands", setup, resolved(setup));
        return run_on(*observable, {make_frame(side, bodies)}, setup);
    };
    // Rods along x (both headings) in a stripe along x: the paper's longitudinal band.
    const auto lanes = band_of(0.0);
    EXPECT_NEAR(scalar(lanes, "band_longitudinal").estimate.mean, expected, 1e-12);
    EXPECT_NEAR(scalar(lanes, "band_transverse").estimate.mean, 0.0, 1e-12);
    EXPECT_NEAR(scalar(lanes, "band_random").estimate.mean, std::sqrt(kPi / (4.0 * 98)), 1e-15);
    const TableResult& lane_table = table(lanes, "bands");
    EXPECT_NEAR(lane_table.rows[0][column(lane_table, "longitudinal_at")], 30.0, 1e-9);
    // The same stripe, rods along y: they cross it, a transverse band.
    const auto front = band_of(kPi / 2 + 0.1);
    EXPECT_NEAR(scalar(front, "band_transverse").estimate.mean, expected, 1e-12);
    EXPECT_NEAR(scalar(front, "band_longitudinal").estimate.mean, 0.0, 1e-12);
    const TableResult& t = table(front, "bands");
    ASSERT_EQ(t.rows.size(), 1u);
    EXPECT_NEAR(t.rows[0][column(t, "axis")], kPi / 2 + 0.1, 1e-12);
    EXPECT_NEAR(t.rows[0][column(t, "rho_0_1")], expected, 1e-12);
}

// A stripe of rods along x that moves across itself at 2 mm/s, through the periodic edge: every
// frame pair gives that velocity along k = (0, 2π/L), the band is there in every frame, and a
// transverse band in none.
TEST(Bands, ABandMovingAcrossItselfHasItsDriftVelocity) {
    const double side = 88.0, w = 20.0, speed = 2.0, interval = 0.1;
    const int rows = 7, columns = 14, frames = 40;  // 8 mm in all, from y = 80 across y = 88
    std::vector<AnalysisFrame> trajectory;
    std::vector<Body> first;
    for (int f = 0; f < frames; ++f) {
        const auto bodies = stripe(side, 80.0 + speed * interval * f, w, rows, columns, 0.0);
        if (f == 0) first = bodies;
        trajectory.push_back(make_frame(side, bodies, static_cast<std::size_t>(f), interval));
    }
    const auto setup = make_setup(side, first, frames, interval);
    const auto observable = make_observable("bands", setup, resolved(setup));
    const auto r = run_on(*observable, trajectory, setup);
    // Positions are exact to rounding (1e-12 mm): the velocity to 1e-9 mm/s.
    EXPECT_NEAR(scalar(r, "band_longitudinal_drift").estimate.mean, speed, 1e-9);
    EXPECT_EQ(scalar(r, "band_longitudinal_drift").estimate.samples, std::size_t{frames - 1});
    EXPECT_EQ(scalar(r, "band_longitudinal_present").estimate.mean, 1.0);
    EXPECT_EQ(scalar(r, "band_transverse_present").estimate.mean, 0.0);
    EXPECT_TRUE(std::isnan(scalar(r, "band_transverse_drift").estimate.mean));
    // bands.threshold = 11: 11 √(π/4·98) = 0.985 lies above the stripe's 0.92, no band counts.
    AnalysisOptions strict;
    strict.band_threshold = 11.0;
    const auto picky = make_observable("bands", setup, resolved(setup, strict));
    const auto none = run_on(*picky, trajectory, setup);
    EXPECT_EQ(scalar(none, "band_longitudinal_present").estimate.mean, 0.0);
    EXPECT_TRUE(std::isnan(scalar(none, "band_longitudinal_drift").estimate.mean));
}

// Pairs of frames count only when both hold the band in the same mode.
TEST(DensityModes, BandVelocitiesSkipFramesWithoutTheBandOrInAnotherMode) {
    const PeriodicBox2D box{50.0, 50.0};
    const std::vector<double> time{0.0, 0.1, 0.2, 0.3, 0.4, 0.5};
    // 49.9 → 0.1 crosses the edge: +0.2 mm in 0.1 s.
    const std::vector<double> at{49.9, 0.1, 0.3, 0.5, 0.7, 0.9};
    const std::vector<double> amplitude{0.5, 0.5, 0.5, 0.1, 0.5, 0.5};
    const std::vector<std::size_t> mode{1, 1, 1, 1, 1, 0};
    const auto v = band_velocities(box, time, at, amplitude, mode, 0.3);
    ASSERT_EQ(v.size(), 2u);  // 0→1 and 1→2; frame 3 has no band, frame 5 another mode
    EXPECT_NEAR(v[0], 2.0, 1e-9);
    EXPECT_NEAR(v[1], 2.0, 1e-9);
}

}  // namespace
}  // namespace rodsea::testing
