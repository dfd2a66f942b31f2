// Time to build the paper's two largest initial states in the full L = 252 mm box, one core:
// 101070 beads at φ = 0.80 and 37147 apolar rods (ℓ_a = 2.5 mm, 9 spheres) at φ = 0.80, each
// with 800 polar rods at φ_p = 0.05 (Table S1). Lattice start plus the default 50 Monte Carlo
// sweeps; the counters give the build's own wall time and the order left after randomisation.
#include <benchmark/benchmark.h>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace {

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
    double seconds = 0.0;
    std::uint64_t seed = 1;
    for (auto _ : state) {
        const rodsea::BodyState bodies =
            rodsea::build_initial_state(params, counts, {}, seed++, &report);
        benchmark::DoNotOptimize(bodies.position.data());
        seconds += report.seconds;
    }
    const auto n = static_cast<double>(state.iterations());
    state.counters["bodies"] = static_cast<double>(counts[0] + counts[1]);
    state.counters["build_s"] = seconds / n;
    state.counters["S_polar"] = report.nematic_order[0];
    state.counters["S_medium"] = report.nematic_order[1];
    state.counters["P_polar"] = report.polar_order[0];
    state.counters["acceptance"] = report.acceptance;
    state.counters["spare_mm"] = params.box.ly - report.row_height;
}
BENCHMARK_CAPTURE(BM_BuildFullBox, beads_0_80, 0.0, 0.80)->Unit(benchmark::kSecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_BuildFullBox, rods_2_5mm_0_80, 2.5, 0.80)
    ->Unit(benchmark::kSecond)
    ->Iterations(3);

}  // namespace
