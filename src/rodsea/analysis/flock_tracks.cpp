#include "rodsea/analysis/flock_tracks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace rodsea {

namespace {

// The periodic mean of coordinates in [0, L): the angle of the mean unit vector on the circle.
double periodic_mean(const std::vector<double>& x, double side) {
    double c = 0.0, s = 0.0;
    for (double v : x) {
        c += std::cos(2.0 * std::numbers::pi * v / side);
        s += std::sin(2.0 * std::numbers::pi * v / side);
    }
    return PeriodicBox2D::wrap(std::atan2(s, c) * side / (2.0 * std::numbers::pi), side);
}

}  // namespace

FlockSummary summarise_flock(std::span<const std::uint32_t> rods, std::span<const Vec3> positions,
                             std::span<const double> angles, const PeriodicBox2D& box) {
    FlockSummary s;
    s.size = rods.size();
    std::vector<double> xs, ys;
    double c = 0.0, sn = 0.0;
    for (std::uint32_t r : rods) {
        xs.push_back(positions[r].x);
        ys.push_back(positions[r].y);
        c += std::cos(angles[r]);
        sn += std::sin(angles[r]);
    }
    s.centre = {periodic_mean(xs, box.lx), periodic_mean(ys, box.ly), 0.0};
    s.polar_order = rods.empty() ? 0.0 : std::hypot(c, sn) / static_cast<double>(rods.size());
    s.heading = std::atan2(sn, c);
    return s;
}

std::vector<FlockSummary> summarise_flocks(std::span<const int> labels,
                                           std::span<const Vec3> positions,
                                           std::span<const double> angles,
                                           const PeriodicBox2D& box) {
    if (positions.size() != labels.size() || angles.size() != labels.size())
        throw std::invalid_argument("summarise_flocks: one label, position and angle per rod");
    std::vector<std::vector<std::uint32_t>> members;
    for (std::size_t r = 0; r < labels.size(); ++r) {
        if (labels[r] < 0) continue;
        const auto l = static_cast<std::size_t>(labels[r]);
        if (l >= members.size()) members.resize(l + 1);
        members[l].push_back(static_cast<std::uint32_t>(r));
    }
    std::vector<FlockSummary> flocks;
    for (const auto& rods : members)
        if (!rods.empty()) flocks.push_back(summarise_flock(rods, positions, angles, box));
    return flocks;
}

void FlockStateColumns::append(const FlockTrack& t) {
    for (const FlockState& s : t.states) {
        track.push_back(t.id);
        time.push_back(s.time);
        size.push_back(static_cast<double>(s.size));
        x.push_back(s.centre.x);
        y.push_back(s.centre.y);
        vx.push_back(s.velocity.x);
        vy.push_back(s.velocity.y);
        polar_order.push_back(s.polar_order);
        heading.push_back(s.heading);
        leader.push_back(s.leader);
    }
}

const char* to_string(FlockEvent::Kind kind) {
    switch (kind) {
        case FlockEvent::Kind::birth:
            return "birth";
        case FlockEvent::Kind::death:
            return "death";
        case FlockEvent::Kind::merge:
            return "merge";
        case FlockEvent::Kind::split:
            return "split";
    }
    return "";
}

