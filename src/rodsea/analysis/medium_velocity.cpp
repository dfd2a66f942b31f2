#include "rodsea/analysis/medium_velocity.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/analysis/histogram_bins.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

namespace {

// Checked before the bins are allocated from them.
const MediumVelocityParameters& checked(const MediumVelocityParameters& p) {
    require_positive("medium_velocity.bin", p.bin, "mm");
    require_positive("medium_velocity.r_max", p.r_max, "mm");
    require_bins("medium_velocity.bin", format_number(p.bin) + " mm", p.r_max / p.bin,
                 "medium_velocity.r_max / medium_velocity.bin");
    if (!std::isfinite(p.d))
        throw InvalidParameter("medium_velocity.d", format_number(p.d) + " mm",
                               "a finite distance");
    return p;
}

}  // namespace

MediumVelocity::MediumVelocity(const MediumVelocityParameters& p)
    : p_(checked(p)),
      bins_(static_cast<std::size_t>(std::ceil(p.r_max / p.bin))),
      sums_(bins_ * kColumns) {}

MediumAtDistance MediumVelocity::compute(const PeriodicGrid2D& medium,
                                         std::span<const Vec3> medium_velocity,
                                         std::span<const Vec3> rods,
                                         std::span<const double> rod_angle,
                                         std::span<const Vec3> rod_velocity) {
    // d on the outer edge of the profile (the default d = r_max) belongs to the last bin; a d
    // beyond the profile has no bin.
    const std::size_t d_bin =
        p_.d <= p_.r_max ? std::min(bins_ - 1, static_cast<std::size_t>(p_.d / p_.bin)) : bins_;
    MediumAtDistance at_d;
    // The pair loop visits ~10⁷ pairs per frame of the largest system: keep it to sums.
    std::vector<double> speed(medium_velocity.size());
    for (std::size_t j = 0; j < speed.size(); ++j)
        speed[j] = std::sqrt(medium_velocity[j].x * medium_velocity[j].x +
                             medium_velocity[j].y * medium_velocity[j].y);
    const double inverse_bin = 1.0 / p_.bin;
    for (std::size_t i = 0; i < rods.size(); ++i) {
        const double c = std::cos(rod_angle[i]), s = std::sin(rod_angle[i]);
        const double vix = rod_velocity[i].x, viy = rod_velocity[i].y;
        medium.for_each_within(rods[i], p_.r_max, [&](std::uint32_t j, const Vec3& d) {
            const auto b = static_cast<std::size_t>(std::sqrt(d.x * d.x + d.y * d.y) * inverse_bin);
            if (b >= bins_) return;
            const double vx = medium_velocity[j].x, vy = medium_velocity[j].y;
            const double along = vx * c + vy * s, across = -vx * s + vy * c;
            const double rx = vx - vix, ry = vy - viy;
            double* row = &sums_[b * kColumns];
            row[kPairs] += 1.0;
            row[kAlong] += along;
            row[kAcross] += across;
            row[kSpeed] += speed[j];
            const double relative_speed = std::sqrt(rx * rx + ry * ry);
            row[kRelativeAlong] += rx * c + ry * s;
            row[kRelativeSpeed] += relative_speed;
            if (b == d_bin) {
                at_d.pairs += 1.0;
                at_d.along += along;
                at_d.speed += speed[j];
                at_d.relative_speed += relative_speed;
            }
        });
    }
    if (at_d.pairs > 0.0) {
        at_d.along /= at_d.pairs;
        at_d.speed /= at_d.pairs;
        at_d.relative_speed /= at_d.pairs;
    }
    return at_d;
}

std::vector<double> MediumVelocity::bin_centres() const {
    std::vector<double> r(bins_);
    for (std::size_t b = 0; b < bins_; ++b)
        r[b] = (static_cast<double>(b) + 0.5) * p_.bin;
    return r;
}

std::vector<double> MediumVelocity::mean_of(Column c) const {
    std::vector<double> v(bins_);
    for (std::size_t b = 0; b < bins_; ++b) {
        const double* row = &sums_[b * kColumns];
        v[b] = c == kPairs ? row[kPairs] : (row[kPairs] > 0 ? row[c] / row[kPairs] : std::nan(""));
    }
    return v;
}

std::vector<double> MediumVelocity::pairs() const {
    return mean_of(kPairs);
}
std::vector<double> MediumVelocity::along() const {
    return mean_of(kAlong);
}
std::vector<double> MediumVelocity::across() const {
    return mean_of(kAcross);
}
std::vector<double> MediumVelocity::speed() const {
    return mean_of(kSpeed);
}
std::vector<double> MediumVelocity::relative_along() const {
    return mean_of(kRelativeAlong);
}
std::vector<double> MediumVelocity::relative_speed() const {
    return mean_of(kRelativeSpeed);
}

}  // namespace rodsea
