#include "rodsea/analysis/medium_velocity_observable.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/error.hpp"

namespace rodsea {

MediumVelocityObservable::MediumVelocityObservable(const AnalysisSetup& setup,
                                                   const AnalysisOptions& options)
    : setup_(setup),
      d_(options.medium_distance),
      r_max_(options.medium_r_max),
      bin_(options.medium_bin),
      bins_(static_cast<std::size_t>(std::ceil(options.medium_r_max / options.medium_bin))),
      sums_(bins_ * kColumns, 0.0) {}

void MediumVelocityObservable::compute(const FrameContext& context) {
    const AnalysisFrame& f = context.frame();
    const BodyGrid& medium = context.grid(BodyGroup::medium);
    // d on the outer edge of the profile (the default d = r_max) belongs to the last bin; a d
    // beyond the profile has no bin.
    const std::size_t d_bin =
        d_ <= r_max_ ? std::min(bins_ - 1, static_cast<std::size_t>(d_ / bin_)) : bins_;
    double at_d_pairs = 0.0, at_d_along = 0.0, at_d_speed = 0.0, at_d_relative = 0.0;
    // The pair loop visits ~10⁷ pairs per frame of the largest system: keep it to sums.
    std::vector<double> speed(f.size());
    for (std::uint32_t j : medium.members())
        speed[j] = std::sqrt(f.vx[j] * f.vx[j] + f.vy[j] * f.vy[j]);
    const double inverse_bin = 1.0 / bin_;
    for (std::uint32_t i : context.members(BodyGroup::polar)) {
        const double c = std::cos(f.theta[i]), s = std::sin(f.theta[i]);
        const double vix = f.vx[i], viy = f.vy[i];
        medium.for_each_within(f.x[i], f.y[i], r_max_, [&](std::uint32_t j, double dx, double dy) {
            const auto b = static_cast<std::size_t>(std::sqrt(dx * dx + dy * dy) * inverse_bin);
            if (b >= bins_) return;
            const double vx = f.vx[j], vy = f.vy[j];
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
                at_d_pairs += 1.0;
                at_d_along += along;
                at_d_speed += speed[j];
                at_d_relative += relative_speed;
            }
        });
    }
    if (at_d_pairs > 0.0) {
        along_at_d_.push_back(at_d_along / at_d_pairs);
        speed_at_d_.push_back(at_d_speed / at_d_pairs);
        relative_speed_at_d_.push_back(at_d_relative / at_d_pairs);
    }
}

ObservableResults MediumVelocityObservable::finish() {
    ObservableResults r;
    r.observable = name();
    r.parameters = {{"d", d_, "mm"}, {"r_max", r_max_, "mm"}, {"bin", bin_, "mm"}};
    TableResult t{
        "medium_velocity",
        "medium velocity around polar rods vs distance: along/across the rod's axis "
        "(lab frame), speed, and relative to the rod (comoving frame)",
        {"r", "pairs", "v_along", "v_across", "speed", "relative_v_along", "relative_speed"},
        {"mm", "", "mm/s", "mm/s", "mm/s", "mm/s", "mm/s"},
        {}};
    for (std::size_t b = 0; b < bins_; ++b) {
        const double* row = &sums_[b * kColumns];
        std::vector<double> out{(static_cast<double>(b) + 0.5) * bin_, row[kPairs]};
        for (int c = kAlong; c < kColumns; ++c)
            out.push_back(row[kPairs] > 0 ? row[c] / row[kPairs] : std::nan(""));
        t.rows.push_back(std::move(out));
    }
    r.tables.push_back(std::move(t));
    if (along_at_d_.empty()) {
        r.notes.push_back("no medium body at d = " + format_number(d_) + " mm from a polar rod " +
                          "(d must be below medium_velocity.r_max = " + format_number(r_max_) +
                          " mm, at most half the box); the profile is still written");
        return r;
    }
    const std::string at = " at d = " + format_number(d_) + " mm from a polar rod (bin of " +
                           format_number(bin_) + " mm), steady mean";
    r.scalars.push_back({"medium_v_along_at_d", "mm/s",
                         "medium velocity along the polar rod's axis" + at,
                         estimate_mean(along_at_d_)});
    r.scalars.push_back({"medium_speed_at_d", "mm/s",
                         "medium speed relative to the polar rod (its comoving frame)" + at,
                         estimate_mean(relative_speed_at_d_)});
    r.scalars.push_back({"medium_lab_speed_at_d", "mm/s", "medium speed in the lab frame" + at,
                         estimate_mean(speed_at_d_)});
    return r;
}

}  // namespace rodsea
