#include "rodsea/neighbors/periodic_cell_list.hpp"

#include <algorithm>

namespace rodsea {

namespace {

int cell_count(double side, double cutoff) {
    const int n = static_cast<int>(std::floor(side / cutoff));
    return n >= 3 ? n : 1;
}

int cell_index(double x, double side, int n) {
    const double wrapped = x - side * std::floor(x / side);
    return std::clamp(static_cast<int>(wrapped / side * n), 0, n - 1);
}

}  // namespace

void PeriodicCellList2D::build(std::span<const Vec3> points, const PeriodicBox2D& box,
                               double cutoff) {
    const int nx = cell_count(box.lx, cutoff), ny = cell_count(box.ly, cutoff);
    if (nx != nx_ || ny != ny_ || !stencil_built_) {
        stencil_built_ = true;
        nx_ = nx;
        ny_ = ny;
        half_stencil_.clear();
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                if ((nx_ == 1 && dx != 0) || (ny_ == 1 && dy != 0)) continue;
                if (dy > 0 || (dy == 0 && dx > 0)) half_stencil_.emplace_back(dx, dy);
            }
        }
    }
    const size_t cells = static_cast<size_t>(nx_) * ny_;
    start_.assign(cells + 1, 0);
    cell_of_.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const int c = cell_index(points[i].y, box.ly, ny_) * nx_ +
                      cell_index(points[i].x, box.lx, nx_);
        cell_of_[i] = static_cast<std::uint32_t>(c);
        ++start_[c + 1];
    }
    for (size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    order_.resize(points.size());
    cursor_.assign(start_.begin(), start_.end() - 1);
    for (size_t i = 0; i < points.size(); ++i)
        order_[cursor_[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
}

}  // namespace rodsea
