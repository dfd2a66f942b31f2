#pragma once
#include "rodsea/math/mat3.hpp"
#include "rodsea/shape/sphere.hpp"

namespace rodsea {

// Geometry of the uniform solid filling the union of the spheres, at unit density:
// volume (mm³), centre of mass (mm) and inertia tensor about the centre of mass (mm⁵).
struct MassProperties {
    double volume = 0.0;
    Vec3 centre_of_mass;
    Mat3 inertia;  // about centre_of_mass, in the definition frame, per unit density
};

// Exact to round-off for chains with all centres on the x axis (the solid is one of revolution,
// integrated piecewise with a Gauss rule that is exact for its polynomial integrands) and for
// spheres that do not overlap. Other arrangements throw InvalidParameter.
MassProperties mass_properties(const SphereList& spheres);

}  // namespace rodsea
