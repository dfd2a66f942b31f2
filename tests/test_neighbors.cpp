// The neighbour layer: every close pair exactly once, with its minimum-image separation, across
// the periodic boundary too.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rodsea/neighbors/periodic_grid.hpp"
#include "rodsea/neighbors/verlet_pair_list.hpp"
#include "rodsea/random.hpp"

namespace rodsea {
namespace {

void expect_matches_brute_force(double lx, double ly, double cutoff, int n, std::uint64_t seed) {
    SplitMix64 rng(seed);
    std::vector<Vec3> points;
    for (int i = 0; i < n; ++i)  // some outside [0, L): the list must wrap them
        points.push_back({rng.uniform(-0.5 * lx, 1.5 * lx), rng.uniform(0, ly), rng.uniform()});
    const PeriodicBox2D box{lx, ly};
    PeriodicGrid2D grid;
    grid.build(points, box, cutoff);
    std::map<std::pair<int, int>, int> seen;
    grid.for_each_pair_within(cutoff, [&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
        const Vec3 expected = box.minimum_image(points[i] - points[j]);
        EXPECT_NEAR(norm(d - expected), 0.0, 1e-12);
        ++seen[{std::min<int>(i, j), std::max<int>(i, j)}];
    });
    int expected = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j) {
            const Vec3 d = box.minimum_image(points[i] - points[j]);
            if (d.x * d.x + d.y * d.y >= cutoff * cutoff) continue;
            ++expected;
            EXPECT_EQ((seen[{i, j}]), 1) << "pair " << i << "," << j;
        }
    }
    EXPECT_EQ(static_cast<int>(seen.size()), expected);
    EXPECT_GT(expected, 0);
}

TEST(PeriodicGrid, FindsEveryClosePairOnceInALargeBox) {
    expect_matches_brute_force(20.0, 13.0, 1.375, 600, 1);
}

TEST(PeriodicGrid, FindsEveryClosePairOnceWhenADirectionHasFewerThanThreeCells) {
    expect_matches_brute_force(3.0, 20.0, 1.375, 150, 2);  // 2 cells in x -> 1
    expect_matches_brute_force(2.0, 2.5, 0.8, 40, 3);      // one cell in all
}

}  // namespace
}  // namespace rodsea

namespace rodsea {
namespace {

// The ball query, as the observables use it: radii from below a cell to half the box, the
// stencil path and the path where the stencil wraps around the box (minimum image per
// candidate) in one or both directions.
TEST(PeriodicGrid, BallQueryFindsExactlyTheBruteForceNeighboursAtAnyRadius) {
    SplitMix64 rng(20);
    const PeriodicBox2D box{30.0, 30.0};
    std::vector<Vec3> points;
    for (int i = 0; i < 600; ++i)
        points.push_back({rng.uniform(0, 30.0), rng.uniform(0, 30.0), 0.0});
    PeriodicGrid2D grid;
    grid.build(points, box, 2.5);
    for (const double radius : {1.0, 2.5, 6.0, 11.0, 15.0}) {
        for (std::uint32_t i = 0; i < 50; ++i) {
            std::vector<std::uint32_t> expected, found;
            for (std::uint32_t j = 0; j < points.size(); ++j) {
                const Vec3 d = box.minimum_image(points[j] - points[i]);
                if (d.x * d.x + d.y * d.y < radius * radius) expected.push_back(j);
            }
            grid.for_each_within(points[i], radius, [&](std::uint32_t j, const Vec3& d) {
                found.push_back(j);
                const Vec3 e = box.minimum_image(points[j] - points[i]);
                EXPECT_NEAR(d.x, e.x, 1e-12);
                EXPECT_NEAR(d.y, e.y, 1e-12);
            });
            std::sort(found.begin(), found.end());
            EXPECT_EQ(found, expected) << "radius " << radius << " point " << i;
        }
    }
}

}  // namespace
}  // namespace rodsea

