#include "rodsea/analyze/autocorrelation_observable.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/error.hpp"

#include "rodsea/analysis/time_correlation.hpp"

namespace rodsea {

AutocorrelationObservable::AutocorrelationObservable(const AnalysisSetup& setup,
                                                     const AnalysisOptions& options)
    : setup_(setup),
      max_lag_(options.autocorrelation_max_lag),
      fit_floor_(options.autocorrelation_fit_floor) {
    for (std::uint32_t s = 0; s < setup.species.size(); ++s) {
        if (setup.species[s].count == 0) continue;
        if (setup.species[s].kind == BodyKind::polar_rod) series_.push_back({s, 1, {}, 0});
        if (setup.species[s].kind != BodyKind::bead) series_.push_back({s, 2, {}, 0});
    }
}

void AutocorrelationObservable::compute(const FrameContext& context) {
    const AnalysisFrame& f = context.frame();
    ++frames_;
    for (Series& s : series_) {
        std::size_t n = 0;
        for (std::uint32_t i = 0; i < f.size(); ++i)
            if (f.species[i] == s.species) {
                s.angles.push_back(static_cast<float>(f.theta[i]));
                ++n;
            }
        s.bodies = n;
    }
}

ObservableResults AutocorrelationObservable::finish() {
    ObservableResults r;
    r.observable = name();
    const double dt = setup_.frame_interval;
    // The window caps the lag: a longer one has no origin to start from.
    const auto lags = std::min(static_cast<std::size_t>(std::llround(max_lag_ / dt)),
                               frames_ > 0 ? frames_ - 1 : 0);
    r.parameters = {{"max_lag", static_cast<double>(lags) * dt, "s"},
                    {"fit_floor", fit_floor_, ""},
                    {"frame_interval", dt, "s"}};
    TableResult table{"orientation_autocorrelation",
                      "C(t) = <cos(θ(t+τ)−θ(τ))> and C2(t) with 2θ, over rods and origins",
                      {"t"},
                      {"s"},
                      {}};
    std::vector<std::vector<double>> curves;
    for (const Series& s : series_) {
        const SpeciesInfo& sp = setup_.species[s.species];
        const std::string label = (s.m == 1 ? "C_" : "C2_") + sp.name;
        const std::vector<double> c =
            orientation_autocorrelation(s.angles, frames_, s.bodies, s.m, lags);
        const std::size_t fit = fit_lag_count(c, fit_floor_);
        const double full = rotational_diffusion_from(c, dt, s.m, fit_floor_, fit);
        std::vector<double> blocks;
        const std::size_t per_block = frames_ / static_cast<std::size_t>(setup_.blocks);
        for (int b = 0; b < setup_.blocks && per_block > 1; ++b) {
            const auto first = static_cast<std::size_t>(b) * per_block;
            const std::vector<float> part(
                s.angles.begin() + static_cast<std::ptrdiff_t>(first * s.bodies),
                s.angles.begin() + static_cast<std::ptrdiff_t>((first + per_block) * s.bodies));
            const auto cb = orientation_autocorrelation(part, per_block, s.bodies, s.m,
                                                        std::min(lags, per_block / 2));
            blocks.push_back(rotational_diffusion_from(cb, dt, s.m, fit_floor_, fit));
        }
        const std::string what = s.m == 1 ? "C = exp(−D_r t)" : "C2 = exp(−4 D_r t)";
        r.scalars.push_back({(s.m == 1 ? "D_r_" : "D_r_C2_") + sp.name, "rad^2/s",
                             "rotational diffusion of " + sp.name + " from the fit " + what +
                                 " over " + std::to_string(fit) + " lags",
                             estimate_from_blocks(full, blocks)});
        if (fit == 0)
            r.notes.push_back(label + " falls below " + format_number(fit_floor_) +
                              " within one frame interval: frames too far apart to fit D_r");
        table.columns.push_back(label);
        table.units.push_back("");
        curves.push_back(c);
    }
    for (std::size_t lag = 0; !curves.empty() && lag < curves[0].size(); ++lag) {
        std::vector<double> row{static_cast<double>(lag) * dt};
        for (const auto& c : curves)
            row.push_back(lag < c.size() ? c[lag] : std::nan(""));
        table.rows.push_back(std::move(row));
    }
    r.tables.push_back(std::move(table));
    return r;
}

}  // namespace rodsea
