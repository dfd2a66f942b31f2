// The neighbour layer: every close pair exactly once, across the periodic boundary too.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "rodsea/neighbors/periodic_cell_list.hpp"
#include "rodsea/random.hpp"

namespace rodsea {
namespace {

void expect_matches_brute_force(double lx, double ly, double cutoff, int n, std::uint64_t seed) {
    SplitMix64 rng(seed);
    std::vector<Vec3> points;
    for (int i = 0; i < n; ++i)  // some outside [0, L): the list must wrap them
        points.push_back({rng.uniform(-0.5 * lx, 1.5 * lx), rng.uniform(0, ly), rng.uniform()});
    const PeriodicBox2D box{lx, ly};
    PeriodicCellList2D cells;
    cells.build(points, box, cutoff);
    std::map<std::pair<int, int>, int> seen;
    cells.for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
        const Vec3 d = box.minimum_image(points[i] - points[j]);
        if (d.x * d.x + d.y * d.y < cutoff * cutoff)
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

TEST(PeriodicCellList, FindsEveryClosePairOnceInALargeBox) {
    expect_matches_brute_force(20.0, 13.0, 1.375, 600, 1);
}

TEST(PeriodicCellList, FindsEveryClosePairOnceWhenADirectionHasFewerThanThreeCells) {
    expect_matches_brute_force(3.0, 20.0, 1.375, 150, 2);  // 2 cells in x -> 1
    expect_matches_brute_force(2.0, 2.5, 0.8, 40, 3);      // one cell in all
}

}  // namespace
}  // namespace rodsea
