#pragma once
// The one neighbour layer of rodsea: a cell list over points in a box periodic in x and y
// (z is ignored: the system is a monolayer, so binning in the plane is enough). Every unordered
// pair of points closer in the plane than `cutoff` is visited exactly once by
// for_each_candidate_pair, together with some farther pairs that the caller filters.
// Used by the engine's contact finder and by analysis.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "rodsea/math/vec3.hpp"

namespace rodsea {

struct PeriodicBox2D {
    double lx = 0.0, ly = 0.0;

    // Minimum-image difference a − b in x and y; z untouched.
    Vec3 minimum_image(Vec3 d) const {
        d.x -= lx * std::nearbyint(d.x / lx);
        d.y -= ly * std::nearbyint(d.y / ly);
        return d;
    }
};

class PeriodicCellList2D {
public:
    // Bins the points. Cells are at least `cutoff` wide; a direction with fewer than three
    // such cells uses a single cell so that no neighbour cell is visited twice.
    void build(std::span<const Vec3> points, const PeriodicBox2D& box, double cutoff);

    template <class Visit>  // visit(i, j) with i != j, indices into the points given to build
    void for_each_candidate_pair(Visit&& visit) const {
        for (int cy = 0; cy < ny_; ++cy) {
            for (int cx = 0; cx < nx_; ++cx) {
                const int c = cy * nx_ + cx;
                const std::uint32_t* begin = order_.data() + start_[c];
                const std::uint32_t* end = order_.data() + start_[c + 1];
                if (begin == end) continue;  // sparse systems: most cells are empty
                for (const std::uint32_t* p = begin; p != end; ++p)
                    for (const std::uint32_t* q = p + 1; q != end; ++q) visit(*p, *q);
                for (const auto& [dx, dy] : half_stencil_) {
                    const int nc = wrap(cy + dy, ny_) * nx_ + wrap(cx + dx, nx_);
                    const std::uint32_t* nb = order_.data() + start_[nc];
                    const std::uint32_t* ne = order_.data() + start_[nc + 1];
                    for (const std::uint32_t* p = begin; p != end; ++p)
                        for (const std::uint32_t* q = nb; q != ne; ++q) visit(*p, *q);
                }
            }
        }
    }

    int cells_x() const { return nx_; }
    int cells_y() const { return ny_; }

private:
    static int wrap(int i, int n) { return i < 0 ? i + n : (i >= n ? i - n : i); }

    int nx_ = 1, ny_ = 1;
    bool stencil_built_ = false;
    std::vector<std::pair<int, int>> half_stencil_;  // neighbour offsets, each pair of cells once
    std::vector<std::uint32_t> start_;               // first index into order_ of each cell
    std::vector<std::uint32_t> order_;               // point indices sorted by cell
    std::vector<std::uint32_t> cell_of_;             // scratch: cell of each point
    std::vector<std::uint32_t> cursor_;              // scratch: next free slot per cell
};

}  // namespace rodsea
