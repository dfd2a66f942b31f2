#include "rodsea/engine/species_table.hpp"

#include <algorithm>

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

}  // namespace

SpeciesTable SpeciesTable::from(const EngineParameters& params) {
    SpeciesTable t;
    t.first_sphere.push_back(0);
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
