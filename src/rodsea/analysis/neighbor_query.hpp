#pragma once
// How the observables find neighbours: the one neighbour layer (neighbors/periodic_grid.hpp),
// built over the points of one frame. A compute object takes a built grid, so that the run
// analysis builds each frame's grids once for all of them; or points and a box, and builds its
// own.
#include <span>

#include "rodsea/math/periodic_box.hpp"
#include "rodsea/neighbors/periodic_grid.hpp"

namespace rodsea {

// 2.5 mm: a few bodies per cell at the paper's densities, small against every radius asked.
inline constexpr double kQueryCell = 2.5;  // mm

inline PeriodicGrid2D query_grid(const PeriodicBox2D& box, std::span<const Vec3> points) {
    PeriodicGrid2D grid;
    grid.build(points, box, kQueryCell);
    return grid;
}

}  // namespace rodsea
