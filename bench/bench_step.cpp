// Speed of one engine step on the reference system: polar rods at φ_p = 0.05 in apolar
// rods (ℓ_a = 2.5 mm) at φ_a = 0.5, box 20 ℓ_p = 90 mm, single thread. Reports steps/s and
// sphere-steps/s, plus the time share of each stage.
#include <benchmark/benchmark.h>

#include "rodsea/engine/simulation.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace {

void BM_StepDenseMixture(benchmark::State& state) {
    const double box = static_cast<double>(state.range(0));
    const rodsea::Scene scene = rodsea::polar_in_apolar_mixture(0.05, 2.5, 0.5, box, 1);
    rodsea::Simulation sim(scene.params, scene.bodies);
    sim.run(2000);  // leave the lattice: let the rods tilt, collide and spread out a little
    const rodsea::StageProfile before = sim.profile();
    for (auto _ : state)
        sim.step();
    const auto steps = static_cast<double>(state.iterations());
    const auto spheres = static_cast<double>(sim.spheres().size());
    state.counters["bodies"] = static_cast<double>(sim.bodies().size());
    state.counters["spheres"] = spheres;
    state.counters["steps/s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
    state.counters["sphere-steps/s"] =
        benchmark::Counter(steps * spheres, benchmark::Counter::kIsRate);
    const rodsea::StageProfile& p = sim.profile();
    const double total = p.total() - before.total();
    state.counters["%free_flight"] = 100 * (p.free_flight - before.free_flight) / total;
    state.counters["%spheres"] = 100 * (p.sphere_update - before.sphere_update) / total;
    state.counters["%search"] = 100 * (p.contact_search - before.contact_search) / total;
    state.counters["%resolve"] = 100 * (p.resolution - before.resolution) / total;
    state.counters["contacts"] =
        static_cast<double>(sim.last_step().body_contacts + sim.last_step().plate_contacts);
}
BENCHMARK(BM_StepDenseMixture)->Arg(90)->Unit(benchmark::kMillisecond)->MinTime(5.0);

}  // namespace

BENCHMARK_MAIN();
