#include "rodsea/engine/species_table.hpp"

#include <algorithm>
#include <cmath>

namespace rodsea {

namespace {

// The principal axis that every sphere centre of `shape` lies on, or -1.
int axis_of_spheres(const Shape& shape) {
    for (int axis = 0; axis < 3; ++axis) {
        const bool on_axis = std::all_of(
            shape.offsets.begin(), shape.offsets.end(),
            [axis](const Vec3& o) { return o[(axis + 1) % 3] == 0.0 && o[(axis + 2) % 3] == 0.0; });
        if (on_axis) return axis;
    }
    return -1;
}

// Appends the spheres of `shape` on `axis` whose line r − a u is the highest of all the spheres'
// over an interval of u in [−1, 1] (where r − a u ≥ r' − a' u for every other sphere) wider
// than kSliver, so that rounding does not keep the middle spheres of a taper, whose lines all
// meet at one u. A dropped sliver rises less than its width times the spread of slopes, 2 max|a|,
// above the kept lines: their radii grow by that for every sphere. Lines that tie everywhere
// keep their first sphere. Any other shape: its bounding sphere.
void append_outline(const Shape& shape, int axis, std::vector<double>& along,
                    std::vector<double>& radius) {
    const std::size_t n = shape.offsets.size();
    if (axis < 0) {
        double reach = 0.0;
        for (std::size_t k = 0; k < n; ++k)
            reach = std::max(reach, norm(shape.offsets[k]) + shape.radii[k]);
        along.push_back(0.0);
        radius.push_back(reach);
        return;
    }
    constexpr double kSliver = 1e-9;  // of u
    double farthest = 0.0;
    for (const Vec3& o : shape.offsets)
        farthest = std::max(farthest, std::abs(o[axis]));
    const double slack = static_cast<double>(n) * kSliver * 2.0 * farthest;  // mm
    for (std::size_t s = 0; s < n; ++s) {
        const double a_s = shape.offsets[s][axis], r_s = shape.radii[s];
        double lo = -1.0, hi = 1.0;
        for (std::size_t t = 0; t < n && lo <= hi; ++t) {
            if (t == s) continue;
            const double da = a_s - shape.offsets[t][axis], dr = r_s - shape.radii[t];
            if (da > 0.0)
                hi = std::min(hi, dr / da);
            else if (da < 0.0)
                lo = std::max(lo, dr / da);
            else if (dr < 0.0 || (dr == 0.0 && t < s))
                hi = -2.0;  // below another sphere's line everywhere, or its twin
        }
        if (hi - lo > kSliver) {
            along.push_back(a_s);
            radius.push_back(r_s + slack);
        }
    }
}

}  // namespace

SpeciesTable SpeciesTable::from(const EngineParameters& params) {
    SpeciesTable t;
    t.first_sphere.push_back(0);
    t.first_outline.push_back(0);
    for (const Species& s : params.species) {
        const Shape& shape = s.shape;
        const Vec3& i = shape.principal_inertia;
        t.inverse_mass.push_back(1.0 / shape.mass);
        t.inverse_inertia.push_back({1.0 / i.x, 1.0 / i.y, 1.0 / i.z});
        t.rotor.push_back(physics::make_rotor(i));
        double reach2 = 0.0;
        for (const Vec3& offset : shape.offsets)
            reach2 = std::max(reach2, norm2(offset));
        t.reach2.push_back(reach2);
        t.sphere_axis.push_back(axis_of_spheres(shape));
        append_outline(shape, t.sphere_axis.back(), t.outline_along, t.outline_radius);
        t.first_outline.push_back(static_cast<std::uint32_t>(t.outline_along.size()));
        t.sphere_offset.insert(t.sphere_offset.end(), shape.offsets.begin(), shape.offsets.end());
        t.sphere_radius.insert(t.sphere_radius.end(), shape.radii.begin(), shape.radii.end());
        t.first_sphere.push_back(static_cast<std::uint32_t>(t.sphere_radius.size()));
        t.plate.push_back(s.plate);
        t.polar.push_back(s.kind == BodyKind::polar_rod ? 1 : 0);
    }
    for (std::size_t a = 0; a < params.species.size(); ++a)
        for (std::size_t b = 0; b < params.species.size(); ++b)
            t.pair.push_back(params.pair_coefficients(a, b));
    return t;
}

}  // namespace rodsea
