// Observables on constructed frames with known answers (docs/model.md §4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis_frames.hpp"
#include "rodsea/analysis/time_correlation.hpp"
#include "rodsea/analyze/autocorrelation_observable.hpp"
#include "rodsea/analyze/corotating_maps_observable.hpp"
#include "rodsea/analyze/drift_observable.hpp"
#include "rodsea/analyze/flock_observable.hpp"
#include "rodsea/analyze/medium_velocity_observable.hpp"
#include "rodsea/analyze/observable_registry.hpp"
#include "rodsea/analyze/order_parameter_observable.hpp"
#include "rodsea/analyze/pair_correlation_observable.hpp"
#include "rodsea/analyze/segregation_observable.hpp"
#include "rodsea/engine/order_parameters.hpp"

namespace rodsea::testing {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(OrderParameters, AlignedRodsHavePAndSOne) {
    SplitMix64 rng(1);
    auto bodies = uniform_bodies(500, 60.0, rng);
    for (Body& b : bodies)
        b.theta = 0.7;
    const auto setup = make_setup(60.0, bodies, 1);
    OrderParameterObservable o(setup);
    const auto r = run_on(o, {make_frame(60.0, bodies)}, setup);
    // Exact up to the rounding of 500 cos/sin sums.
    EXPECT_NEAR(scalar(r, "P_polar").estimate.mean, 1.0, 1e-12);
    EXPECT_NEAR(scalar(r, "S_polar").estimate.mean, 1.0, 1e-12);
}

TEST(OrderParameters, ApolarRodsHalfEachWayHavePZeroSOne) {
    SplitMix64 rng(2);
    auto bodies = uniform_bodies(400, 60.0, rng);
    for (std::size_t i = 0; i < bodies.size(); ++i)
        bodies[i].theta = 0.3 + (i % 2 ? kPi : 0.0);
    EXPECT_NEAR(orientational_order(std::vector<double>{0.3, 0.3 + kPi}, 1), 0.0, 1e-15);
    const auto setup = make_setup(60.0, bodies, 1);
    OrderParameterObservable o(setup);
    const auto r = run_on(o, {make_frame(60.0, bodies)}, setup);
    EXPECT_NEAR(scalar(r, "P_polar").estimate.mean, 0.0, 1e-12);
    EXPECT_NEAR(scalar(r, "S_polar").estimate.mean, 1.0, 1e-12);
}

TEST(OrderParameters, IsotropicRodsHavePOfOrderOneOverSqrtN) {
    // For N independent uniform angles E[N P²] = 1 exactly, and N P² is close to exponential
    // with unit spread, so the mean of 400 draws is 1 ± 0.05: 0.2 is four standard errors.
    SplitMix64 rng(3);
    const std::size_t n = 1000;
    double sum = 0.0;
    const int draws = 400;
    for (int d = 0; d < draws; ++d) {
        std::vector<double> angles;
        for (std::size_t i = 0; i < n; ++i)
            angles.push_back(rng.uniform(-kPi, kPi));
        const double p = orientational_order(angles, 1);
        sum += static_cast<double>(n) * p * p;
    }
    EXPECT_NEAR(sum / draws, 1.0, 0.2);
}

TEST(Drift, MeanVelocitiesAndTheMediumAlongThePolarHeading) {
    // Polar rods heading at 0.5 rad, moving (1, 2) mm/s; the medium moving (3, −1) mm/s, whose
    // component along the heading is 3 cos 0.5 − sin 0.5. Two frames, the second with the
    // medium's velocity reversed: its mean velocity averages to zero, and so does the drift.
    std::vector<Body> moving, reversed;
    SplitMix64 rng(9);
    for (int i = 0; i < 30; ++i)
        moving.push_back({rng.uniform(0, 40), rng.uniform(0, 40), 0.5, 0, 1.0, 2.0});
    for (int i = 0; i < 70; ++i)
        moving.push_back(
            {rng.uniform(0, 40), rng.uniform(0, 40), rng.uniform(-kPi, kPi), 1, 3.0, -1.0});
    reversed = moving;
    for (Body& b : reversed)
        if (b.species == 1) b.vx = -b.vx, b.vy = -b.vy;
    const auto setup = make_setup(40.0, moving, 2);
    DriftObservable o(setup);
    const auto r = run_on(o, {make_frame(40.0, moving, 0), make_frame(40.0, reversed, 1)}, setup);
    // Sums of 30 or 70 equal numbers: exact to a few ulps.
    EXPECT_NEAR(scalar(r, "vx_polar").estimate.mean, 1.0, 1e-12);
    EXPECT_NEAR(scalar(r, "vy_polar").estimate.mean, 2.0, 1e-12);
    EXPECT_NEAR(scalar(r, "vx_medium").estimate.mean, 0.0, 1e-12);
    const TableResult& t = table(r, "drift");
    const double along = 3.0 * std::cos(0.5) - std::sin(0.5);
    EXPECT_NEAR(t.rows[0][column(t, "v_medium_along_polar")], along, 1e-12);
    EXPECT_NEAR(t.rows[1][column(t, "v_medium_along_polar")], -along, 1e-12);
    EXPECT_NEAR(t.rows[0][column(t, "vy_medium")], -1.0, 1e-12);
}

TEST(Drift, AgitationIsTheSpreadAboutTheDriftAndTheSpinsRms) {
    // Every body moves at its species' drift plus a jitter whose partner body carries the
    // opposite one, so the species' mean stays the drift and the rms about it is the jitter's
    // size, whatever the jitter's directions: 3 mm/s for the polar rods, 4 for the medium. Spins
    // are ±5 and ±0.5 rad/s. Exact to rounding of sums of 30 and 70 terms.
    std::vector<Body> bodies;
    SplitMix64 rng(11);
    const auto add_pairs = [&](int pairs, std::uint32_t species, double vx, double vy,
                               double jitter, double spin) {
        for (int i = 0; i < pairs; ++i) {
            const double a = rng.uniform(-kPi, kPi);
            for (const double sign : {1.0, -1.0})
                bodies.push_back({rng.uniform(0, 40), rng.uniform(0, 40), 0.3, species,
                                  vx + sign * jitter * std::cos(a),
                                  vy + sign * jitter * std::sin(a), sign * spin});
        }
    };
    add_pairs(15, 0, 1.0, 2.0, 3.0, 5.0);
    add_pairs(35, 1, 3.0, -1.0, 4.0, 0.5);
    const auto setup = make_setup(40.0, bodies, 1);
    DriftObservable o(setup);
    const auto r = run_on(o, {make_frame(40.0, bodies, 0)}, setup);
    EXPECT_NEAR(scalar(r, "vx_polar").estimate.mean, 1.0, 1e-12);
    EXPECT_NEAR(scalar(r, "v_rms_polar").estimate.mean, 3.0, 1e-12);
    EXPECT_NEAR(scalar(r, "spin_rms_polar").estimate.mean, 5.0, 1e-12);
    EXPECT_NEAR(scalar(r, "v_rms_medium").estimate.mean, 4.0, 1e-12);
    EXPECT_NEAR(scalar(r, "spin_rms_medium").estimate.mean, 0.5, 1e-12);
    EXPECT_EQ(scalar(r, "spin_rms_medium").unit, "rad/s");
    const TableResult& t = table(r, "drift");
    EXPECT_NEAR(t.rows[0][column(t, "v_rms_medium")], 4.0, 1e-12);
}

TEST(PairCorrelation, UniformRandomPointsHaveGOfROne) {
    SplitMix64 rng(4);
    const double side = 80.0;
    std::vector<AnalysisFrame> frames;
    std::vector<Body> first;
    for (std::size_t k = 0; k < 10; ++k) {
        const auto bodies = uniform_bodies(1500, side, rng);
        if (k == 0) first = bodies;
        frames.push_back(make_frame(side, bodies, k));
    }
    const auto setup = make_setup(side, first, frames.size());
    AnalysisOptions options;
    options.pair_r_max = 20.0;
    options.pair_bin = 0.5;
    PairCorrelationObservable o(setup, resolved(setup, options));
    const auto r = run_on(o, frames, setup);
    const TableResult& t = table(r, "pair_correlation_polar");
    double pairs = 0.0, ideal = 0.0;
    for (const auto& row : t.rows) {
        const double count = row[column(t, "pairs")], g = row[column(t, "g")];
        // Poisson counts: g within 5 standard errors in every one of the 40 bins.
        EXPECT_NEAR(g, 1.0, 5.0 / std::sqrt(count / g)) << "r = " << row[0];
        pairs += count;
        ideal += count / g;
        // Independent angles: G and G2 average to 0 within their sampling error.
        EXPECT_NEAR(row[column(t, "G")], 0.0, 5.0 / std::sqrt(count));
    }
    EXPECT_NEAR(pairs / ideal, 1.0, 5.0 / std::sqrt(ideal));
}

TEST(PairCorrelation, ErrorBarsAreTheSpreadOfTheTimeBlocks) {
    // Two polar rods 2.4 mm apart, one frame per block of 4, turned against each other by 0,
    // π/3, π/2 and π: G in their bin is cos δ = 1, 1/2, 0, −1 block by block, pooled 1/8 (each
    // block holds the same two ordered pairs), and G_err is the standard error of those four,
    // √(Σ (G_k − 1/8)² / 3 / 4). G₂ = cos 2δ = 1, −1/2, −1, 1 likewise; g is the same in every
    // block, so its error is 0. A bin no pair reaches has no value and no error.
    const double side = 20.0;
    const std::vector<double> turns{0.0, kPi / 3.0, kPi / 2.0, kPi};
    std::vector<AnalysisFrame> frames;
    std::vector<Body> first;
    for (std::size_t k = 0; k < turns.size(); ++k) {
        const std::vector<Body> bodies{{5.0, 5.0, 0.3, 0}, {7.4, 5.0, 0.3 + turns[k], 0}};
        if (k == 0) first = bodies;
        frames.push_back(make_frame(side, bodies, k));
    }
    const auto setup = make_setup(side, first, frames.size());
    ASSERT_EQ(setup.blocks, 4);
    AnalysisOptions options;
    options.pair_r_max = 5.0;
    options.pair_bin = 1.0;
    PairCorrelationObservable o(setup, resolved(setup, options));
    const auto r = run_on(o, frames, setup);
    const TableResult& t = table(r, "pair_correlation_polar");
    const auto& row = t.rows[2];  // r in [2, 3) mm
    const auto standard_error = [](std::vector<double> v) {
        double mean = 0.0, ss = 0.0;
        for (double x : v)
            mean += x / static_cast<double>(v.size());
        for (double x : v)
            ss += (x - mean) * (x - mean);
        return std::sqrt(ss / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()));
    };
    // Sums of four cosines of exact angles: within a few ulps.
    EXPECT_NEAR(row[column(t, "G")], 0.125, 1e-12);
    EXPECT_NEAR(row[column(t, "G_err")], standard_error({1.0, 0.5, 0.0, -1.0}), 1e-12);
    EXPECT_NEAR(row[column(t, "G2")], 0.125, 1e-12);
    EXPECT_NEAR(row[column(t, "G2_err")], standard_error({1.0, -0.5, -1.0, 1.0}), 1e-12);
    EXPECT_EQ(row[column(t, "g_err")], 0.0);
    EXPECT_TRUE(std::isnan(t.rows[4][column(t, "G")]));
    EXPECT_TRUE(std::isnan(t.rows[4][column(t, "G_err")]));
}

