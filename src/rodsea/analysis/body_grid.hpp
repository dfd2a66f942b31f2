#pragma once
// The analysis' neighbour layer: bodies of one group binned into square periodic cells, queried
// for every member within any radius up to half the box. Unlike the engine's cell list (fixed
// cutoff, each pair once), observables need ordered pairs (reference rod → neighbour), radii from
// a few mm (flocks) to 100 mm (medium flow), and queries from one group into another (polar rods
// → medium). Each cell is visited at most once per query, and the minimum image is taken per
// candidate, so radii whose stencil wraps around the box are still exact.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "rodsea/analysis/analysis_frame.hpp"

namespace rodsea {

class BodyGrid {
  public:
    // Bins `members` (indices into the frame) into cells at least `cell_side` wide.
    void build(const AnalysisFrame& frame, std::vector<std::uint32_t> members, double cell_side);

    const std::vector<std::uint32_t>& members() const { return members_; }

    // visit(j, dx, dy) for every member j with (dx, dy) = p_j − (px, py) (minimum image) and
    // dx² + dy² < radius². Requires radius ≤ half the shorter box side (unique minimum image).
    template <class Visit>
    void for_each_within(double px, double py, double radius, Visit&& visit) const {
        const int cx = cell_index(px, box_.lx, nx_), cy = cell_index(py, box_.ly, ny_);
        // A point in cell c is at most one cell width from its cell's edge, so members within
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
                    double dx = sx_[s] + shift_x - px, dy = sy_[s] + shift_y - py;
                    if (all_x) dx -= box_.lx * std::nearbyint(dx / box_.lx);
                    if (all_y) dy -= box_.ly * std::nearbyint(dy / box_.ly);
                    if (dx * dx + dy * dy < r2) visit(slot_body_[s], dx, dy);
                }
            }
        }
    }

  private:
    static int cell_index(double v, double side, int n) {
        return std::min(n - 1, static_cast<int>(v / side * n));
    }

    PeriodicBox2D box_;
    int nx_ = 1, ny_ = 1;
    double wx_ = 0.0, wy_ = 0.0;
    std::vector<std::uint32_t> members_;
    std::vector<std::uint32_t> start_;      // first slot of each cell
    std::vector<std::uint32_t> slot_body_;  // frame index of each slot
    std::vector<double> sx_, sy_;           // positions in slot order (contiguous per cell)
};

}  // namespace rodsea
