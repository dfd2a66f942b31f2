// DBSCAN on rod centres in a periodic box: planted flocks are found, clusters do not care where
// the box boundary is, and the labels are scikit-learn's, number for number.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/error.hpp"
#include "rodsea/random.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

constexpr double kEps = 2.25;  // mm, the default

// Whether a and b group the same points together and call the same points noise, whatever the
// cluster numbers are.
bool same_partition(const std::vector<int>& a, const std::vector<int>& b) {
    if (a.size() != b.size()) return false;
    std::map<int, int> a_to_b, b_to_a;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if ((a[i] == -1) != (b[i] == -1)) return false;
        if (a[i] == -1) continue;
        // emplace keeps the first pairing seen: any later disagreement breaks the bijection.
        if (a_to_b.emplace(a[i], b[i]).first->second != b[i]) return false;
        if (b_to_a.emplace(b[i], a[i]).first->second != a[i]) return false;
    }
    return true;
}

int cluster_count(const std::vector<int>& labels) {
    std::set<int> clusters(labels.begin(), labels.end());
    clusters.erase(-1);
    return static_cast<int>(clusters.size());
}

// n points uniformly in a disc, random heights: z must not matter.
void add_disc(std::vector<Vec3>& points, SplitMix64& rng, double cx, double cy, double radius,
              int n) {
    for (int k = 0; k < n; ++k) {
        const double r = radius * std::sqrt(rng.uniform());
        const double phi = 2.0 * std::numbers::pi * rng.uniform();
        points.push_back({cx + r * std::cos(phi), cy + r * std::sin(phi), rng.uniform(-5.0, 5.0)});
    }
}

// Two flocks of five points (a unit square and its centre: each point has the other four within
// sqrt 2 mm, so all are core for min_samples = 5) and a point between them, 2.2 mm from one
// corner of each and beyond eps from every other point of both (2.42 and 2.75 mm): a border
// point of both flocks. One more point, 2 mm from the border point only, keeps the border point
// below core (2 corners + it + itself = 4 < 5) and is itself noise, since border points do not
// spread a cluster. Order: the border point, the flock listed first, the other, the noise point.
struct Bridge {
    std::vector<Vec3> points;
    int border = 0, left_first = 0, right_first = 0, noise = 0;
};
constexpr int kBridgeMinSamples = 5;
constexpr int kFlockSize = 5;
Bridge bridge(double x0, double y0, bool left_flock_first) {
    Bridge b;
    const auto flock = [&](double x) {
        for (const double dx : {0.0, 1.0})
            for (const double dy : {0.0, 1.0})
                b.points.push_back({x + dx, y0 + dy, 0.0});
        b.points.push_back({x + 0.5, y0 + 0.5, 0.0});
    };
    b.points.push_back({x0 + 3.2, y0, 0.0});
    b.border = 0;
    if (left_flock_first) {
        b.left_first = 1, b.right_first = 1 + kFlockSize;
        flock(x0), flock(x0 + 5.4);
    } else {
        b.right_first = 1, b.left_first = 1 + kFlockSize;
        flock(x0 + 5.4), flock(x0);
    }
    b.points.push_back({x0 + 3.2, y0 - 2.0, 0.0});
    b.noise = 1 + 2 * kFlockSize;
    return b;
}

