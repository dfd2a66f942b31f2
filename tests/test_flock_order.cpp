// The order that independently heading flocks would give (analysis/flock_order.hpp): its limits
// (one aligned flock, lone rods only), a constructed frame, and its defining property, that it is
// the root mean square of P over random rotations of each flock and lone rod.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "rodsea/analysis/flock_order.hpp"
#include "rodsea/engine/order_parameters.hpp"

namespace rodsea {
namespace {

TEST(FlockOrder, OneAlignedFlockIsFullyOrderedAndLoneRodsAreARandomWalk) {
    const std::vector<double> aligned(12, 0.7);
    EXPECT_DOUBLE_EQ(independent_flock_order(aligned, std::vector<int>(12, 0)), 1.0);
    // 16 lone rods: √(16)/16, the 1/√N of independent headings, whatever the headings are.
    std::vector<double> lone;
    for (int i = 0; i < 16; ++i)
        lone.push_back(0.1 * i);
    EXPECT_NEAR(independent_flock_order(lone, std::vector<int>(16, -1)), 0.25, 1e-15);
    EXPECT_EQ(independent_flock_order({}, {}), 0.0);
}

TEST(FlockOrder, AlignedFlocksCountAsTheirSizesSquared) {
    // Flocks of 3 and 5 rods, each aligned within itself but heading apart, and 2 lone rods:
    // √(3² + 5² + 1 + 1) / 10 = 0.6, independent of where each flock heads.
    const std::vector<double> angles{0.3, 0.3, 0.3, 2.0, 2.0, 2.0, 2.0, 2.0, -1.0, 3.0};
    const std::vector<int> labels{0, 0, 0, 1, 1, 1, 1, 1, -1, -1};
    EXPECT_NEAR(independent_flock_order(angles, labels), 0.6, 1e-15);
}

TEST(FlockOrder, IsTheRootMeanSquareOfPOverRandomRotationsOfEachFlock) {
    // Flocks with internal spread (not aligned), lone rods, labels not in order.
    const std::vector<double> angles{0.1, 0.5, -0.2, 1.0, 2.9, 3.1, 2.7, 0.0, -2.0, 1.4, 1.6};
    const std::vector<int> labels{1, 1, 1, -1, 0, 0, 0, -1, -1, 2, 2};
    const double expected = independent_flock_order(angles, labels);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> turn(0.0, 2.0 * std::numbers::pi);
    const int draws = 200000;
    double sum = 0.0, sum_sq = 0.0;
    std::vector<double> rotated(angles.size());
    for (int d = 0; d < draws; ++d) {
        const double flock_turn[3] = {turn(rng), turn(rng), turn(rng)};
        for (std::size_t i = 0; i < angles.size(); ++i)
            rotated[i] = angles[i] + (labels[i] < 0 ? turn(rng) : flock_turn[labels[i]]);
        const double p2 = std::pow(orientational_order(rotated, 1), 2);
        sum += p2;
        sum_sq += p2 * p2;
    }
    const double mean = sum / draws;
    const double standard_error = std::sqrt((sum_sq / draws - mean * mean) / draws);
    // The identity is exact; the Monte Carlo mean of P² scatters by its standard error
    // (~4×10⁻⁴ here), so 4 of them fail once in ~15 000 seeds, and the seed is fixed.
    EXPECT_NEAR(mean, expected * expected, 4.0 * standard_error);
    EXPECT_LT(standard_error, 0.01 * expected * expected);  // the check has teeth
}

TEST(FlockOrder, RefusesALabelCountThatDiffersFromTheRods) {
    const std::vector<double> angles{0.0, 1.0};
    const std::vector<int> labels{0};
    EXPECT_THROW(independent_flock_order(angles, labels), std::invalid_argument);
}

}  // namespace
}  // namespace rodsea
