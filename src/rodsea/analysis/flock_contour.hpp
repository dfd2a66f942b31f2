#pragma once
// The flock shape of the paper (SI): the closed contour of g(r,θ) at a fraction (70 %) of its
// maximum. Along each θ ray the contour sits where g last stays above the level, counted from
// the first bin that reaches it, so the excluded-volume hole near r = 0 of real rods lies
// inside the contour. σ_f is the contour's extent along the reference rod's axis (x') over its
// extent across it (y').
#include <span>
#include <vector>

namespace rodsea {

struct FlockContour {
    std::vector<double> theta;     // rad, centre of each angular bin
    std::vector<double> radius;    // mm, contour distance along that ray (0: g never reaches it)
    double level = 0.0;            // the g value of the contour
    double aspect_ratio = 0.0;     // σ_f = x' extent / y' extent; NaN when degenerate
    double enclosed_g_area = 0.0;  // Σ g · bin area inside the contour, mm²
    bool closed = true;            // false: some ray stays above the level to the map's edge
    int empty_rays = 0;            // rays that never reach the level
    int rays_at_edge = 0;          // rays that stay above the level to the map's edge
    bool sparse = false;           // no bin had `min_pairs`: the maximum is over every bin

    // Rays on which the contour closes inside the map, round the reference rod.
    int closed_rays() const { return static_cast<int>(theta.size()) - empty_rays - rays_at_edge; }
    // Only a contour closed in every direction encloses a flock: σ_f and N_avg of any other are
    // not numbers (a contour through the reference rod, or cut by the map's edge).
    bool encloses_a_flock() const {
        return level > 0.0 && !theta.empty() && closed_rays() == static_cast<int>(theta.size());
    }
};

// `g` is [r_bin * theta_bins + theta_bin]; bins without data are NaN and count as below level.
// The maximum that sets the level is taken over bins whose `pairs` reach `min_pairs` (all bins
// when `pairs` is empty or none does).
FlockContour flock_contour(std::span<const double> g, std::span<const double> r_edges,
                           std::span<const double> theta_edges, double level_fraction,
                           std::span<const double> pairs = {}, double min_pairs = 0.0);

}  // namespace rodsea