TEST(Dbscan, FindsPlantedBlobsAndIsolatedNoise) {
    // 5x5 grids of spacing 1 mm with jitter below 0.1 mm: nearest neighbours stay within
    // 1.2 mm < eps, so every blob is connected, and even a corner sees 8 points within eps, so
    // every point is core for min_samples = 3. Blob centres 20 mm apart and noise points 10 mm
    // from everything leave no path between blobs.
    const PeriodicBox2D box{100.0, 80.0};
    SplitMix64 rng(11);
    std::vector<Vec3> points;
    std::vector<int> blob_of;
    const double centres[][2] = {{10, 10}, {30, 10}, {50, 30}, {70, 50}, {90, 70}};
    for (int blob = 0; blob < 5; ++blob) {
        for (int i = 0; i < 5; ++i) {
            for (int j = 0; j < 5; ++j) {
                points.push_back({centres[blob][0] + i + rng.uniform(-0.1, 0.1),
                                  centres[blob][1] + j + rng.uniform(-0.1, 0.1),
                                  rng.uniform(-5.0, 5.0)});
                blob_of.push_back(blob);
            }
        }
    }
    for (const auto& [x, y] : {std::pair{20.0, 40.0}, {40.0, 60.0}, {80.0, 20.0}, {60.0, 5.0}}) {
        points.push_back({x, y, 0.0});
        blob_of.push_back(-1);
    }
    // Interleave blobs and noise, so that numbering in order of first index is not trivially
    // the order of construction.
    for (std::size_t i = points.size() - 1; i > 0; --i) {
        const std::size_t k = rng.next() % (i + 1);
        std::swap(points[i], points[k]);
        std::swap(blob_of[i], blob_of[k]);
    }

    const std::vector<int> labels = dbscan(points, box, {kEps, 3});
    EXPECT_TRUE(same_partition(labels, blob_of));
    EXPECT_EQ(cluster_count(labels), 5);
    // All points are core or noise here, so the clusters appear in the order 0, 1, 2, ...
    int next = 0;
    for (const int label : labels) {
        if (label == next) ++next;
        EXPECT_LT(label, next) << "cluster " << label << " appears before cluster " << next;
    }
}

TEST(Dbscan, ClusterAcrossTheBoundaryIsOne) {
    // A chain of spacing 1 mm through x = 0, given half below 0 and half near L (as unwrapped
    // and wrapped coordinates both occur in trajectories): one cluster.
    const PeriodicBox2D box{40.0, 30.0};
    std::vector<Vec3> chain;
    for (int k = -3; k <= 3; ++k)
        chain.push_back({k < 0 ? box.lx + k : k, 15.0, 0.0});
    chain.push_back({-3.5, 15.5, 0.0});  // the same side as x = 36.5
    const std::vector<int> chain_labels = dbscan(chain, box, {kEps, 3});
    EXPECT_EQ(chain_labels, std::vector<int>(chain.size(), 0));

    // Four points at the four corners of the box, 0.5 mm in from each side: each is 1 mm from
    // two of them and sqrt 2 mm from the one across both x and y. With min_samples = 4 a
    // point is core only if that diagonal neighbour counts: without the double wrap all four
    // would be noise.
    for (const double lo : {0.5, -0.5}) {  // inside the box, and the same points given outside
        const std::vector<Vec3> corners{{lo, lo, 0.0},
                                        {box.lx - 0.5, 0.5, 0.0},
                                        {0.5, box.ly - 0.5, 0.0},
                                        {box.lx - lo, box.ly - lo, 0.0}};
        EXPECT_EQ(dbscan(corners, box, {kEps, 4}), std::vector<int>(4, 0)) << "lo = " << lo;
    }
}

