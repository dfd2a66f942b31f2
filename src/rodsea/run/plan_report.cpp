#include "rodsea/run/plan_report.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/cli/machine_memory.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/error.hpp"
#include "rodsea/run/steady_stop.hpp"

namespace rodsea {

namespace {

// Per-body bytes: the state arrays, the inverse inertia and the resolver's bookkeeping.
constexpr std::uint64_t kBodyBytes = sizeof(std::uint32_t) + 3 * sizeof(Vec3) + sizeof(Quat) +
                                     sizeof(double) + 9 * sizeof(double) + sizeof(int);
// Per-sphere bytes: the sphere table, the cell list's ordered copies, and about three contacts
// per sphere in a dense monolayer (two neighbours and a plate).
constexpr std::uint64_t kSphereBytes = sizeof(std::uint32_t) + sizeof(double) + sizeof(Vec3) +
                                       2 * (sizeof(Vec3) + 16) + 3 * sizeof(Contact);

// Which executor will step the run, and whether it can here.
std::string describe_backend(const RunControl& control) {
    std::ostringstream text;
    if (control.backend == BackendKind::cpu) {
        text << "cpu, " << control.threads << (control.threads == 1 ? " thread" : " threads")
             << " (run.threads)";
        return text.str();
    }
    const GpuAvailability gpu = gpu_availability();
    if (gpu.usable)
        text << "gpu: " << gpu.description;
    else
        text << "gpu, NOT usable here: " << gpu.description
             << " (run refuses it; --backend cpu steps on the cores)";
    return text.str();
}

std::string fixed(double v, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
}

}  // namespace

std::string format_bytes(std::uint64_t bytes) {
    const char* units[] = {"B", "kB", "MB", "GB", "TB"};
    double v = static_cast<double>(bytes);
    int u = 0;
    while (v >= 1000.0 && u < 4) {
        v /= 1000.0;
        ++u;
    }
    return fixed(v, u == 0 ? 0 : 1) + " " + units[u];
}

ResourceEstimate estimate_resources(const RunPlan& plan) {
    ResourceEstimate e;
    for (size_t s = 0; s < plan.counts.size(); ++s) {
        const auto n = static_cast<std::uint64_t>(plan.counts[s]);
        e.bodies += n;
        e.spheres += n * plan.engine.species[s].shape.sphere_count();
    }
    e.memory_bytes = e.bodies * kBodyBytes + e.spheres * kSphereBytes;
    // position, velocity, angular velocity (3 floats) and orientation (4 floats) per body, and
    // a step (int64) and time (double) per element, and the box edges.
    e.frame_bytes = e.bodies * (3 + 3 + 3 + 4) * sizeof(float) + 5 * 16 + 3 * sizeof(double);
    e.frames = plan.total_steps() / plan.steps_per_output() + 1 +
               (plan.total_steps() % plan.steps_per_output() != 0 ? 1 : 0);
    const std::uint64_t columns = 4 * plan.engine.species.size() + 5;
    e.trajectory_bytes = e.frames * (e.frame_bytes + columns * 24);
    e.checkpoint_bytes =
        e.bodies * (3 + 3 + 3 + 4) * sizeof(double) + e.bodies * 4 + plan.config_toml.size() + 4096;
    return e;
}

void check_fits_in_memory(const RunPlan& plan) {
    check_fits_in_memory(std::vector<RunPlan>{plan});
}

namespace {

// What runs stepped together need in all (memory, output), and how big they are.
void add_to(ResourceEstimate& all, const ResourceEstimate& e) {
    all.bodies += e.bodies;
    all.spheres += e.spheres;
    all.memory_bytes += e.memory_bytes;
    all.trajectory_bytes += e.trajectory_bytes;
}

}  // namespace

void check_fits_in_memory(const std::vector<RunPlan>& plans) {
    ResourceEstimate all;
    for (const RunPlan& plan : plans)
        add_to(all, estimate_resources(plan));
    const std::optional<std::uint64_t> available = available_memory_bytes();
    if (!available || all.memory_bytes <= *available) return;
    throw InvalidParameter(
        "species",
        std::to_string(all.bodies) + " bodies (" + std::to_string(all.spheres) + " spheres" +
            (plans.size() > 1 ? " in " + std::to_string(plans.size()) + " runs" : "") +
            "), about " + format_bytes(all.memory_bytes) + " of memory",
        "what this machine has available, " + format_bytes(*available),
        plans.size() > 1 ? "fewer runs at once, smaller boxes or area fractions, or a machine "
                           "with more memory"
                         : "a smaller box.side or smaller area fractions, or a machine with more "
                           "memory");
}

void describe_ensemble(const std::vector<RunPlan>& plans,
                       const std::vector<std::filesystem::path>& dirs, const RunControl& stepping,
                       std::ostream& out, bool point_to_info) {
    out << "rodsea run: " << plans.size()
        << " runs stepped together as one ensemble, each into its own directory\n";
    out << "  run  bodies   spheres  dt/us  duration/s        steps  frames    output  directory\n";
    ResourceEstimate all;
    for (std::size_t r = 0; r < plans.size(); ++r) {
        const RunPlan& plan = plans[r];
        const ResourceEstimate e = estimate_resources(plan);
        char line[256];
        std::snprintf(
            line, sizeof line, "  %3zu  %6llu  %8llu  %5.3g  %10.6g  %11llu  %6llu  %8s  ", r,
            static_cast<unsigned long long>(e.bodies), static_cast<unsigned long long>(e.spheres),
            plan.engine.dt * 1e6, plan.control.duration,
            static_cast<unsigned long long>(plan.total_steps()),
            static_cast<unsigned long long>(e.frames), format_bytes(e.trajectory_bytes).c_str());
        out << line << dirs[r].string() << "\n";
        add_to(all, e);
    }
    out << "total    " << all.bodies << " bodies, " << all.spheres << " spheres; output "
        << format_bytes(all.trajectory_bytes) << "\n";
    out << "backend  " << describe_backend(stepping)
        << "; each run's trajectory is the one it has alone on this backend\n";
    out << "memory   about " << format_bytes(all.memory_bytes);
    if (const std::optional<std::uint64_t> available = available_memory_bytes())
        out << " of the " << format_bytes(*available) << " available here";
    out << "\n";
    if (point_to_info) out << "each run's plan in full: rodsea info CONFIG\n";
}

void describe_plan(const RunPlan& plan, std::ostream& out, bool brief) {
    const EngineParameters& p = plan.engine;
    const DriveParameters& d = p.drive;
    const double area = p.box.lx * p.box.ly;
    out << "box      " << p.box.lx << " x " << p.box.ly << " mm, periodic in x and y\n";
    out << "drive    Gamma = " << d.gamma
        << ", f = " << d.angular_frequency / (2 * std::numbers::pi)
        << " Hz (Omega = " << fixed(d.angular_frequency, 2)
        << " rad/s), A = " << fixed(d.amplitude() * 1e3, 3)
        << " um, peak plate speed A*Omega = " << fixed(d.amplitude() * d.angular_frequency, 2)
        << " mm/s\n";
    out << "         gap w = " << d.gap << " mm, g = " << d.gravity << " mm/s^2\n";
    // Mass in the polar rod's mass unit, density relative to the paper's polar rod's: the two
    // readings of the paper's "mass ratio 0.20" side by side.
    out << "species  name          kind         spheres  area/mm^2  vol/mm^3    mass  density"
           "     count    phi      plate mu/e\n";
    const ResourceEstimate e = estimate_resources(plan);
    double phi_total = 0.0;
    for (size_t s = 0; s < p.species.size(); ++s) {
        const Species& sp = p.species[s];
        const double phi = static_cast<double>(plan.counts[s]) * sp.shape.projected_area / area;
        phi_total += phi;
        char line[256];
        std::snprintf(line, sizeof line,
                      "         %-13s %-12s %7zu  %9.5f  %8.4f  %6.4f  %7.4f  %8lld  %6.4f",
                      sp.name.c_str(), to_string(sp.kind), sp.shape.sphere_count(),
                      sp.shape.projected_area, sp.shape.volume, sp.shape.mass,
                      sp.shape.mass / sp.shape.volume / polar_rod_density(), plan.counts[s], phi);
        out << line;
        if (plan.requested_area_fraction[s] >= 0)
            out << " (asked " << plan.requested_area_fraction[s] << ")";
        out << "  " << sp.plate.friction << "/" << sp.plate.restitution << "\n";
    }
    out << "         total " << e.bodies << " bodies, " << e.spheres << " spheres, area fraction "
        << fixed(phi_total, 4) << "\n";
    out << "contacts body-body mu = " << p.body_body.friction << ", e = " << p.body_body.restitution
        << (p.body_body_by_pair.empty() ? " (all pairs)" : " (with per-pair overrides)") << "\n";
    out << "noise    epsilon = " << p.noise_epsilon << " 1/mm, mode " << to_string(p.noise_mode)
        << (p.noise_mode == physics::NoiseMode::set
                ? " (each plate hit of a polar rod sets omega_z = epsilon |u_n| eta)\n"
                : " (each plate hit of a polar rod adds epsilon |u_n| eta to omega_z)\n");
    const double duration = static_cast<double>(plan.total_steps()) * p.dt;
    const double period = 2.0 * std::numbers::pi / d.angular_frequency;
    out << "time     dt = " << p.dt * 1e6 << " us, " << plan.total_steps()
        << " steps = " << duration << " s = " << fixed(duration / period, 1)
        << " drive periods, seed " << p.seed << "\n";
    out << "backend  " << describe_backend(plan.control) << "\n";
    if (plan.control.steady_samples > 0)
        out << "         stop when steady: once the steady window holds "
            << plan.control.steady_samples << " independent samples of "
            << (plan.control.steady_series == "all" ? std::string("every order series")
                                                    : plan.control.steady_series)
            << " (checked every frame from frame " << kSteadyMinimumFrames << " on); " << duration
            << " s at most\n";
    out << "output   a frame every " << plan.steps_per_output() << " steps ("
        << plan.frame_interval() << " s), " << e.frames << " frames of "
        << format_bytes(e.frame_bytes) << " = " << format_bytes(e.trajectory_bytes)
        << "; checkpoint " << format_bytes(e.checkpoint_bytes) << " every "
        << format_duration(plan.control.checkpoint_interval * 60.0) << " of wall time\n";
    out << "memory   about " << format_bytes(e.memory_bytes);
    if (const std::optional<std::uint64_t> available = available_memory_bytes())
        out << " of the " << format_bytes(*available) << " available here"
            << (e.memory_bytes > *available ? ": TOO LARGE for this machine, run refuses it" : "");
    out << "\n";
    const PackingCheck packing = check_packing(p, plan.counts);
    out << "packing  " << (packing.ok ? "feasible" : "IMPOSSIBLE: " + packing.message) << "\n";
    if (packing.ok) out << "start    " << planned_start(p, plan.counts, plan.builder) << "\n";
    if (brief) return;
    out << "CHOICEs in force (docs/model.md; each is a config key):\n";
    for (const std::string& c : plan.choices)
        out << "  - " << c << "\n";
}

}  // namespace rodsea
