// The dense isotropic starts (docs/builder.md) at the densest points of the paper's Table S1, each
// with polar rods at φ_p = 0.05: 2.5 mm rods at φ_a = 0.80 and 4.5 mm rods at 0.75 (above the
// jamming of random packings: the mosaic), beads at 0.75 (below it: compression) and at 0.80
// (the mosaic: one crystal). Each start must be valid (exact counts, no overlaps, runs), without
// lattice memory in orientation (S, P at the chance level of the independent directions) and in
// position (segregation Σ not above that of random mixing), where the lattice start, the control,
// is far from both.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "builder_checks.hpp"
#include "rodsea/analysis/segregation.hpp"
#include "rodsea/builder/initial_state.hpp"
#include "rodsea/engine/order_parameters.hpp"

namespace rodsea {
namespace {

using namespace test;

// Σ in cells of 2 ℓ_p = 9 mm, the analysis default (docs/model.md §4).
constexpr double kSegregationCell = 9.0;

double sigma_of(const Request& r, const BodyState& bodies) {
    const PeriodicBox2D box{r.params.box.lx, r.params.box.ly};
    std::vector<std::uint8_t> polar;
    for (const std::uint32_t s : bodies.species)
        polar.push_back(s == 0 ? 1 : 0);
    return segregation(box, segregation_grid(box, kSegregationCell), bodies.position, polar);
}

// Mean + 4 standard deviations of Σ over 40 realisations of the same counts at uniformly random
// positions: a start that is not segregated stays below it (hard bodies are more evenly spread
// than random points, so their Σ is lower), with probability 1 − 3e-5 for Gaussian scatter.
double random_mixing_bound(const Request& r) {
    const PeriodicBox2D box{r.params.box.lx, r.params.box.ly};
    const SegregationGrid grid = segregation_grid(box, kSegregationCell);
    constexpr int kSamples = 40;
    double mean = 0.0, mean2 = 0.0;
    for (int k = 0; k < kSamples; ++k) {
        const double s = random_mixing_segregation(r.counts[0], r.counts[1], grid, 1, 77 + k);
        mean += s / kSamples;
        mean2 += s * s / kSamples;
    }
    return mean + 4.0 * std::sqrt(std::max(0.0, mean2 - mean * mean));
}

// The independent directions of the medium: every body after compression; the domains of a
// mosaic, whose directors are independent and uniform. With K domains of unequal weight the sum
// of their e^{2iθ} has the statistics of K_eff = (Σ n_k)² / Σ n_k² ≥ K / (1 + CV²) terms; the
// jittered grid's cells vary in area by a CV below 0.5, so K_eff ≥ 0.8 K.
double independent_directions(const BuildReport& report, long long bodies) {
    return report.start == StartKind::mosaic ? 0.8 * report.domains : static_cast<double>(bodies);
}

void expect_random_dense_start(double medium_length, double phi_medium, double side,
                               StartKind expected) {
    const Request r = mixture(0.05, medium_length, phi_medium, side);
    BuildReport report;
    const BodyState bodies = build_initial_state(r.params, r.counts, {}, 21, &report);
    std::printf("[ measured ] %s, %.1f s\n", describe_start(report).c_str(), report.seconds);
    EXPECT_EQ(report.start, expected);
    expect_valid_start(r, bodies);
    // Polar rods: random and isotropic wherever the medium is (inserted at random).
    expect_isotropic(bodies, 0, r.counts[0]);
    // Beads have no axis: their S means nothing.
    if (medium_length > 0.0) {
        const double n = independent_directions(report, r.counts[1]);
        const double bound = 3.0 / std::sqrt(n);
        const double s = orientational_order(bodies, 1, 2);
        std::printf("[ measured ] medium S %.3f, bound 3/sqrt(%.0f) = %.3f\n", s, n, bound);
        EXPECT_LT(s, bound);
    }
    const double sigma = sigma_of(r, bodies), bound = random_mixing_bound(r);
    std::printf("[ measured ] Sigma %.3f, random mixing + 4 sd %.3f\n", sigma, bound);
    EXPECT_LT(sigma, bound);
    expect_runs(r, bodies);

    // The control: the lattice start of the same counts (rows of polar rods along x between rows
    // of the medium) fails both tests, so they can tell.
    BuilderOptions lattice;
    lattice.orientation = InitialOrientation::aligned;
    lattice.randomisation_sweeps = 0;
    const BodyState rows = build_initial_state(r.params, r.counts, lattice, 21);
    std::printf("[ measured ] lattice control: Sigma %.3f, polar S %.3f\n", sigma_of(r, rows),
                orientational_order(rows, 0, 2));
    EXPECT_GT(sigma_of(r, rows), bound);
    EXPECT_GT(orientational_order(rows, 0, 2), 0.9);
}

TEST(DenseStart, ShortRodsAtEightyPercentAreAMosaicOfRandomDomains) {
    expect_random_dense_start(2.5, 0.80, 100.0, StartKind::mosaic);
}

TEST(DenseStart, LongRodsAtSeventyFivePercentAreAMosaicOfRandomDomains) {
    expect_random_dense_start(4.5, 0.75, 100.0, StartKind::mosaic);
}

// A small box holds few domains (4 of 20 mm in the 38 mm box): independent random directors
// gave its medium S = 0.27 at frame 0. Evenly spaced directors dealt to cancel the domains'
// Q tensors leave it at the chance level of its ~840 rods, for every seed.
TEST(DenseStart, ShortRodsAtEightyPercentInASmallBoxAreIsotropic) {
    const Request r = mixture(0.05, 2.5, 0.80, 37.8);
    const double chance = 3.0 / std::sqrt(static_cast<double>(r.counts[1]));
    for (const std::uint64_t seed : {1, 2, 3}) {
        BuildReport report;
        const BodyState bodies = build_initial_state(r.params, r.counts, {}, seed, &report);
        const double s = orientational_order(bodies, 1, 2);
        std::printf("[ measured ] seed %llu: %s; medium S %.3f, 3/sqrt(N) %.3f\n",
                    static_cast<unsigned long long>(seed), describe_start(report).c_str(), s,
                    chance);
        EXPECT_EQ(report.start, StartKind::mosaic);
        EXPECT_LT(s, chance) << "seed " << seed;
    }
}

TEST(DenseStart, BeadsAtSeventyFivePercentAreARandomPacking) {
    expect_random_dense_start(0.0, 0.75, 100.0, StartKind::compression);
}

TEST(DenseStart, BeadsAtEightyPercentAreACrystalWithRandomPolarRods) {
    expect_random_dense_start(0.0, 0.80, 100.0, StartKind::mosaic);
}

}  // namespace
}  // namespace rodsea
