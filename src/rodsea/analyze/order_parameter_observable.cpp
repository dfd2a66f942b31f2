#include "rodsea/analyze/order_parameter_observable.hpp"

#include <cmath>

#include "rodsea/engine/order_parameters.hpp"

namespace rodsea {

OrderParameterObservable::OrderParameterObservable(const AnalysisSetup& setup) : setup_(setup) {
    for (std::uint32_t s = 0; s < setup.species.size(); ++s)
        if (setup.species[s].kind != BodyKind::bead && setup.species[s].count > 0)
            oriented_.push_back(s);
    polar_.resize(setup.species.size());
    nematic_.resize(setup.species.size());
}

void OrderParameterObservable::compute(const FrameContext& context) {
    const AnalysisFrame& f = context.frame();
    times_.push_back(f.time);
    steady_.push_back(context.steady() ? 1 : 0);
    std::vector<std::vector<double>> angles(setup_.species.size());
    for (std::size_t i = 0; i < f.size(); ++i)
        angles[f.species[i]].push_back(f.theta[i]);
    for (std::uint32_t s : oriented_) {
        polar_[s].push_back(orientational_order(angles[s], 1));
        nematic_[s].push_back(orientational_order(angles[s], 2));
    }
}

ObservableResults OrderParameterObservable::finish() {
    ObservableResults r;
    r.observable = name();
    TableResult table{"order_parameters",
                      "P and S per species, every frame (steady = 1 inside the averaged window)",
                      {"time", "steady"},
                      {"s", ""},
                      {}};
    for (std::uint32_t s : oriented_) {
        const SpeciesInfo& sp = setup_.species[s];
        table.columns.push_back("P_" + sp.name);
        table.columns.push_back("S_" + sp.name);
        table.units.insert(table.units.end(), {"", ""});
        if (sp.kind == BodyKind::polar_rod)
            r.scalars.push_back({"P_" + sp.name, "",
                                 "polar order |<(cos θ, sin θ)>| of " + sp.name + ", steady mean",
                                 steady_estimate(polar_[s], steady_)});
        r.scalars.push_back({"S_" + sp.name, "",
                             "nematic order |<(cos 2θ, sin 2θ)>| of " + sp.name + ", steady mean",
                             steady_estimate(nematic_[s], steady_)});
    }
    for (std::size_t k = 0; k < times_.size(); ++k) {
        std::vector<double> row{times_[k], static_cast<double>(steady_[k])};
        for (std::uint32_t s : oriented_) {
            row.push_back(polar_[s][k]);
            row.push_back(nematic_[s][k]);
        }
        table.rows.push_back(std::move(row));
    }
    r.tables.push_back(std::move(table));
    return r;
}

}  // namespace rodsea
