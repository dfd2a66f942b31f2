#include "rodsea/analysis/defect_tracks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace rodsea {

const char* to_string(DefectEvent::Kind kind) {
    switch (kind) {
        case DefectEvent::Kind::birth:
            return "birth";
        case DefectEvent::Kind::death:
            return "death";
        case DefectEvent::Kind::creation:
            return "creation";
        case DefectEvent::Kind::annihilation:
            return "annihilation";
    }
    return "";
}

DefectTracker::DefectTracker(PeriodicBox2D box, double link, double pair)
    : box_(box), link_(link), pair_(pair) {
    if (!(link > 0.0) || !(pair > 0.0))
        throw std::invalid_argument("DefectTracker: link and pair distances must be positive");
}

double DefectTracker::distance(const NematicDefect& a, const NematicDefect& b) const {
    const Vec3 d = box_.minimum_image(Vec3{a.x - b.x, a.y - b.y, 0.0});
    return std::hypot(d.x, d.y);
}

void DefectTracker::pair_up(std::vector<int>& lone, const std::vector<NematicDefect>& where,
                            double time, DefectEvent::Kind paired, DefectEvent::Kind single) {
    // Candidate ± pairs by distance, closest first; each defect in one pair at most.
    std::vector<std::tuple<double, int, int>> candidates;
    for (std::size_t a = 0; a < lone.size(); ++a)
        for (std::size_t b = a + 1; b < lone.size(); ++b) {
            const NematicDefect &da = where[static_cast<std::size_t>(lone[a])],
                                &db = where[static_cast<std::size_t>(lone[b])];
            if (da.charge + db.charge != 0.0) continue;
            const double d = distance(da, db);
            if (d <= pair_) candidates.emplace_back(d, static_cast<int>(a), static_cast<int>(b));
        }
    std::sort(candidates.begin(), candidates.end());
    std::vector<bool> used(lone.size(), false);
    for (const auto& [d, a, b] : candidates) {
        if (used[static_cast<std::size_t>(a)] || used[static_cast<std::size_t>(b)]) continue;
        used[static_cast<std::size_t>(a)] = used[static_cast<std::size_t>(b)] = true;
        events_.push_back(
            {paired, time, {lone[static_cast<std::size_t>(a)], lone[static_cast<std::size_t>(b)]}});
    }
    for (std::size_t k = 0; k < lone.size(); ++k)
        if (!used[k]) events_.push_back({single, time, {lone[k]}});
}

void DefectTracker::add_frame(double time, std::span<const NematicDefect> defects) {
    if (frames_ > 0 && !(time > last_time_))
        throw std::invalid_argument("DefectTracker: frames must come later in time");
    // Links of the same charge within `link`, nearest first.
    std::vector<std::tuple<double, int, std::size_t>> links;  // distance, track, defect
    for (const int t : alive_) {
        const DefectTrack& track = tracks_[static_cast<std::size_t>(t)];
        for (std::size_t d = 0; d < defects.size(); ++d) {
            if (defects[d].charge != track.charge) continue;
            const double r = distance(track.states.back(), defects[d]);
            if (r <= link_) links.emplace_back(r, t, d);
        }
    }
    std::sort(links.begin(), links.end());
    std::vector<int> track_of(defects.size(), -1);
    std::vector<bool> continued(tracks_.size(), false);
    for (const auto& [r, t, d] : links) {
        if (continued[static_cast<std::size_t>(t)] || track_of[d] >= 0) continue;
        continued[static_cast<std::size_t>(t)] = true;
        track_of[d] = t;
    }
    // The tracks that ended: annihilated in pairs, or died.
    std::vector<int> ended;
    std::vector<NematicDefect> last_seen(tracks_.size());
    for (const int t : alive_)
        if (!continued[static_cast<std::size_t>(t)]) {
            ended.push_back(t);
            last_seen[static_cast<std::size_t>(t)] =
                tracks_[static_cast<std::size_t>(t)].states.back();
        }
    pair_up(ended, last_seen, time, DefectEvent::Kind::annihilation, DefectEvent::Kind::death);
    // Every defect continues its track or starts one; new ones are created in pairs or born.
    std::vector<int> fresh, alive;
    std::vector<NematicDefect> where(tracks_.size() + defects.size());
    for (std::size_t d = 0; d < defects.size(); ++d) {
        int t = track_of[d];
        if (t < 0) {
            t = static_cast<int>(tracks_.size());
            tracks_.push_back({t, defects[d].charge, {}, {}});
            fresh.push_back(t);
        }
        DefectTrack& track = tracks_[static_cast<std::size_t>(t)];
        track.times.push_back(time);
        track.states.push_back(defects[d]);
        alive.push_back(t);
    }
    where.resize(tracks_.size());
    for (const int t : fresh)
        where[static_cast<std::size_t>(t)] = tracks_[static_cast<std::size_t>(t)].states.back();
    pair_up(fresh, where, time, DefectEvent::Kind::creation, DefectEvent::Kind::birth);
    alive_ = std::move(alive);
    last_time_ = time;
    ++frames_;
}

}  // namespace rodsea
