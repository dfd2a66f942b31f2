#pragma once
// Continuum fields of one frame on a periodic grid (the End Matter's fields): the area
// fraction of a group of bodies, its polarisation p = ⟨(cos θ, sin θ)⟩, its nematic tensor
// Q = ⟨(cos 2θ, sin 2θ)⟩ (S = |Q|, director ½ arg Q) and its velocity. Each body is spread over
// the four cells nearest its centre with cloud-in-cell (bilinear) weights that sum to 1, so totals
// are conserved exactly: Σ_cells φ A_cell = Σ_bodies A_body, and the grid sums of the weighted
// numerators are the bodies' sums.
#include <cstddef>
#include <span>
#include <vector>

#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

// An nx × ny grid of square-ish cells tiling the box: cells of at least `cell` mm... exactly
// L / n wide, n = max(1, floor(L / cell)).
struct FieldGrid {
    int nx = 1, ny = 1;
    double dx = 0.0, dy = 0.0;  // mm
    static FieldGrid of(const PeriodicBox2D& box, double cell);
    std::size_t cells() const {
        return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
    }
    std::size_t index(int i, int j) const {  // periodic in both
        const int a = ((i % nx) + nx) % nx, b = ((j % ny) + ny) % ny;
        return static_cast<std::size_t>(b) * static_cast<std::size_t>(nx) +
               static_cast<std::size_t>(a);
    }
};

// The fields of one group of bodies; each map is [j * nx + i] (row j along y). Where a cell
// holds no weight, p, Q and v are NaN.
struct GroupFields {
    std::vector<double> weight;         // Σ of the bodies' cloud-in-cell weights (bodies per cell)
    std::vector<double> area_fraction;  // Σ w A_body / A_cell
    std::vector<double> px, py;         // polarisation, weighted mean of (cos θ, sin θ)
    std::vector<double> qxx, qxy;       // nematic tensor, weighted mean of (cos 2θ, sin 2θ)
    std::vector<double> vx, vy;         // weighted mean in-plane velocity, mm/s
    double S(std::size_t c) const;      // |Q|
    double director(std::size_t c) const;  // ½ arg Q, rad, in (−π/2, π/2]
};

// Bodies' centres (mm), in-plane angles (rad), velocities (mm/s; may be empty: v is then NaN)
// and projected area (mm², one value for the group).
GroupFields coarse_grain(const FieldGrid& grid, const PeriodicBox2D& box,
                         std::span<const Vec3> centres, std::span<const double> angles,
                         std::span<const Vec3> velocities, double body_area);

}  // namespace rodsea
