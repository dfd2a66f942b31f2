#include "rodsea/analysis/coarse_grained_fields.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rodsea/analysis/histogram_bins.hpp"

namespace rodsea {

FieldGrid FieldGrid::of(const PeriodicBox2D& box, double cell) {
    if (!(cell > 0.0) || !std::isfinite(cell) || !(box.lx > 0.0) || !(box.ly > 0.0))
        throw std::invalid_argument("FieldGrid: cell and box sides must be positive");
    require_bins("fields.cell", format_number(cell) + " mm",
                 std::floor(box.lx / cell) * std::floor(box.ly / cell),
                 "the box sides / fields.cell, squared");
    FieldGrid g;
    g.nx = std::max(1, static_cast<int>(box.lx / cell));
    g.ny = std::max(1, static_cast<int>(box.ly / cell));
    g.dx = box.lx / g.nx;
    g.dy = box.ly / g.ny;
    return g;
}

double GroupFields::S(std::size_t c) const {
    return std::hypot(qxx[c], qxy[c]);
}

double GroupFields::director(std::size_t c) const {
    return 0.5 * std::atan2(qxy[c], qxx[c]);
}

GroupFields coarse_grain(const FieldGrid& grid, const PeriodicBox2D& box,
                         std::span<const Vec3> centres, std::span<const double> angles,
                         std::span<const Vec3> velocities, double body_area) {
    if (angles.size() != centres.size() ||
        (!velocities.empty() && velocities.size() != centres.size()))
        throw std::invalid_argument("coarse_grain: one angle (and velocity) per centre");
    const std::size_t n = grid.cells();
    GroupFields f;
    for (std::vector<double>* v :
         {&f.weight, &f.area_fraction, &f.px, &f.py, &f.qxx, &f.qxy, &f.vx, &f.vy})
        v->assign(n, 0.0);
    for (std::size_t b = 0; b < centres.size(); ++b) {
        // Cell centres sit at (i + ½) dx: the body's position in those units, split between the
        // two nearest centres along each axis.
        const double u = PeriodicBox2D::wrap(centres[b].x, box.lx) / grid.dx - 0.5;
        const double v = PeriodicBox2D::wrap(centres[b].y, box.ly) / grid.dy - 0.5;
        const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
        const double fu = u - i, fv = v - j;
        const double c1 = std::cos(angles[b]), s1 = std::sin(angles[b]);
        const double c2 = std::cos(2.0 * angles[b]), s2 = std::sin(2.0 * angles[b]);
        const double w[4] = {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv};
        const std::size_t at[4] = {grid.index(i, j), grid.index(i + 1, j), grid.index(i, j + 1),
                                   grid.index(i + 1, j + 1)};
        for (int k = 0; k < 4; ++k) {
            const std::size_t c = at[k];
            f.weight[c] += w[k];
            f.px[c] += w[k] * c1;
            f.py[c] += w[k] * s1;
            f.qxx[c] += w[k] * c2;
            f.qxy[c] += w[k] * s2;
            if (!velocities.empty()) {
                f.vx[c] += w[k] * velocities[b].x;
                f.vy[c] += w[k] * velocities[b].y;
            }
        }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double cell_area = grid.dx * grid.dy;
    for (std::size_t c = 0; c < n; ++c) {
        f.area_fraction[c] = f.weight[c] * body_area / cell_area;
        const double w = f.weight[c];
        for (std::vector<double>* m : {&f.px, &f.py, &f.qxx, &f.qxy, &f.vx, &f.vy})
            (*m)[c] = w > 0.0 ? (*m)[c] / w : nan;
        if (velocities.empty()) f.vx[c] = f.vy[c] = nan;
    }
    return f;
}

}  // namespace rodsea
