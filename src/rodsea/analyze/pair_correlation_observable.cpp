#include "rodsea/analyze/pair_correlation_observable.hpp"

#include <functional>

#include "rodsea/analysis/statistics.hpp"

namespace rodsea {

namespace {

using Curve = std::function<std::vector<double>(const PairCorrelation&)>;

// Each curve beside its error bar, the standard error of its time-block values (NaN where fewer
// than two blocks have a pair in the bin).
TableResult table(const std::vector<PairCorrelation>& blocks, const std::string& name,
                  const std::string& description, bool polar) {
    PairCorrelation all = blocks.front();
    for (std::size_t k = 1; k < blocks.size(); ++k)
        all += blocks[k];
    std::vector<std::pair<std::string, Curve>> curves{
        {"g", [](const PairCorrelation& p) { return p.pair_density(); }}};
    if (polar)
        curves.emplace_back("G", [](const PairCorrelation& p) { return p.polar_correlation(); });
    curves.emplace_back("G2", [](const PairCorrelation& p) { return p.nematic_correlation(); });

    TableResult t{name, description, {"r", "pairs"}, {"mm", ""}, {}};
    for (const auto& [column, _] : curves) {
        t.columns.insert(t.columns.end(), {column, column + "_err"});
        t.units.insert(t.units.end(), {"", ""});
    }
    std::vector<std::vector<double>> pooled, per_block;
    for (const auto& [_, curve] : curves) {
        pooled.push_back(curve(all));
        for (const PairCorrelation& b : blocks)
            per_block.push_back(curve(b));
    }
    const std::vector<double> r = all.bin_centres();
    for (std::size_t bin = 0; bin < r.size(); ++bin) {
        std::vector<double> row{r[bin], all.pair_counts()[bin]};
        for (std::size_t c = 0; c < curves.size(); ++c) {
            std::vector<double> values;
            for (std::size_t k = 0; k < blocks.size(); ++k) {
                const std::vector<double>& v = per_block[c * blocks.size() + k];
                // A block without frames kept the untrimmed range; it has no value anywhere.
                if (bin < v.size() && blocks[k].frames() > 0) values.push_back(v[bin]);
            }
            row.push_back(pooled[c][bin]);
            row.push_back(estimate_from_blocks(pooled[c][bin], values).error);
        }
        t.rows.push_back(std::move(row));
    }
    return t;
}

}  // namespace

PairCorrelationObservable::PairCorrelationObservable(const AnalysisSetup& setup,
                                                     const AnalysisOptions& options)
    : bin_(options.pair_bin) {
    const auto blocks = static_cast<std::size_t>(setup.blocks);
    if (setup.polar_count() > 1) polar_.assign(blocks, PairCorrelation({options.pair_r_max, bin_}));
    if (setup.has_kind(BodyKind::apolar_rod))
        medium_.assign(blocks, PairCorrelation({options.medium_pair_r_max, bin_}));
}

void PairCorrelationObservable::compute(const FrameContext& context) {
    const auto block = static_cast<std::size_t>(context.block());
    if (!polar_.empty()) {
        const GroupArrays& g = context.group(BodyGroup::polar);
        polar_[block].compute(g.grid, g.angle);
    }
    if (!medium_.empty()) {
        const GroupArrays& g = context.group(BodyGroup::medium_rods);
        medium_[block].compute(g.grid, g.angle);
    }
}

ObservableResults PairCorrelationObservable::finish() {
    ObservableResults r;
    r.observable = name();
    const auto range = [](const std::vector<PairCorrelation>& blocks) {
        double r_max = 0.0;
        for (const PairCorrelation& b : blocks)
            if (b.frames() > 0) r_max = b.r_max();
        return r_max;
    };
    r.parameters = {{"r_max_polar", range(polar_), "mm"},
                    {"r_max_medium", range(medium_), "mm"},
                    {"bin", bin_, "mm"}};
    if (!polar_.empty())
        r.tables.push_back(table(polar_, "pair_correlation_polar",
                                 "g(r), G(r) = <cos(θi−θj)>, G2(r) = <cos 2(θi−θj)> of polar rods, "
                                 "steady average; *_err from the spread of the time blocks",
                                 true));
    if (!medium_.empty())
        r.tables.push_back(table(medium_, "pair_correlation_medium",
                                 "g(r) and G2(r) = <cos 2(θi−θj)> of the apolar medium rods, "
                                 "steady average; *_err from the spread of the time blocks",
                                 false));
    else
        r.notes.push_back(
            "no apolar rods in the medium: G2(r) of the medium is not defined for beads");
    return r;
}

}  // namespace rodsea
