// Time to build the densest initial states of the paper's Table S1 in the full L = 252 mm box, one
// core, each with 800 polar rods at φ_p = 0.05: beads at φ_a = 0.75 and 0.80, apolar rods of
// ℓ_a = 2.5 mm at 0.80 and of 4.5 mm at 0.75. Start (compression or mosaic) plus the default 50
// Monte Carlo sweeps. The counters give the build's own wall time, how it started (0 insertion,
// 1 compression, 2 mosaic, 3 lattice), and how random the start is: S and P per species against
// 1/√N, and the segregation Σ (cells of 2 ℓ_p = 9 mm, docs/model.md §4) against the mean and spread
// of Σ for the same bodies at random positions.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "rodsea/analysis/segregation.hpp"
#include "rodsea/builder/initial_state.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace {

constexpr double kSegregationCell = 9.0;  // mm, 2 ℓ_p
constexpr int kBaselineSamples = 20;

void BM_BuildFullBox(benchmark::State& state, double medium_length, double phi_medium) {
    rodsea::EngineParameters params;
    params.box = {252.0, 252.0};
    params.species = {rodsea::polar_rod_species(), medium_length == 0.0
                                                       ? rodsea::bead_species()
                                                       : rodsea::apolar_rod_species(medium_length)};
    const std::vector<long long> counts{
        rodsea::count_for_area_fraction(0.05, params.box, params.species[0].shape),
        rodsea::count_for_area_fraction(phi_medium, params.box, params.species[1].shape)};
    rodsea::BuildReport report;
    rodsea::BodyState bodies;
    double seconds = 0.0;
    std::uint64_t seed = 1;
    for (auto _ : state) {
        bodies = rodsea::build_initial_state(params, counts, {}, seed++, &report);
        benchmark::DoNotOptimize(bodies.position.data());
        seconds += report.seconds;
    }
    const auto n = static_cast<double>(state.iterations());
    state.counters["bodies"] = static_cast<double>(counts[0] + counts[1]);
    state.counters["build_s"] = seconds / n;
    state.counters["start"] = static_cast<double>(report.start);
    state.counters["domains"] = report.domains;
    state.counters["relax_iterations"] = report.relaxation_iterations;
    state.counters["S_polar"] = report.nematic_order[0];
    state.counters["P_polar"] = report.polar_order[0];
    state.counters["S_medium"] = report.nematic_order[1];
    state.counters["chance_polar"] = 1.0 / std::sqrt(static_cast<double>(counts[0]));
    state.counters["chance_medium"] = 1.0 / std::sqrt(static_cast<double>(counts[1]));

    const rodsea::PeriodicBox2D box{params.box.lx, params.box.ly};
    const rodsea::SegregationGrid grid = rodsea::segregation_grid(box, kSegregationCell);
    std::vector<std::uint8_t> polar;
    for (const std::uint32_t s : bodies.species)
        polar.push_back(s == 0 ? 1 : 0);
    double mean = 0.0, mean2 = 0.0;
    for (int k = 0; k < kBaselineSamples; ++k) {
        const double sigma =
            rodsea::random_mixing_segregation(counts[0], counts[1], grid, 1, 1000 + k);
        mean += sigma / kBaselineSamples;
        mean2 += sigma * sigma / kBaselineSamples;
    }
    state.counters["Sigma"] = rodsea::segregation(box, grid, bodies.position, polar);
    state.counters["Sigma_random"] = mean;
    state.counters["Sigma_random_sd"] = std::sqrt(std::max(0.0, mean2 - mean * mean));
}
BENCHMARK_CAPTURE(BM_BuildFullBox, beads_0_75, 0.0, 0.75)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_BuildFullBox, beads_0_80, 0.0, 0.80)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_BuildFullBox, rods_2_5mm_0_80, 2.5, 0.80)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_BuildFullBox, rods_4_5mm_0_75, 4.5, 0.75)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
