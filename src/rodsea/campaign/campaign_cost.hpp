#pragma once
// What a campaign will cost, measured rather than assumed: each point's system is built in a
// small box at the same area fractions and stepped for a fraction of a second on one thread,
// giving this machine's sphere-steps per second at that density; the point's runs then cost
// spheres × steps / that rate.
#include <iosfwd>
#include <utility>
#include <vector>

#include "rodsea/campaign/campaign_points.hpp"

namespace rodsea {

struct PointCost {
    std::uint64_t bodies = 0, spheres = 0, steps = 0;
    double sphere_steps = 0.0;   // per run
    double measured_rate = 0.0;  // sphere-steps/s on one thread; 0 when not measured
    double core_hours = 0.0;     // all replicates; NaN when not measured
    double measured_box = 0.0;   // mm, side of the box it was measured in
};

// `seconds_per_point` of stepping per point (after a short warm-up); 0 measures nothing.
std::vector<PointCost> estimate_campaign_cost(const Campaign& campaign, const CampaignGrid& grid,
                                              const CampaignScaling& scaling,
                                              const EpsilonLookup& epsilon,
                                              double seconds_per_point);

// How `campaign run` would spend the plan's wall time.
struct PlannedExecution {
    int jobs = 1, threads = 1;
    bool ensemble = false;
};

// The wall time of runs that each take `run_core_seconds` (finite, >= 0) on one thread, if
// threads scale perfectly: --jobs processes take the runs in order, each as a process frees; an
// --ensemble deals them to min(threads, runs) workers by cost as it does its systems
// (work_shares.hpp), or, with two threads or more per run, steps them in turn on every thread.
// The ensemble deals by the cost of a step, this by a whole run's: the same when the runs have
// as many steps, an approximation when their durations or time steps differ.
double planned_wall_seconds(const std::vector<double>& run_core_seconds, PlannedExecution how);

// Seconds of one step of a system of `spheres` spheres (an ensemble's: all its systems' together)
// on the GPU backend on one H200, from its measured steps (docs/performance.md, "Measured on an
// H200": ~50 µs of dependent kernels whatever the size, and ~0.14 ns per sphere above that; the
// measured systems lie within 25 % of it).
double h200_step_seconds(double spheres);

// GPU-hours of the runs (steps and spheres of each) on one H200: each run alone, one after
// another; and all of them as one ensemble, every run's spheres in every step until the longest
// run's steps are taken (an upper bound: an ensemble drops each run that ends).
struct GpuHours {
    double alone = 0.0, ensemble = 0.0;
};
GpuHours h200_hours(const std::vector<std::pair<std::uint64_t, std::uint64_t>>& steps_and_spheres);

// The plan: every point with its counts, spheres, steps and cost, and the totals.
void describe_campaign(const Campaign& campaign, const CampaignGrid& grid,
                       const CampaignScaling& scaling, const std::vector<PointCost>& costs,
                       PlannedExecution how, std::ostream& out);

}  // namespace rodsea
