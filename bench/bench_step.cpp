// Speed of one engine step. BM_StepDenseMixture is the reference system of the engine issue
// (polar rods at φ_p = 0.05 in apolar rods of ℓ_a = 2.5 mm at φ_a = 0.5, box 20 ℓ_p = 90 mm),
// BM_StepScaling the same mixture at 10³ to 10⁵ bodies and the paper's largest system, each on 1
// and 2 threads. Reports steps/s, sphere-steps/s, the time share of each stage and the Verlet
// list's rebuild interval. (Memory per sphere is measured per process, docs/performance.md: a
// benchmark run shares one heap between its cases.)
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "rodsea/engine/ensemble.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace {

void report(benchmark::State& state, const rodsea::Simulation& sim,
            const rodsea::StageProfile& before, std::uint64_t builds_before) {
    const auto steps = static_cast<double>(state.iterations());
    const auto spheres = static_cast<double>(sim.spheres().size());
    state.counters["bodies"] = static_cast<double>(sim.bodies().size());
    state.counters["spheres"] = spheres;
    state.counters["threads"] = sim.options().threads;
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
    const auto builds = static_cast<double>(sim.pair_list_builds() - builds_before);
    state.counters["steps/rebuild"] = builds > 0 ? steps / builds : steps;
}

void run_mixture(benchmark::State& state, const rodsea::Scene& scene, int threads) {
    auto sim = std::make_unique<rodsea::Simulation>(scene.params, scene.bodies,
                                                    rodsea::BackendOptions{.threads = threads});
    sim->run(2000);  // leave the lattice: let the rods tilt, collide and spread out a little
    const rodsea::StageProfile before = sim->profile();
    const std::uint64_t builds_before = sim->pair_list_builds();
    for (auto _ : state)
        sim->step();
    report(state, *sim, before, builds_before);
}

void BM_StepDenseMixture(benchmark::State& state) {
    const double box = static_cast<double>(state.range(0));
    run_mixture(state, rodsea::polar_in_apolar_mixture(0.05, 2.5, 0.5, box, 1),
                static_cast<int>(state.range(1)));
}
BENCHMARK(BM_StepDenseMixture)
    ->ArgNames({"box_mm", "threads"})
    ->Args({90, 1})
    ->Args({90, 2})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(5.0)
    ->UseRealTime();