namespace rodsea {
namespace {

TEST(PeriodicGrid, RefusesCellsCutoffsAndRadiiItCannotServe) {
    PeriodicGrid2D grid;
    const std::vector<Vec3> points{{1, 1, 0}, {2, 2, 0}};
    const PeriodicBox2D box{10, 10};
    EXPECT_THROW(grid.build(points, box, 0.0), std::invalid_argument);
    EXPECT_THROW(grid.build(points, box, std::nan("")), std::invalid_argument);
    EXPECT_THROW(grid.build(points, {0.0, 10.0}, 1.0), std::invalid_argument);
    grid.build(points, box, 1.0);  // cells of 1 mm
    const auto none = [](std::uint32_t, std::uint32_t, const Vec3&) {};
    EXPECT_THROW(grid.for_each_pair_within(1.5, none), std::invalid_argument);
    EXPECT_NO_THROW(grid.for_each_pair_within(1.0, none));
    EXPECT_THROW(grid.for_each_within(points[0], 5.5, [](std::uint32_t, const Vec3&) {}),
                 std::invalid_argument);
    // Wrapping maps into [0, L) even where x − L floor(x/L) rounds to L.
    EXPECT_EQ(PeriodicBox2D::wrap(-1e-18, 10.0), 0.0);
    EXPECT_EQ(PeriodicBox2D::wrap(-2.5, 10.0), 7.5);
    EXPECT_EQ(PeriodicBox2D::wrap(std::nextafter(20.0, 0.0), 10.0),
              std::nextafter(20.0, 0.0) - 10.0);
    EXPECT_EQ(PeriodicBox2D::wrap(34.0, 10.0), 4.0);
    EXPECT_EQ(PeriodicBox2D::wrap(-10.0, 10.0), 0.0);
}

}  // namespace
}  // namespace rodsea

