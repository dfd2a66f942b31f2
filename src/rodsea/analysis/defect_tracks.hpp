#pragma once
// Nematic defects followed in time: each frame's defects are linked to the previous
// frame's of the same charge, nearest first (minimum image), when they moved less than a
// linking distance. A +1/2 and a −1/2 that appear together closer than the pair distance are a
// creation; two that vanish together closer than it, an annihilation; the others are born or
// die alone (at the grid's resolution, or across a frame that missed them).
#include <span>
#include <vector>

#include "rodsea/analysis/nematic_defects.hpp"
#include "rodsea/math/periodic_box.hpp"

namespace rodsea {

struct DefectTrack {
    int id = 0;
    double charge = 0.0;
    std::vector<double> times;          // s
    std::vector<NematicDefect> states;  // one per time
};

struct DefectEvent {
    enum class Kind { birth, death, creation, annihilation };
    Kind kind;
    double time = 0.0;
    std::vector<int> tracks;  // the track (birth, death) or the pair (creation, annihilation)
};
const char* to_string(DefectEvent::Kind kind);

class DefectTracker {
  public:
    // link: the farthest a defect moves between frames (mm); pair: the farthest apart a ± pair
    // is created or annihilated (mm).
    DefectTracker(PeriodicBox2D box, double link, double pair);

    void add_frame(double time, std::span<const NematicDefect> defects);

    const std::vector<DefectTrack>& tracks() const { return tracks_; }
    const std::vector<DefectEvent>& events() const { return events_; }

  private:
    double distance(const NematicDefect& a, const NematicDefect& b) const;
    // Unmatched defects of opposite charge, closest first, paired into events of `kind`.
    void pair_up(std::vector<int>& lone, const std::vector<NematicDefect>& where, double time,
                 DefectEvent::Kind paired, DefectEvent::Kind single);

    PeriodicBox2D box_;
    double link_, pair_;
    std::vector<DefectTrack> tracks_;
    std::vector<DefectEvent> events_;
    std::vector<int> alive_;  // tracks in the previous frame
    double last_time_ = 0.0;
    std::size_t frames_ = 0;
};

}  // namespace rodsea
