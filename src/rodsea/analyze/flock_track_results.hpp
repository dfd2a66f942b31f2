#pragma once
// The flocks observable's record of flocks followed in time (analysis/flock_tracks.hpp): a row
// per track (lifetime, size, speed, polar order, leaders), a row per event (birth, death, merge,
// split), every state of every track in analysis.h5, and steady-window rates and means.
#include <cstdint>
#include <vector>

#include "rodsea/analysis/flock_tracks.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

// `bodies`: the trajectory index of each rod the tracker was given; `steady_from`: the first
// steady frame's time (s), negative when no frame is steady.
void add_flock_track_results(const FlockTracker& tracker, const std::vector<std::uint32_t>& bodies,
                             const AnalysisSetup& setup, double steady_from,
                             ObservableResults& results);

}  // namespace rodsea
