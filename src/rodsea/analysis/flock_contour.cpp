#include "rodsea/analysis/flock_contour.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rodsea {

FlockContour flock_contour(std::span<const double> g, std::span<const double> r_edges,
                           std::span<const double> theta_edges, double level_fraction,
                           std::span<const double> pairs, double min_pairs) {
    const std::size_t nr = r_edges.size() - 1, nt = theta_edges.size() - 1;
    FlockContour c;
    double gmax = 0.0;
    for (std::size_t b = 0; b < g.size(); ++b)
        if (std::isfinite(g[b]) && (pairs.empty() || pairs[b] >= min_pairs))
            gmax = std::max(gmax, g[b]);
    if (gmax == 0.0 && !pairs.empty()) {
        c.sparse = true;
        for (double v : g)
            if (std::isfinite(v)) gmax = std::max(gmax, v);
    }
    c.level = level_fraction * gmax;
    const auto at = [&](std::size_t k, std::size_t t) {
        const double v = g[k * nt + t];
        return std::isfinite(v) ? v : 0.0;
    };
    const auto centre = [&](std::size_t k) { return 0.5 * (r_edges[k] + r_edges[k + 1]); };
    double xmin = 0.0, xmax = 0.0, ymin = 0.0, ymax = 0.0;
    for (std::size_t t = 0; t < nt; ++t) {
        const double theta = 0.5 * (theta_edges[t] + theta_edges[t + 1]);
        double radius = 0.0;
        std::size_t first = 0;
        while (first < nr && at(first, t) < c.level)
            ++first;
        if (first == nr) ++c.empty_rays;
        if (gmax > 0.0 && first < nr) {
            std::size_t last = first;
            while (last + 1 < nr && at(last + 1, t) >= c.level)
                ++last;
            if (last + 1 < nr) {
                // Linear interpolation between the last bin above the level and the next one.
                const double above = at(last, t), below = at(last + 1, t);
                const double frac = above > below ? (above - c.level) / (above - below) : 0.0;
                radius = centre(last) + frac * (centre(last + 1) - centre(last));
            } else {
                radius = r_edges[nr];
                c.closed = false;
                ++c.rays_at_edge;
            }
        }
        c.theta.push_back(theta);
        c.radius.push_back(radius);
        const double dtheta = theta_edges[t + 1] - theta_edges[t];
        for (std::size_t k = 0; k < nr && centre(k) < radius; ++k)
            c.enclosed_g_area += at(k, t) * 0.5 * dtheta *
                                 (r_edges[k + 1] * r_edges[k + 1] - r_edges[k] * r_edges[k]);
        const double x = radius * std::cos(theta), y = radius * std::sin(theta);
        xmin = std::min(xmin, x), xmax = std::max(xmax, x);
        ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    }
    c.aspect_ratio =
        ymax > ymin ? (xmax - xmin) / (ymax - ymin) : std::numeric_limits<double>::quiet_NaN();
    return c;
}

}  // namespace rodsea
