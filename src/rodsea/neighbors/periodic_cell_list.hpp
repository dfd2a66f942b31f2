#pragma once
// The one neighbour layer of rodsea: a cell list over points in a box periodic in x and y
// (z is ignored for binning: the system is a monolayer, so cells in the plane are enough).
// for_each_pair_within visits every unordered pair closer in the plane than the cutoff exactly
// once, with its minimum-image separation. Used by the engine's contact finder and by analysis.
//
// Points are copied into cell order on build, so the pair loops read contiguous memory, and
// the periodic images of a neighbour cell are a fixed shift per cell pair, not a rounding per
// point pair.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

class PeriodicCellList2D {
  public:
    // Bins the points with cells at least `cutoff` wide; a direction with fewer than three such
    // cells uses a single cell, so that no neighbour cell is visited twice.
    void build(std::span<const Vec3> points, const PeriodicBox2D& box, double cutoff);

    // Same, for discs: a pair is close when its discs overlap in the plane (distance <
    // r_i + r_j, each 2 r ≤ cutoff), and pairs with the same group (e.g. spheres of one rigid
    // body) are never visited. Both tests run on the cell-ordered copies, before any visit.
    // Throws std::invalid_argument for a cutoff that is not positive and finite, radii and
    // groups not one per point, or a disc wider than the cutoff.
    void build(std::span<const Vec3> points, std::span<const double> radii,
               std::span<const std::uint32_t> groups, const PeriodicBox2D& box, double cutoff);

    // visit(i, j, d): i != j index the points given to build, d = p_i − p_j (minimum image in
    // x, y), d.x² + d.y² < cutoff² (points) or < (r_i + r_j)² (discs).
    template <class Visit>
    void for_each_pair_within(Visit&& visit) const {
        const double c2 = cutoff_ * cutoff_;
        const bool discs = !sorted_radius_.empty();
        const auto consider = [&](std::uint32_t a, std::uint32_t b, double sx, double sy) {
            if (discs && sorted_group_[a] == sorted_group_[b]) return;
            Vec3 d = sorted_[a] - sorted_[b];
            d.x += sx;
            d.y += sy;
            if (single_x_) d.x -= box_.lx * std::nearbyint(d.x / box_.lx);
            if (single_y_) d.y -= box_.ly * std::nearbyint(d.y / box_.ly);
            const double reach = discs ? sorted_radius_[a] + sorted_radius_[b] : 0.0;
            if (d.x * d.x + d.y * d.y < (discs ? reach * reach : c2))
                visit(order_[a], order_[b], d);
        };
        for (int cy = 0; cy < ny_; ++cy) {
            for (int cx = 0; cx < nx_; ++cx) {
                const int c = cy * nx_ + cx;
                const std::uint32_t begin = start_[c], end = start_[c + 1];
                if (begin == end) continue;  // sparse systems: most cells are empty
                for (std::uint32_t a = begin; a < end; ++a)
                    for (std::uint32_t b = a + 1; b < end; ++b)
                        consider(a, b, 0.0, 0.0);
                for (const auto& [dx, dy] : half_stencil_) {
                    int ncx = cx + dx, ncy = cy + dy;
                    double sx = 0.0, sy = 0.0;  // brings the neighbour's image next to cell c
                    if (ncx < 0)
                        ncx += nx_, sx = box_.lx;
                    else if (ncx >= nx_)
                        ncx -= nx_, sx = -box_.lx;
                    if (ncy < 0)
                        ncy += ny_, sy = box_.ly;
                    else if (ncy >= ny_)
                        ncy -= ny_, sy = -box_.ly;
                    const int nc = ncy * nx_ + ncx;
                    const std::uint32_t nbegin = start_[nc], nend = start_[nc + 1];
                    for (std::uint32_t a = begin; a < end; ++a)
                        for (std::uint32_t b = nbegin; b < nend; ++b)
                            consider(a, b, sx, sy);
                }
            }
        }
    }

  private:
    PeriodicBox2D box_;
    double cutoff_ = 0.0;
    int nx_ = 1, ny_ = 1;
    bool single_x_ = true, single_y_ = true;
    bool stencil_built_ = false;
    std::vector<std::pair<int, int>> half_stencil_;  // neighbour offsets, each pair of cells once
    std::vector<std::uint32_t> start_;               // first slot of each cell
    std::vector<std::uint32_t> order_;               // original index of each slot
    std::vector<Vec3> sorted_;                       // wrapped points in slot order
    std::vector<double> sorted_radius_;              // discs only, slot order
    std::vector<std::uint32_t> sorted_group_;        // discs only, slot order
    std::vector<std::uint32_t> cell_of_;             // scratch: cell of each point
    std::vector<Vec3> wrapped_;                      // scratch: points wrapped into the box
    std::vector<std::uint32_t> cursor_;              // scratch: next free slot per cell
};

}  // namespace rodsea
