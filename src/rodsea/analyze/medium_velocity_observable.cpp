#include "rodsea/analyze/medium_velocity_observable.hpp"

#include "rodsea/error.hpp"

namespace rodsea {

MediumVelocityObservable::MediumVelocityObservable(const AnalysisSetup&,
                                                   const AnalysisOptions& options)
    : parameters_{options.medium_distance, options.medium_r_max, options.medium_bin},
      profile_(parameters_) {}

void MediumVelocityObservable::compute(const FrameContext& context) {
    const GroupArrays& medium = context.group(BodyGroup::medium);
    const GroupArrays& polar = context.group(BodyGroup::polar);
    const MediumAtDistance at_d =
        profile_.compute(medium.grid, medium.velocity, polar.position, polar.angle, polar.velocity);
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
    r.parameters = {{"d", p.d, "mm"}, {"r_max", p.r_max, "mm"}, {"bin", p.bin, "mm"}};
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
