#include "rodsea/builder/placement.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/error.hpp"

namespace rodsea {

long long count_for_area_fraction(double area_fraction, const Box& box, const Shape& shape) {
    require_in_closed_range("area_fraction", area_fraction, 0.0, 1.0);
    return std::llround(area_fraction * box.lx * box.ly / shape.projected_area);
}

Quat flat_orientation(double angle) {
    return Quat::from_axis_angle({0, 0, 1}, angle);
}

Quat tipped_orientation(double angle, double tilt) {
    return flat_orientation(angle) * Quat::from_axis_angle({0, 1, 0}, -tilt);
}

double resting_height(const Shape& shape, const Quat& orientation, const DriveParameters& drive,
                      double clearance) {
    double lowest = 0.0;  // lowest point of the body relative to its centre of mass
    for (size_t s = 0; s < shape.sphere_count(); ++s)
        lowest = std::min(lowest, rotate(orientation, shape.offsets[s]).z - shape.radii[s]);
    return physics::plate_state(drive.motion(), 0.0).base_z - lowest + clearance;
}

}  // namespace rodsea
