#include "rodsea/builder/footprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rodsea {

Footprint footprint_of(const Shape& shape) {
    Footprint f;
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (size_t s = 0; s < shape.sphere_count(); ++s) {
        lo = std::min(lo, shape.offsets[s].x - shape.radii[s]);
        hi = std::max(hi, shape.offsets[s].x + shape.radii[s]);
    }
    f.centre_offset = 0.5 * (lo + hi);
    f.half_length = 0.5 * (hi - lo);
    for (size_t s = 0; s < shape.sphere_count(); ++s) {
        const double a = shape.offsets[s].x - f.centre_offset, b = shape.offsets[s].y;
        f.along.push_back(a);
        f.across.push_back(b);
        f.radius.push_back(shape.radii[s]);
        f.half_width = std::max(f.half_width, std::abs(b) + shape.radii[s]);
        f.max_radius = std::max(f.max_radius, shape.radii[s]);
        // Sub-nanometre offsets are round-off of the principal-frame shift, not geometry.
        if (std::hypot(a, b) > 1e-9) f.rotatable = true;
    }
    return f;
}

}  // namespace rodsea
