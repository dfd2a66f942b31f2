#include "rodsea/neighbors/periodic_grid.hpp"

#include <stdexcept>
#include <string>

namespace rodsea {

namespace {

int cell_count(double side, double cell) {
    const double n = std::floor(side / cell);
    // Fewer than three cells would make a cell its own neighbour's neighbour twice; a billion
    // cells of a tiny cutoff would not fit in memory: both get a coarser grid.
    if (n < 3.0) return 1;
    return static_cast<int>(std::min(n, 1e4));
}

}  // namespace

void PeriodicGrid2D::check_cutoff(double cutoff, double width) {
    if (!(cutoff > 0.0) || cutoff > width * (1.0 + 1e-12))
        throw std::invalid_argument("PeriodicGrid2D: a pair cutoff of " + std::to_string(cutoff) +
                                    " mm needs cells at least that wide (they are " +
                                    std::to_string(width) + " mm)");
}

void PeriodicGrid2D::check_radius(double radius) const {
    if (!(radius >= 0.0) || radius > 0.5 * std::min(box_.lx, box_.ly))
        throw std::invalid_argument("PeriodicGrid2D: a query radius of " + std::to_string(radius) +
                                    " mm exceeds half the box");
}

void PeriodicGrid2D::build(std::span<const Vec3> points, const PeriodicBox2D& box, double cell) {
    if (!(cell > 0.0) || !std::isfinite(cell) || !(box.lx > 0.0) || !(box.ly > 0.0) ||
        !std::isfinite(box.lx) || !std::isfinite(box.ly))
        throw std::invalid_argument("PeriodicGrid2D: the cell and box sides must be positive");
    const int nx = cell_count(box.lx, cell), ny = cell_count(box.ly, cell);
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
    box_ = box;
    wx_ = box.lx / nx_;
    wy_ = box.ly / ny_;
    to_cx_ = nx_ / box.lx;
    to_cy_ = ny_ / box.ly;

    const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    start_.assign(cells + 1, 0);
    slot_of_.resize(points.size());  // the cell of each point, until the slots are known
    sorted_.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 w{PeriodicBox2D::wrap(points[i].x, box.lx),
                     PeriodicBox2D::wrap(points[i].y, box.ly), points[i].z};
        const auto c = static_cast<std::uint32_t>(cell_y(w.y) * nx_ + cell_x(w.x));
        slot_of_[i] = c;
        ++start_[c + 1];
    }
    for (std::size_t c = 0; c < cells; ++c)
        start_[c + 1] += start_[c];
    order_.resize(points.size());
    cursor_.assign(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::uint32_t slot = cursor_[slot_of_[i]]++;
        order_[slot] = static_cast<std::uint32_t>(i);
        slot_of_[i] = slot;
        sorted_[slot] = {PeriodicBox2D::wrap(points[i].x, box.lx),
                         PeriodicBox2D::wrap(points[i].y, box.ly), points[i].z};
    }
}

}  // namespace rodsea
