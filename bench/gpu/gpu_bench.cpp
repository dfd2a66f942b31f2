// Times the engine's step on the GPU backend and, beside it, on the CPU backend with every core,
// for the system sizes (10⁴, 10⁵, 10⁶ spheres of the reference mixture, the paper's
// largest rod and bead systems, and an ensemble of 64 systems of 10⁴ spheres), and checks that
// two GPU runs give the same bits. Needs only the
// engine and the builder (no Google Benchmark, no Debian packages): bench/gpu/run.sh builds it on
// a machine that has CUDA and nothing else.
//
//   rodsea_gpu_bench [--seconds S] [--cpu-threads T] [--only NAME] [--skip-cpu]
//                    [--launches-only]   (the GPU's `gpu-launches` row alone: for a profiler)
//                    [--settle-steps N]  (steps before timing; default 40000, 0.05 s)
//
// Prints one CSV row per system and backend: spheres, steps/s, sphere-steps/s, simulated seconds
// per wall hour, the microseconds per step of each stage (or of whole steps, `whole_us`, where a
// device queues a run's steps together), the contacts and sweeps of the last step and the
// neighbour-list builds per 1000 steps. The GPU has three rows: `gpu` (runs of steps replayed as
// CUDA graphs), `gpu-launches` (each kernel launched singly: RODSEA_GPU_GRAPHS=0) and
// `gpu-stages` (each stage waited for and timed: BackendOptions::time_stages).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/ensemble.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace {

struct System {
    std::string name;
    std::vector<rodsea::Scene> scenes;  // one, or an ensemble's
};

