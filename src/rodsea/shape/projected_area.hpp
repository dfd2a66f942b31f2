#pragma once
#include "rodsea/shape/sphere.hpp"

namespace rodsea {

// Exact area (mm²) of the union of the spheres' great discs projected on the body's x-y plane,
// i.e. the footprint of a body lying flat. Computed by Green's theorem over the boundary arcs
// of the union, so it is exact to round-off for any arrangement of discs.
double projected_area(const SphereList& spheres);

}  // namespace rodsea