// Rods on a rectangular lattice, 5.25 mm apart along their axis and 1.75 mm across it (mid-bin
// distances), the lattice turned with the rods by `angle`.
std::vector<Body> aligned_lattice(double side, double angle, double x0, double y0) {
    std::vector<Body> bodies;
    const int along = 6, across = 20;
    const double c = std::cos(angle), s = std::sin(angle);
    for (int i = 0; i < along; ++i)
        for (int j = 0; j < across; ++j) {
            const double u = 5.25 * i, v = 1.75 * j;
            bodies.push_back({x0 + u * c - v * s, y0 + u * s + v * c, angle, 0});
        }
    (void)side;
    return bodies;
}

TEST(CorotatingMaps, AlignedLatticeIsAnisotropicInTheRodFrame) {
    const double side = 100.0;
    AnalysisOptions options;
    options.corotating_r_max = 6.0;
    options.corotating_r_bins = 12;     // 0.5 mm rings
    options.corotating_theta_bins = 8;  // 45° sectors centred on ±22.5°, ±67.5°, ...
    for (const double angle : {0.0, 0.9, -2.3}) {
        const auto bodies = aligned_lattice(side, angle, 3.0, 97.0);  // across the corner
        const auto setup = make_setup(side, bodies, 1);
        CorotatingMapsObservable o(setup, resolved(setup, options));
        const auto r = run_on(o, {make_frame(side, bodies)}, setup);
        const MapResult& g = r.maps[0];
        const MapResult& G = r.maps[1];
        const auto at = [&](const MapResult& m, double radius, double theta) {
            const auto k = static_cast<std::size_t>(radius / 0.5);
            const auto t = static_cast<std::size_t>((theta + kPi) / (2 * kPi / 8));
            return m.values[k * 8 + t];
        };
        // The neighbours across the axis (1.75 mm, θ' = ±90°) fill the sectors around ±90°; the
        // sectors along the axis at that distance are empty; the next rod ahead is 5.25 mm away.
        // A neighbour exactly at θ' = ±90° or 0 sits on a sector edge and may fall either side.
        const auto either_side = [&](double radius, double theta) {
            const double wrapped = theta + 0.2 > kPi ? theta + 0.2 - 2 * kPi : theta + 0.2;
            return std::max(at(g, radius, theta - 0.2), at(g, radius, wrapped));
        };
        EXPECT_GT(either_side(1.75, kPi / 2), 10.0) << "angle " << angle;
        EXPECT_GT(either_side(1.75, -kPi / 2), 10.0) << "angle " << angle;
        EXPECT_EQ(at(g, 1.75, 0.2), 0.0) << "angle " << angle;
        EXPECT_EQ(at(g, 1.75, -0.2), 0.0) << "angle " << angle;
        EXPECT_EQ(at(g, 1.75, kPi - 0.2), 0.0) << "angle " << angle;
        EXPECT_GT(either_side(5.25, 0.0), 10.0) << "angle " << angle;
        EXPECT_GT(either_side(5.25, kPi - 0.0001), 10.0) << "angle " << angle;
        // All rods point the same way: G = 1 wherever there are pairs.
        for (std::size_t b = 0; b < G.values.size(); ++b) {
            if (std::isfinite(G.values[b])) {
                EXPECT_NEAR(G.values[b], 1.0, 1e-12);
            }
        }
    }
}

