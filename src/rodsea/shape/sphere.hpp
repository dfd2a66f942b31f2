#pragma once
#include <vector>

#include "rodsea/math/vec3.hpp"

namespace rodsea {

// One sphere of a rigid body, in the frame the shape was defined in (mm).
struct Sphere {
    Vec3 centre;
    double radius = 0.0;
};

using SphereList = std::vector<Sphere>;

}  // namespace rodsea
