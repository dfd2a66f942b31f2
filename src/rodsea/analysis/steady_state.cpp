#include "rodsea/analysis/steady_state.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/analysis/statistics.hpp"

namespace rodsea {

namespace {

bool decides(const std::vector<double>& x) {
    if (x.size() < 4) return false;
    if (std::any_of(x.begin(), x.end(), [](double v) { return !std::isfinite(v); })) return false;
    return std::any_of(x.begin(), x.end(), [&](double v) { return v != x.front(); });
}

// Means of the two halves of x[first..] against their τ_int errors: a difference beyond three
// combined standard errors is a drift, not noise (a 0.3 % false alarm for Gaussian errors).
bool drifts(std::span<const double> x, std::size_t first) {
    const std::size_t n = x.size() - first;
    if (n < 8) return false;
    const Estimate a = estimate_mean(x.subspan(first, n / 2));
    const Estimate b = estimate_mean(x.subspan(first + n / 2));
    const double error = std::hypot(a.error, b.error);
    return std::isfinite(error) && std::abs(a.mean - b.mean) > 3.0 * error;
}

}  // namespace

double independent_samples(std::span<const double> x, std::size_t first) {
    if (first >= x.size()) return 0.0;
    const std::span<const double> kept = x.subspan(first);
    return static_cast<double>(kept.size()) / (2.0 * integrated_autocorrelation_time(kept));
}

SteadyChoice latest_steady_start(std::span<const NamedSeries> series) {
    SteadyChoice choice;
    for (const NamedSeries& s : series) {
        SeriesStart start{s.name, 0, 0.0, false};
        if (decides(s.values)) {
            start.start = steady_start(s.values);
            if (choice.decided_by.empty() || start.start > choice.first) {
                choice.first = start.start;
                choice.decided_by = s.name;
            }
        }
        choice.series.push_back(start);
    }
    for (std::size_t k = 0; k < series.size(); ++k) {
        const std::vector<double>& x = series[k].values;
        if (!decides(x) || choice.first >= x.size()) continue;
        choice.series[k].n_eff = independent_samples(x, choice.first);
        choice.series[k].drifting = drifts(x, choice.first);
    }
    return choice;
}

}  // namespace rodsea