TEST(CorotatingMaps, NeighbourAheadAndLeftLandsInItsBinOnly) {
    // Two parallel rods, the second 2 mm ahead of the first (towards its thin end) and 1 mm to
    // its left: in the first rod's frame it sits at θ' = atan2(1, 2), and the first rod sits at
    // atan2(−1, −2) in the second's. A mirrored frame or a reversed axis puts them elsewhere.
    const double side = 50.0;
    AnalysisOptions options;
    options.corotating_r_max = 4.0;
    options.corotating_r_bins = 8;
    options.corotating_theta_bins = 36;
    for (const double angle : {0.0, 1.1, -2.5, 3.0}) {
        const double c = std::cos(angle), s = std::sin(angle);
        const std::vector<Body> bodies{{49.5, 0.3, angle, 0},
                                       {49.5 + 2 * c - 1 * s, 0.3 + 2 * s + 1 * c, angle, 0}};
        const auto setup = make_setup(side, bodies, 1);
        CorotatingMapsObservable o(setup, resolved(setup, options));
        const auto r = run_on(o, {make_frame(side, bodies)}, setup);
        const auto bin_of = [&](double radius, double theta) {
            return static_cast<std::size_t>(radius / 0.5) * 36 +
                   static_cast<std::size_t>((theta + kPi) / (2 * kPi / 36));
        };
        const std::size_t ahead = bin_of(std::sqrt(5.0), std::atan2(1.0, 2.0));
        const std::size_t behind = bin_of(std::sqrt(5.0), std::atan2(-1.0, -2.0));
        for (std::size_t b = 0; b < r.maps[0].values.size(); ++b) {
            if (b == ahead || b == behind)
                EXPECT_GT(r.maps[0].values[b], 0.0) << "angle " << angle;
            else
                EXPECT_EQ(r.maps[0].values[b], 0.0) << "angle " << angle << " bin " << b;
        }
    }
}

