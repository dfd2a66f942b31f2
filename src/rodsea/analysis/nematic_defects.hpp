#pragma once
// Topological defects of a nematic director field on a periodic grid: the winding of
// the director around each plaquette of four neighbouring cells, with the nematic symmetry θ ≡
// θ + π (each step's difference taken in (−π/2, π/2]), gives charge 0, ±1/2 or ±1. The core is
// refined inside its plaquette towards the corners where the order S is lowest, and a +1/2
// defect gets its orientation: the direction of ∇·Q at the core, along the comet's axis from its
// rounded head towards its tail, where the director is radial.
#include <cstddef>
#include <span>
#include <vector>

#include "rodsea/analysis/coarse_grained_fields.hpp"

namespace rodsea {

struct NematicDefect {
    double x = 0.0, y = 0.0;   // mm, the refined core, in [0, L)
    double charge = 0.0;       // ±0.5 or ±1
    double orientation = 0.0;  // rad, +1/2 only (NaN for the others)
};

// The defects of the field Q = S (cos 2θ, sin 2θ) given as its components on `grid` (maps
// [j * nx + i]). Plaquettes with a cell of no weight (NaN) are skipped.
std::vector<NematicDefect> find_nematic_defects(const FieldGrid& grid, std::span<const double> qxx,
                                                std::span<const double> qxy);

}  // namespace rodsea
