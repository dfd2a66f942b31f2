// Coarse-grained fields and nematic defects on constructed states whose answers are
// known: totals conserved by the cloud-in-cell kernel, aligned rods fully ordered, and director
// fields with planted ±1/2 defects (alone, in a pair, across the periodic boundary) found with
// their charge, core and, for +1/2, orientation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "defect_fields.hpp"
#include "rodsea/analysis/coarse_grained_fields.hpp"
#include "rodsea/analysis/defect_tracks.hpp"
#include "rodsea/analysis/nematic_defects.hpp"
#include "rodsea/random.hpp"

namespace rodsea {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(CoarseGrainedFields, TheKernelConservesEveryTotal) {
    const PeriodicBox2D box{40.0, 30.0};
    const FieldGrid grid = FieldGrid::of(box, 4.0);
    ASSERT_EQ(grid.nx, 10);
    ASSERT_EQ(grid.ny, 7);
    SplitMix64 rng(3);
    std::vector<Vec3> x;
    std::vector<double> theta;
    std::vector<Vec3> v;
    double sum_vx = 0.0, sum_cos = 0.0;
    for (int b = 0; b < 500; ++b) {
        x.push_back({rng.uniform(-5.0, 45.0), rng.uniform(0.0, 30.0), 0.4});  // some outside
        theta.push_back(rng.uniform(-kPi, kPi));
        v.push_back({rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), 0.0});
        sum_vx += v.back().x;
        sum_cos += std::cos(theta.back());
    }
    const double area = 2.0;
    const GroupFields f = coarse_grain(grid, box, x, theta, v, area);
    double weight = 0.0, covered = 0.0, momentum = 0.0, polar = 0.0;
    for (std::size_t c = 0; c < grid.cells(); ++c) {
        weight += f.weight[c];
        covered += f.area_fraction[c] * grid.dx * grid.dy;
        momentum += f.weight[c] * f.vx[c];
        polar += f.weight[c] * f.px[c];
    }
    // Weights of a body sum to 1 exactly; the sums carry round-off only.
    EXPECT_NEAR(weight, 500.0, 1e-9);
    EXPECT_NEAR(covered, 500.0 * area, 1e-9);
    EXPECT_NEAR(momentum, sum_vx, 1e-9);
    EXPECT_NEAR(polar, sum_cos, 1e-9);
}

TEST(CoarseGrainedFields, AlignedRodsAreFullyOrderedAlongTheirAngle) {
    const PeriodicBox2D box{20.0, 20.0};
    const FieldGrid grid = FieldGrid::of(box, 2.0);
    std::vector<Vec3> x;
    std::vector<double> theta;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            x.push_back({i + 0.5, j + 0.5, 0.0});
            theta.push_back(0.4);
        }
    const GroupFields f = coarse_grain(grid, box, x, theta, {}, 1.0);
    for (std::size_t c = 0; c < grid.cells(); ++c) {
        EXPECT_NEAR(f.S(c), 1.0, 1e-12);
        EXPECT_NEAR(f.director(c), 0.4, 1e-12);
        EXPECT_NEAR(std::hypot(f.px[c], f.py[c]), 1.0, 1e-12);
        EXPECT_NEAR(f.area_fraction[c], 1.0 / 4.0 * 4.0, 1e-12);  // one body per mm², A = 1
        EXPECT_TRUE(std::isnan(f.vx[c]));
    }
}

// Q = (cos 2θ, sin 2θ) on the grid's cell centres from a director field θ(x, y).
template <class Director>
void director_field(const FieldGrid& g, Director theta, std::vector<double>& qxx,
                    std::vector<double>& qxy) {
    qxx.assign(g.cells(), 0.0);
    qxy.assign(g.cells(), 0.0);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const double t = theta((i + 0.5) * g.dx, (j + 0.5) * g.dy);
            qxx[g.index(i, j)] = std::cos(2.0 * t);
            qxy[g.index(i, j)] = std::sin(2.0 * t);
        }
}

using testing::defect_angle;

std::vector<NematicDefect> interior(const std::vector<NematicDefect>& all, double lo, double hi) {
    std::vector<NematicDefect> in;
    for (const NematicDefect& d : all)
        if (d.x > lo && d.x < hi && d.y > lo && d.y < hi) in.push_back(d);
    return in;
}

TEST(NematicDefects, APlusHalfIsFoundWithItsCoreAndOrientation) {
    const double L = 40.0;
    const FieldGrid grid = FieldGrid::of({L, L}, 1.0);
    for (const double turn : {0.0, 0.3, 1.2, -2.0}) {
        std::vector<double> qxx, qxy;
        // θ = φ/2 + turn/2 is the comet θ = φ/2 turned by `turn`.
        director_field(
            grid,
            [&](double x, double y) { return 0.5 * std::atan2(y - 20.3, x - 19.6) + 0.5 * turn; },
            qxx, qxy);
        const auto found = interior(find_nematic_defects(grid, qxx, qxy), 5.0, 35.0);
        ASSERT_EQ(found.size(), 1u) << "turn " << turn;
        EXPECT_EQ(found[0].charge, 0.5);
        // Within a cell of the planted core.
        EXPECT_LT(std::hypot(found[0].x - 19.6, found[0].y - 20.3), 1.0);
        // The orientation turns with the field; 0.1 rad: differences over one plaquette.
        EXPECT_NEAR(std::remainder(found[0].orientation - turn, 2.0 * kPi), 0.0, 0.1)
            << "turn " << turn;
    }
}