// The mixture with about `bodies` bodies: its 90 mm box holds 3063.
void BM_StepScaling(benchmark::State& state) {
    const double bodies = static_cast<double>(state.range(0));
    const double box = 90.0 * std::sqrt(bodies / 3063.0);
    run_mixture(state, rodsea::polar_in_apolar_mixture(0.05, 2.5, 0.5, box, 1),
                static_cast<int>(state.range(1)));
}
BENCHMARK(BM_StepScaling)
    ->ArgNames({"bodies", "threads"})
    ->ArgsProduct({{1000, 10000, 100000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->UseRealTime();

// The paper's largest system by size (docs/model.md §6: ≈ 3.5×10⁵ spheres): 3203 polar rods and
// 37147 apolar rods of 9 spheres (ℓ_a = 2.5 mm), 3.76×10⁵ spheres. The paper packs them into L =
// 252 mm, denser than the lattice start can reach, so the box here is widened to φ_a = 0.5 (L ≈ 350
// mm): the same bodies and spheres at the reference mixture's density.
void BM_StepPaperLargest(benchmark::State& state) {
    const double apolar_area = rodsea::apolar_rod_species(2.5).shape.projected_area;
    const double polar_area = rodsea::polar_rod_species().shape.projected_area;
    const double side = std::sqrt(37147.0 * apolar_area / 0.5);
    const double phi_polar = 3203.0 * polar_area / (side * side);
    run_mixture(state, rodsea::polar_in_apolar_mixture(phi_polar, 2.5, 0.5, side, 1),
                static_cast<int>(state.range(0)));
}
BENCHMARK(BM_StepPaperLargest)
    ->ArgNames({"threads"})
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->UseRealTime();

// The Fig. 4a point at σ = 5.625 (polar rods at φ_p = 0.05 in medium rods of ℓ_a = 4.5 mm, 17
// spheres each, at φ_a = 0.75, the 38 mm box): long rods packed side by side, where the sphere
// pairs and the plate contacts per body are the most of any campaign.
void BM_StepDenseLongRods(benchmark::State& state) {
    run_mixture(state, rodsea::polar_in_apolar_mixture(0.05, 4.5, 0.75, 38.0, 1),
                static_cast<int>(state.range(0)));
}
BENCHMARK(BM_StepDenseLongRods)
    ->ArgNames({"threads"})
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(3.0)
    ->UseRealTime();

// The bead medium of SI S5 near its densest point (φ_a = 0.70 of 0.8 mm beads, polar rods at
// φ_p = 0.05, a 38 mm box: the reproduction's bead campaign), 1 thread: a bead touches several
// others at once, so contacts and sweeps per sphere are the rod mixture's several times over.
void BM_StepBeadMedium(benchmark::State& state) {
    const double side = 38.0;
    const rodsea::Species polar = rodsea::polar_rod_species(), bead = rodsea::bead_species();
    const auto count = [&](const rodsea::Species& s, double phi) {
        return std::llround(phi * side * side / s.shape.projected_area);
    };
    const rodsea::Scene scene =
        rodsea::monolayer({{polar, count(polar, 0.05)},
                           {bead, count(bead, static_cast<double>(state.range(0)) / 100)}},
                          {side, side}, 1);
    std::uint64_t impulses_before = 0;
    auto sim = std::make_unique<rodsea::Simulation>(scene.params, scene.bodies);
    sim->run(4000);  // one drive period: the layer leaves the lattice
    impulses_before = sim->totals().impulses;
    const rodsea::StageProfile before = sim->profile();
    const std::uint64_t builds_before = sim->pair_list_builds();
    for (auto _ : state)
        sim->step();
    report(state, *sim, before, builds_before);
    state.counters["impulses/step"] =
        static_cast<double>(sim->totals().impulses - impulses_before) /
        static_cast<double>(state.iterations());
}
BENCHMARK(BM_StepBeadMedium)
    ->ArgNames({"phi_a_percent"})
    ->Arg(50)
    ->Arg(70)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(3.0)
    ->UseRealTime();

// `rodsea run` steps every run as an Ensemble, a lone run as an ensemble of one: what that layer
// costs per step, on a system small enough (≈ 300 bodies, 30 mm) for it to show, beside the
// Simulation it wraps (arg 0: Simulation, 1: Ensemble of one).
void BM_StepEnsembleOfOne(benchmark::State& state) {
    const rodsea::Scene scene = rodsea::polar_in_apolar_mixture(0.05, 2.5, 0.5, 30.0, 1);
    rodsea::Simulation sim(scene.params, scene.bodies);
    sim.run(2000);
    std::vector<rodsea::Simulation> one;
    one.push_back(rodsea::Simulation::resume(scene.params, sim.bodies(), sim.step_count()));
    rodsea::Ensemble ensemble(std::move(one), {});
    const bool through_ensemble = state.range(0) == 1;
    for (auto _ : state) {
        if (through_ensemble)
            ensemble.step();
        else
            sim.step();
    }
    state.counters["bodies"] = static_cast<double>(sim.bodies().size());
    state.counters["steps/s"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_StepEnsembleOfOne)
    ->ArgNames({"ensemble"})
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(3.0)
    ->UseRealTime();

// A campaign's small runs stepped as one CPU ensemble (`campaign run --ensemble`, `rodsea run A B
// C D`): four systems like the 38 mm reproduction boxes (≈ 500 bodies each, different seeds) on 1
// and 2 threads. Counts a step of the ensemble as a step of each system.
void BM_StepEnsembleOfFour(benchmark::State& state) {
    constexpr int kSystems = 4;
    std::vector<rodsea::Simulation> systems;
    double spheres = 0;
    for (int k = 0; k < kSystems; ++k) {
        const rodsea::Scene scene = rodsea::polar_in_apolar_mixture(
            0.05, 2.5, 0.5, 38.0, static_cast<std::uint64_t>(k + 1));
        rodsea::Simulation sim(scene.params, scene.bodies);
        sim.run(2000);
        spheres += static_cast<double>(sim.spheres().size());
        systems.push_back(rodsea::Simulation::resume(scene.params, sim.bodies(), sim.step_count()));
    }
    rodsea::Ensemble ensemble(std::move(systems), {.threads = static_cast<int>(state.range(0))});
    for (auto _ : state)
        ensemble.step();
    const auto steps = static_cast<double>(state.iterations());
    state.counters["systems"] = kSystems;
    state.counters["spheres"] = spheres;
    state.counters["system-steps/s"] =
        benchmark::Counter(steps * kSystems, benchmark::Counter::kIsRate);
    state.counters["sphere-steps/s"] =
        benchmark::Counter(steps * spheres, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_StepEnsembleOfFour)
    ->ArgNames({"threads"})
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(3.0)
    ->UseRealTime();

// The Fig. 4a campaign's three 38 mm systems at φ_a = 0.75 (medium rods of 1.0, 2.5, 4.5 mm:
// σ = 1.25, 3.125, 5.625) as one ensemble on 2 threads: unlike systems, whose spheres misjudge
// their cost (the short rods' system has the fewest spheres and the costliest steps), so the
// dealing of systems to workers shows (ensemble.hpp, work_shares.hpp). Counts a step of the
// ensemble as a step of each system.
void BM_StepUnlikeEnsemble(benchmark::State& state) {
    std::vector<rodsea::Simulation> systems;
    double spheres = 0;
    std::uint64_t seed = 1;
    for (const double medium_length : {1.0, 2.5, 4.5}) {
        const rodsea::Scene scene =
            rodsea::polar_in_apolar_mixture(0.05, medium_length, 0.75, 38.0, seed++);
        rodsea::Simulation sim(scene.params, scene.bodies);
        sim.run(2000);
        spheres += static_cast<double>(sim.spheres().size());
        systems.push_back(rodsea::Simulation::resume(scene.params, sim.bodies(), sim.step_count()));
    }
    rodsea::Ensemble ensemble(std::move(systems), {.threads = 2});
    ensemble.run(1100);  // past the first look at the systems' costs: timed as a long run steps
    for (auto _ : state)
        ensemble.step();
    const auto steps = static_cast<double>(state.iterations());
    state.counters["spheres"] = spheres;
    state.counters["sphere-steps/s"] =
        benchmark::Counter(steps * spheres, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_StepUnlikeEnsemble)->Unit(benchmark::kMicrosecond)->MinTime(5.0)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