// Points uniform in an ellipse with semi-axes (a, b) along and across the rods (θ = 0), at
// random centres, one cluster per frame: the ellipse's autocorrelation has elliptical level
// sets of aspect a/b, so the 70 % contour of g(r,θ) has σ_f = a/b.
std::vector<AnalysisFrame> elliptical_clusters(double side, double a, double b, std::size_t frames,
                                               double cx, double cy, SplitMix64& rng,
                                               std::vector<Body>* first) {
    std::vector<AnalysisFrame> out;
    for (std::size_t k = 0; k < frames; ++k) {
        std::vector<Body> bodies;
        while (bodies.size() < 400) {
            const double u = rng.uniform(-1, 1), v = rng.uniform(-1, 1);
            if (u * u + v * v <= 1.0) bodies.push_back({cx + a * u, cy + b * v, 0.0, 0});
        }
        if (k == 0 && first) *first = bodies;
        out.push_back(make_frame(side, bodies, k));
    }
    return out;
}

TEST(CorotatingMaps, PlantedEllipticalFlockGivesItsAspectRatio) {
    const double side = 200.0;
    for (const double aspect : {3.0, 0.5}) {
        SplitMix64 rng(5);
        std::vector<Body> first;
        const double a = aspect >= 1 ? 12.0 : 4.0, b = aspect >= 1 ? 4.0 : 8.0;
        const auto frames = elliptical_clusters(side, a, b, 100, 100.0, 100.0, rng, &first);
        auto setup = make_setup(side, first, frames.size());
        AnalysisOptions options;
        options.corotating_r_max = 2.2 * std::max(a, b);
        options.corotating_r_bins = 60;
        options.corotating_theta_bins = 72;
        CorotatingMapsObservable o(setup, resolved(setup, options));
        const auto r = run_on(o, frames, setup);
        // The tolerance: 10 %; binning (0.4 mm rings) and the noise of the map's
        // maximum stay well inside it with 400 points × 100 frames.
        EXPECT_NEAR(scalar(r, "sigma_f").estimate.mean, aspect, 0.1 * aspect);
    }
}

