// The GPU backend against the CPU backend on the validation tier's measurements, with nothing but
// the engine and the builder (a GPU machine has no Debian packages for the full CLI):
//   - a lone polar rod: its speed along its axis and the fraction of copies going thick → thin
//     at ε = 0, its D_r at ε = 0.02 /mm (docs/validation.md's single-body tables);
//   - the dense mixture (polar rods at φ_p = 0.05 in 2.5 mm rods at φ_a = 0.5): body and plate
//     collisions per body per second and P after a fixed time, over seeds;
//   - determinism: the same start stepped twice on the GPU gives the same bits.
// Each CPU/GPU pair is the same copies or seeds; z = |gpu − cpu| / sqrt(err_gpu² + err_cpu²)
// must stay below 3. Prints a Markdown table; exits 1 when a check fails.
//
//   rodsea_gpu_validate [--quick]          --quick: a smaller tier, for a machine without a GPU
//                                           (then the GPU columns are the host's twin)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "rodsea/builder/placement.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/ensemble.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace {

using rodsea::BackendKind;
using rodsea::BackendOptions;

struct Estimate {
    double mean = 0.0, error = 0.0;  // error: standard error over independent samples
};

Estimate estimate(const std::vector<double>& v) {
    double mean = 0.0;
    for (double x : v)
        mean += x / static_cast<double>(v.size());
    double var = 0.0;
    for (double x : v)
        var += (x - mean) * (x - mean) / static_cast<double>(v.size() - 1);
    return {mean, std::sqrt(var / static_cast<double>(v.size()))};
}

// Copies of a lone polar rod, each in its own 20 mm box with its own start and noise seed (as
// `rodsea calibrate` makes them), stepped as one ensemble.
struct LoneRod {
    Estimate speed;          // mm/s along body +x (thick → thin)
    Estimate rotational;     // D_r from ⟨Δθ²⟩ = 2 D_r t over the measured time, rad²/s
    double forward = 0.0;    // fraction of copies going thick → thin
    std::uint64_t hash = 0;  // of the first copy's final state
};

// `copies` copies at each noise of `epsilons`, all stepped as one ensemble (a device's step costs
// about as much for 32 lone rods as for 16).
std::vector<LoneRod> lone_rods(const std::vector<double>& epsilons, int copies, double seconds,
                               const BackendOptions& options) {
    const rodsea::Species polar = rodsea::polar_rod_species();
    std::vector<rodsea::Simulation> systems;
    for (const double epsilon : epsilons)
        for (int c = 0; c < copies; ++c) {
            rodsea::SplitMix64 rng(1000 + static_cast<std::uint64_t>(c));
            rodsea::EngineParameters p;
            p.box = {20.0, 20.0};
            p.species = {polar};
            p.noise_epsilon = epsilon;
            p.seed = 1 + 7919ULL * static_cast<std::uint64_t>(c);
            const rodsea::Quat q = rodsea::tipped_orientation(
                rng.uniform(-std::numbers::pi, std::numbers::pi), rng.uniform(-0.1, 0.1));
            rodsea::BodyState body;
            body.add(0, {10.0, 10.0, rodsea::resting_height(polar.shape, q, p.drive)}, q, {},
                     {0.0, 0.0, rng.uniform(-2.0, 2.0)});
            systems.emplace_back(p, body);
        }
    const std::size_t n = systems.size();
    rodsea::Ensemble ensemble(std::move(systems), options);
    const double period = 2.0 * std::numbers::pi / rodsea::DriveParameters{}.angular_frequency;
    const auto steps = static_cast<std::uint64_t>(std::llround(period / 1.25e-6));
    ensemble.run(40 * steps);  // 0.2 s of settling
    const auto periods = static_cast<int>(std::llround(seconds / period));
    std::vector<double> along(n, 0.0), angle(n, 0.0), last_angle(n);
    std::vector<rodsea::Vec3> last(n);
    for (std::size_t c = 0; c < n; ++c) {
        last[c] = ensemble.bodies(c).position[0];
        last_angle[c] = rodsea::in_plane_angle(ensemble.bodies(c).orientation[0]);
    }
    const rodsea::PeriodicBox2D box{20.0, 20.0};
    for (int k = 0; k < periods; ++k) {
        ensemble.run(steps);
        for (std::size_t c = 0; c < n; ++c) {
            const rodsea::BodyState& b = ensemble.bodies(c);
            const rodsea::Vec3 d = box.minimum_image(b.position[0] - last[c]);
            last[c] = b.position[0];
            const double theta = rodsea::in_plane_angle(b.orientation[0]);
            double turn = theta - last_angle[c];
            turn -= 2.0 * std::numbers::pi * std::round(turn / (2.0 * std::numbers::pi));
            last_angle[c] = theta;
            angle[c] += turn;
            along[c] += d.x * std::cos(theta) + d.y * std::sin(theta);
        }
    }
    const double t = periods * period;
    std::vector<LoneRod> rods;
    for (std::size_t e = 0; e < epsilons.size(); ++e) {
        std::vector<double> speed, diffusion;
        LoneRod r;
        for (int k = 0; k < copies; ++k) {
            const std::size_t c =
                e * static_cast<std::size_t>(copies) + static_cast<std::size_t>(k);
            speed.push_back(along[c] / t);
            diffusion.push_back(angle[c] * angle[c] / (2.0 * t));
            if (along[c] > 0.0) r.forward += 1.0 / copies;
        }
        r.speed = estimate(speed);
        r.rotational = estimate(diffusion);
        r.hash = ensemble.state_hash(e * static_cast<std::size_t>(copies));
        rods.push_back(r);
    }
    return rods;
}

