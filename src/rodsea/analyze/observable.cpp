#include "rodsea/analyze/observable.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rodsea {

bool AnalysisSetup::has_kind(BodyKind kind) const {
    return count_of(kind) > 0;
}

double AnalysisSetup::polar_length() const {
    for (const SpeciesInfo& s : species)
        if (s.kind == BodyKind::polar_rod) return s.length;
    return 0.0;
}

long long AnalysisSetup::count_of(BodyKind kind) const {
    long long n = 0;
    for (const SpeciesInfo& s : species)
        if (s.kind == kind) n += s.count;
    return n;
}

long long AnalysisSetup::total_count() const {
    long long n = 0;
    for (const SpeciesInfo& s : species)
        n += s.count;
    return n;
}

int AnalysisSetup::block_of(std::size_t steady_index) const {
    if (steady_frames == 0) return 0;
    const auto b =
        static_cast<int>(steady_index * static_cast<std::size_t>(blocks) / steady_frames);
    return std::clamp(b, 0, blocks - 1);
}

Estimate steady_estimate(std::span<const double> series, std::span<const char> steady) {
    std::vector<double> kept;
    for (std::size_t i = 0; i < series.size() && i < steady.size(); ++i)
        if (steady[i]) kept.push_back(series[i]);
    return estimate_mean(kept);
}

Estimate rate_estimate(std::size_t events, double seconds, double per) {
    Estimate e;
    const auto n = static_cast<double>(events);
    if (!(seconds > 0.0) || !(per > 0.0)) {
        e.mean = e.error = std::numeric_limits<double>::quiet_NaN();
        return e;
    }
    e.mean = n / (seconds * per);
    // No event seen is not a rate known to be 0: its error is that of one event.
    e.error = std::sqrt(std::max(n, 1.0)) / (seconds * per);
    e.samples = events;
    e.n_eff = n;
    return e;
}

double steady_seconds(const AnalysisSetup& setup) {
    if (setup.steady_frames < 2) return 0.0;
    return static_cast<double>(setup.steady_frames - 1) * setup.frame_interval;
}

}  // namespace rodsea
