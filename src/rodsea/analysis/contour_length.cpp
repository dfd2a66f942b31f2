#include "rodsea/analysis/contour_length.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace rodsea {

namespace {

struct Point {
    double x, y;
};

double distance(const Point& a, const Point& b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

}  // namespace

LevelSet level_set(const FieldGrid& grid, std::span<const double> values, double level) {
    if (values.size() != grid.cells())
        throw std::invalid_argument("level_set: one value per cell of the grid");
    const auto at = [&](int i, int j) {
        const double v = values[grid.index(i, j)];
        return std::isnan(v) ? -INFINITY : v;
    };
    LevelSet result;
    std::size_t above = 0;
    for (double v : values)
        above += v > level ? 1 : 0;
    result.above_fraction = static_cast<double>(above) / static_cast<double>(values.size());
    // A level line needs a cell on each side; a grid one cell wide has no plaquettes of its own.
    if (grid.nx < 2 && grid.ny < 2) return result;
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            // Corners anticlockwise from the lower left, in cell units relative to it.
            const double f[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
            const Point corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            bool up[4];
            int count = 0;
            for (int k = 0; k < 4; ++k)
                count += (up[k] = f[k] > level) ? 1 : 0;
            if (count == 0 || count == 4) continue;
            // The crossing on edge k (corner k to corner k+1), scaled to mm.
            const auto crossing = [&](int k) {
                const int l = (k + 1) % 4;
                const double fk = std::isinf(f[k]) ? level - 1.0 : f[k];
                const double fl = std::isinf(f[l]) ? level - 1.0 : f[l];
                const double t = (level - fk) / (fl - fk);
                return Point{(corner[k].x + t * (corner[l].x - corner[k].x)) * grid.dx,
                             (corner[k].y + t * (corner[l].y - corner[k].y)) * grid.dy};
            };
            std::vector<int> edges;
            for (int k = 0; k < 4; ++k)
                if (up[k] != up[(k + 1) % 4]) edges.push_back(k);
            if (edges.size() == 2) {
                result.length += distance(crossing(edges[0]), crossing(edges[1]));
                continue;
            }
            // A saddle: four crossings. If the centre is on the side of corners 0 and 2, the
            // line separates corners 1 and 3 from the rest, and the reverse.
            double mean = 0.0;
            for (double v : f)
                mean += std::isinf(v) ? level - 1.0 : v;
            const bool centre_up = 0.25 * mean > level;
            if (centre_up == up[0]) {
                result.length += distance(crossing(0), crossing(1));  // around corner 1
                result.length += distance(crossing(2), crossing(3));  // around corner 3
            } else {
                result.length += distance(crossing(3), crossing(0));  // around corner 0
                result.length += distance(crossing(1), crossing(2));  // around corner 2
            }
        }
    return result;
}

}  // namespace rodsea