// The reference mixture (polar rods at φ_p = 0.05 in 2.5 mm apolar rods at φ_a = 0.5) with about
// `spheres` spheres: its 90 mm box holds about 28 000.
rodsea::Scene mixture_with(double spheres) {
    const double side = 90.0 * std::sqrt(spheres / 28'000.0);
    return rodsea::polar_in_apolar_mixture(0.05, 2.5, 0.5, side, 1);
}

// The paper's largest systems by their bodies, at φ = 0.5 so that the start can be built (the
// paper packs them into 252 mm; bench_step.cpp does the same).
rodsea::Scene paper_rods() {
    const double apolar_area = rodsea::apolar_rod_species(2.5).shape.projected_area;
    const double polar_area = rodsea::polar_rod_species().shape.projected_area;
    const double side = std::sqrt(37147.0 * apolar_area / 0.5);
    return rodsea::polar_in_apolar_mixture(3203.0 * polar_area / (side * side), 2.5, 0.5, side, 1);
}
rodsea::Scene paper_beads() {
    const rodsea::Species polar = rodsea::polar_rod_species(), bead = rodsea::bead_species();
    const double side = std::sqrt(
        (800.0 * polar.shape.projected_area + 101070.0 * bead.shape.projected_area) / 0.5);
    return rodsea::monolayer({{polar, 800}, {bead, 101070}}, {side, side}, 1);
}

struct Timing {
    double steps_per_second = 0.0;
    rodsea::StageProfile per_step;
    std::size_t contacts = 0;
    int sweeps = 0;
    double builds_per_kilostep = 0.0;
};

// A state to time from: the scene's start stepped for 0.05 s (ten drive periods: the bodies fall
// from their starting heights onto the base within two and are shaken from then on), on the GPU
// where there is one. Without one, 2000 steps (0.0025 s) on the CPU: the bodies have not yet met
// the plates. (On the CPU the steps of the reference mixture cost within 2 % of each other after
// either: a shaken layer has few contacts at a time.)
struct Start {
    std::vector<rodsea::EngineParameters> params;
    std::vector<rodsea::BodyState> bodies;
    std::vector<std::uint64_t> steps;
};
constexpr std::uint64_t kSettledSteps = 40'000, kCpuWarmUpSteps = 2'000;

Start settled(const std::vector<rodsea::Scene>& scenes, bool gpu, int cpu_threads,
              std::uint64_t settle_steps) {
    std::vector<rodsea::Simulation> systems;
    for (const rodsea::Scene& s : scenes)
        systems.emplace_back(s.params, s.bodies);
    rodsea::BackendOptions o;
    o.backend = gpu ? rodsea::BackendKind::gpu : rodsea::BackendKind::cpu;
    o.threads = cpu_threads;
    rodsea::Ensemble ensemble(std::move(systems), o);
    ensemble.run(gpu ? settle_steps : kCpuWarmUpSteps);
    Start start;
    for (std::size_t m = 0; m < ensemble.size(); ++m) {
        start.params.push_back(ensemble.parameters(m));
        start.bodies.push_back(ensemble.bodies(m));
        start.steps.push_back(ensemble.step_count(m));
    }
    return start;
}

// Steps a Simulation or an Ensemble for `seconds` of wall time, in runs of `chunk` steps, after
// one run that lets the backend size its lists: steps/s and seconds per step of each stage.
template <class Stepper>
Timing time_stepping(Stepper& stepper, double seconds, std::uint64_t chunk) {
    stepper.run(chunk);
    const rodsea::StageProfile before = stepper.profile();
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t steps = 0;
    double elapsed = 0.0;
    while (elapsed < seconds) {
        stepper.run(chunk);
        steps += chunk;
        elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    const rodsea::StageProfile& p = stepper.profile();
    const double n = static_cast<double>(steps);
    Timing t;
    t.steps_per_second = n / elapsed;
    t.per_step = {(p.free_flight - before.free_flight) / n,
                  (p.sphere_update - before.sphere_update) / n,
                  (p.contact_search - before.contact_search) / n,
                  (p.resolution - before.resolution) / n,
                  (p.noise - before.noise) / n,
                  (p.whole_steps - before.whole_steps) / n};
    return t;
}

// Every system of `start` stepped together (one system: a Simulation's own path).
Timing time_steps(const Start& start, const rodsea::BackendOptions& options, double seconds) {
    const std::uint64_t chunk = rodsea::Simulation::kStepsPerRun;
    if (start.bodies.size() == 1) {
        rodsea::Simulation sim =
            rodsea::Simulation::resume(start.params[0], start.bodies[0], start.steps[0], options);
        const std::uint64_t builds = sim.pair_list_builds();
        Timing t = time_stepping(sim, seconds, chunk);
        t.contacts = sim.last_step().body_contacts + sim.last_step().plate_contacts;
        t.sweeps = sim.last_step().sweeps;
        t.builds_per_kilostep = 1000.0 * static_cast<double>(sim.pair_list_builds() - builds) /
                                static_cast<double>(sim.step_count() - start.steps[0]);
        return t;
    }
    std::vector<rodsea::Simulation> systems;
    for (std::size_t m = 0; m < start.bodies.size(); ++m)
        systems.push_back(
            rodsea::Simulation::resume(start.params[m], start.bodies[m], start.steps[m], options));
    rodsea::Ensemble ensemble(std::move(systems), options);
    Timing t = time_stepping(ensemble, seconds, chunk);
    for (std::size_t m = 0; m < ensemble.size(); ++m) {
        t.contacts += ensemble.last_step(m).body_contacts + ensemble.last_step(m).plate_contacts;
        t.sweeps = std::max(t.sweeps, ensemble.last_step(m).sweeps);
    }
    return t;
}

void print_row(const std::string& system, const char* backend, int threads, double spheres,
               const Timing& t) {
    const rodsea::StageProfile& s = t.per_step;
    const double simulated_per_hour = t.steps_per_second * rodsea::EngineParameters{}.dt * 3600.0;
    std::printf("%s,%s,%d,%.0f,%.1f,%.4g,%.3g,%.3g,%.3g,%.3g,%.3g,%.3g,%.3g,%zu,%d,%.3g\n",
                system.c_str(), backend, threads, spheres, t.steps_per_second,
                t.steps_per_second * spheres, simulated_per_hour, s.free_flight * 1e6,
                s.sphere_update * 1e6, s.contact_search * 1e6, s.resolution * 1e6, s.noise * 1e6,
                s.whole_steps * 1e6, t.contacts, t.sweeps, t.builds_per_kilostep);
    std::fflush(stdout);
}

// The GPU's three ways of running (the file's header): graphs, single launches, timed stages.
template <class Time>
void gpu_rows(const std::string& system, double spheres, bool launches_only, Time&& time) {
    const std::pair<const char*, bool> ways[] = {
        {"gpu", false}, {"gpu-launches", false}, {"gpu-stages", true}};
    for (const auto& [name, stages] : ways) {
        if (launches_only && std::string(name) != "gpu-launches") continue;
        setenv("RODSEA_GPU_GRAPHS", std::string(name) == "gpu-launches" ? "0" : "1", 1);
        rodsea::BackendOptions o;
        o.backend = rodsea::BackendKind::gpu;
        o.time_stages = stages;
        print_row(system, name, 0, spheres, time(o));
    }
    unsetenv("RODSEA_GPU_GRAPHS");
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 5.0;
    int cpu_threads = omp_get_num_procs();
    std::string only;
    bool skip_cpu = false, launches_only = false;
    std::uint64_t settle_steps = kSettledSteps;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--seconds" && i + 1 < argc)
            seconds = std::atof(argv[++i]);
        else if (arg == "--cpu-threads" && i + 1 < argc)
            cpu_threads = std::atoi(argv[++i]);
        else if (arg == "--only" && i + 1 < argc)
            only = argv[++i];
        else if (arg == "--skip-cpu")
            skip_cpu = true;
        else if (arg == "--launches-only")
            launches_only = true;
        else if (arg == "--settle-steps" && i + 1 < argc)
            settle_steps = std::strtoull(argv[++i], nullptr, 10);
        else {
            std::fprintf(stderr,
                         "usage: rodsea_gpu_bench [--seconds S] [--cpu-threads T] [--only NAME] "
                         "[--skip-cpu] [--launches-only] [--settle-steps N]\n");
            return 2;
        }
    }
    const rodsea::GpuAvailability gpu = rodsea::gpu_availability();
    std::fprintf(stderr, "GPU: %s%s\n", gpu.usable ? "" : "none usable: ", gpu.description.c_str());

    std::vector<System> systems;
    const auto want = [&only](const char* name) { return only.empty() || only == name; };
    if (want("mixture-1e4")) systems.push_back({"mixture-1e4", {mixture_with(1e4)}});
    if (want("mixture-1e5")) systems.push_back({"mixture-1e5", {mixture_with(1e5)}});
    if (want("mixture-1e6")) systems.push_back({"mixture-1e6", {mixture_with(1e6)}});
    if (want("paper-rods")) systems.push_back({"paper-rods", {paper_rods()}});
    if (want("paper-beads")) systems.push_back({"paper-beads", {paper_beads()}});
    if (want("ensemble-64x1e4")) {  // 64 mixtures of about 10⁴ spheres, different seeds
        System e{"ensemble-64x1e4", {}};
        for (int i = 0; i < 64; ++i)
            e.scenes.push_back(rodsea::polar_in_apolar_mixture(0.05, 2.5, 0.5,
                                                               90.0 * std::sqrt(1e4 / 28'000.0),
                                                               static_cast<std::uint64_t>(i + 1)));
        systems.push_back(std::move(e));
    }

    std::printf(
        "system,backend,threads,spheres,steps_per_s,sphere_steps_per_s,simulated_s_per_hour,"
        "free_flight_us,spheres_us,search_us,resolution_us,noise_us,whole_us,contacts,sweeps,"
        "builds_per_1000_steps\n");
    for (const System& s : systems) {
        const Start start = settled(s.scenes, gpu.usable, cpu_threads, settle_steps);
        double spheres = 0.0;
        for (const rodsea::Scene& scene : s.scenes)
            spheres += static_cast<double>(
                rodsea::Simulation(scene.params, scene.bodies).spheres().size());
        if (gpu.usable)
            gpu_rows(s.name, spheres, launches_only, [&](const rodsea::BackendOptions& o) {
                return time_steps(start, o, seconds);
            });
        if (!skip_cpu) {
            rodsea::BackendOptions o;
            o.threads = cpu_threads;
            print_row(s.name, "cpu", cpu_threads, spheres, time_steps(start, o, seconds));
        }
    }

    // Determinism: the same start stepped twice on the GPU gives the same bits.
    if (gpu.usable) {
        rodsea::Scene scene = mixture_with(1e5);
        scene.params.noise_epsilon = 0.02;
        rodsea::BackendOptions o;
        o.backend = rodsea::BackendKind::gpu;
        rodsea::Simulation a(scene.params, scene.bodies, o), b(scene.params, scene.bodies, o);
        a.run(3000);
        b.run(3000);
        std::fprintf(stderr, "determinism: two GPU runs of 3000 steps: %s (%016llx, %016llx)\n",
                     a.state_hash() == b.state_hash() ? "same bits" : "DIFFERENT",
                     static_cast<unsigned long long>(a.state_hash()),
                     static_cast<unsigned long long>(b.state_hash()));
        if (a.state_hash() != b.state_hash()) return 1;
    }
    return 0;
}
