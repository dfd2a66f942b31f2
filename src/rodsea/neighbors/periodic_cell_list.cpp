#include "rodsea/neighbors/periodic_cell_list.hpp"

#include <algorithm>
#include <stdexcept>

namespace rodsea {

namespace {

int cell_count(double side, double cutoff) {
    const int n = static_cast<int>(std::floor(side / cutoff));
    return n >= 3 ? n : 1;
}

constexpr auto wrap = PeriodicBox2D::wrap;

}  // namespace

void PeriodicCellList2D::build(std::span<const Vec3> points, const PeriodicBox2D& box,
                               double cutoff) {
    build(points, {}, {}, box, cutoff);
}

void PeriodicCellList2D::build(std::span<const Vec3> points, std::span<const double> radii,
                               std::span<const std::uint32_t> groups, const PeriodicBox2D& box,
                               double cutoff) {
    if (!(cutoff > 0.0) || !std::isfinite(cutoff) || !(box.lx > 0.0) || !(box.ly > 0.0))
        throw std::invalid_argument("PeriodicCellList2D: cutoff and box sides must be positive");
    if (radii.size() != groups.size() || (!radii.empty() && radii.size() != points.size()))
        throw std::invalid_argument("PeriodicCellList2D: radii and groups need one per point");
    if (!radii.empty() && 2.0 * *std::max_element(radii.begin(), radii.end()) > cutoff)
        throw std::invalid_argument("PeriodicCellList2D: a disc is wider than the cutoff");
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
    box_ = box;
    cutoff_ = cutoff;
    single_x_ = nx_ == 1;
    single_y_ = ny_ == 1;

    const size_t cells = static_cast<size_t>(nx_) * ny_;
    start_.assign(cells + 1, 0);
    cell_of_.resize(points.size());
    wrapped_.resize(points.size());
    const double to_cx = nx_ / box.lx, to_cy = ny_ / box.ly;
    for (size_t i = 0; i < points.size(); ++i) {
        wrapped_[i] = {wrap(points[i].x, box.lx), wrap(points[i].y, box.ly), points[i].z};
        const int cx = std::min(static_cast<int>(wrapped_[i].x * to_cx), nx_ - 1);
        const int cy = std::min(static_cast<int>(wrapped_[i].y * to_cy), ny_ - 1);
        const int c = cy * nx_ + cx;
        cell_of_[i] = static_cast<std::uint32_t>(c);
        ++start_[c + 1];
    }
    for (size_t c = 0; c < cells; ++c)
        start_[c + 1] += start_[c];
    order_.resize(points.size());
    sorted_.resize(points.size());
    sorted_radius_.resize(radii.size());
    sorted_group_.resize(groups.size());
    cursor_.assign(start_.begin(), start_.end() - 1);
    for (size_t i = 0; i < points.size(); ++i) {
        const std::uint32_t slot = cursor_[cell_of_[i]]++;
        order_[slot] = static_cast<std::uint32_t>(i);
        sorted_[slot] = wrapped_[i];
        if (!radii.empty()) {
            sorted_radius_[slot] = radii[i];
            sorted_group_[slot] = groups[i];
        }
    }
}

}  // namespace rodsea
