#pragma once
#include <cmath>

#include "rodsea/engine/parameters.hpp"

namespace rodsea {

// Where the plates are at time t: base at A cos Ωt, lid w above it, both moving together.
struct PlateState {
    double base_z = 0.0;      // mm
    double lid_z = 0.0;       // mm
    double velocity_z = 0.0;  // mm/s
};

inline PlateState plate_state(const DriveParameters& drive, double t) {
    const double a = drive.amplitude();
    const double phase = drive.angular_frequency * t;
    const double base = a * std::cos(phase);
    return {base, base + drive.gap, -a * drive.angular_frequency * std::sin(phase)};
}

}  // namespace rodsea
