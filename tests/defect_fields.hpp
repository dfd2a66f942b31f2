#pragma once
// Director fields with planted nematic defects, for the tests of the defect search, its
// observable and its overlay.
#include <cmath>

namespace rodsea::testing {

// The director angle at (x, y) of a defect of charge k at (x0, y0) summed over its periodic
// images in a square box of side L, `images` boxes out each way: θ = k Σ arg(r − r_n). One
// charge alone is not periodic (a torus holds zero net charge): a ± pair summed this way is.
inline double defect_angle(double x, double y, double x0, double y0, double k, double L,
                           int images) {
    double t = 0.0;
    for (int a = -images; a <= images; ++a)
        for (int b = -images; b <= images; ++b)
            t += k * std::atan2(y - y0 - b * L, x - x0 - a * L);
    return t;
}

// A +1/2 at (xp, y0) and a −1/2 at (xm, y0), periodic in a box of side L.
inline double pair_angle(double x, double y, double xp, double xm, double y0, double L) {
    return defect_angle(x, y, xp, y0, 0.5, L, 8) + defect_angle(x, y, xm, y0, -0.5, L, 8);
}

}  // namespace rodsea::testing
