#include "rodsea/analysis/pair_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rodsea/analysis/histogram_bins.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

PairCorrelation::PairCorrelation(const PairCorrelationParameters& p) : bin_(p.bin) {
    require_positive("pair.bin", p.bin, "mm");
    require_positive("pair.r_max", p.r_max, "mm");
    require_bins("pair.bin", format_number(p.bin) + " mm", p.r_max / p.bin,
                 "pair.r_max / pair.bin");
    bins_ = static_cast<std::size_t>(std::ceil(p.r_max / p.bin));
    pairs_.assign(bins_, 0.0);
    cos1_.assign(bins_, 0.0);
    cos2_.assign(bins_, 0.0);
}

void PairCorrelation::compute(const PeriodicGrid2D& points, std::span<const double> angles) {
    const PeriodicBox2D& box = points.box();
    // The last bin may reach past the allowed radius by less than one bin: keep it inside L/2.
    const double half = 0.5 * std::min(box.lx, box.ly);
    while (r_max() > half && bins_ > 1) {
        --bins_;
        pairs_.pop_back(), cos1_.pop_back(), cos2_.pop_back();
    }
    ++frames_;
    area_ = box.lx * box.ly;
    const double n = static_cast<double>(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        const Vec3 p = points.point(i);
        const double ti = angles[i];
        points.for_each_within(p, r_max(), [&](std::uint32_t j, const Vec3& d) {
            if (j == i) return;
            const auto b = static_cast<std::size_t>(std::sqrt(d.x * d.x + d.y * d.y) / bin_);
            if (b >= bins_) return;
            const double a = ti - angles[j];
            pairs_[b] += 1.0;
            cos1_[b] += std::cos(a);
            cos2_[b] += std::cos(2.0 * a);
        });
    }
    reference_pairs_ += n * (n - 1.0);
}

PairCorrelation& PairCorrelation::operator+=(const PairCorrelation& other) {
    if (other.frames_ == 0) return *this;
    if (frames_ == 0) return *this = other;
    // The blocks of one run share its box, so its bins and area; min() only keeps a mismatch
    // from reading past the shorter.
    bins_ = std::min(bins_, other.bins_);
    pairs_.resize(bins_), cos1_.resize(bins_), cos2_.resize(bins_);
    for (std::size_t b = 0; b < bins_; ++b) {
        pairs_[b] += other.pairs_[b];
        cos1_[b] += other.cos1_[b];
        cos2_[b] += other.cos2_[b];
    }
    reference_pairs_ += other.reference_pairs_;
    frames_ += other.frames_;
    area_ = other.area_;
    return *this;
}

std::vector<double> PairCorrelation::bin_centres() const {
    std::vector<double> r(bins_);
    for (std::size_t b = 0; b < bins_; ++b)
        r[b] = (static_cast<double>(b) + 0.5) * bin_;
    return r;
}

std::vector<double> PairCorrelation::pair_density() const {
    std::vector<double> g(bins_, std::nan(""));
    for (std::size_t b = 0; b < bins_; ++b) {
        const double r0 = static_cast<double>(b) * bin_, r1 = r0 + bin_;
        const double shell = std::numbers::pi * (r1 * r1 - r0 * r0);
        // Ideal gas: each of the N(N−1) ordered pairs lands in the shell with probability shell/A.
        const double ideal = reference_pairs_ * shell / area_;
        if (ideal > 0.0) g[b] = pairs_[b] / ideal;
    }
    return g;
}

std::vector<double> PairCorrelation::polar_correlation() const {
    std::vector<double> c(bins_, std::nan(""));
    for (std::size_t b = 0; b < bins_; ++b)
        if (pairs_[b] > 0.0) c[b] = cos1_[b] / pairs_[b];
    return c;
}

std::vector<double> PairCorrelation::nematic_correlation() const {
    std::vector<double> c(bins_, std::nan(""));
    for (std::size_t b = 0; b < bins_; ++b)
        if (pairs_[b] > 0.0) c[b] = cos2_[b] / pairs_[b];
    return c;
}

}  // namespace rodsea