// Blobs (some wrapping, some touching), bridges and uniform noise in a non-square box. The two
// bridges sit in a strip (y > 37 mm, away from x = 30 and the corner) that the random blobs
// cannot reach, and noise keeps 3 mm from them, so that their border points stay shared.
const PeriodicBox2D kMixedBox{60.0, 45.0};
std::vector<Vec3> mixed_configuration(std::uint64_t seed) {
    const PeriodicBox2D& box = kMixedBox;
    SplitMix64 rng(seed);
    std::vector<Vec3> points;
    add_disc(points, rng, 0.5, 20.0, 3.0, 40);           // across x = 0
    add_disc(points, rng, 30.0, box.ly - 0.5, 3.0, 40);  // across y = L
    add_disc(points, rng, box.lx - 1.0, 1.0, 3.5, 50);   // across the corner
    add_disc(points, rng, 20.0, 10.0, 4.0, 35);          // sparse: core and border points
    add_disc(points, rng, 26.0, 10.0, 2.0, 15);          // 6 mm away: may or may not join
    for (int k = 0; k < 8; ++k)                          // varied density
        add_disc(points, rng, rng.uniform(0.0, box.lx), rng.uniform(5.0, 27.0),
                 rng.uniform(1.5, 5.0), 10 + static_cast<int>(rng.next() % 25));
    std::vector<Vec3> bridges;
    for (const auto& [x0, left] : {std::pair{10.0, true}, {40.0, false}}) {
        const Bridge b = bridge(x0, 41.0, left);
        points.insert(points.begin() + static_cast<long>(rng.next() % points.size()),
                      b.points.begin(), b.points.end());
        bridges.insert(bridges.end(), b.points.begin(), b.points.end());
    }
    while (points.size() < 450) {
        const Vec3 q{rng.uniform(0.0, box.lx), rng.uniform(0.0, box.ly), 0.0};
        if (std::all_of(bridges.begin(), bridges.end(),
                        [&](const Vec3& r) { return norm(box.minimum_image(q - r)) > 3.0; }))
            points.push_back(q);
    }
    const Vec3 duplicate = points[7];  // exact duplicates: distance 0 counts
    points.push_back(duplicate);
    points.push_back(duplicate);
    points.push_back({5.0, 35.0, 0.0});  // a pair exactly eps apart (2.25² = 5.0625 exactly)
    points.push_back({5.0 + kEps, 35.0, 0.0});
    return points;
}

TEST(Dbscan, PartitionIsInvariantUnderPeriodicShifts) {
    // Labels depend only on the neighbour sets and the index order, and a shift (mod L) keeps
    // both: the labels must be identical, numbering included. Rounding moves separations by
    // ~1e-14 mm; with fixed seeds no pair lies that close to eps except the planted exact-eps
    // pair, whose shifts below are multiples of 2^-4 mm (exact in binary).
    const PeriodicBox2D box = kMixedBox;
    const std::vector<Vec3> points = mixed_configuration(5);
    for (const int min_samples : {3, 6}) {
        const std::vector<int> reference = dbscan(points, box, {kEps, min_samples});
        ASSERT_GT(cluster_count(reference), 3);
        SplitMix64 rng(17);
        for (int trial = 0; trial < 6; ++trial) {
            const double sx = std::round(16.0 * rng.uniform(-2.0 * box.lx, 2.0 * box.lx)) / 16.0;
            const double sy = std::round(16.0 * rng.uniform(-2.0 * box.ly, 2.0 * box.ly)) / 16.0;
            std::vector<Vec3> shifted = points;
            for (Vec3& p : shifted) {
                p.x += sx, p.y += sy;
                if (trial % 2 == 0)  // half the trials as wrapped positions, half unwrapped
                    p.x = PeriodicBox2D::wrap(p.x, box.lx), p.y = PeriodicBox2D::wrap(p.y, box.ly);
            }
            EXPECT_EQ(dbscan(shifted, box, {kEps, min_samples}), reference)
                << "min_samples " << min_samples << ", shift (" << sx << ", " << sy << ")";
        }
    }
}

TEST(Dbscan, MinSamplesCountsThePointItself) {
    const PeriodicBox2D box{20.0, 20.0};
    const std::vector<Vec3> pair{{5.0, 5.0, 0.0}, {6.0, 5.0, 0.0}};
    EXPECT_EQ(dbscan(pair, box, {kEps, 2}), (std::vector<int>{0, 0}));
    EXPECT_EQ(dbscan(pair, box, {kEps, 3}), (std::vector<int>{-1, -1}));
    // min_samples = 1: every point is core, a lone point is a cluster of its own.
    const std::vector<Vec3> lone{{5.0, 5.0, 0.0}, {15.0, 15.0, 0.0}};
    EXPECT_EQ(dbscan(lone, box, {kEps, 1}), (std::vector<int>{0, 1}));
    EXPECT_TRUE(dbscan({}, box, {kEps, 3}).empty());
}

