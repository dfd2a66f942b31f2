#include "rodsea/analyze/drift_observable.hpp"

#include <algorithm>
#include <cmath>

namespace rodsea {

DriftObservable::DriftObservable(const AnalysisSetup& setup)
    : setup_(setup),
      vx_(setup.species.size()),
      vy_(setup.species.size()),
      v_rms_(setup.species.size()),
      spin_rms_(setup.species.size()) {}

void DriftObservable::compute(const FrameContext& context) {
    const AnalysisFrame& f = context.frame();
    times_.push_back(f.time);
    steady_.push_back(context.steady() ? 1 : 0);
    const std::size_t n = setup_.species.size();
    std::vector<double> sx(n), sy(n), speed2(n), spin2(n), count(n);
    double px = 0.0, py = 0.0, mx = 0.0, my = 0.0, medium = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        const std::uint32_t s = f.species[i];
        sx[s] += f.velocity[i].x;
        sy[s] += f.velocity[i].y;
        speed2[s] += f.velocity[i].x * f.velocity[i].x + f.velocity[i].y * f.velocity[i].y;
        spin2[s] += f.spin_z[i] * f.spin_z[i];
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
        if (count[s] == 0.0) {
            for (auto* series : {&vx_, &vy_, &v_rms_, &spin_rms_})
                (*series)[s].push_back(std::nan(""));
            continue;
        }
        const double mean_x = sx[s] / count[s], mean_y = sy[s] / count[s];
        vx_[s].push_back(mean_x);
        vy_[s].push_back(mean_y);
        // ⟨|v − ⟨v⟩|²⟩ = ⟨|v|²⟩ − |⟨v⟩|²; the drift is mm/s against tens of mm/s of agitation, so
        // the subtraction loses nothing. max() guards the rounding of a species at rest.
        const double spread = speed2[s] / count[s] - (mean_x * mean_x + mean_y * mean_y);
        v_rms_[s].push_back(std::sqrt(std::max(spread, 0.0)));
        spin_rms_[s].push_back(std::sqrt(spin2[s] / count[s]));
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
                      "mean in-plane velocity of each species every frame, and its agitation: the "
                      "rms in-plane speed about that mean and the rms spin about z (steady = 1 "
                      "inside the averaged window)",
                      {"time", "steady"},
                      {"s", ""},
                      {}};
    for (std::size_t s = 0; s < setup_.species.size(); ++s) {
        const std::string& name = setup_.species[s].name;
        if (setup_.species[s].count == 0) continue;
        table.columns.insert(table.columns.end(),
                             {"vx_" + name, "vy_" + name, "v_rms_" + name, "spin_rms_" + name});
        table.units.insert(table.units.end(), {"mm/s", "mm/s", "mm/s", "rad/s"});
        r.scalars.push_back({"vx_" + name, "mm/s", "mean x velocity of " + name + ", steady mean",
                             steady_estimate(vx_[s], steady_)});
        r.scalars.push_back({"vy_" + name, "mm/s", "mean y velocity of " + name + ", steady mean",
                             steady_estimate(vy_[s], steady_)});
        r.scalars.push_back({"v_rms_" + name, "mm/s",
                             "rms in-plane speed of " + name + " about its mean, steady mean",
                             steady_estimate(v_rms_[s], steady_)});
        r.scalars.push_back({"spin_rms_" + name, "rad/s",
                             "rms spin about z of " + name + ", steady mean",
                             steady_estimate(spin_rms_[s], steady_)});
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
            for (const auto* series : {&vx_, &vy_, &v_rms_, &spin_rms_})
                row.push_back((*series)[s][k]);
        }
        if (!along_.empty()) row.push_back(along_[k]);
        table.rows.push_back(std::move(row));
    }
    r.tables.push_back(std::move(table));
    return r;
}

}  // namespace rodsea
