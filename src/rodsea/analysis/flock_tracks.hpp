#pragma once
// Flocks followed in time: each frame's DBSCAN flocks are linked to the previous
// frame's by the polar rods they share. A flock that takes most of one earlier flock's members,
// and most of its own from it, continues that flock's track. A flock drawing members from
// several earlier flocks is a merge (its track continues the largest contributor's; the others
// end, merged); an earlier flock whose members go to several flocks is a split (the largest part
// continues; the others start new tracks). Flocks with no predecessor are born; flocks with no
// successor die. Per track and frame: size, centre, velocity (the centre's displacement over
// the frame interval, minimum image), polar order, and its leading rod, the member furthest
// ahead along the flock's direction of motion.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

struct FlockState {
    double time = 0.0;  // s
    std::size_t size = 0;
    Vec3 centre;    // mm, in the box (periodic mean)
    Vec3 velocity;  // mm/s; NaN in the track's first frame
    double polar_order = 0.0;
    double heading = 0.0;      // rad, the mean direction of the members
    std::uint32_t leader = 0;  // the leading rod (index among the rods given)
};

// One flock of one frame: its size, centre (the periodic mean of its rods' centres), mean
// heading and polar order.
struct FlockSummary {
    std::size_t size = 0;
    Vec3 centre;           // mm, in the box
    double heading = 0.0;  // rad
    double polar_order = 0.0;
};

// The flocks of a frame from DBSCAN labels (−1: in no flock), in label order.
std::vector<FlockSummary> summarise_flocks(std::span<const int> labels,
                                           std::span<const Vec3> positions,
                                           std::span<const double> angles,
                                           const PeriodicBox2D& box);
// One flock from its rods' indices.
FlockSummary summarise_flock(std::span<const std::uint32_t> rods, std::span<const Vec3> positions,
                             std::span<const double> angles, const PeriodicBox2D& box);

struct FlockTrack {
    int id = 0;
    double born = 0.0, ended = -1.0;  // s; ended < 0 while the track lives
    std::vector<FlockState> states;
    // How many consecutive frames each leader led, in order: (rod, frames).
    std::vector<std::pair<std::uint32_t, int>> leaders;
    double lifetime() const { return (ended >= 0.0 ? ended : states.back().time) - born; }
};

// Tracks' states as columns, one entry per track and frame, in the order appended.
struct FlockStateColumns {
    std::vector<int> track;
    std::vector<double> time, size, x, y, vx, vy, polar_order, heading;
    std::vector<std::uint32_t> leader;  // index among the rods given to the tracker
    void append(const FlockTrack& t);
};

struct FlockEvent {
    enum class Kind { birth, death, merge, split };
    Kind kind;
    double time = 0.0;
    std::vector<int> from, to;  // track ids before and after
};
const char* to_string(FlockEvent::Kind kind);

class FlockTracker {
  public:
    explicit FlockTracker(PeriodicBox2D box) : box_(box) {}

    // One frame, in time order: the flock label of each rod (−1: in no flock, as dbscan gives),
    // and the rods' positions (mm) and in-plane angles (rad), the same rods in every frame.
    void add_frame(double time, std::span<const int> labels, std::span<const Vec3> positions,
                   std::span<const double> angles);

    const std::vector<FlockTrack>& tracks() const { return tracks_; }
    const std::vector<FlockEvent>& events() const { return events_; }

  private:
    PeriodicBox2D box_;
    std::vector<FlockTrack> tracks_;
    std::vector<FlockEvent> events_;
    std::vector<int> track_of_rod_;  // the previous frame's track of each rod, −1 for none
    std::vector<int> alive_;         // tracks in the previous frame
    double last_time_ = 0.0;
    bool first_ = true;
};

}  // namespace rodsea