TEST(Dbscan, DistanceExactlyEpsIsANeighbour) {
    // sklearn's test is distance <= eps, the cell list's is < cutoff: a pair at exactly eps
    // (representable: 2.25 and 2.25² are exact) must be found, also across the boundary, and
    // one ulp further is not.
    const PeriodicBox2D box{20.0, 20.0};
    const DbscanParameters p{kEps, 2};
    EXPECT_EQ(dbscan(std::vector<Vec3>{{0.0, 3.0, 0.0}, {kEps, 3.0, 0.0}}, box, p),
              (std::vector<int>{0, 0}));
    EXPECT_EQ(dbscan(std::vector<Vec3>{{-1.125, 3.0, 0.0}, {1.125, 3.0, 0.0}}, box, p),
              (std::vector<int>{0, 0}));
    const double beyond = std::nextafter(kEps, 10.0);
    EXPECT_EQ(dbscan(std::vector<Vec3>{{0.0, 3.0, 0.0}, {beyond, 3.0, 0.0}}, box, p),
              (std::vector<int>{-1, -1}));
}

TEST(Dbscan, BorderPointJoinsTheClusterGrownFirst) {
    const PeriodicBox2D box{30.0, 30.0};
    for (const bool left_first : {true, false}) {
        const Bridge b = bridge(10.0, 10.0, left_first);
        const std::vector<int> labels = dbscan(b.points, box, {kEps, kBridgeMinSamples});
        const int left = labels[b.left_first], right = labels[b.right_first];
        // Both flocks are clusters, distinct since the bridge point does not spread,
        // numbered in the order of their first index.
        EXPECT_EQ(left, left_first ? 0 : 1);
        EXPECT_EQ(right, left_first ? 1 : 0);
        EXPECT_EQ(labels[b.border], 0) << "border point joins the first cluster grown";
        EXPECT_EQ(labels[b.noise], -1) << "reachable only through a border point";
        for (int k = 0; k < kFlockSize; ++k) {
            EXPECT_EQ(labels[b.left_first + k], left);
            EXPECT_EQ(labels[b.right_first + k], right);
        }
    }
}

// Runs scripts/dbscan_reference.py (sklearn on the minimum-image distance matrix).
std::vector<int> sklearn_labels(const std::vector<Vec3>& points, const PeriodicBox2D& box,
                                const DbscanParameters& p, const ScratchDir& scratch) {
    const auto in = scratch.path() / "points.txt", out = scratch.path() / "labels.txt";
    const auto err = scratch.path() / "python.err";
    {
        std::ofstream f(in);
        f.precision(17);  // round-trips doubles: Python sees exactly our points
        for (const Vec3& q : points)
            f << q.x << ' ' << q.y << ' ' << q.z << '\n';
    }
    std::ostringstream cmd;
    cmd.precision(17);
    cmd << "/usr/bin/python3 '" << RODSEA_SOURCE_DIR << "/scripts/dbscan_reference.py' '"
        << in.string() << "' '" << out.string() << "' --eps " << p.eps << " --min-samples "
        << p.min_samples << " --box " << box.lx << ' ' << box.ly << " 2>'" << err.string() << "'";
    const int status = std::system(cmd.str().c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd.str() << " failed:\n"
                                                               << read_text(err);
    std::vector<int> labels;
    std::ifstream f(out);
    for (int label; f >> label;)
        labels.push_back(label);
    return labels;
}

// Points that are not core but lie within eps of core points of two different clusters: the
// case where the numbering rule decides a label. Brute force, independent of the cell list.
int shared_border_points(const std::vector<Vec3>& points, const PeriodicBox2D& box,
                         const DbscanParameters& p, const std::vector<int>& labels) {
    const auto close = [&](std::size_t i, std::size_t j) {
        const Vec3 d = box.minimum_image(points[i] - points[j]);
        return d.x * d.x + d.y * d.y <= p.eps * p.eps;
    };
    std::vector<int> count(points.size(), 0);
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = 0; j < points.size(); ++j)
            count[i] += close(i, j) ? 1 : 0;
    int shared = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (count[i] >= p.min_samples) continue;
        std::set<int> reached;
        for (std::size_t j = 0; j < points.size(); ++j)
            if (count[j] >= p.min_samples && close(i, j)) reached.insert(labels[j]);
        shared += reached.size() >= 2 ? 1 : 0;
    }
    return shared;
}

