#pragma once
// The box, periodic in x and y (the plates bound z): wrapping into it and the minimum image.
#include <cmath>

#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

struct PeriodicBox2D {
    double lx = 0.0, ly = 0.0;  // mm

    // x mapped into [0, side): exactly, including the x just below 0 that rounds to side.
    // Without a division for x within one side of the box, the usual case (a body moved
    // micrometres in a step): free flight wraps every body every step.
    RODSEA_HD static double wrap(double x, double side) {
        if (x >= 0.0 && x < side) return x;
        if (x >= side && x < 2.0 * side) return x - side;  // exact (Sterbenz), so below side
        const double w = x < 0.0 && x >= -side ? x + side : x - side * std::floor(x / side);
        return w < side ? w : 0.0;
    }

    // Minimum-image difference in x and y; z untouched.
    RODSEA_HD Vec3 minimum_image(Vec3 d) const {
        d.x -= lx * std::nearbyint(d.x / lx);
        d.y -= ly * std::nearbyint(d.y / ly);
        return d;
    }
};

}  // namespace rodsea
