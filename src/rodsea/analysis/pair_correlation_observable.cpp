#include "rodsea/analysis/pair_correlation_observable.hpp"

#include <cmath>
#include <numbers>

namespace rodsea {

PairCorrelationObservable::PairCorrelationObservable(const AnalysisSetup& setup,
                                                     const AnalysisOptions& options)
    : setup_(setup),
      bin_(options.pair_bin),
      has_medium_rods_(setup.has_kind(BodyKind::apolar_rod)) {
    const auto init = [&](Accumulator& acc, double r_max) {
        acc.bins = static_cast<std::size_t>(std::ceil(r_max / bin_));
        acc.r_max = static_cast<double>(acc.bins) * bin_;
        acc.pairs.assign(acc.bins, 0.0);
        acc.cos1.assign(acc.bins, 0.0);
        acc.cos2.assign(acc.bins, 0.0);
    };
    init(polar_, options.pair_r_max);
    init(medium_, options.medium_pair_r_max);
    // The last bin may reach past the allowed radius by less than one bin: keep it inside L/2.
    const double half = 0.5 * std::min(setup.box.lx, setup.box.ly);
    for (Accumulator* acc : {&polar_, &medium_})
        while (acc->r_max > half && acc->bins > 1) {
            --acc->bins;
            acc->r_max -= bin_;
            acc->pairs.pop_back(), acc->cos1.pop_back(), acc->cos2.pop_back();
        }
}

void PairCorrelationObservable::accumulate(const FrameContext& context, BodyGroup group,
                                           BodyKind kind, Accumulator& acc) const {
    const AnalysisFrame& f = context.frame();
    const BodyGrid& grid = context.grid(group);
    double n = 0.0;
    for (std::uint32_t i : grid.members()) {
        if (context.species()[f.species[i]].kind != kind) continue;
        n += 1.0;
        const double ti = f.theta[i];
        grid.for_each_within(f.x[i], f.y[i], acc.r_max, [&](std::uint32_t j, double dx, double dy) {
            if (j == i || context.species()[f.species[j]].kind != kind) return;
            const auto b = static_cast<std::size_t>(std::sqrt(dx * dx + dy * dy) / bin_);
            if (b >= acc.bins) return;
            const double d = ti - f.theta[j];
            acc.pairs[b] += 1.0;
            acc.cos1[b] += std::cos(d);
            acc.cos2[b] += std::cos(2.0 * d);
        });
    }
    acc.reference_pairs += n * (n - 1.0);
}

void PairCorrelationObservable::compute(const FrameContext& context) {
    ++frames_;
    if (setup_.polar_count() > 1)
        accumulate(context, BodyGroup::polar, BodyKind::polar_rod, polar_);
    if (has_medium_rods_) accumulate(context, BodyGroup::medium, BodyKind::apolar_rod, medium_);
}

TableResult PairCorrelationObservable::table(const Accumulator& acc, const std::string& name,
                                             const std::string& description, bool polar) const {
    TableResult t{name, description, {"r", "pairs", "g"}, {"mm", "", ""}, {}};
    if (polar) t.columns.push_back("G"), t.units.push_back("");
    t.columns.push_back("G2");
    t.units.push_back("");
    const double area = setup_.box.lx * setup_.box.ly;
    for (std::size_t b = 0; b < acc.bins; ++b) {
        const double r0 = static_cast<double>(b) * bin_, r1 = r0 + bin_;
        const double shell = std::numbers::pi * (r1 * r1 - r0 * r0);
        // Ideal gas: each of the N(N−1) ordered pairs lands in the shell with probability shell/A.
        const double ideal = acc.reference_pairs * shell / area;
        const double nan = std::nan("");
        std::vector<double> row{0.5 * (r0 + r1), acc.pairs[b],
                                ideal > 0.0 ? acc.pairs[b] / ideal : nan};
        if (polar) row.push_back(acc.pairs[b] > 0 ? acc.cos1[b] / acc.pairs[b] : nan);
        row.push_back(acc.pairs[b] > 0 ? acc.cos2[b] / acc.pairs[b] : nan);
        t.rows.push_back(std::move(row));
    }
    return t;
}

ObservableResults PairCorrelationObservable::finish() {
    ObservableResults r;
    r.observable = name();
    r.parameters = {{"r_max_polar", polar_.r_max, "mm"},
                    {"r_max_medium", medium_.r_max, "mm"},
                    {"bin", bin_, "mm"}};
    if (setup_.polar_count() > 1)
        r.tables.push_back(table(polar_, "pair_correlation_polar",
                                 "g(r), G(r) = <cos(θi−θj)>, G2(r) = <cos 2(θi−θj)> of polar rods, "
                                 "steady average",
                                 true));
    if (has_medium_rods_)
        r.tables.push_back(table(medium_, "pair_correlation_medium",
                                 "g(r) and G2(r) = <cos 2(θi−θj)> of the apolar medium rods, "
                                 "steady average",
                                 false));
    else
        r.notes.push_back(
            "no apolar rods in the medium: G2(r) of the medium is not defined for beads");
    return r;
}

}  // namespace rodsea
