#include "rodsea/neighbors/verlet_pair_list.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rodsea {

VerletPairList::VerletPairList(double skin) : skin_(skin) {
    if (!(skin > 0.0) || !std::isfinite(skin))
        throw std::invalid_argument("VerletPairList: the skin must be positive and finite");
}

bool VerletPairList::update(std::span<const Vec3> points, std::span<const double> radii,
                            std::span<const std::uint32_t> groups, const PeriodicBox2D& box,
                            double travel) {
    const bool changed = builds_ == 0 || points.size() != reference_.size() || box.lx != box_.lx ||
                         box.ly != box_.ly;
    if (!changed) {
        slack_ += travel;
        if (slack_ <= 0.5 * skin_) return false;
        slack_ = largest_move(points);  // the bound ran out: measure
        if (slack_ <= 0.5 * skin_) return false;
    }
    rebuild(points, radii, groups, box);
    slack_ = 0.0;
    return true;
}

double VerletPairList::largest_move(std::span<const Vec3> points) const {
    double largest2 = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec3 d = minimum_image(points[i] - reference_[i]);
        largest2 = std::max(largest2, d.x * d.x + d.y * d.y);
    }
    return std::sqrt(largest2);
}

void VerletPairList::rebuild(std::span<const Vec3> points, std::span<const double> radii,
                             std::span<const std::uint32_t> groups, const PeriodicBox2D& box) {
    box_ = box;
    half_x_ = 0.5 * box.lx;
    half_y_ = 0.5 * box.ly;
    if (radii.size() != points.size() || groups.size() != points.size())
        throw std::invalid_argument("VerletPairList: radii and groups need one per point");
    // Discs grown by skin / 2 each overlap when their centres are closer than r_i + r_j + skin;
    // no pair is farther apart than the widest such disc.
    const double half_skin = 0.5 * skin_;
    double widest = 0.0;
    for (const double r : radii)
        widest = std::max(widest, 2.0 * (r + half_skin));
    keys_.clear();
    if (!points.empty()) {
        grid_.build(points, box, widest);
        grid_.for_each_pair_within(widest, [&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
            if (groups[i] == groups[j]) return;  // spheres of one rigid body never meet
            const double reach = (radii[i] + half_skin) + (radii[j] + half_skin);
            if (d.x * d.x + d.y * d.y >= reach * reach) return;
            const auto lo = std::min(i, j), hi = std::max(i, j);
            keys_.push_back(static_cast<std::uint64_t>(lo) << 32 | hi);
        });
    }
    std::sort(keys_.begin(), keys_.end());
    first_.resize(keys_.size());
    second_.resize(keys_.size());
    for (size_t k = 0; k < keys_.size(); ++k) {
        first_[k] = static_cast<std::uint32_t>(keys_[k] >> 32);
        second_[k] = static_cast<std::uint32_t>(keys_[k] & 0xffffffffu);
    }
    reference_.assign(points.begin(), points.end());
    ++builds_;
}

}  // namespace rodsea
