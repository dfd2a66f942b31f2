#pragma once
// The one neighbour layer of rodsea (freud's NeighborQuery): points binned into the cells of a
// grid periodic in x and y (z is ignored: the system is a monolayer), with two traversals that
// serve the engine's Verlet list, DBSCAN and every observable:
//   for_each_pair_within(cutoff, visit)    each unordered pair closer than the cutoff once;
//   for_each_within(q, radius, visit)      every point closer than any radius ≤ L/2 to q.
// Points are copied into cell order on build, so both loops read contiguous memory, and the
// periodic image of a neighbour cell is a fixed shift per cell pair, not a rounding per point
// pair. order()[s] is the point in slot s: neighbours in space are neighbours in memory.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

class PeriodicGrid2D {
  public:
    // Bins the points (wrapped into the box; they may lie outside it) into cells at least
    // `cell` wide; a direction with fewer than three such cells uses a single cell. Throws
    // std::invalid_argument for a cell or box side that is not positive and finite.
    void build(std::span<const Vec3> points, const PeriodicBox2D& box, double cell);

    const PeriodicBox2D& box() const { return box_; }
    std::size_t size() const { return order_.size(); }
    double cell_width() const { return std::min(wx_, wy_); }             // mm, the narrower side
    std::span<const std::uint32_t> order() const { return order_; }      // point of each slot
    std::span<const std::uint32_t> slot_of() const { return slot_of_; }  // slot of each point
    Vec3 point(std::uint32_t i) const { return sorted_[slot_of_[i]]; }   // wrapped into the box

    // visit(i, j, d) once per unordered pair i != j with d = p_i − p_j (minimum image in x, y;
    // z as given) and d.x² + d.y² < cutoff². The cutoff may not exceed cell_width(). Throws
    // std::invalid_argument when it does.
    template <class Visit>
    void for_each_pair_within(double cutoff, Visit&& visit) const;

    // The cell pairs behind that loop, for a caller with its own loop over their points:
    // visit(a_begin, a_end, b_begin, b_end, sx, sy, same) for each occupied cell c of the rows
    // [row_begin, row_end) (rows along y, 0 .. rows()), first with itself (same: take the slot
    // pairs a < b), then with each occupied neighbour of the half stencil; (sx, sy) (mm) brings
    // the neighbour's image next to c. Along an axis of a single cell there is no shift: the
    // minimum image is taken per pair there (single_cell_x(), single_cell_y()). Slots index
    // slot_points() and order(). The pairs of disjoint row ranges are disjoint, and all the
    // rows give every pair once, so that threads can split the rows between them.
    template <class VisitCells>
    void for_each_cell_pair(int row_begin, int row_end, VisitCells&& visit) const;
    int rows() const { return ny_; }
    bool single_cell_x() const { return nx_ == 1; }
    bool single_cell_y() const { return ny_ == 1; }
    std::span<const Vec3> slot_points() const { return sorted_; }  // wrapped, in slot order

    // visit(j, d) for every point j with d = p_j − q (minimum image in x, y; z as given) and
    // d.x² + d.y² < radius². The radius may not exceed half the shorter box side (the minimum
    // image must be unique; std::invalid_argument otherwise); each cell is visited at most once
    // per query.
    template <class Visit>
    void for_each_within(const Vec3& q, double radius, Visit&& visit) const;

  private:
    int cell_x(double x) const { return std::min(nx_ - 1, static_cast<int>(x * to_cx_)); }
    int cell_y(double y) const { return std::min(ny_ - 1, static_cast<int>(y * to_cy_)); }
    static void check_cutoff(double cutoff, double width);
    void check_radius(double radius) const;

    PeriodicBox2D box_;
    int nx_ = 1, ny_ = 1;
    double wx_ = 0.0, wy_ = 0.0;        // cell sides, mm
    double to_cx_ = 0.0, to_cy_ = 0.0;  // cells per mm
    bool stencil_built_ = false;
    std::vector<std::pair<int, int>> half_stencil_;  // neighbour offsets, each pair of cells once
    std::vector<std::uint32_t> start_;               // first slot of each cell
    std::vector<std::uint32_t> order_;               // original index of each slot
    std::vector<std::uint32_t> slot_of_;             // slot of each original index
    std::vector<Vec3> sorted_;                       // wrapped points in slot order
    std::vector<std::uint32_t> cursor_;              // scratch: next free slot per cell
};

