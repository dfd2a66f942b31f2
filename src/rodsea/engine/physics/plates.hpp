#pragma once
// The two plates: base at A cos Ωt, lid w above it, both moving together.
#include <cmath>

#include "rodsea/math/hostdevice.hpp"

namespace rodsea::physics {

// The drive as the step needs it: A (mm), Ω (rad/s) and the gap w (mm).
struct PlateMotion {
    double amplitude = 0.0;
    double angular_frequency = 0.0;
    double gap = 0.0;
};

// Where the plates are at time t.
struct PlateState {
    double base_z = 0.0;      // mm
    double lid_z = 0.0;       // mm
    double velocity_z = 0.0;  // mm/s
};

RODSEA_HD inline PlateState plate_state(const PlateMotion& m, double t) {
    const double phase = m.angular_frequency * t;
    const double base = m.amplitude * std::cos(phase);
    return {base, base + m.gap, -m.amplitude * m.angular_frequency * std::sin(phase)};
}

}  // namespace rodsea::physics
