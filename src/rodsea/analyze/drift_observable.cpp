#include "rodsea/analyze/drift_observable.hpp"

#include <cmath>

namespace rodsea {

DriftObservable::DriftObservable(const AnalysisSetup& setup)
    : setup_(setup), vx_(setup.species.size()), vy_(setup.species.size()) {}

void DriftObservable::compute(const FrameContext& context) {
    const AnalysisFrame& f = context.frame();
    times_.push_back(f.time);
    steady_.push_back(context.steady() ? 1 : 0);
    const std::size_t n = setup_.species.size();
    std::vector<double> sx(n), sy(n), count(n);
    double px = 0.0, py = 0.0, mx = 0.0, my = 0.0, medium = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        const std::uint32_t s = f.species[i];
        sx[s] += f.velocity[i].x;
        sy[s] += f.velocity[i].y;
        count[s] += 1.0;
        if (setup_.species[s].kind == BodyKind::polar_rod) {
            px += std::cos(f.theta[i]);
            py += std::sin(f.theta[i]);
        } else {
            mx += f.velocity[i].x;
            my += f.velocity[i].y;
            medium += 1.0;
        }
    }
    for (std::size_t s = 0; s < n; ++s) {
        vx_[s].push_back(count[s] > 0.0 ? sx[s] / count[s] : std::nan(""));
        vy_[s].push_back(count[s] > 0.0 ? sy[s] / count[s] : std::nan(""));
    }
    // p̂ is undefined when the polar rods' headings cancel exactly (P = 0): no projection then.
    const double p = std::hypot(px, py);
    if (setup_.polar_count() > 0 && medium > 0.0)
        along_.push_back(p > 0.0 ? (mx * px + my * py) / (medium * p) : std::nan(""));
}

ObservableResults DriftObservable::finish() {
    ObservableResults r;
    r.observable = name();
    TableResult table{"drift",
                      "mean in-plane velocity of each species every frame (steady = 1 inside the "
                      "averaged window)",
                      {"time", "steady"},
                      {"s", ""},
                      {}};
    for (std::size_t s = 0; s < setup_.species.size(); ++s) {
        const std::string& name = setup_.species[s].name;
        if (setup_.species[s].count == 0) continue;
        table.columns.insert(table.columns.end(), {"vx_" + name, "vy_" + name});
        table.units.insert(table.units.end(), {"mm/s", "mm/s"});
        r.scalars.push_back({"vx_" + name, "mm/s", "mean x velocity of " + name + ", steady mean",
                             steady_estimate(vx_[s], steady_)});
        r.scalars.push_back({"vy_" + name, "mm/s", "mean y velocity of " + name + ", steady mean",
                             steady_estimate(vy_[s], steady_)});
    }
    if (!along_.empty()) {
        table.columns.push_back("v_medium_along_polar");
        table.units.push_back("mm/s");
        r.scalars.push_back(
            {"v_medium_along_polar", "mm/s",
             "the medium's mean velocity along the polar rods' mean heading, steady mean",
             steady_estimate(along_, steady_)});
    }
    for (std::size_t k = 0; k < times_.size(); ++k) {
        std::vector<double> row{times_[k], static_cast<double>(steady_[k])};
        for (std::size_t s = 0; s < setup_.species.size(); ++s) {
            if (setup_.species[s].count == 0) continue;
            row.push_back(vx_[s][k]);
            row.push_back(vy_[s][k]);
        }
        if (!along_.empty()) row.push_back(along_[k]);
        table.rows.push_back(std::move(row));
    }
    r.tables.push_back(std::move(table));
    return r;
}

}  // namespace rodsea
