#pragma once
// What a body lying flat looks like from above: the great discs of its spheres, placed relative
// to the body's geometric centre (the middle of its span along the body x axis), not to its
// centre of mass. The builder positions geometric centres because the lattice's pitch and row
// spacing are symmetric about them, and rotating a polar rod about its middle sweeps less area
// than rotating it about its off-centre centre of mass.
#include <vector>

#include "rodsea/shape/shape.hpp"

namespace rodsea {

struct Footprint {
    std::vector<double> along;   // disc centre along the body axis from the geometric centre, mm
    std::vector<double> across;  // disc centre across the axis (0 for sphere chains), mm
    std::vector<double> radius;  // mm
    double centre_offset = 0.0;  // geometric centre along the body x axis from the centre of mass
    double half_length = 0.0;    // half the span along the axis, mm
    double half_width = 0.0;     // largest distance of a disc edge from the axis, mm
    double max_radius = 0.0;     // mm
    bool rotatable = false;      // false when turning about z moves no disc (a bead)

    size_t size() const { return radius.size(); }
};

// The footprint of a body with orientation flat_orientation(θ): its principal x axis in the
// plane, its z axis vertical. Sphere heights are ignored: two flat bodies whose discs do not
// overlap in the plane cannot overlap in 3D.
Footprint footprint_of(const Shape& shape);

}  // namespace rodsea