TEST(Dbscan, AgreesWithScikitLearnLabelForLabel) {
    const int probe = std::system("/usr/bin/python3 -c 'import numpy, sklearn' 2>/dev/null");
    ASSERT_TRUE(WIFEXITED(probe) && WEXITSTATUS(probe) == 0)
        << "/usr/bin/python3 cannot import numpy and sklearn, which this cross-check needs: run "
           "scripts/install-deps.sh (it installs python3-sklearn)";
    const ScratchDir scratch("dbscan-sklearn");
    struct Case {
        PeriodicBox2D box;
        DbscanParameters p;
        bool expect_shared_border;
    };
    // The default parameters; the bridges' min_samples, where their border points are shared;
    // a denser requirement with a larger eps; and a box under three cells wide in x, where the
    // cell list falls back to one cell with an explicit minimum image.
    const Case cases[] = {{kMixedBox, {kEps, 3}, false},
                          {kMixedBox, {kEps, kBridgeMinSamples}, true},
                          {kMixedBox, {3.0, 8}, false},
                          {{6.5, 11.0}, {kEps, 4}, false}};
    int shared_total = 0;
    for (const Case& c : cases) {
        std::vector<Vec3> points = mixed_configuration(23);
        if (c.box.lx < 10.0) {
            // Mixed would fill the small box: two blobs 6.4 mm apart (one across both
            // boundaries) and a few uniform points.
            SplitMix64 rng(29);
            points.clear();
            add_disc(points, rng, 0.0, 0.0, 1.5, 8);
            add_disc(points, rng, 3.25, 5.5, 1.0, 6);
            for (int k = 0; k < 5; ++k)
                points.push_back({rng.uniform(0.0, c.box.lx), rng.uniform(0.0, c.box.ly), 0.0});
        }
        const std::vector<int> ours = dbscan(points, c.box, c.p);
        const std::vector<int> theirs = sklearn_labels(points, c.box, c.p, scratch);
        ASSERT_EQ(theirs.size(), points.size());
        SCOPED_TRACE("box " + std::to_string(c.box.lx) + " eps " + std::to_string(c.p.eps) +
                     " min_samples " + std::to_string(c.p.min_samples));
        // Same partition first (a clearer message if grouping differs), then the numbers.
        EXPECT_TRUE(same_partition(ours, theirs));
        EXPECT_EQ(ours, theirs);
        // Not a vacuous comparison: clusters and noise both present.
        EXPECT_GE(cluster_count(ours), 2);
        EXPECT_GT(std::count(ours.begin(), ours.end(), -1), 0);
        const int shared = shared_border_points(points, c.box, c.p, ours);
        if (c.expect_shared_border) {
            EXPECT_GE(shared, 2) << "the two bridges";
        }
        shared_total += shared;
    }
    RecordProperty("shared_border_points", shared_total);
}

TEST(Dbscan, RejectsInvalidParameters) {
    const PeriodicBox2D box{20.0, 20.0};
    const std::vector<Vec3> points{{1.0, 1.0, 0.0}};
    for (const double eps : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()}) {
        try {
            dbscan(points, box, {eps, 3});
            ADD_FAILURE() << "eps = " << eps << " accepted";
        } catch (const InvalidParameter& e) {
            EXPECT_EQ(e.name(), "dbscan.eps");
        }
    }
    for (const int min_samples : {0, -2}) {
        try {
            dbscan(points, box, {kEps, min_samples});
            ADD_FAILURE() << "min_samples = " << min_samples << " accepted";
        } catch (const InvalidParameter& e) {
            EXPECT_EQ(e.name(), "dbscan.min_samples");
        }
    }
    EXPECT_THROW(dbscan(points, PeriodicBox2D{0.0, 20.0}, {}), InvalidParameter);
}

}  // namespace
}  // namespace rodsea