TEST(CorotatingMaps, AContourThatDoesNotCloseGivesANullShapeAndSaysWhy) {
    // Polar rods in head-to-tail pairs (the second 4.6 mm ahead of the first along its axis),
    // the pairs at random: g(r,θ) peaks sharply straight ahead and straight behind, and in most
    // other directions never reaches 70 % of that peak. That contour passes through the
    // reference rod and encloses no flock: σ_f and N_avg must be null (NaN, JSON null) with the
    // reason and the number of directions that closed, not numbers with error bars.
    const double side = 100.0;
    SplitMix64 rng(8);
    std::vector<Body> first;
    std::vector<AnalysisFrame> frames;
    for (int k = 0; k < 10; ++k) {
        std::vector<Body> bodies;
        for (int i = 0; i < 150; ++i) {
            const double x = rng.uniform(0, side), y = rng.uniform(0, side);
            const double angle = rng.uniform(-kPi, kPi);
            bodies.push_back({x, y, angle, 0});
            bodies.push_back({x + 4.6 * std::cos(angle), y + 4.6 * std::sin(angle), angle, 0});
        }
        if (k == 0) first = bodies;
        frames.push_back(make_frame(side, bodies, k));
    }
    const auto setup = make_setup(side, first, frames.size());
    CorotatingMapsObservable o(setup, resolved(setup, AnalysisOptions{}));
    const auto r = run_on(o, frames, setup);
    EXPECT_TRUE(std::isnan(scalar(r, "sigma_f").estimate.mean));
    EXPECT_TRUE(std::isnan(scalar(r, "sigma_f").estimate.error));
    EXPECT_TRUE(std::isnan(scalar(r, "N_avg").estimate.mean));
    double closed = -1.0, directions = -1.0;
    for (const ParameterValue& p : r.parameters) {
        if (p.name == "contour_closed_directions") closed = p.value;
        if (p.name == "contour_directions") directions = p.value;
    }
    std::printf("[ measured ] the contour closes in %g of %g directions\n", closed, directions);
    EXPECT_EQ(directions, 72.0);
    EXPECT_GE(closed, 0.0);
    EXPECT_LT(closed, 0.5 * directions);
    bool said = false;
    for (const std::string& note : r.notes)
        said = said || note.find("σ_f and N_avg null") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST(CorotatingMaps, FlockAcrossThePeriodicCornerGivesTheSameMap) {
    const double side = 200.0;
    SplitMix64 rng_a(6), rng_b(6);
    std::vector<Body> first;
    const auto inside = elliptical_clusters(side, 10.0, 4.0, 20, 100.0, 100.0, rng_a, &first);
    const auto corner = elliptical_clusters(side, 10.0, 4.0, 20, 0.0, 0.0, rng_b, nullptr);
    const auto setup = make_setup(side, first, inside.size());
    AnalysisOptions options;
    options.corotating_r_max = 22.0;
    CorotatingMapsObservable a(setup, resolved(setup, options)), b(setup, resolved(setup, options));
    const auto ra = run_on(a, inside, setup), rb = run_on(b, corner, setup);
    // The same relative positions up to rounding of the shift: at most a few of the 1.6·10⁵
    // pairs per frame can change bin, so the maps agree to a part in 10⁴.
    double diff = 0.0, total = 0.0;
    for (std::size_t i = 0; i < ra.maps[0].values.size(); ++i) {
        diff += std::abs(ra.maps[0].values[i] - rb.maps[0].values[i]);
        total += ra.maps[0].values[i];
    }
    EXPECT_LT(diff / total, 1e-4);
    EXPECT_NEAR(scalar(ra, "sigma_f").estimate.mean, scalar(rb, "sigma_f").estimate.mean, 1e-3);
}

TEST(Autocorrelation, FftMatchesTheDirectSum) {
    SplitMix64 rng(7);
    const std::size_t frames = 37, bodies = 5;
    std::vector<float> angles(frames * bodies);
    for (auto& a : angles)
        a = static_cast<float>(rng.uniform(-kPi, kPi));
    for (int m : {1, 2}) {
        const auto c = orientation_autocorrelation(angles, frames, bodies, m, frames - 1);
        for (std::size_t lag = 0; lag < frames; ++lag) {
            double direct = 0.0;
            for (std::size_t b = 0; b < bodies; ++b)
                for (std::size_t t = 0; t + lag < frames; ++t)
                    direct += std::cos(m * (static_cast<double>(angles[(t + lag) * bodies + b]) -
                                            angles[t * bodies + b]));
            direct /= static_cast<double>(bodies * (frames - lag));
            EXPECT_NEAR(c[lag], direct, 1e-12);  // FFT rounding on O(1) sums of 37 terms
        }
    }
}

TEST(Autocorrelation, RecoversTheRotationalDiffusionOfARandomWalk) {
    // θ(t + Δ) = θ(t) + sqrt(2 D_r Δ) ξ: C(t) = exp(−D_r t) and C₂(t) = exp(−4 D_r t).
    const double dr = 0.8, interval = 0.01, side = 60.0;
    const std::size_t rods = 300, frames = 600;
    SplitMix64 rng(8);
    std::vector<Body> bodies = uniform_bodies(rods, side, rng);
    std::vector<AnalysisFrame> out;
    const auto gaussian = [&] {  // Box–Muller from the project's portable generator
        const double u = 1.0 - rng.uniform(), v = rng.uniform();
        return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * kPi * v);
    };
    for (std::size_t k = 0; k < frames; ++k) {
        out.push_back(make_frame(side, bodies, k, interval));
        for (Body& b : bodies)
            b.theta += std::sqrt(2.0 * dr * interval) * gaussian();
    }
    const auto setup = make_setup(side, bodies, frames, interval);
    AutocorrelationObservable o(setup, resolved(setup));
    const auto r = run_on(o, out, setup);
    // The 5 %: with 300 rods × 600 origins the fit's statistical error is about 1 %.
    EXPECT_NEAR(scalar(r, "D_r_polar").estimate.mean, dr, 0.05 * dr);
    EXPECT_NEAR(scalar(r, "D_r_C2_polar").estimate.mean, dr, 0.05 * dr);
    EXPECT_GT(scalar(r, "D_r_polar").estimate.error, 0.0);
}

TEST(Segregation, MixedCellsGiveZeroAndPureCellsGiveOne) {
    // 10 × 10 cells of 9 mm (a = 2 ℓ_p) in a 90 mm box.
    const double side = 90.0;
    std::vector<Body> mixed, pure;
    for (int cx = 0; cx < 10; ++cx)
        for (int cy = 0; cy < 10; ++cy) {
            const double x = 9.0 * cx + 4.5, y = 9.0 * cy + 4.5;
            // Mixed: every cell 1 polar + 3 medium, the global fraction.
            mixed.push_back({x, y, 0.0, 0});
            for (int k = 0; k < 3; ++k)
                mixed.push_back({x + k - 1.0, y + 2.0, 0.0, 1});
            // Pure: a quarter of the cells polar only (a 5 × 5 block across the periodic edge).
            const bool polar = (cx + 2) % 10 < 5 && (cy + 7) % 10 < 5;
            for (int k = 0; k < 4; ++k)
                pure.push_back({x + k - 1.5, y, 0.0, polar ? 0u : 1u});
        }
    for (const auto& [bodies, expected] : {std::pair{mixed, 0.0}, {pure, 1.0}}) {
        const auto setup = make_setup(side, bodies, 1);
        SegregationObservable o(setup, resolved(setup));
        const auto r = run_on(o, {make_frame(side, bodies)}, setup);
        EXPECT_NEAR(scalar(r, "Sigma_raw").estimate.mean, expected, 1e-12);
    }
}

