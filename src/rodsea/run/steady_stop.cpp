#include "rodsea/run/steady_stop.hpp"

#include <algorithm>
#include <limits>

#include "rodsea/analyze/structure_series.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/trajectory_reader.hpp"

namespace rodsea {

void check_steady_series(const RunPlan& plan) {
    const std::string& wanted = plan.control.steady_series;
    if (wanted == "all") return;
    const std::vector<std::string> columns = steady_series_columns(analysis_setup(plan));
    if (std::find(columns.begin(), columns.end(), wanted) != columns.end()) return;
    std::string allowed = "all";
    for (const std::string& c : columns)
        allowed += ", " + c;
    throw InvalidParameter("time.steady_series", wanted, allowed,
                           "the order series of this run's species");
}

SteadyStop::SteadyStop(const RunPlan& plan, const std::vector<SeriesColumn>& columns)
    : samples_(plan.control.steady_samples), counted_(plan.control.steady_series) {
    for (const std::string& name : steady_series_columns(analysis_setup(plan))) {
        const auto at = std::find_if(columns.begin(), columns.end(),
                                     [&](const SeriesColumn& c) { return c.name == name; });
        if (at == columns.end()) continue;
        index_.push_back(static_cast<std::size_t>(at - columns.begin()));
        series_.push_back({name, {}});
    }
}

void SteadyStop::restore(const TrajectoryReader& reader, std::size_t frames) {
    for (NamedSeries& s : series_) {
        s.values = reader.series(s.name);
        s.values.resize(std::min(s.values.size(), frames));
    }
}

void SteadyStop::add_row(const std::vector<double>& row) {
    for (std::size_t k = 0; k < series_.size(); ++k)
        series_[k].values.push_back(row[index_[k]]);
}

std::optional<SteadyVerdict> SteadyStop::verdict() const {
    if (!active() || series_.empty() || series_.front().values.size() < kSteadyMinimumFrames)
        return std::nullopt;
    const SteadyChoice choice = latest_steady_start(series_);
    if (choice.decided_by.empty()) return std::nullopt;
    SteadyVerdict v{choice.first, choice.decided_by, "", std::numeric_limits<double>::infinity()};
    for (const SeriesStart& s : choice.series) {
        // Series that cannot decide (constant, not applicable) have n_eff 0 and are not counted.
        const bool counts = counted_ == "all" ? s.n_eff > 0.0 : s.name == counted_;
        if (!counts) continue;
        if (s.drifting) return std::nullopt;
        if (s.n_eff < v.n_eff) {
            v.n_eff = s.n_eff;
            v.counted = s.name;
        }
    }
    if (v.counted.empty() || v.n_eff < static_cast<double>(samples_)) return std::nullopt;
    return v;
}

}  // namespace rodsea
