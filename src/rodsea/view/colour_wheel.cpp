#include "rodsea/view/colour_wheel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rodsea {

namespace {

// Saturation and value below 1 keep neighbouring hues apart on screen without the glare of pure
// RGB primaries; every hue then stays well away from grey and white.
constexpr double kSaturation = 0.80, kValue = 0.92;

Rgb hsv(double hue_turns, double saturation, double value) {
    double h = hue_turns - std::floor(hue_turns);  // [0, 1)
    h *= 6.0;
    const int sector = static_cast<int>(h) % 6;
    const double f = h - std::floor(h);
    const double p = value * (1.0 - saturation);
    const double q = value * (1.0 - saturation * f);
    const double t = value * (1.0 - saturation * (1.0 - f));
    switch (sector) {
        case 0:
            return {value, t, p};
        case 1:
            return {q, value, p};
        case 2:
            return {p, value, t};
        case 3:
            return {p, q, value};
        case 4:
            return {t, p, value};
        default:
            return {value, p, q};
    }
}

}  // namespace

Rgb direction_colour(double theta) {
    return hsv(theta / (2.0 * std::numbers::pi), kSaturation, kValue);
}

Rgb nematic_colour(double theta) {
    return direction_colour(2.0 * theta);
}

Rgb label_colour(int label) {
    if (label < 0) return {0.35, 0.35, 0.35};
    // Successive labels step round the wheel by the golden angle, so that any few consecutive
    // flocks get clearly different hues; the value alternates to separate near-repeats.
    const double golden = 0.5 * (3.0 - std::sqrt(5.0));
    return hsv(static_cast<double>(label) * golden, 0.85, label % 2 == 0 ? 0.95 : 0.70);
}

}  // namespace rodsea