TEST(Segregation, RandomMixingIsZeroAfterTheBaseline) {
    const double side = 90.0;
    SplitMix64 rng(9);
    std::vector<AnalysisFrame> frames;
    std::vector<Body> first;
    for (std::size_t k = 0; k < 40; ++k) {
        auto bodies = uniform_bodies(100, side, rng, 0);
        const auto medium = uniform_bodies(900, side, rng, 1);
        bodies.insert(bodies.end(), medium.begin(), medium.end());
        if (k == 0) first = bodies;
        frames.push_back(make_frame(side, bodies, k));
    }
    const auto setup = make_setup(side, first, frames.size());
    SegregationObservable o(setup, resolved(setup));
    const auto r = run_on(o, frames, setup);
    const Estimate sigma = scalar(r, "Sigma").estimate;
    // Finite counts alone give a clearly non-zero raw Σ; the baseline takes it away to within
    // the error bar (4 σ: 40 independent frames).
    EXPECT_GT(scalar(r, "Sigma_raw").estimate.mean, 0.2);
    EXPECT_NEAR(sigma.mean, 0.0, 4.0 * sigma.error);
    EXPECT_LT(sigma.error, 0.02);
}

TEST(MediumVelocity, UniformFlowIsSeenAlongTheRodsAtEveryDistance) {
    const double side = 60.0;
    SplitMix64 rng(10);
    std::vector<Body> bodies;
    for (int i = 0; i < 20; ++i)  // polar rods along x, moving at 5 mm/s, some at the edges
        bodies.push_back(
            {i < 5 ? 0.2 : rng.uniform(0, side), rng.uniform(0, side), 0.0, 0, 5.0, 0.0});
    for (int i = 0; i < 2000; ++i)  // the medium drifts at 2 mm/s along x
        bodies.push_back(
            {rng.uniform(0, side), rng.uniform(0, side), rng.uniform(-kPi, kPi), 1, 2.0, 0.0});
    const auto setup = make_setup(side, bodies, 1);
    AnalysisOptions options;
    options.medium_distance = 20.0;
    options.medium_bin = 2.0;
    MediumVelocityObservable o(setup, resolved(setup, options));
    const auto r = run_on(o, {make_frame(side, bodies)}, setup);
    const TableResult& t = table(r, "medium_velocity");
    for (const auto& row : t.rows) {
        if (row[column(t, "pairs")] == 0) continue;
        EXPECT_NEAR(row[column(t, "v_along")], 2.0, 1e-12);
        EXPECT_NEAR(row[column(t, "v_across")], 0.0, 1e-12);
        EXPECT_NEAR(row[column(t, "speed")], 2.0, 1e-12);
        EXPECT_NEAR(row[column(t, "relative_v_along")], -3.0, 1e-12);
    }
    EXPECT_NEAR(scalar(r, "medium_v_along_at_d").estimate.mean, 2.0, 1e-12);
    // Every medium body within r_max of a rod counts once per rod: 20 rods × 2000 bodies ×
    // (π 20² / 60²) ≈ 6981 pairs expected, Poisson spread ≈ 84 (plus rod-position noise).
    double pairs = 0.0;
    for (const auto& row : t.rows)
        pairs += row[column(t, "pairs")];
    EXPECT_NEAR(pairs, 20.0 * 2000.0 * kPi * 400.0 / 3600.0, 600.0);
}

// The plates agitate every body in the plane far faster than the medium flows: instantaneous
// velocities here are a drift of 2 mm/s along x plus ±40 mm/s of independent jitter per body and
// frame. With lag = 2 the velocities come from the positions, which move with the drift alone
// (some across the periodic edge), so the profile is the drift to rounding, while the
// instantaneous profile's speed is the jitter's.
TEST(MediumVelocity, ALagMeasuresTheFlowUnderTheAgitation) {
    const double side = 60.0, interval = 0.1;
    SplitMix64 rng(31);
    std::vector<Body> start;
    for (int i = 0; i < 10; ++i)  // polar rods along x, drifting at 5 mm/s
        start.push_back({rng.uniform(0, side), rng.uniform(0, side), 0.0, 0, 0.0, 0.0});
    for (int i = 0; i < 1000; ++i)  // the medium, at 2 mm/s; some start 0.3 mm from the edge
        start.push_back({i < 50 ? side - 0.3 : rng.uniform(0, side), rng.uniform(0, side),
                         rng.uniform(-kPi, kPi), 1, 0.0, 0.0});
    std::vector<AnalysisFrame> frames;
    for (std::size_t k = 0; k < 8; ++k) {
        std::vector<Body> now = start;
        for (Body& b : now) {
            const double drift = b.species == 0 ? 5.0 : 2.0;
            b.x += drift * interval * static_cast<double>(k);
            b.vx = drift + rng.uniform(-40.0, 40.0);
            b.vy = rng.uniform(-40.0, 40.0);
        }
        frames.push_back(make_frame(side, now, k, interval));
    }
    const auto setup = make_setup(side, start, frames.size(), interval);
    AnalysisOptions options;
    options.medium_distance = 20.0;
    options.medium_bin = 2.0;
    options.medium_lag = 2;
    MediumVelocityObservable lagged(setup, resolved(setup, options));
    const auto r = run_on(lagged, frames, setup);
    const TableResult& t = table(r, "medium_velocity");
    // 0.2 mm over 0.2 s from coordinates near 60 mm: ~1e-14 mm of rounding, 1e-13 mm/s.
    for (const auto& row : t.rows) {
        if (row[column(t, "pairs")] == 0) continue;
        EXPECT_NEAR(row[column(t, "v_along")], 2.0, 1e-9);
        EXPECT_NEAR(row[column(t, "v_across")], 0.0, 1e-9);
        EXPECT_NEAR(row[column(t, "speed")], 2.0, 1e-9);
        EXPECT_NEAR(row[column(t, "relative_speed")], 3.0, 1e-9);
    }
    EXPECT_NEAR(scalar(r, "medium_speed_at_d").estimate.mean, 3.0, 1e-9);
    // Six of the eight frames have a frame two before them.
    EXPECT_EQ(scalar(r, "medium_lab_speed_at_d").estimate.samples, 6u);
    // Instantaneously, |v| of a uniform ±40 mm/s jitter averages (40/3)(√2 + ln(1+√2)) ≈ 30.6
    // mm/s: the drift is lost under it.
    options.medium_lag = 0;
    MediumVelocityObservable instantaneous(setup, resolved(setup, options));
    const auto raw = run_on(instantaneous, frames, setup);
    EXPECT_GT(scalar(raw, "medium_lab_speed_at_d").estimate.mean, 25.0);
    // Too few frames for the lag: said, and nothing measured.
    options.medium_lag = 8;
    MediumVelocityObservable too_long(setup, resolved(setup, options));
    const auto none = run_on(too_long, frames, setup);
    EXPECT_TRUE(std::any_of(none.notes.begin(), none.notes.end(), [](const std::string& n) {
        return n.find("needs more steady frames") != std::string::npos;
    }));
}