void FlockTracker::add_frame(double time, std::span<const int> labels,
                             std::span<const Vec3> positions, std::span<const double> angles) {
    const std::size_t n = labels.size();
    if (positions.size() != n || angles.size() != n)
        throw std::invalid_argument("FlockTracker: one label, position and angle per rod");
    if (!first_ && (n != track_of_rod_.size() || !(time > last_time_)))
        throw std::invalid_argument("FlockTracker: the same rods in every frame, later in time");
    if (first_) track_of_rod_.assign(n, -1);

    // The members of each flock of this frame, and what they were before.
    std::map<int, std::vector<std::uint32_t>> members;
    for (std::size_t r = 0; r < n; ++r)
        if (labels[r] >= 0) members[labels[r]].push_back(static_cast<std::uint32_t>(r));
    std::map<int, std::map<int, int>> from;  // flock → earlier track → shared rods
    std::map<int, std::map<int, int>> to;    // earlier track → flock → shared rods
    for (const auto& [flock, rods] : members)
        for (std::uint32_t r : rods)
            if (const int t = track_of_rod_[r]; t >= 0) {
                ++from[flock][t];
                ++to[t][flock];
            }
    const auto largest = [](const std::map<int, int>& shares) {
        return std::max_element(shares.begin(), shares.end(),
                                [](const auto& a, const auto& b) {
                                    return a.second < b.second ||
                                           (a.second == b.second && a.first > b.first);
                                })
            ->first;
    };

    // Each earlier track continues into the flock that took most of its rods, if that flock
    // took most of its own rods from it; contested flocks go to the largest contributor.
    std::map<int, int> track_of_flock;
    std::map<int, int> continued;  // earlier track → flock
    for (const auto& [flock, shares] : from) {
        const int t = largest(shares);
        if (continued.count(t) == 0 || from[continued[t]][t] < shares.at(t)) {
            if (continued.count(t)) track_of_flock.erase(continued[t]);
            continued[t] = flock;
            track_of_flock[flock] = t;
        }
    }
    std::vector<int> alive;
    for (const auto& [flock, rods] : members) {
        int id;
        if (auto it = track_of_flock.find(flock); it != track_of_flock.end()) {
            id = it->second;
        } else {
            id = static_cast<int>(tracks_.size());
            tracks_.push_back({});
            tracks_.back().id = id;
            tracks_.back().born = time;
            // A flock of rods that were in earlier flocks split from them; else it is born.
            if (from.count(flock)) {
                for (const auto& [t, shared] : from[flock])
                    events_.push_back({FlockEvent::Kind::split, time, {t}, {id}});
            } else {
                events_.push_back({FlockEvent::Kind::birth, time, {}, {id}});
            }
        }
        if (from.count(flock) && from[flock].size() > 1) {
            FlockEvent merge{FlockEvent::Kind::merge, time, {}, {id}};
            for (const auto& [t, shared] : from[flock])
                merge.from.push_back(t);
            events_.push_back(merge);
        }
        // The flock's state: centre, heading, polar order, velocity, leader.
        FlockTrack& track = tracks_[static_cast<std::size_t>(id)];
        const FlockSummary summary = summarise_flock(rods, positions, angles, box_);
        FlockState s;
        s.time = time;
        s.size = summary.size;
        s.centre = summary.centre;
        s.polar_order = summary.polar_order;
        s.heading = summary.heading;
        const double nan = std::numeric_limits<double>::quiet_NaN();
        s.velocity = {nan, nan, nan};
        Vec3 ahead{std::cos(s.heading), std::sin(s.heading), 0.0};
        if (!track.states.empty() && track.states.back().time < time) {
            const Vec3 d = box_.minimum_image(s.centre - track.states.back().centre);
            const double dt = time - track.states.back().time;
            s.velocity = {d.x / dt, d.y / dt, 0.0};
            const double speed = std::hypot(s.velocity.x, s.velocity.y);
            if (speed > 0.0) ahead = {s.velocity.x / speed, s.velocity.y / speed, 0.0};
        }
        double front = -std::numeric_limits<double>::infinity();
        for (std::uint32_t r : rods) {
            const Vec3 d = box_.minimum_image(positions[r] - s.centre);
            const double along = d.x * ahead.x + d.y * ahead.y;
            if (along > front) front = along, s.leader = r;
        }
        if (!track.leaders.empty() && track.leaders.back().first == s.leader)
            ++track.leaders.back().second;
        else
            track.leaders.push_back({s.leader, 1});
        track.states.push_back(s);
        alive.push_back(id);
    }
    // Earlier tracks that continue nowhere: merged into another, or dead.
    for (const int t : alive_) {
        if (std::find(alive.begin(), alive.end(), t) != alive.end()) continue;
        tracks_[static_cast<std::size_t>(t)].ended = time;
        const bool merged = to.count(t) != 0;
        if (!merged) events_.push_back({FlockEvent::Kind::death, time, {t}, {}});
    }
    // `alive` lists the tracks in the order of `members`.
    std::fill(track_of_rod_.begin(), track_of_rod_.end(), -1);
    std::size_t k = 0;
    for (const auto& [flock, rods] : members) {
        for (std::uint32_t r : rods)
            track_of_rod_[r] = alive[k];
        ++k;
    }
    alive_ = std::move(alive);
    last_time_ = time;
    first_ = false;
}

}  // namespace rodsea
