// The coasting step (run.stepping = "coasting", cpu/coasting_backend.hpp) against the step that
// flies every body, on the reproduction's systems, one thread: steps/s of each, the fraction of
// bodies the coasting step advanced per step, why its coasts ended, and where its time went.
// Each case settles 8000 steps (10 ms, two drive periods) off the builder's start first, on its
// own stepping. docs/performance.md, "Coasting", has the table.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>

#include "rodsea/engine/simulation.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace {

// The systems of the reproduction (docs/reproduction.md): polar rods at φ_p = 0.05 among ℓ_a =
// 2.5 mm rods (σ = 3.125) or 0.8 mm beads.
rodsea::Scene coasting_scene(int system) {
    using rodsea::polar_in_apolar_mixture;
    switch (system) {
        case 0:
            return polar_in_apolar_mixture(0.05, 2.5, 0.05, 37.8, 1);
        case 1:
            return polar_in_apolar_mixture(0.05, 2.5, 0.50, 37.8, 1);
        case 2:
            return polar_in_apolar_mixture(0.05, 2.5, 0.80, 37.8, 1);
        case 3:
            return polar_in_apolar_mixture(0.05, 2.5, 0.50, 63.0, 1);
        case 4: {
            const double side = 37.8;
            const rodsea::Species polar = rodsea::polar_rod_species(),
                                  bead = rodsea::bead_species();
            const auto count = [&](const rodsea::Species& s, double phi) {
                return std::llround(phi * side * side / s.shape.projected_area);
            };
            return rodsea::monolayer({{polar, count(polar, 0.05)}, {bead, count(bead, 0.70)}},
                                     {side, side}, 1);
        }
        default: {
            // The paper's largest rod system by size (bench_step.cpp, BM_StepPaperLargest).
            const double apolar_area = rodsea::apolar_rod_species(2.5).shape.projected_area;
            const double polar_area = rodsea::polar_rod_species().shape.projected_area;
            const double side = std::sqrt(37147.0 * apolar_area / 0.5);
            return polar_in_apolar_mixture(3203.0 * polar_area / (side * side), 2.5, 0.5, side, 1);
        }
    }
}

void BM_StepCoasting(benchmark::State& state) {
    const rodsea::Scene scene = coasting_scene(static_cast<int>(state.range(0)));
    const bool coasting = state.range(1) != 0;
    auto sim = std::make_unique<rodsea::Simulation>(
        scene.params, scene.bodies, rodsea::BackendOptions{.threads = 1, .coasting = coasting});
    sim->run(8000);
    const rodsea::StageProfile before = sim->profile();
    const rodsea::StepTally tally_before = sim->totals();
    for (auto _ : state)
        sim->step();
    const auto steps = static_cast<double>(state.iterations());
    const auto bodies = static_cast<double>(sim->bodies().size());
    state.counters["bodies"] = bodies;
    state.counters["steps/s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
    state.counters["flown"] =
        static_cast<double>(sim->totals().body_steps - tally_before.body_steps) / (steps * bodies);
    const rodsea::StageProfile& p = sim->profile();
    const double total = p.total() - before.total();
    state.counters["%flight+coasts"] = 100 * (p.free_flight - before.free_flight) / total;
    state.counters["%spheres"] = 100 * (p.sphere_update - before.sphere_update) / total;
    state.counters["%search"] = 100 * (p.contact_search - before.contact_search) / total;
    state.counters["%resolve"] = 100 * (p.resolution - before.resolution) / total;
}
BENCHMARK(BM_StepCoasting)
    ->ArgNames({"system", "coasting"})
    ->ArgsProduct({{0, 1, 2, 3, 4, 5}, {0, 1}})
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(3.0)
    ->UseRealTime();

}  // namespace