TEST(MediumVelocity, CrossFlowIsResolvedAlongAndAcrossTheRodAxis) {
    // Rods at 0.6 rad moving at (5, 0) mm/s in a medium flowing at (0, 3) mm/s: along the axis
    // 3 sin 0.6, across 3 cos 0.6; relative to the rod (−5, 3), speed √34.
    const double side = 60.0;
    SplitMix64 rng(22);
    std::vector<Body> bodies;
    for (int i = 0; i < 10; ++i)
        bodies.push_back({rng.uniform(0, side), rng.uniform(0, side), 0.6, 0, 5.0, 0.0});
    for (int i = 0; i < 1000; ++i)
        bodies.push_back({rng.uniform(0, side), rng.uniform(0, side), 0.0, 1, 0.0, 3.0});
    const auto setup = make_setup(side, bodies, 1);
    AnalysisOptions options;
    options.medium_distance = 20.0;
    MediumVelocityObservable o(setup, resolved(setup, options));
    const auto r = run_on(o, {make_frame(side, bodies)}, setup);
    const TableResult& t = table(r, "medium_velocity");
    for (const auto& row : t.rows) {
        if (row[column(t, "pairs")] == 0) continue;
        EXPECT_NEAR(row[column(t, "v_along")], 3.0 * std::sin(0.6), 1e-12);
        EXPECT_NEAR(row[column(t, "v_across")], 3.0 * std::cos(0.6), 1e-12);
        EXPECT_NEAR(row[column(t, "speed")], 3.0, 1e-12);
        EXPECT_NEAR(row[column(t, "relative_v_along")], -5.0 * std::cos(0.6) + 3.0 * std::sin(0.6),
                    1e-12);
        EXPECT_NEAR(row[column(t, "relative_speed")], std::sqrt(34.0), 1e-12);
    }
    EXPECT_NEAR(scalar(r, "medium_speed_at_d").estimate.mean, std::sqrt(34.0), 1e-12);
    EXPECT_NEAR(scalar(r, "medium_lab_speed_at_d").estimate.mean, 3.0, 1e-12);
}

TEST(Flocks, LargestFlockAndLabelsOfPlantedClusters) {
    const double side = 100.0;
    std::vector<Body> bodies;
    // A 7-rod flock across the x edge, a 4-rod flock, and 3 isolated rods.
    for (int k = 0; k < 7; ++k)
        bodies.push_back({std::fmod(98.5 + 1.0 * k, side), 50.0, 0.0, 0});
    for (int k = 0; k < 4; ++k)
        bodies.push_back({30.0 + 1.0 * k, 20.0, 0.0, 0});
    for (int k = 0; k < 3; ++k)
        bodies.push_back({70.0, 10.0 + 20.0 * k, 0.0, 0});
    const auto setup = make_setup(side, bodies, 1);
    FlockObservable o(setup, resolved(setup));
    const auto r = run_on(o, {make_frame(side, bodies)}, setup);
    EXPECT_EQ(scalar(r, "N_m").estimate.mean, 7.0);
    EXPECT_EQ(scalar(r, "flock_count").estimate.mean, 2.0);
    EXPECT_NEAR(scalar(r, "flock_fraction").estimate.mean, 11.0 / 14.0, 1e-15);
    const LabelResult& labels = r.labels[0];
    ASSERT_EQ(labels.labels.size(), bodies.size());
    for (int k = 1; k < 7; ++k)
        EXPECT_EQ(labels.labels[k], labels.labels[0]);
    EXPECT_NE(labels.labels[7], labels.labels[0]);
    for (std::size_t k = 11; k < 14; ++k)
        EXPECT_EQ(labels.labels[k], -1);
}

