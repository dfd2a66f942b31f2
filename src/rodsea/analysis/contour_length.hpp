#pragma once
// The length of a level line of a periodic field sampled at the cells of a FieldGrid (e.g.
// the interface between polar-rich and medium-rich regions). Marching squares: on each
// plaquette of four neighbouring cell centres the line crosses the edges whose ends lie on
// either side of the level, at the linearly interpolated point; a saddle (opposite corners on
// the same side) is split by the plaquette's mean value. The line is closed on the torus.
#include <span>

#include "rodsea/analysis/coarse_grained_fields.hpp"

namespace rodsea {

struct LevelSet {
    double length = 0.0;          // mm, total length of the level line f = level
    double above_fraction = 0.0;  // fraction of the cells with f > level
};

// `values` is a map [j * nx + i] on `grid`; NaN cells count as below the level.
LevelSet level_set(const FieldGrid& grid, std::span<const double> values, double level);

}  // namespace rodsea
