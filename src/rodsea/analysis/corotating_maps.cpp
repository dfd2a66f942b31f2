#include "rodsea/analysis/corotating_maps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rodsea/analysis/histogram_bins.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

CorotatingMaps::CorotatingMaps(const CorotatingParameters& p)
    : r_max_(p.r_max),
      nr_(static_cast<std::size_t>(p.r_bins)),
      nt_(static_cast<std::size_t>(p.theta_bins)) {
    require_positive("corotating.r_max", p.r_max, "mm");
    require_positive_count("corotating.r_bins", p.r_bins);
    require_positive_count("corotating.theta_bins", p.theta_bins);
    require_bins("corotating.theta_bins", std::to_string(p.theta_bins),
                 static_cast<double>(p.r_bins) * p.theta_bins,
                 "corotating.r_bins × corotating.theta_bins");
    for (std::size_t k = 0; k <= nr_; ++k)
        r_edges_.push_back(r_max_ * static_cast<double>(k) / static_cast<double>(nr_));
    for (std::size_t t = 0; t <= nt_; ++t)
        theta_edges_.push_back(-std::numbers::pi + 2.0 * std::numbers::pi * static_cast<double>(t) /
                                                       static_cast<double>(nt_));
    pairs_.assign(nr_ * nt_, 0.0);
    cos_sum_.assign(nr_ * nt_, 0.0);
}

void CorotatingMaps::compute(const PeriodicGrid2D& rods, std::span<const double> angles) {
    const double dr = r_max_ / static_cast<double>(nr_);
    const double dtheta = 2.0 * std::numbers::pi / static_cast<double>(nt_);
    for (std::uint32_t i = 0; i < rods.size(); ++i) {
        const double c = std::cos(angles[i]), s = std::sin(angles[i]);
        rods.for_each_within(rods.point(i), r_max_, [&](std::uint32_t j, const Vec3& d) {
            if (j == i) return;
            // The neighbour in the reference rod's frame: x' along its axis.
            const double xp = d.x * c + d.y * s, yp = -d.x * s + d.y * c;
            const auto k = std::min(nr_ - 1, static_cast<std::size_t>(std::hypot(xp, yp) / dr));
            const auto t = std::min(nt_ - 1, static_cast<std::size_t>(
                                                 (std::atan2(yp, xp) + std::numbers::pi) / dtheta));
            pairs_[k * nt_ + t] += 1.0;
            cos_sum_[k * nt_ + t] += std::cos(angles[j] - angles[i]);
        });
    }
    const auto n = static_cast<double>(rods.size());
    area_ = rods.box().lx * rods.box().ly;
    reference_pairs_ += n * (n - 1.0);
    partners_ += n > 0.0 ? (n - 1.0) / area_ : 0.0;
    ++frames_;
}

CorotatingMaps& CorotatingMaps::operator+=(const CorotatingMaps& other) {
    for (std::size_t b = 0; b < pairs_.size(); ++b) {
        pairs_[b] += other.pairs_[b];
        cos_sum_[b] += other.cos_sum_[b];
    }
    reference_pairs_ += other.reference_pairs_;
    partners_ += other.partners_;
    frames_ += other.frames_;
    if (other.area_ > 0.0) area_ = other.area_;
    return *this;
}

std::vector<double> CorotatingMaps::pair_density() const {
    std::vector<double> g(nr_ * nt_, std::nan(""));
    for (std::size_t k = 0; k < nr_; ++k) {
        const double bin_area = 0.5 *
                                (r_edges_[k + 1] * r_edges_[k + 1] - r_edges_[k] * r_edges_[k]) *
                                (theta_edges_[1] - theta_edges_[0]);
        const double ideal = area_ > 0.0 ? reference_pairs_ * bin_area / area_ : 0.0;
        for (std::size_t t = 0; t < nt_; ++t)
            if (ideal > 0.0) g[k * nt_ + t] = pairs_[k * nt_ + t] / ideal;
    }
    return g;
}

std::vector<double> CorotatingMaps::polar_correlation() const {
    std::vector<double> c(nr_ * nt_, std::nan(""));
    for (std::size_t b = 0; b < c.size(); ++b)
        if (pairs_[b] > 0.0) c[b] = cos_sum_[b] / pairs_[b];
    return c;
}

double CorotatingMaps::partner_density() const {
    return frames_ > 0 ? partners_ / static_cast<double>(frames_) : 0.0;
}

}  // namespace rodsea