TEST(Flocks, OrderBetweenFlocksIsSetAgainstIndependentlyHeadingFlocks) {
    // Two flocks of 5 rods and 2 lone rods (N = 12): P of independently heading flocks is
    // √(5² + 5² + 1 + 1)/12 in every frame. In two frames all head the same way (P = 1), in two
    // the second flock and one lone rod head the other way (P = 0): ⟨P²⟩ = 1/2 against
    // ⟨P_independent²⟩ = 52/144, so flock_alignment = 72/52.
    const double side = 100.0;
    auto frame_bodies = [](double flip) {
        std::vector<Body> bodies;
        for (int k = 0; k < 5; ++k)
            bodies.push_back({10.0 + 1.0 * k, 10.0, 0.0, 0});
        for (int k = 0; k < 5; ++k)
            bodies.push_back({60.0 + 1.0 * k, 60.0, flip, 0});
        bodies.push_back({30.0, 80.0, 0.0, 0});
        bodies.push_back({80.0, 30.0, flip, 0});
        return bodies;
    };
    const auto together = frame_bodies(0.0), apart = frame_bodies(kPi);
    const auto setup = make_setup(side, together, 4);
    FlockObservable o(setup, resolved(setup));
    const auto r = run_on(o,
                          {make_frame(side, together, 0), make_frame(side, together, 1),
                           make_frame(side, apart, 2), make_frame(side, apart, 3)},
                          setup);
    const double independent = std::sqrt(52.0) / 12.0;
    const TableResult& t = table(r, "flocks");
    for (const auto& row : t.rows)
        EXPECT_NEAR(row[column(t, "P_independent")], independent, 1e-14);
    EXPECT_NEAR(scalar(r, "P_independent").estimate.mean, independent, 1e-14);
    EXPECT_NEAR(scalar(r, "flock_alignment").estimate.mean, 72.0 / 52.0, 1e-12);
}

TEST(PeriodicWrap, EveryObservableIsInvariantUnderAShiftOfTheWholeFrame) {
    // A clustered mixture, then the same frame shifted by whole segregation cells (9 mm) so that
    // clusters straddle the edges: every scalar and every table entry must be the same.
    const double side = 90.0;
    SplitMix64 rng(21);
    std::vector<Body> bodies;
    for (int c = 0; c < 6; ++c) {
        const double cx = rng.uniform(0, side), cy = rng.uniform(0, side);
        for (int k = 0; k < 15; ++k)
            bodies.push_back({cx + rng.uniform(-3, 3), cy + rng.uniform(-3, 3),
                              0.3 * c + rng.uniform(-0.2, 0.2), 0, rng.uniform(-9, 9),
                              rng.uniform(-9, 9)});
    }
    for (int k = 0; k < 800; ++k)
        bodies.push_back({rng.uniform(0, side), rng.uniform(0, side), rng.uniform(-kPi, kPi), 1,
                          rng.uniform(-5, 5), rng.uniform(-5, 5)});
    std::vector<Body> shifted = bodies;
    for (Body& b : shifted)
        b.x += 27.0, b.y += 63.0;
    const auto setup = make_setup(side, bodies, 1);
    AnalysisOptions options;
    options.medium_distance = 30.0;
    for (const std::string name :
         {"order", "pair", "corotating", "flocks", "segregation", "bands", "medium_velocity"}) {
        const auto a = make_observable(name, setup, resolved(setup, options));
        const auto b = make_observable(name, setup, resolved(setup, options));
        const auto ra = run_on(*a, {make_frame(side, bodies)}, setup);
        const auto rb = run_on(*b, {make_frame(side, shifted)}, setup);
        ASSERT_EQ(ra.scalars.size(), rb.scalars.size());
        // Shifting rounds positions by an ulp: a pair could change bin only if its distance lay
        // within ~1e-14 mm of an edge, so values agree to rounding.
        for (std::size_t k = 0; k < ra.scalars.size(); ++k) {
            const double x = ra.scalars[k].estimate.mean, y = rb.scalars[k].estimate.mean;
            if (std::isnan(x)) {
                EXPECT_TRUE(std::isnan(y)) << name << " " << ra.scalars[k].name;  // null both
            } else {
                EXPECT_NEAR(x, y, 1e-9) << name << " " << ra.scalars[k].name;
            }
        }
        for (std::size_t t = 0; t < ra.tables.size(); ++t)
            for (std::size_t row = 0; row < ra.tables[t].rows.size(); ++row)
                for (std::size_t c = 0; c < ra.tables[t].rows[row].size(); ++c) {
                    // Where a band lies moves with the frame (test_density_modes.cpp checks it
                    // moves with it); everything else must not change.
                    const std::string& header = ra.tables[t].columns[c];
                    if (header.size() > 3 && header.ends_with("_at")) continue;
                    const double x = ra.tables[t].rows[row][c], y = rb.tables[t].rows[row][c];
                    if (std::isnan(x)) {
                        EXPECT_TRUE(std::isnan(y)) << name;
                    } else {
                        EXPECT_NEAR(x, y, 1e-9 * std::max(1.0, std::abs(x)))
                            << name << " " << ra.tables[t].name << " row " << row << " col " << c;
                    }
                }
    }
}

}  // namespace
}  // namespace rodsea::testing