template <class Visit>
void PeriodicGrid2D::for_each_pair_within(double cutoff, Visit&& visit) const {
    check_cutoff(cutoff, cell_width());
    const double c2 = cutoff * cutoff;
    const bool single_x = nx_ == 1, single_y = ny_ == 1;
    const auto cells = [&](std::uint32_t a_begin, std::uint32_t a_end, std::uint32_t b_begin,
                           std::uint32_t b_end, double sx, double sy, bool same) {
        for (std::uint32_t a = a_begin; a < a_end; ++a) {
            for (std::uint32_t b = same ? a + 1 : b_begin; b < b_end; ++b) {
                Vec3 d = sorted_[a] - sorted_[b];
                d.x += sx;
                d.y += sy;
                if (single_x) d.x -= box_.lx * std::nearbyint(d.x / box_.lx);
                if (single_y) d.y -= box_.ly * std::nearbyint(d.y / box_.ly);
                if (d.x * d.x + d.y * d.y < c2) visit(order_[a], order_[b], d);
            }
        }
    };
    for_each_cell_pair(0, ny_, cells);
}

template <class VisitCells>
void PeriodicGrid2D::for_each_cell_pair(int row_begin, int row_end, VisitCells&& visit) const {
    for (int cy = std::max(row_begin, 0); cy < std::min(row_end, ny_); ++cy) {
        for (int cx = 0; cx < nx_; ++cx) {
            const int c = cy * nx_ + cx;
            const std::uint32_t begin = start_[c], end = start_[c + 1];
            if (begin == end) continue;  // sparse systems: most cells are empty
            visit(begin, end, begin, end, 0.0, 0.0, true);
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
                if (start_[nc] != start_[nc + 1])
                    visit(begin, end, start_[nc], start_[nc + 1], sx, sy, false);
            }
        }
    }
}

template <class Visit>
void PeriodicGrid2D::for_each_within(const Vec3& q, double radius, Visit&& visit) const {
    check_radius(radius);
    const double px = PeriodicBox2D::wrap(q.x, box_.lx), py = PeriodicBox2D::wrap(q.y, box_.ly);
    const int cx = cell_x(px), cy = cell_y(py);
    // A point in cell c is at most one cell width from its cell's edge, so points within
    // `radius` lie at most floor(radius / w) + 1 cells away.
    const int kx = static_cast<int>(radius / wx_) + 1, ky = static_cast<int>(radius / wy_) + 1;
    const bool all_x = 2 * kx + 1 >= nx_, all_y = 2 * ky + 1 >= ny_;
    const int x0 = all_x ? 0 : cx - kx, x1 = all_x ? nx_ - 1 : cx + kx;
    const int y0 = all_y ? 0 : cy - ky, y1 = all_y ? ny_ - 1 : cy + ky;
    const double r2 = radius * radius;
    for (int gy = y0; gy <= y1; ++gy) {
        const int wy = (gy % ny_ + ny_) % ny_;
        // A stencil that stays within one image needs no per-candidate minimum image: the
        // cell's shift to the image next to the query point is known.
        const double shift_y = all_y ? 0.0 : box_.ly * static_cast<double>((gy - wy) / ny_);
        for (int gx = x0; gx <= x1; ++gx) {
            const int wx = (gx % nx_ + nx_) % nx_;
            const double shift_x = all_x ? 0.0 : box_.lx * static_cast<double>((gx - wx) / nx_);
            const int c = wy * nx_ + wx;
            for (std::uint32_t s = start_[c]; s < start_[c + 1]; ++s) {
                Vec3 d{sorted_[s].x + shift_x - px, sorted_[s].y + shift_y - py,
                       sorted_[s].z - q.z};
                if (all_x) d.x -= box_.lx * std::nearbyint(d.x / box_.lx);
                if (all_y) d.y -= box_.ly * std::nearbyint(d.y / box_.ly);
                if (d.x * d.x + d.y * d.y < r2) visit(order_[s], d);
            }
        }
    }
}

}  // namespace rodsea