TEST(NematicDefects, AMinusHalfIsFound) {
    const double L = 40.0;
    const FieldGrid grid = FieldGrid::of({L, L}, 1.0);
    std::vector<double> qxx, qxy;
    director_field(
        grid, [&](double x, double y) { return -0.5 * std::atan2(y - 20.7, x - 20.2); }, qxx, qxy);
    const auto found = interior(find_nematic_defects(grid, qxx, qxy), 5.0, 35.0);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].charge, -0.5);
    EXPECT_LT(std::hypot(found[0].x - 20.2, found[0].y - 20.7), 1.0);
    EXPECT_TRUE(std::isnan(found[0].orientation));
}

// A ± pair summed over images is periodic: exactly two defects on the whole torus, net charge
// zero, also when the pair straddles the periodic boundary.
TEST(NematicDefects, APairOnTheTorusAlsoAcrossTheBoundary) {
    const double L = 32.0;
    const FieldGrid grid = FieldGrid::of({L, L}, 1.0);
    for (const auto& [xp, xm] : {std::pair{12.3, 20.6}, std::pair{1.4, 29.7}}) {
        std::vector<double> qxx, qxy;
        director_field(
            grid,
            [&](double x, double y) {
                return defect_angle(x, y, xp, 16.4, 0.5, L, 12) +
                       defect_angle(x, y, xm, 16.4, -0.5, L, 12);
            },
            qxx, qxy);
        const auto found = find_nematic_defects(grid, qxx, qxy);
        ASSERT_EQ(found.size(), 2u) << "pair at " << xp << ", " << xm;
        double total = 0.0;
        for (const NematicDefect& d : found) {
            total += d.charge;
            const double planted = d.charge > 0 ? xp : xm;
            const double dx = std::remainder(d.x - planted, L);
            EXPECT_LT(std::hypot(dx, d.y - 16.4), 1.0) << "charge " << d.charge;
        }
        EXPECT_EQ(total, 0.0);
    }
}

NematicDefect defect(double x, double y, double charge) {
    NematicDefect d;
    d.x = x;
    d.y = y;
    d.charge = charge;
    return d;
}

int count(const std::vector<DefectEvent>& events, DefectEvent::Kind kind) {
    return static_cast<int>(std::count_if(events.begin(), events.end(),
                                          [&](const DefectEvent& e) { return e.kind == kind; }));
}

// A +1/2 that crosses the periodic edge keeps its track; a ± pair that is created, moves apart,
// comes back and annihilates gives one creation and one annihilation, no births or deaths.
TEST(DefectTracks, TracksCrossTheEdgeAndPairsAreCreatedAndAnnihilated) {
    const PeriodicBox2D box{40.0, 40.0};
    DefectTracker tracker(box, 2.0, 3.0);
    const double xs[] = {38.5, 39.5, 0.5, 1.5};
    for (int k = 0; k < 4; ++k) {
        std::vector<NematicDefect> frame{defect(xs[k], 10.0, 0.5)};
        if (k == 1)
            frame.push_back(defect(20.0, 30.0, 0.5)), frame.push_back(defect(21.5, 30.0, -0.5));
        if (k == 2)
            frame.push_back(defect(19.5, 30.0, 0.5)), frame.push_back(defect(22.0, 30.0, -0.5));
        tracker.add_frame(0.1 * k, frame);
    }
    ASSERT_EQ(tracker.tracks().size(), 3u);
    EXPECT_EQ(tracker.tracks()[0].states.size(), 4u);  // across x = 40 → 0
    EXPECT_EQ(count(tracker.events(), DefectEvent::Kind::creation), 1);
    EXPECT_EQ(count(tracker.events(), DefectEvent::Kind::annihilation), 1);
    EXPECT_EQ(count(tracker.events(), DefectEvent::Kind::birth), 1);  // the first frame's +1/2
    EXPECT_EQ(count(tracker.events(), DefectEvent::Kind::death), 0);
    // A lone defect that vanishes dies alone; one that jumps farther than the link is a new one.
    tracker.add_frame(0.4, std::vector<NematicDefect>{defect(9.0, 10.0, 0.5)});
    EXPECT_EQ(count(tracker.events(), DefectEvent::Kind::death), 1);
    EXPECT_EQ(count(tracker.events(), DefectEvent::Kind::birth), 2);
}

}  // namespace
}  // namespace rodsea