namespace rodsea {
namespace {

struct Discs {
    std::vector<Vec3> points;
    std::vector<double> radii;
    std::vector<std::uint32_t> groups;
};

Discs random_discs(const PeriodicBox2D& box, int n, std::uint64_t seed) {
    SplitMix64 rng(seed);
    Discs d;
    for (int i = 0; i < n; ++i) {
        d.points.push_back({rng.uniform(-1.0, box.lx + 1.0), rng.uniform(0, box.ly), 0.0});
        d.radii.push_back(rng.uniform(0.2, 0.6875));
        d.groups.push_back(static_cast<std::uint32_t>(i / 4));
    }
    return d;
}

// Every pair of different groups closer in the plane than `reach(i, j)`, brute force.
template <class Reach>
std::vector<std::pair<std::uint32_t, std::uint32_t>> close_pairs(const Discs& d,
                                                                 const PeriodicBox2D& box,
                                                                 Reach reach) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (std::uint32_t i = 0; i < d.points.size(); ++i) {
        for (std::uint32_t j = i + 1; j < d.points.size(); ++j) {
            if (d.groups[i] == d.groups[j]) continue;
            const Vec3 s = box.minimum_image(d.points[i] - d.points[j]);
            const double r = reach(i, j);
            if (s.x * s.x + s.y * s.y < r * r) out.emplace_back(i, j);
        }
    }
    return out;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> listed(const VerletPairList& list,
                                                            const Discs& d,
                                                            const PeriodicBox2D& box) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    list.for_each_pair(d.points, [&](std::uint32_t i, std::uint32_t j, const Vec3& s) {
        EXPECT_NEAR(norm(s - box.minimum_image(d.points[i] - d.points[j])), 0.0, 1e-12);
        out.emplace_back(i, j);
    });
    return out;
}

// Built: exactly the pairs of different groups within r_i + r_j + skin, sorted by (i < j).
TEST(VerletPairList, HoldsExactlyThePairsWithinReachPlusSkinInSortedOrder) {
    const PeriodicBox2D box{12.0, 9.0};
    const Discs d = random_discs(box, 400, 7);
    VerletPairList list(0.1);
    EXPECT_TRUE(list.update(d.points, d.radii, d.groups, box));
    const auto expected = close_pairs(
        d, box, [&](std::uint32_t i, std::uint32_t j) { return d.radii[i] + d.radii[j] + 0.1; });
    EXPECT_EQ(listed(list, d, box), expected);  // brute force visits (i < j) in sorted order
    EXPECT_GT(expected.size(), 100u);
}

// Threads split the grid's cell rows: on any number of them, more than the rows too, the list is
// the brute-force one in the same order, after a first build by a larger team and after a forced
// rebuild (no pair a larger team found may linger).
TEST(VerletPairList, IsTheSameListOnAnyNumberOfThreads) {
    const PeriodicBox2D box{12.0, 9.0};
    const Discs d = random_discs(box, 400, 17);
    const auto expected = close_pairs(
        d, box, [&](std::uint32_t i, std::uint32_t j) { return d.radii[i] + d.radii[j] + 0.1; });
    for (const int threads : {1, 2, 3, 5, 64}) {
        VerletPairList list(0.1);
        EXPECT_TRUE(list.update(d.points, d.radii, d.groups, box,
                                std::numeric_limits<double>::infinity(), 7));
        list.build(d.points, d.radii, d.groups, box, threads);
        EXPECT_EQ(listed(list, d, box), expected) << threads << " threads";
        EXPECT_EQ(list.builds(), 2u);
    }
    // A box a single cell row high (fewer than three cells of the widest disc across).
    const PeriodicBox2D flat{12.0, 2.5};
    const Discs f = random_discs(flat, 60, 18);
    const auto flat_expected = close_pairs(
        f, flat, [&](std::uint32_t i, std::uint32_t j) { return f.radii[i] + f.radii[j] + 0.1; });
    VerletPairList list(0.1);
    list.build(f.points, f.radii, f.groups, flat, 4);
    EXPECT_EQ(listed(list, f, flat), flat_expected);
    EXPECT_GT(flat_expected.size(), 10u);

    // Enough points for threads to share the measurement of the largest move, whose bound is
    // made to run out at once (travel = skin): moves below skin / 2 keep the list on any number
    // of threads, one point moved past it rebuilds it on any number.
    const PeriodicBox2D wide{60.0, 60.0};
    Discs many = random_discs(wide, 5000, 19);
    std::vector<VerletPairList> lists(3, VerletPairList(0.1));
    for (int t = 0; t < 3; ++t)
        lists[static_cast<size_t>(t)].build(many.points, many.radii, many.groups, wide, t + 1);
    SplitMix64 rng(20);
    for (Vec3& p : many.points)
        p.x += rng.uniform(-0.045, 0.045);
    for (int t = 0; t < 3; ++t)
        EXPECT_FALSE(lists[static_cast<size_t>(t)].update(many.points, many.radii, many.groups,
                                                          wide, 0.1, t + 1))
            << t + 1 << " threads";
    many.points[4321].y += 0.06;
    for (int t = 0; t < 3; ++t)
        EXPECT_TRUE(lists[static_cast<size_t>(t)].update(many.points, many.radii, many.groups, wide,
                                                         0.1, t + 1))
            << t + 1 << " threads";
}

// Moves smaller than skin / 2 keep the list, and it still holds every overlapping pair; a
// sphere whose wrapped image jumps by a box side has not moved; a move past skin / 2 rebuilds.
TEST(VerletPairList, KeepsItsPairsUntilAPointMovesHalfTheSkin) {
    const PeriodicBox2D box{12.0, 9.0};
    const double skin = 0.1;
    Discs d = random_discs(box, 400, 8);
    VerletPairList list(skin);
    list.update(d.points, d.radii, d.groups, box);
    SplitMix64 rng(9);
    for (Vec3& p : d.points) {  // each point moves up to 0.035 in x and y: < skin / 2 in all
        p.x += rng.uniform(-0.035, 0.035);
        p.y += rng.uniform(-0.035, 0.035);
    }
    // The sphere furthest right belongs to a body that crossed x = L and was wrapped.
    const auto rightmost = std::max_element(d.points.begin(), d.points.end(),
                                            [](const Vec3& a, const Vec3& b) { return a.x < b.x; });
    rightmost->x -= box.lx;
    EXPECT_FALSE(list.update(d.points, d.radii, d.groups, box));
    EXPECT_EQ(list.builds(), 1u);
    const auto overlapping = close_pairs(
        d, box, [&](std::uint32_t i, std::uint32_t j) { return d.radii[i] + d.radii[j]; });
    const auto held = listed(list, d, box);
    for (const auto& pair : overlapping)
        EXPECT_TRUE(std::binary_search(held.begin(), held.end(), pair))
            << pair.first << "," << pair.second;

    d.points[10].y += 0.051;
    EXPECT_TRUE(list.update(d.points, d.radii, d.groups, box));
    EXPECT_EQ(list.builds(), 2u);
}

// The sifted visit keeps exactly the listed pairs a contact test would not reject (|d| < r_i + r_j
// in 3D, d ≠ 0), in list order and with the same d to the bit, across several blocks of pairs; a
// point with a NaN height keeps all its pairs, so that the contact search still sees the NaN.
TEST(VerletPairList, VisitsExactlyThePairsThatMayTouchInListOrder) {
    const PeriodicBox2D box{12.0, 9.0};
    Discs d = random_discs(box, 1500, 10);
    SplitMix64 rng(11);
    for (Vec3& p : d.points)
        p.z = rng.uniform(-0.5, 0.5);  // some close in the plane are apart in height
    d.points[5] = d.points[9];         // a pair at distance 0: listed, and rejected
    VerletPairList list(0.1);
    list.update(d.points, d.radii, d.groups, box);
    d.points[3].z = std::numeric_limits<double>::quiet_NaN();
    struct Visit {
        std::size_t k;  // the pair's place in the list
        std::uint32_t i, j;
        Vec3 d;
    };
    std::vector<Visit> expected;
    std::size_t nan_pairs = 0, k = 0;
    bool twins = false;
    list.for_each_pair(d.points, [&](std::uint32_t i, std::uint32_t j, const Vec3& s) {
        const double reach = d.radii[i] + d.radii[j], d2 = norm2(s);
        if (!(d2 >= reach * reach || d2 == 0.0)) expected.push_back({k, i, j, s});
        nan_pairs += std::isnan(d2);
        twins = twins || (i == 5 && j == 9);
        ++k;
    });
    ASSERT_TRUE(twins);
    const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };  // NaN ≠ NaN
    // The whole list, ranges starting and ending inside blocks (as threads split it), none.
    const std::size_t all = list.size();
    const std::vector<std::pair<std::size_t, std::size_t>> ranges = {
        {0, all}, {77, all}, {0, 300}, {300, 301}, {all / 2, all / 2}, {all / 3, 2 * all / 3}};
    for (const auto& [begin, end] : ranges) {
        std::vector<Visit> sifted;
        list.for_each_touching_pair(d.points, d.radii, begin, end,
                                    [&](std::uint32_t i, std::uint32_t j, const Vec3& s) {
                                        sifted.push_back({0, i, j, s});
                                    });
        std::vector<Visit> tail;
        std::copy_if(expected.begin(), expected.end(), std::back_inserter(tail),
                     [&](const Visit& v) { return v.k >= begin && v.k < end; });
        ASSERT_EQ(sifted.size(), tail.size()) << "pairs " << begin << " to " << end;
        for (std::size_t n = 0; n < tail.size(); ++n) {
            ASSERT_EQ(sifted[n].i, tail[n].i) << n;
            ASSERT_EQ(sifted[n].j, tail[n].j) << n;
            ASSERT_EQ(bits(sifted[n].d.x), bits(tail[n].d.x)) << n;
            ASSERT_EQ(bits(sifted[n].d.y), bits(tail[n].d.y)) << n;
            ASSERT_EQ(bits(sifted[n].d.z), bits(tail[n].d.z)) << n;
        }
    }
    EXPECT_GT(list.size(), 3u * 256u);                // several blocks
    EXPECT_LT(expected.size(), list.size() * 3 / 4);  // and the sift drops pairs
    EXPECT_GT(nan_pairs, 0u);
}

TEST(VerletPairList, RefusesASkinThatIsNotPositive) {
    EXPECT_THROW(VerletPairList(0.0), std::invalid_argument);
    EXPECT_THROW(VerletPairList(-1.0), std::invalid_argument);
}

}  // namespace
}  // namespace rodsea
