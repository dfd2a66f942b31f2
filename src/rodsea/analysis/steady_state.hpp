#pragma once
// The steady window of a run from all of its order series at once: each series' own steady start
// (Chodera's rule, statistics.hpp), and the window from the latest of them, because a run is
// steady only once every order parameter is: the polar rods' P can settle while the medium still
// loses the order it started with, or the other way round. The series that decided is named so
// that the choice can be checked.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace rodsea {

struct NamedSeries {
    std::string name;
    std::vector<double> values;  // one per frame
};

struct SeriesStart {
    std::string name;
    std::size_t start = 0;  // the series' own first steady sample
    double n_eff = 0.0;     // its independent samples from the common window's start on
    // Its mean over the first and the second half of the window differ by more than three
    // standard errors: still relaxing, or never steady (a trend, a slow oscillation).
    bool drifting = false;
};

struct SteadyChoice {
    std::size_t first = 0;   // the window's first sample: the latest of the series' starts
    std::string decided_by;  // the series whose start that is; empty without series
    std::vector<SeriesStart> series;
};

// Series that are constant, empty or hold a NaN are reported but do not decide.
SteadyChoice latest_steady_start(std::span<const NamedSeries> series);

// n / (2 τ_int) of the samples from `first` on.
double independent_samples(std::span<const double> x, std::size_t first = 0);

}  // namespace rodsea
