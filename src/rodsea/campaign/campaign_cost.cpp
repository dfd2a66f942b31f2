#include "rodsea/campaign/campaign_cost.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iterator>
#include <limits>
#include <ostream>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/engine/work_shares.hpp"
#include "rodsea/error.hpp"
#include "rodsea/number_text.hpp"
#include "rodsea/run/plan_report.hpp"

namespace rodsea {

namespace {

// Big enough for cells and neighbour lists to behave as in a large box, small enough to build
// and step in a fraction of a second at the densest packings.
constexpr double kMeasureBox = 40.0;  // mm
constexpr double kMeasureBoxes[] = {kMeasureBox, 60.0, 90.0, 130.0};

// The CPU time of the calling thread, s. A one-thread Simulation steps on the calling thread
// (OpenMP's master runs a team of one), so this is the time the steps cost, whatever else
// shares the core: a plan made beside running simulations gives the core-hours of a core of
// its own, not its share of a busy one (wall clock: from 0.1 to 1.2 of the rate, run to run).
// NaN where the clock is not available; the measurement then falls back on the wall clock.
double thread_cpu_seconds() {
    timespec now{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now) != 0)
        return std::numeric_limits<double>::quiet_NaN();
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double measure_rate(const RunPlan& plan, double seconds, std::uint64_t spheres) {
    using Clock = std::chrono::steady_clock;
    BodyState bodies =
        build_initial_state(plan.engine, plan.counts, plan.builder, plan.engine.seed);
    Simulation sim(plan.engine, std::move(bodies), {.threads = 1});
    sim.run(20);  // the first steps fill the neighbour lists
    const double cpu_start = thread_cpu_seconds();
    const auto wall_start = Clock::now();
    // On a starved core the CPU time comes slowly: the wall clock bounds the wait.
    const double wall_limit = 20.0 * seconds;
    std::uint64_t steps = 0;
    double cpu = 0.0, wall = 0.0;
    const bool on_cpu_clock = std::isfinite(cpu_start);
    while ((on_cpu_clock ? cpu : wall) < seconds && wall < wall_limit) {
        sim.run(10);
        steps += 10;
        if (on_cpu_clock) cpu = thread_cpu_seconds() - cpu_start;
        wall = std::chrono::duration<double>(Clock::now() - wall_start).count();
    }
    const double spent = on_cpu_clock && std::isfinite(cpu) && cpu > 0.0 ? cpu : wall;
    return static_cast<double>(spheres) * static_cast<double>(steps) / spent;
}

}  // namespace

std::vector<PointCost> estimate_campaign_cost(const Campaign& campaign, const CampaignGrid& grid,
                                              const CampaignScaling& scaling,
                                              const EpsilonLookup& epsilon,
                                              double seconds_per_point) {
    std::vector<PointCost> costs;
    for (const CampaignPoint& p : grid.points) {
        PointCost c;
        const ResourceEstimate e = estimate_resources(p.plan);
        c.bodies = e.bodies;
        c.spheres = e.spheres;
        c.steps = p.plan.total_steps();
        c.sphere_steps = static_cast<double>(c.spheres) * static_cast<double>(c.steps);
        c.core_hours = std::numeric_limits<double>::quiet_NaN();
        // The lattice start of a dense mixture needs room for whole rows: a box too small for
        // the packing is replaced by a larger one, up to the point's own.
        std::vector<double> boxes(std::begin(kMeasureBoxes), std::end(kMeasureBoxes));
        boxes.push_back(p.plan.engine.box.lx);  // at last the point's own
        for (const double box : boxes) {
            if (seconds_per_point <= 0.0) break;
            CampaignScaling small = scaling;
            const double side = p.plan.engine.box.lx;
            small.scale = scaling.scale * std::min(1.0, box / side);
            try {
                const RunPlan probe =
                    small.scale == scaling.scale
                        ? p.plan
                        : config_with_settings(campaign.base_toml, campaign.base_source, p.settings,
                                               "campaign point " + p.name, small, epsilon);
                c.measured_box = probe.engine.box.lx;
                c.measured_rate =
                    measure_rate(probe, seconds_per_point, estimate_resources(probe).spheres);
                c.core_hours = c.sphere_steps * campaign.replicates / c.measured_rate / 3600.0;
                break;
            } catch (const InvalidParameter&) {
                c.measured_rate = 0.0;  // this box cannot hold the packing; try a larger one
            }
            if (box >= side) break;
        }
        costs.push_back(c);
    }
    return costs;
}

double planned_wall_seconds(const std::vector<double>& run_core_seconds, PlannedExecution how) {
    const auto threads = static_cast<std::size_t>(std::max(1, how.threads));
    const std::size_t runs = run_core_seconds.size();
    if (runs == 0) return 0.0;
    if (how.ensemble) {
        const std::size_t workers = workers_side_by_side(threads, runs);
        if (workers > 1)
            return busiest_share(share_by_cost(run_core_seconds, workers), run_core_seconds);
        double total = 0.0;  // in turn, each run on every thread
        for (const double s : run_core_seconds)
            total += s;
        return total / static_cast<double>(threads);
    }
    std::vector<double> free_at(static_cast<std::size_t>(std::max(1, how.jobs)), 0.0);
    for (const double s : run_core_seconds) {
        const auto first_free = std::min_element(free_at.begin(), free_at.end());
        *first_free += s / static_cast<double>(threads);
    }
    return *std::max_element(free_at.begin(), free_at.end());
}

double h200_step_seconds(double spheres) {
    return 50e-6 + 0.14e-9 * spheres;
}

GpuHours h200_hours(const std::vector<std::pair<std::uint64_t, std::uint64_t>>& steps_and_spheres) {
    GpuHours h;
    std::uint64_t longest = 0;
    double spheres = 0.0;
    for (const auto& [steps, n] : steps_and_spheres) {
        h.alone += static_cast<double>(steps) * h200_step_seconds(static_cast<double>(n)) / 3600.0;
        longest = std::max(longest, steps);
        spheres += static_cast<double>(n);
    }
    if (!steps_and_spheres.empty())
        h.ensemble = static_cast<double>(longest) * h200_step_seconds(spheres) / 3600.0;
    return h;
}

void describe_campaign(const Campaign& campaign, const CampaignGrid& grid,
                       const CampaignScaling& scaling, const std::vector<PointCost>& costs,
                       PlannedExecution how, std::ostream& out) {
    out << "campaign " << campaign.name;
    if (!campaign.description.empty()) out << ": " << campaign.description;
    out << "\n  " << grid.points.size() << " point" << (grid.points.size() == 1 ? "" : "s") << " x "
        << campaign.replicates << " replicate" << (campaign.replicates == 1 ? "" : "s")
        << " (seeds " << campaign.first_seed << "-"
        << campaign.first_seed + static_cast<std::uint64_t>(campaign.replicates) - 1
        << ") = " << grid.runs.size() << " runs; base " << campaign.base_source;
    if (scaling.scale != 1.0) out << "; --scale " << exact_number(scaling.scale);
    if (scaling.duration) out << "; --duration " << exact_number(*scaling.duration) << " s";
    out << "\n\n";
    std::size_t width = 5;
    for (const CampaignPoint& p : grid.points)
        width = std::max(width, p.name.size());
    width = std::min<std::size_t>(width, kNameColumnWidth);
    const int w = static_cast<int>(width);
    char line[640];
    std::snprintf(line, sizeof line, "  %-*s %7s %8s %9s %7s %11s %12s %9s %8s\n", w, "point",
                  "box mm", "bodies", "spheres", "dur. s", "steps", "Msph-steps/s", "core-h",
                  "meas. mm");
    out << line;
    double total_sphere_steps = 0.0, total_core_hours = 0.0;
    bool all_measured = true;
    for (std::size_t i = 0; i < grid.points.size(); ++i) {
        const CampaignPoint& p = grid.points[i];
        const PointCost& c = costs[i];
        total_sphere_steps += c.sphere_steps * campaign.replicates;
        all_measured = all_measured && std::isfinite(c.core_hours);
        if (std::isfinite(c.core_hours)) total_core_hours += c.core_hours;
        const std::string name = name_in_column(p.name, width);
        std::snprintf(
            line, sizeof line, "  %-*s %7.1f %8llu %9llu %7g %11llu %12s %9s %8s\n", w,
            name.c_str(), p.plan.engine.box.lx, static_cast<unsigned long long>(c.bodies),
            static_cast<unsigned long long>(c.spheres), p.plan.control.duration,
            static_cast<unsigned long long>(c.steps),
            c.measured_rate > 0 ? format_number(std::round(c.measured_rate / 1e5) / 10).c_str()
                                : "-",
            std::isfinite(c.core_hours) ? format_number(std::round(c.core_hours * 10) / 10).c_str()
                                        : "-",
            c.measured_rate > 0 ? format_number(std::round(c.measured_box)).c_str() : "-");
        out << line;
    }
    out << "\n  total " << format_number(total_sphere_steps) << " sphere-steps";
    if (all_measured && !costs.empty()) {
        out << ", about " << format_number(total_core_hours)
            << " core-hours on this machine (throughput measured on one thread in a box of "
            << format_number(kMeasureBox)
            << " mm, larger where a dense packing needs it, at each point's area fractions, from "
               "its initial state)";
        std::vector<double> run_core_seconds;
        for (const PointCost& c : costs)
            for (int r = 0; r < campaign.replicates; ++r)
                run_core_seconds.push_back(c.sphere_steps / c.measured_rate);
        out << "\n  ";
        if (how.ensemble)
            out << "with --ensemble --threads " << how.threads;
        else
            out << "with --jobs " << how.jobs << " --threads " << how.threads;
        out << ": about " << format_duration(planned_wall_seconds(run_core_seconds, how))
            << " of wall time "
            << (how.ensemble && workers_side_by_side(static_cast<std::size_t>(how.threads),
                                                     run_core_seconds.size()) > 1
                    ? "if each run keeps its one-thread rate side by side (it loses some to "
                      "shared caches and each step's join: see docs/performance.md)"
                    : "if threads scale perfectly (they do not: see docs/performance.md)");
    } else {
        out << " (cost not measured: --no-measure, or a point could not be built even in its own "
               "box)";
    }
    std::vector<std::pair<std::uint64_t, std::uint64_t>> runs;
    for (const PointCost& c : costs)
        for (int r = 0; r < campaign.replicates; ++r)
            runs.emplace_back(c.steps, c.spheres);
    const GpuHours gpu = h200_hours(runs);
    const auto hours = [](double h) {
        return format_number(h < 10 ? std::round(h * 10) / 10 : std::round(h));
    };
    out << "\n  on one H200 GPU (--backend gpu; its measured step, within ~25 %: "
           "docs/performance.md): about "
        << hours(gpu.alone) << " GPU-hours run by run, about " << hours(gpu.ensemble)
        << " as one ensemble (--ensemble)\n";
}

}  // namespace rodsea
