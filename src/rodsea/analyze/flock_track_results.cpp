#include "rodsea/analyze/flock_track_results.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rodsea {

void add_flock_track_results(const FlockTracker& tracker, const std::vector<std::uint32_t>& bodies,
                             const AnalysisSetup& setup, double steady_from, ObservableResults& r) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const bool any_steady = steady_from >= 0.0;
    TableResult tracks{
        "flock_tracks",
        "each flock followed in time: born (first frame), last seen, ended (the frame it was "
        "gone: merged or dead; NaN if alive at the end), lifetime (ended − born; alive: last "
        "seen − born), frames, mean and largest size (rods), mean speed of its centre, mean "
        "polar order, how many rods led it and the longest lead",
        {"track", "born", "last_seen", "ended", "lifetime", "frames", "mean_size", "max_size",
         "mean_speed", "mean_polar_order", "leaders", "longest_lead"},
        {"", "s", "s", "s", "s", "", "", "", "mm/s", "", "", "s"},
        {}};
    std::vector<double> lifetimes, tenures;
    FlockStateColumns states;
    for (const FlockTrack& track : tracker.tracks()) {
        states.append(track);
        double sizes = 0.0, largest = 0.0, speed = 0.0, polar = 0.0;
        int moving = 0;
        for (const FlockState& s : track.states) {
            sizes += static_cast<double>(s.size);
            largest = std::max(largest, static_cast<double>(s.size));
            polar += s.polar_order;
            if (!std::isnan(s.velocity.x)) {
                speed += std::hypot(s.velocity.x, s.velocity.y);
                ++moving;
            }
        }
        const auto frames = static_cast<double>(track.states.size());
        int longest = 0;
        for (const auto& [rod, led] : track.leaders) {
            longest = std::max(longest, led);
            // A stint cut by the window's start or the run's end is left out, like a lifetime.
            if (any_steady && track.born > steady_from && track.ended >= 0.0)
                tenures.push_back(led * setup.frame_interval);
        }
        const bool ended = track.ended >= 0.0;
        if (ended && any_steady && track.born > steady_from) lifetimes.push_back(track.lifetime());
        tracks.rows.push_back({static_cast<double>(track.id), track.born, track.states.back().time,
                               ended ? track.ended : nan, track.lifetime(), frames, sizes / frames,
                               largest, moving ? speed / moving : nan, polar / frames,
                               static_cast<double>(track.leaders.size()),
                               longest * setup.frame_interval});
    }
    r.tables.push_back(std::move(tracks));

    TableResult events{"flock_events",
                       "flock events, a row per track involved: kind 0 birth, 1 death, 2 merge "
                       "(from: each merging track, to: the one that continues), 3 split (from: "
                       "the track split, to: the new one); −1: none",
                       {"event", "time", "kind", "from", "to"},
                       {"", "s", "", "", ""},
                       {}};
    std::size_t merges = 0, splits = 0, index = 0;
    for (const FlockEvent& e : tracker.events()) {
        const std::vector<int> from = e.from.empty() ? std::vector<int>{-1} : e.from;
        const std::vector<int> to = e.to.empty() ? std::vector<int>{-1} : e.to;
        for (int f : from)
            for (int g : to)
                events.rows.push_back({static_cast<double>(index), e.time,
                                       static_cast<double>(e.kind), static_cast<double>(f),
                                       static_cast<double>(g)});
        ++index;
        if (!any_steady || e.time <= steady_from) continue;
        merges += e.kind == FlockEvent::Kind::merge ? 1 : 0;
        splits += e.kind == FlockEvent::Kind::split ? 1 : 0;
    }
    r.tables.push_back(std::move(events));
    const double window = steady_seconds(setup);
    r.scalars.push_back({"flock_lifetime", "s",
                         "mean lifetime of the flocks born and ended inside the steady window",
                         estimate_mean(lifetimes)});
    r.scalars.push_back({"flock_merge_rate", "1/s", "flock merges per second, steady window",
                         rate_estimate(merges, window)});
    r.scalars.push_back({"flock_split_rate", "1/s", "flock splits per second, steady window",
                         rate_estimate(splits, window)});
    r.scalars.push_back({"leader_tenure", "s",
                         "mean time a rod stays its flock's leader (flocks born and ended in the "
                         "steady window)",
                         estimate_mean(tenures)});
    // Track ids, sizes and leaders as integers; leaders by their body index in the trajectory.
    std::vector<std::int32_t> id(states.track.begin(), states.track.end()), size, leader;
    for (std::size_t k = 0; k < states.time.size(); ++k) {
        size.push_back(static_cast<std::int32_t>(states.size[k]));
        leader.push_back(static_cast<std::int32_t>(bodies[states.leader[k]]));
    }
    const auto n = static_cast<std::uint64_t>(states.time.size());
    r.datasets.push_back(
        {"flock_tracks/track", "track of each state (flock_tracks.csv)", "", {n}, id});
    r.datasets.push_back({"flock_tracks/time", "time", "s", {n}, states.time});
    r.datasets.push_back({"flock_tracks/size", "polar rods in the flock", "", {n}, size});
    r.datasets.push_back({"flock_tracks/x", "centre, x (periodic mean)", "mm", {n}, states.x});
    r.datasets.push_back({"flock_tracks/y", "centre, y", "mm", {n}, states.y});
    r.datasets.push_back({"flock_tracks/vx",
                          "velocity of the centre over the last frame interval, x (NaN in a "
                          "track's first frame)",
                          "mm/s",
                          {n},
                          states.vx});
    r.datasets.push_back({"flock_tracks/vy", "velocity of the centre, y", "mm/s", {n}, states.vy});
    r.datasets.push_back({"flock_tracks/polar_order",
                          "polar order of the flock's rods",
                          "",
                          {n},
                          states.polar_order});
    r.datasets.push_back(
        {"flock_tracks/heading", "mean direction of the flock's rods", "rad", {n}, states.heading});
    r.datasets.push_back({"flock_tracks/leader",
                          "the leading rod (furthest ahead along the motion), body index in the "
                          "trajectory",
                          "",
                          {n},
                          leader});
}

}  // namespace rodsea
