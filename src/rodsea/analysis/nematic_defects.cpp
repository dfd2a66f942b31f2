#include "rodsea/analysis/nematic_defects.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace rodsea {

namespace {

constexpr double kPi = std::numbers::pi;

// A director difference with the nematic symmetry: in (−π/2, π/2].
double nematic_step(double from, double to) {
    double d = to - from;
    d -= kPi * std::round(d / kPi);
    return d <= -0.5 * kPi ? d + kPi : d;
}

}  // namespace

std::vector<NematicDefect> find_nematic_defects(const FieldGrid& grid, std::span<const double> qxx,
                                                std::span<const double> qxy) {
    if (qxx.size() != grid.cells() || qxy.size() != grid.cells())
        throw std::invalid_argument("find_nematic_defects: one Q per cell");
    const auto theta = [&](std::size_t c) { return 0.5 * std::atan2(qxy[c], qxx[c]); };
    const auto order = [&](std::size_t c) { return std::hypot(qxx[c], qxy[c]); };
    std::vector<NematicDefect> found;
    const double lx = grid.dx * grid.nx, ly = grid.dy * grid.ny;
    for (int j = 0; j < grid.ny; ++j) {
        for (int i = 0; i < grid.nx; ++i) {
            // Counter-clockwise (x right, y up): the corners are cell centres.
            const std::size_t c[4] = {grid.index(i, j), grid.index(i + 1, j),
                                      grid.index(i + 1, j + 1), grid.index(i, j + 1)};
            bool defined = true;
            for (std::size_t k : c)
                defined = defined && std::isfinite(qxx[k]) && std::isfinite(qxy[k]) &&
                          (qxx[k] != 0.0 || qxy[k] != 0.0);
            if (!defined) continue;
            double winding = 0.0;
            for (int k = 0; k < 4; ++k)
                winding += nematic_step(theta(c[k]), theta(c[(k + 1) % 4]));
            const double charge = std::round(winding / kPi) * 0.5;
            if (charge == 0.0) continue;
            // Corners at offsets (0,0), (1,0), (1,1), (0,1) cells from cell (i, j)'s centre;
            // weights 1 − S/S_max pull the core towards the disordered corners.
            const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            double s_max = 0.0;
            for (std::size_t k : c)
                s_max = std::max(s_max, order(k));
            double wsum = 0.0, ox = 0.0, oy = 0.0;
            for (int k = 0; k < 4; ++k) {
                const double w = s_max > 0.0 ? 1.0 - order(c[k]) / s_max + 1e-9 : 1.0;
                wsum += w;
                ox += w * corner[k][0];
                oy += w * corner[k][1];
            }
            NematicDefect d;
            d.charge = charge;
            d.x = PeriodicBox2D::wrap((i + 0.5 + ox / wsum) * grid.dx, lx);
            d.y = PeriodicBox2D::wrap((j + 0.5 + oy / wsum) * grid.dy, ly);
            d.orientation = std::numeric_limits<double>::quiet_NaN();
            if (charge == 0.5) {
                // ∇·Q from the unit Q of the corners (S drops at the core: only the direction
                // matters), by differences across the plaquette.
                double ux[4], uy[4];
                for (int k = 0; k < 4; ++k) {
                    const double s = order(c[k]);
                    ux[k] = qxx[c[k]] / s;
                    uy[k] = qxy[c[k]] / s;
                }
                const double dxx = ((ux[1] + ux[2]) - (ux[0] + ux[3])) / (2.0 * grid.dx);
                const double dyx = ((ux[2] + ux[3]) - (ux[0] + ux[1])) / (2.0 * grid.dy);
                const double dxy = ((uy[1] + uy[2]) - (uy[0] + uy[3])) / (2.0 * grid.dx);
                const double dyy = ((uy[2] + uy[3]) - (uy[0] + uy[1])) / (2.0 * grid.dy);
                d.orientation = std::atan2(dxy - dyx, dxx + dyy);
            }
            found.push_back(d);
        }
    }
    return found;
}

}  // namespace rodsea
