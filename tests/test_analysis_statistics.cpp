// Error bars and the steady-state start on series whose statistics are known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "rodsea/analysis/statistics.hpp"
#include "rodsea/analysis/steady_state.hpp"
#include "rodsea/random.hpp"

namespace rodsea {
namespace {

double gaussian(SplitMix64& rng) {
    const double u = 1.0 - rng.uniform(), v = rng.uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

// x_t = ρ x_{t−1} + ξ_t has τ_int = (1 + ρ) / (2 (1 − ρ)) exactly.
std::vector<double> ar1(double rho, std::size_t n, std::uint64_t seed) {
    SplitMix64 rng(seed);
    std::vector<double> x(n);
    double v = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        x[i] = v = rho * v + gaussian(rng);
    return x;
}

TEST(Statistics, IntegratedAutocorrelationTimeOfAnAr1Series) {
    for (const double rho : {0.0, 0.5, 0.9}) {
        const double expected = (1 + rho) / (2 * (1 - rho));
        // Sokal's estimator has relative error ≈ sqrt(2(2W+1)/n) ≈ 3 % here: 10 % is safe.
        EXPECT_NEAR(integrated_autocorrelation_time(ar1(rho, 200000, 11)), expected, 0.1 * expected)
            << "rho " << rho;
    }
}

TEST(Statistics, ErrorBarsCoverTheTrueMeanAtTheirNominalRate) {
    // 200 independent AR(1) series (ρ = 0.8): the true mean is 0, and |mean| < error should hold
    // for ≈ 68 % of them. Binomial spread of the count is ±6.6: accept 55–81 %.
    int covered = 0;
    for (std::uint64_t s = 0; s < 200; ++s) {
        // Hashed seeds: consecutive SplitMix64 seeds would give the same stream shifted by one.
        const Estimate e = estimate_mean(ar1(0.8, 4000, splitmix64(100 + s)));
        if (std::abs(e.mean) < e.error) ++covered;
    }
    EXPECT_GE(covered, 110);
    EXPECT_LE(covered, 162);
}

TEST(Statistics, UncorrelatedSeriesGetTheTextbookError) {
    const auto x = ar1(0.0, 10000, 12);
    const Estimate e = estimate_mean(x);
    // Unit variance: error 1/sqrt(n) = 0.01, times sqrt(2 τ_int) with τ_int ≈ 0.5 ± 3 %.
    EXPECT_NEAR(e.error, 0.01, 0.001);
    EXPECT_NEAR(e.tau_int, 0.5, 0.05);
}

TEST(Statistics, ConstantSeriesHasZeroError) {
    const std::vector<double> x(50, 0.25);
    const Estimate e = estimate_mean(x);
    EXPECT_EQ(e.mean, 0.25);
    EXPECT_EQ(e.error, 0.0);
}

TEST(Statistics, SteadyStartSkipsAnExponentialTransient) {
    // A relaxation 5·exp(−t/40) on top of unit white noise over 2000 samples: keeping samples
    // before t ≈ 100 (where the bias is > 0.4 noise widths) inflates τ_int; starting after 400
    // throws away data for nothing.
    SplitMix64 rng(13);
    std::vector<double> x;
    for (int t = 0; t < 2000; ++t)
        x.push_back(5.0 * std::exp(-t / 40.0) + gaussian(rng));
    const std::size_t start = steady_start(x);
    EXPECT_GE(start, 80u);
    EXPECT_LE(start, 400u);
    // Already steady: keep everything (up to the candidate grid's first steps).
    EXPECT_LE(steady_start(ar1(0.0, 2000, 14)), 120u);
}

TEST(Statistics, BlockErrorIsTheStandardErrorOfTheBlocks) {
    const std::vector<double> blocks{1.0, 2.0, 3.0, 4.0};
    const Estimate e = estimate_from_blocks(2.5, blocks);
    // Sample standard deviation sqrt(5/3), over sqrt(4).
    EXPECT_NEAR(e.error, std::sqrt(5.0 / 3.0) / 2.0, 1e-15);
    EXPECT_EQ(e.mean, 2.5);
}

// Unit white noise with an exponential transient of amplitude 5 and decay time `tau` on top.
std::vector<double> relaxing(double tau, std::uint64_t seed) {
    SplitMix64 rng(seed);
    std::vector<double> x;
    for (int t = 0; t < 2000; ++t)
        x.push_back(5.0 * std::exp(-t / tau) + gaussian(rng));
    return x;
}

TEST(Replicates, MeanAndErrorFromTheSpread) {
    // Four replicates 1, 2, 3, 4 each quoting σ = 1: sd = √(5/3), error sd/2, χ² = 5 over 3 dof.
    const ReplicateEstimate r =
        combine_replicates(std::vector<double>{1, 2, 3, 4}, std::vector<double>{1, 1, 1, 1});
    EXPECT_EQ(r.replicates, 4u);
    EXPECT_DOUBLE_EQ(r.mean, 2.5);
    EXPECT_DOUBLE_EQ(r.error, std::sqrt(5.0 / 3.0) / 2.0);
    EXPECT_DOUBLE_EQ(r.chi2_per_dof, 5.0 / 3.0);
    EXPECT_DOUBLE_EQ(r.own_error, 0.5);  // √(4 · 1²) / 4
    // The central 95 % of χ²/3 (scipy.stats.chi2.ppf(0.025, 3) / 3 and ppf(0.975, 3) / 3).
    EXPECT_NEAR(r.chi2_low, 0.0719318, 1e-6);
    EXPECT_NEAR(r.chi2_high, 3.1161345, 1e-6);
    // A NaN value (an observable undefined in one run) is left out; a missing σ leaves χ² unknown.
    const ReplicateEstimate partial =
        combine_replicates(std::vector<double>{1, std::nan(""), 3}, std::vector<double>{0, 1, 1});
    EXPECT_EQ(partial.replicates, 2u);
    EXPECT_DOUBLE_EQ(partial.mean, 2.0);
    EXPECT_DOUBLE_EQ(partial.error, 1.0);
    EXPECT_TRUE(std::isnan(partial.chi2_per_dof));
    EXPECT_TRUE(std::isnan(combine_replicates(std::vector<double>{1}, {}).error));
}

TEST(Replicates, ErrorsFromFewSamplesWidenTheRangeToTheirOwnScatter) {
    // 200 sets of 8 replicates whose errors are honest but each estimated from 4 degrees of
    // freedom (σ √(χ²_4 / 4), as a run of n_eff = 5 quotes). Given those degrees of freedom,
    // χ²/dof falls inside the range in 95 % of the sets (binomial sd 1.5 %: 5 % is over three of
    // them). The χ² law's range, which takes the errors as exact, misses many more: their scatter
    // raises χ²/dof's mean to ν/(ν − 2) = 2, near the law's 97.5 % point for 7 dof, 2.29.
    SplitMix64 rng(43);
    int inside = 0, inside_law = 0;
    const int sets = 200;
    const std::vector<double> dof(8, 4.0);
    for (int s = 0; s < sets; ++s) {
        std::vector<double> x(8), e(8);
        for (std::size_t i = 0; i < x.size(); ++i) {
            x[i] = 0.3 + 0.1 * gaussian(rng);
            double chi2 = 0.0;
            for (int k = 0; k < 4; ++k)
                chi2 += std::pow(gaussian(rng), 2);
            e[i] = 0.1 * std::sqrt(chi2 / 4.0);
        }
        const ReplicateEstimate r = combine_replicates(x, e, dof);
        inside += r.chi2_per_dof >= r.chi2_low && r.chi2_per_dof <= r.chi2_high;
        const ReplicateEstimate law = combine_replicates(x, e);
        inside_law += law.chi2_per_dof >= law.chi2_low && law.chi2_per_dof <= law.chi2_high;
    }
    EXPECT_NEAR(inside / double(sets), 0.95, 0.05);
    EXPECT_LT(inside_law / double(sets), 0.85);
}

TEST(Replicates, ErrorsFromManySamplesGiveTheChiSquareLawsRange) {
    // Errors from 10⁴ degrees of freedom are as good as exact: the Monte Carlo range of four
    // equal errors is the χ²/3 law's (0.0719, 3.116) to its sampling accuracy (20 000 draws: about
    // 4 % at the 2.5 % point, 1.5 % at the 97.5 % point), and the same on every call.
    const std::vector<double> x{1, 2, 3, 4}, e{1, 1, 1, 1}, dof(4, 1e4);
    const ReplicateEstimate r = combine_replicates(x, e, dof);
    EXPECT_NEAR(r.chi2_low / 0.0719318, 1.0, 0.12);
    EXPECT_NEAR(r.chi2_high / 3.1161345, 1.0, 0.05);
    EXPECT_DOUBLE_EQ(r.chi2_per_dof, 5.0 / 3.0);  // the statistic itself does not change
    const ReplicateEstimate again = combine_replicates(x, e, dof);
    EXPECT_EQ(again.chi2_low, r.chi2_low);
    EXPECT_EQ(again.chi2_high, r.chi2_high);
}

TEST(Replicates, HonestErrorsPassTheChiSquareTestAtItsNominalRate) {
    // 2000 sets of 8 Gaussian replicates quoting their true σ: χ²/dof falls inside the central
    // 95 % range in 95 % of the sets (binomial sd 0.5 %: 2 % is four of them); σ quoted 4× too
    // small puts a set above it when its true χ²/7 exceeds 2.29 / 16, with probability 0.995
    // (binomial sd 0.16 %).
    SplitMix64 rng(41);
    int inside = 0, caught = 0;
    const int sets = 2000;
    for (int s = 0; s < sets; ++s) {
        std::vector<double> x(8);
        for (double& v : x)
            v = 0.3 + 0.1 * gaussian(rng);
        const ReplicateEstimate honest = combine_replicates(x, std::vector<double>(8, 0.1));
        inside += honest.chi2_per_dof >= honest.chi2_low && honest.chi2_per_dof <= honest.chi2_high;
        const ReplicateEstimate small = combine_replicates(x, std::vector<double>(8, 0.025));
        caught += small.chi2_per_dof > small.chi2_high;
    }
    EXPECT_NEAR(inside / double(sets), 0.95, 0.02);
    EXPECT_GT(caught / double(sets), 0.98);
}

TEST(SteadyState, TheWindowStartsAfterTheSlowestTransient) {
    // P relaxes in 10 samples, S of the medium in 100: the window must wait for S (its own start
    // lies past t ≈ 250, where its bias falls below 0.4 noise widths), and say that S decided.
    // A constant series (no information) and one with a NaN (not applicable) do not decide.
    const std::vector<NamedSeries> series{{"P", relaxing(10.0, 21)},
                                          {"S", relaxing(100.0, 22)},
                                          {"flat", std::vector<double>(2000, 0.3)},
                                          {"gap", std::vector<double>(2000, std::nan(""))}};
    const SteadyChoice choice = latest_steady_start(series);
    EXPECT_EQ(choice.decided_by, "S");
    EXPECT_EQ(choice.first, steady_start(series[1].values));
    EXPECT_GE(choice.first, 200u);
    EXPECT_LT(steady_start(series[0].values), choice.first);
    ASSERT_EQ(choice.series.size(), 4u);
    EXPECT_EQ(choice.series[0].start, steady_start(series[0].values));
    // White noise from the window on: n_eff ≈ n (τ_int = 1/2), within Sokal's ~10 %.
    const double n = static_cast<double>(2000 - choice.first);
    EXPECT_NEAR(choice.series[0].n_eff, n, 0.15 * n);
    EXPECT_FALSE(choice.series[0].drifting);
    EXPECT_FALSE(choice.series[1].drifting);
    EXPECT_EQ(choice.series[3].n_eff, 0.0);
}

TEST(SteadyState, ATrendIsFlaggedAsDrifting) {
    // A series still rising to its end (the dilute run whose P never settled): its halves differ
    // by 0.5 (a slope of 1/2000 per sample over 1000 samples), 16 standard errors of 0.032.
    SplitMix64 rng(31);
    std::vector<double> rising;
    for (int t = 0; t < 2000; ++t)
        rising.push_back(t / 2000.0 + gaussian(rng));
    const std::vector<NamedSeries> series{{"P", rising}};
    const SteadyChoice choice = latest_steady_start(series);
    EXPECT_TRUE(choice.series[0].drifting);
}

}  // namespace
}  // namespace rodsea
