// Flocks followed in time on constructed sequences with planted events: a flock that moves (its
// velocity and its leader known), two that merge, one that splits, one born and one that dies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/analysis/flock_tracks.hpp"

namespace rodsea {
namespace {

// A frame of rods: labels from DBSCAN as rodsea analyze finds them.
struct Frame {
    std::vector<Vec3> x;
    std::vector<double> theta;
};

std::vector<int> labels_of(const Frame& f, const PeriodicBox2D& box) {
    return dbscan(f.x, box, {.eps = 1.5, .min_samples = 2});
}

// A line of `n` rods 1 mm apart along x, from (x0, y), heading along +x.
void add_line(Frame& f, double x0, double y, int n, double theta = 0.0) {
    for (int i = 0; i < n; ++i) {
        f.x.push_back({x0 + i, y, 0.0});
        f.theta.push_back(theta);
    }
}

int count(const std::vector<FlockEvent>& events, FlockEvent::Kind kind) {
    return static_cast<int>(std::count_if(events.begin(), events.end(),
                                          [&](const FlockEvent& e) { return e.kind == kind; }));
}

TEST(FlockTracks, AMovingFlockKeepsItsTrackVelocityAndLeader) {
    const PeriodicBox2D box{40.0, 40.0};
    FlockTracker tracker(box);
    for (int k = 0; k < 5; ++k) {  // 5 rods moving +x at 20 mm/s, frames 0.1 s apart
        Frame f;
        add_line(f, PeriodicBox2D::wrap(36.0 + 2.0 * k, 40.0), 10.0, 5);
        for (Vec3& x : f.x)
            x.x = PeriodicBox2D::wrap(x.x, 40.0);  // across the periodic edge at k = 2
        tracker.add_frame(0.1 * k, labels_of(f, box), f.x, f.theta);
    }
    ASSERT_EQ(tracker.tracks().size(), 1u);
    const FlockTrack& t = tracker.tracks()[0];
    ASSERT_EQ(t.states.size(), 5u);
    EXPECT_TRUE(std::isnan(t.states[0].velocity.x));
    for (std::size_t k = 1; k < 5; ++k) {
        EXPECT_NEAR(t.states[k].velocity.x, 20.0, 1e-9);  // the planted velocity, across the edge
        EXPECT_NEAR(t.states[k].velocity.y, 0.0, 1e-9);
        EXPECT_EQ(t.states[k].leader, 4u);  // the rod at the front
    }
    EXPECT_NEAR(t.states[0].polar_order, 1.0, 1e-12);
    ASSERT_EQ(t.leaders.size(), 1u);
    EXPECT_EQ(t.leaders[0].second, 5);
    EXPECT_NEAR(t.lifetime(), 0.4, 1e-12);
    EXPECT_EQ(count(tracker.events(), FlockEvent::Kind::birth), 1);
}

TEST(FlockTracks, TwoFlocksMergeAndOneSplits) {
    const PeriodicBox2D box{40.0, 40.0};
    FlockTracker tracker(box);
    Frame a, b, c;
    add_line(a, 5.0, 10.0, 4);   // flock 1: rods 0-3
    add_line(a, 12.0, 10.0, 6);  // flock 2: rods 4-9, 4 mm ahead of flock 1
    tracker.add_frame(0.0, labels_of(a, box), a.x, a.theta);
    add_line(b, 7.0, 10.0, 4);  // closed up: one flock of 10
    add_line(b, 11.0, 10.0, 6);
    tracker.add_frame(0.1, labels_of(b, box), b.x, b.theta);
    ASSERT_EQ(count(tracker.events(), FlockEvent::Kind::merge), 1);
    const FlockEvent& merge =
        *std::find_if(tracker.events().begin(), tracker.events().end(),
                      [](const FlockEvent& e) { return e.kind == FlockEvent::Kind::merge; });
    EXPECT_EQ(merge.from.size(), 2u);
    // The larger contributor (6 rods) carries on; the other ends, merged, not dead.
    const int survivor = merge.to[0];
    EXPECT_EQ(tracker.tracks()[static_cast<std::size_t>(survivor)].states.front().size, 6u);
    EXPECT_EQ(count(tracker.events(), FlockEvent::Kind::death), 0);
    // Then it splits 7 / 3.
    add_line(c, 7.0, 10.0, 3);
    add_line(c, 14.0, 10.0, 7);
    tracker.add_frame(0.2, labels_of(c, box), c.x, c.theta);
    ASSERT_EQ(count(tracker.events(), FlockEvent::Kind::split), 1);
    EXPECT_EQ(tracker.tracks()[static_cast<std::size_t>(survivor)].states.back().size, 7u);
}

TEST(FlockTracks, FlocksAreBornAndDie) {
    const PeriodicBox2D box{40.0, 40.0};
    FlockTracker tracker(box);
    Frame a, b;
    add_line(a, 5.0, 5.0, 3);
    a.x.push_back({30.0, 30.0, 0.0});  // alone: in no flock
    a.theta.push_back(0.0);
    a.x.push_back({20.0, 30.0, 0.0});
    a.theta.push_back(0.0);
    tracker.add_frame(0.0, labels_of(a, box), a.x, a.theta);
    // The line scatters; the two lone rods meet.
    b.x = {
        {5.0, 5.0, 0.0}, {10.0, 10.0, 0.0}, {15.0, 5.0, 0.0}, {25.0, 30.0, 0.0}, {26.0, 30.0, 0.0}};
    b.theta.assign(5, 0.0);
    tracker.add_frame(0.1, labels_of(b, box), b.x, b.theta);
    EXPECT_EQ(count(tracker.events(), FlockEvent::Kind::birth), 2);
    EXPECT_EQ(count(tracker.events(), FlockEvent::Kind::death), 1);
    EXPECT_NEAR(tracker.tracks()[0].ended, 0.1, 1e-12);
}

}  // namespace
}  // namespace rodsea
