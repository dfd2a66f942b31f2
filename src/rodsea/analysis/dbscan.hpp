#pragma once
// Density-based clustering of rod centres, to find the flocks of polar rods (docs/model.md §4) in a
// periodic box. The semantics are scikit-learn's DBSCAN exactly, labels and their numbering
// included, so that results can be cross-checked against (and compared with) Python analyses.
#include <span>
#include <vector>

#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

struct DbscanParameters {
    double eps = 2.25;    // mm, neighbourhood radius in the x-y plane (distance <= eps, as sklearn)
    int min_samples = 3;  // neighbours within eps, the point itself included, for a core point
};

// Labels per point: -1 noise, clusters 0, 1, ... numbered exactly as scikit-learn's DBSCAN numbers
// them (clusters are grown in order of their lowest-index unvisited core point; a border point
// reachable from several clusters joins the first one grown). z is ignored.
// Throws InvalidParameter (rodsea/error.hpp) for eps not positive/finite or min_samples < 1.
std::vector<int> dbscan(std::span<const Vec3> points, const PeriodicBox2D& box,
                        const DbscanParameters& parameters);

}  // namespace rodsea

namespace rodsea {

// The number of points in each cluster: sizes[k] for label k; noise (−1) is not counted.
std::vector<double> cluster_sizes(std::span<const int> labels);

}  // namespace rodsea
