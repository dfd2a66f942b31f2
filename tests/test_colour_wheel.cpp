// The colour wheels of `rodsea render`: a polar rod's colour turns with its axis and tells head
// from tail; the medium's nematic colour does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rodsea/view/colour_wheel.hpp"

namespace rodsea {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ColourWheel, PeriodicInTheAngleAndDistinctForOppositeDirections) {
    for (double theta : {0.0, 0.7, 2.0, -2.5}) {
        const Rgb a = direction_colour(theta), b = direction_colour(theta + 2.0 * kPi);
        EXPECT_NEAR(a.r, b.r, 1e-12);
        EXPECT_NEAR(a.g, b.g, 1e-12);
        EXPECT_NEAR(a.b, b.b, 1e-12);
        const Rgb n = nematic_colour(theta), m = nematic_colour(theta + kPi);
        EXPECT_NEAR(n.r, m.r, 1e-12);
        EXPECT_NEAR(n.g, m.g, 1e-12);
        EXPECT_NEAR(n.b, m.b, 1e-12);
        // A head and a tail must not look alike: opposite directions differ by a lot in some
        // channel (the wheel's complementary hues).
        const Rgb o = direction_colour(theta + kPi);
        EXPECT_GT(std::max({std::abs(a.r - o.r), std::abs(a.g - o.g), std::abs(a.b - o.b)}), 0.5);
    }
    // θ = 0 (along +x) is red.
    const Rgb red = direction_colour(0.0);
    EXPECT_GT(red.r, 0.9);
    EXPECT_LT(std::max(red.g, red.b), 0.2);
}

}  // namespace
}  // namespace rodsea
