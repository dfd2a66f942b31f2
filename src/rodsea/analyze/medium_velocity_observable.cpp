#include "rodsea/analyze/medium_velocity_observable.hpp"

#include "rodsea/error.hpp"

namespace rodsea {

MediumVelocityObservable::MediumVelocityObservable(const AnalysisSetup& setup,
                                                   const AnalysisOptions& options)
    : parameters_{options.medium_distance, options.medium_r_max, options.medium_bin},
      profile_(parameters_),
      lag_(options.medium_lag),
      frame_interval_(setup.frame_interval) {}

std::vector<Vec3> MediumVelocityObservable::velocities(const PeriodicBox2D& box,
                                                       std::span<const Vec3> now,
                                                       const std::vector<Vec3>& then,
                                                       double seconds) {
    std::vector<Vec3> v(now.size());
    for (std::size_t i = 0; i < now.size(); ++i) {
        // A body moves far less than half the box between frames: the nearest image is its
        // own path.
        const Vec3 d = box.minimum_image(now[i] - then[i]);
        v[i] = {d.x / seconds, d.y / seconds, 0.0};
    }
    return v;
}

void MediumVelocityObservable::compute(const FrameContext& context) {
    const GroupArrays& medium = context.group(BodyGroup::medium);
    const GroupArrays& polar = context.group(BodyGroup::polar);
    MediumAtDistance at_d;
    if (lag_ == 0) {
        at_d = profile_.compute(medium.grid, medium.velocity, polar.position, polar.angle,
                                polar.velocity);
    } else {
        past_.push_back({context.frame().time, polar.position, medium.position});
        if (past_.size() <= static_cast<std::size_t>(lag_)) return;
        const Past& then = past_.front();
        const double seconds = context.frame().time - then.time;
        const PeriodicBox2D& box = context.frame().box;
        at_d = profile_.compute(medium.grid, velocities(box, medium.position, then.medium, seconds),
                                polar.position, polar.angle,
                                velocities(box, polar.position, then.polar, seconds));
        past_.pop_front();
    }
    ++measured_frames_;
    if (at_d.pairs > 0.0) {
        along_at_d_.push_back(at_d.along);
        speed_at_d_.push_back(at_d.speed);
        relative_speed_at_d_.push_back(at_d.relative_speed);
    }
}

ObservableResults MediumVelocityObservable::finish() {
    ObservableResults r;
    r.observable = name();
    const MediumVelocityParameters& p = parameters_;
    r.parameters = {{"d", p.d, "mm"},
                    {"r_max", p.r_max, "mm"},
                    {"bin", p.bin, "mm"},
                    {"lag", static_cast<double>(lag_), "frames"},
                    {"lag_time", static_cast<double>(lag_) * frame_interval_, "s"}};
    TableResult t{
        "medium_velocity",
        "medium velocity around polar rods vs distance: along/across the rod's axis "
        "(lab frame), speed, and relative to the rod (comoving frame)",
        {"r", "pairs", "v_along", "v_across", "speed", "relative_v_along", "relative_speed"},
        {"mm", "", "mm/s", "mm/s", "mm/s", "mm/s", "mm/s"},
        {}};
    const std::vector<std::vector<double>> columns{
        profile_.bin_centres(),   profile_.pairs(), profile_.along(),
        profile_.across(),        profile_.speed(), profile_.relative_along(),
        profile_.relative_speed()};
    for (std::size_t b = 0; b < columns[0].size(); ++b) {
        std::vector<double> row;
        for (const std::vector<double>& c : columns)
            row.push_back(c[b]);
        t.rows.push_back(std::move(row));
    }
    r.tables.push_back(std::move(t));
    if (lag_ > 0)
        r.notes.push_back("velocities from each body's displacement over " + std::to_string(lag_) +
                          " frames (" + format_number(static_cast<double>(lag_) * frame_interval_) +
                          " s), not the instantaneous ones");
    if (lag_ > 0 && measured_frames_ == 0) {
        r.notes.push_back("medium_velocity.lag = " + std::to_string(lag_) +
                          " frames needs more steady frames than that: nothing measured");
        return r;
    }
    if (along_at_d_.empty()) {
        r.notes.push_back("no medium body at d = " + format_number(p.d) + " mm from a polar rod " +
                          "(d must be below medium_velocity.r_max = " + format_number(p.r_max) +
                          " mm, at most half the box); the profile is still written");
        return r;
    }
    const std::string at = " at d = " + format_number(p.d) + " mm from a polar rod (bin of " +
                           format_number(p.bin) + " mm), steady mean";
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