// The dense mixture over seeds: collisions per body per second and P at the end.
struct Mixture {
    Estimate body_rate, plate_rate, polar_order;
    std::uint64_t hash = 0;  // of the first seed's final state
};

Mixture mixture(int seeds, double seconds, const BackendOptions& options) {
    std::vector<rodsea::Simulation> systems;
    for (int s = 0; s < seeds; ++s) {
        const rodsea::Scene scene = rodsea::polar_in_apolar_mixture(
            0.05, 2.5, 0.5, 30.0, static_cast<std::uint64_t>(s + 1));
        systems.emplace_back(scene.params, scene.bodies);
    }
    rodsea::Ensemble ensemble(std::move(systems), options);
    const auto steps = static_cast<std::uint64_t>(std::llround(seconds / 1.25e-6));
    ensemble.run(steps);
    std::vector<double> body(seeds), plate(seeds), order;
    for (int s = 0; s < seeds; ++s) {
        body[s] = static_cast<double>(ensemble.last_run(s).body_collisions);
        plate[s] = static_cast<double>(ensemble.last_run(s).plate_collisions);
        const double n = static_cast<double>(ensemble.bodies(s).size());
        body[s] /= n * seconds;
        plate[s] /= n * seconds;
        order.push_back(rodsea::orientational_order(ensemble.bodies(s), 0, 1));
    }
    return {estimate(body), estimate(plate), estimate(order), ensemble.state_hash(0)};
}

int failures = 0;

void compare(const char* what, const char* unit, const Estimate& cpu, const Estimate& gpu) {
    const double e = std::sqrt(cpu.error * cpu.error + gpu.error * gpu.error);
    const double z = e > 0.0 ? std::abs(gpu.mean - cpu.mean) / e : (gpu.mean == cpu.mean ? 0 : 99);
    const bool ok = z < 3.0;
    if (!ok) ++failures;
    std::printf("| %s | %s | %.5g ± %.2g | %.5g ± %.2g | %.2f | %s |\n", what, unit, cpu.mean,
                cpu.error, gpu.mean, gpu.error, z, ok ? "ok" : "FAIL");
}

}  // namespace

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each row as it comes, should a time limit cut it
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const rodsea::GpuAvailability gpu = rodsea::gpu_availability();
    BackendOptions on_cpu, on_gpu;
    on_gpu.backend = gpu.usable ? BackendKind::gpu : BackendKind::gpu_on_host;
    if (!gpu.usable && !quick) {
        std::fprintf(stderr, "no GPU: %s (--quick runs a small tier on the host's twin)\n",
                     gpu.description.c_str());
        return 2;
    }
    std::printf("GPU: %s\n\n", gpu.usable ? gpu.description.c_str() : "none: the host's twin");
    const int copies = quick ? 4 : 16, seeds = quick ? 2 : 8;
    const double rod_seconds = quick ? 0.2 : 2.0, mixture_seconds = quick ? 0.02 : 0.2;
    std::printf("| quantity | unit | cpu | %s | z | |\n|---|---|---|---|---|---|\n",
                gpu.usable ? "gpu" : "gpu-on-host");

    const std::vector<LoneRod> rods_cpu = lone_rods({0.0, 0.02}, copies, rod_seconds, on_cpu);
    const std::vector<LoneRod> rods_gpu = lone_rods({0.0, 0.02}, copies, rod_seconds, on_gpu);
    const LoneRod &still_cpu = rods_cpu[0], &still_gpu = rods_gpu[0];
    const LoneRod &noisy_cpu = rods_cpu[1], &noisy_gpu = rods_gpu[1];
    compare("lone polar rod, ε = 0: speed along +x", "mm/s", still_cpu.speed, still_gpu.speed);
    std::printf("| lone polar rod, ε = 0: copies going thick → thin | | %.2f | %.2f | | %s |\n",
                still_cpu.forward, still_gpu.forward,
                still_cpu.forward == still_gpu.forward ? "ok" : "differ");
    compare("lone polar rod, ε = 0.02 /mm: D_r", "rad²/s", noisy_cpu.rotational,
            noisy_gpu.rotational);

    const Mixture mix_cpu = mixture(seeds, mixture_seconds, on_cpu);
    const Mixture mix_gpu = mixture(seeds, mixture_seconds, on_gpu);
    compare("dense mixture: body collisions", "1/(body s)", mix_cpu.body_rate, mix_gpu.body_rate);
    compare("dense mixture: plate collisions", "1/(body s)", mix_cpu.plate_rate,
            mix_gpu.plate_rate);
    compare("dense mixture: P at the end", "", mix_cpu.polar_order, mix_gpu.polar_order);

    const Mixture again = mixture(1, mixture_seconds, on_gpu);
    const bool repeatable = again.hash == mix_gpu.hash;
    if (!repeatable) ++failures;
    std::printf("\ndeterminism: the mixture's first seed twice on %s: %s\n",
                gpu.usable ? "the GPU" : "the host's twin",
                repeatable ? "the same bits" : "DIFFERENT BITS");
    std::printf("the CPU's bits: lone rod %s, mixture %s\n",
                noisy_cpu.hash == noisy_gpu.hash ? "equal" : "different",
                mix_cpu.hash == mix_gpu.hash ? "equal" : "different");
    std::printf("%s\n", failures == 0 ? "all checks pass" : "SOME CHECKS FAIL");
    return failures == 0 ? 0 : 1;
}
