#include "rodsea/analyze/pair_correlation_observable.hpp"

namespace rodsea {

namespace {

TableResult table(const PairCorrelation& p, const std::string& name, const std::string& description,
                  bool polar) {
    TableResult t{name, description, {"r", "pairs", "g"}, {"mm", "", ""}, {}};
    if (polar) t.columns.push_back("G"), t.units.push_back("");
    t.columns.push_back("G2");
    t.units.push_back("");
    const std::vector<double> r = p.bin_centres(), g = p.pair_density(), g1 = p.polar_correlation(),
                              g2 = p.nematic_correlation();
    for (std::size_t b = 0; b < r.size(); ++b) {
        std::vector<double> row{r[b], p.pair_counts()[b], g[b]};
        if (polar) row.push_back(g1[b]);
        row.push_back(g2[b]);
        t.rows.push_back(std::move(row));
    }
    return t;
}

}  // namespace

PairCorrelationObservable::PairCorrelationObservable(const AnalysisSetup& setup,
                                                     const AnalysisOptions& options)
    : bin_(options.pair_bin) {
    if (setup.polar_count() > 1)
        polar_.emplace(PairCorrelationParameters{options.pair_r_max, bin_});
    if (setup.has_kind(BodyKind::apolar_rod))
        medium_.emplace(PairCorrelationParameters{options.medium_pair_r_max, bin_});
}

void PairCorrelationObservable::compute(const FrameContext& context) {
    if (polar_) {
        const GroupArrays& g = context.group(BodyGroup::polar);
        polar_->compute(g.grid, g.angle);
    }
    if (medium_) {
        const GroupArrays& g = context.group(BodyGroup::medium_rods);
        medium_->compute(g.grid, g.angle);
    }
}

ObservableResults PairCorrelationObservable::finish() {
    ObservableResults r;
    r.observable = name();
    r.parameters = {{"r_max_polar", polar_ ? polar_->r_max() : 0.0, "mm"},
                    {"r_max_medium", medium_ ? medium_->r_max() : 0.0, "mm"},
                    {"bin", bin_, "mm"}};
    if (polar_)
        r.tables.push_back(table(*polar_, "pair_correlation_polar",
                                 "g(r), G(r) = <cos(θi−θj)>, G2(r) = <cos 2(θi−θj)> of polar rods, "
                                 "steady average",
                                 true));
    if (medium_)
        r.tables.push_back(table(*medium_, "pair_correlation_medium",
                                 "g(r) and G2(r) = <cos 2(θi−θj)> of the apolar medium rods, "
                                 "steady average",
                                 false));
    else
        r.notes.push_back(
            "no apolar rods in the medium: G2(r) of the medium is not defined for beads");
    return r;
}

}  // namespace rodsea
