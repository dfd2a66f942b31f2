// Single-body experiments, the raw material of `rodsea calibrate`: the D_r estimator recovers a
// known rotational diffusion, and a lone polar rod without noise keeps its axis (D_r ≈ 0) while
// it travels along it consistently.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rodsea/calibration/single_body_experiment.hpp"
#include "rodsea/random.hpp"

namespace rodsea {
namespace {

// Angles of a rotational random walk with diffusion coefficient d_r, sampled every `interval`.
SingleBodyTrace random_walk(double d_r, double interval, std::size_t samples, std::uint64_t seed) {
    SplitMix64 rng(seed);
    SingleBodyTrace t;
    double angle = 0.0;
    for (std::size_t k = 0; k < samples; ++k) {
        // Gaussian step of variance 2 D_r Δt by Box–Muller.
        const double u = std::max(rng.uniform(), 1e-300), v = rng.uniform();
        angle += std::sqrt(2.0 * d_r * interval) * std::sqrt(-2.0 * std::log(u)) *
                 std::cos(2.0 * std::numbers::pi * v);
        t.angle.push_back(angle);
        t.axial.push_back(0.01);  // 2 mm/s at a 5 ms interval
        t.transverse.push_back(0.0);
    }
    return t;
}

TEST(SingleBodyExperiment, RecoversTheRotationalDiffusionOfARandomWalk) {
    // 16 walks of 2 s at 5 ms, D_r = 0.8 rad²/s: C(t) falls to 0.2 in 2 s, and the
    // jackknife error must cover the truth (3 errors: a miss once in ~370).
    std::vector<SingleBodyTrace> walks;
    for (std::uint64_t s = 0; s < 16; ++s)
        walks.push_back(random_walk(0.8, 0.005, 400, 11 + s));
    const SingleBodyResult r = combine_single_body_traces(walks, 0.005);
    EXPECT_NEAR(r.rotational_diffusion.mean, 0.8, 3.0 * r.rotational_diffusion.error);
    // The error is an honest fraction: 16 walks of 1.6 correlation times each give ~10 %.
    EXPECT_GT(r.rotational_diffusion.error, 0.02);
    EXPECT_LT(r.rotational_diffusion.error, 0.25);
    EXPECT_NEAR(r.axial_speed.mean, 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(r.forward_fraction, 1.0);
    EXPECT_EQ(r.period_speeds.size(), 16u * 400u);
    EXPECT_DOUBLE_EQ(r.correlation.front(), 1.0);
}

TEST(SingleBodyExperiment, WithoutNoiseALonePolarRodKeepsItsAxisAndTravelsAlongIt) {
    // ε = 0 and nothing to collide with: nothing turns the rod once its start spin has died
    // down, so its axis does not diffuse. 4 copies × 1 s at the default drive and gap.
    SingleBodyExperiment e;
    e.species = polar_rod_species();
    e.copies = 4;
    e.duration = 1.0;
    std::vector<SingleBodyTrace> traces;
    for (int c = 0; c < e.copies; ++c)
        traces.push_back(run_single_body_copy(e, c));
    const SingleBodyResult r = combine_single_body_traces(traces, 0.005);
    // The paper's smallest non-zero D_r is 0.026 rad²/s: "no noise" must be far below it.
    EXPECT_LT(r.rotational_diffusion.mean, 1e-3);
    // Every copy travels the same way along its axis, many standard errors from zero.
    EXPECT_TRUE(r.forward_fraction == 0.0 || r.forward_fraction == 1.0);
    EXPECT_GT(std::abs(r.axial_speed.mean), 5.0 * r.axial_speed.error);
    EXPECT_GT(std::abs(r.axial_speed.mean), 3.0 * std::abs(r.transverse_speed.mean));
    EXPECT_EQ(r.unresolved, 0u);
}

TEST(SingleBodyExperiment, NoiseMakesTheAxisDiffuse) {
    // ε = 0.01 /mm kicks the rod at every plate hit: D_r well above zero (~0.07 rad²/s).
    SingleBodyExperiment e;
    e.species = polar_rod_species();
    e.epsilon = 0.01;
    e.copies = 4;
    e.duration = 1.0;
    std::vector<SingleBodyTrace> traces;
    for (int c = 0; c < e.copies; ++c)
        traces.push_back(run_single_body_copy(e, c));
    const SingleBodyResult r = combine_single_body_traces(traces, 0.005);
    EXPECT_GT(r.rotational_diffusion.mean, 0.01);
}

}  // namespace
}  // namespace rodsea
