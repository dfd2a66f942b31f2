// The sphere table's world centres: for a body whose spheres lie on one principal axis (every rod
// and bead) they are x + s u, u one column of the rotation, which must equal the general
// x + R · offset to the last bit (the products with zero offset components add ±0), and any other
// body keeps the general product.
#include <gtest/gtest.h>

#include <cmath>

#include "rodsea/engine/cpu/sphere_table.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

TEST(SphereTable, SpheresOnAnAxisAreWhereTheRotationMatrixPutsThem) {
    EngineParameters params;
    params.species = {
        polar_rod_species(), apolar_rod_species(2.5), bead_species(),
        Species{"bent",
                BodyKind::bead,
                make_shape({{{0, 0, 0}, 0.3}, {{1.0, 0.2, 0}, 0.2}, {{0.1, 0.9, 0.3}, 0.25}}, 1.0),
                {0.0, 0.3}}};
    // The rods' and the bead's centres lie on x exactly, so they take the x + s u path.
    const std::vector<Species>& species = params.species;
    for (size_t k = 0; k < 3; ++k)
        for (const Vec3& o : species[k].shape.offsets) {
            ASSERT_EQ(o.y, 0.0);
            ASSERT_EQ(o.z, 0.0);
        }
    BodyState bodies;
    std::uint64_t h = 3;
    const auto uniform = [&h] {
        h = splitmix64(h);
        return static_cast<double>(h >> 11) * 0x1.0p-53 * 2.0 - 1.0;  // [-1, 1)
    };
    for (std::uint32_t b = 0; b < 400; ++b) {
        const Vec3 axis{uniform(), uniform(), uniform()};
        bodies.add(b % 4, {50 * uniform(), 50 * uniform(), uniform()},
                   Quat::from_axis_angle(normalized(axis), 3.2 * uniform()));
    }
    const SpeciesTable table_species = SpeciesTable::from(params);
    cpu::SphereTable table;
    table.assign(bodies.species, table_species);
    table.update_positions(bodies.view(), table_species, 1);
    for (std::uint32_t b = 0; b < bodies.size(); ++b) {
        const Mat3 r = to_matrix(bodies.orientation[b]);
        const Shape& shape = species[bodies.species[b]].shape;
        for (std::uint32_t s = table.first_of[b]; s < table.first_of[b + 1]; ++s) {
            const Vec3 expected = bodies.position[b] + r * shape.offsets[s - table.first_of[b]];
            ASSERT_EQ(table.position[s].x, expected.x) << "body " << b;
            ASSERT_EQ(table.position[s].y, expected.y) << "body " << b;
            ASSERT_EQ(table.position[s].z, expected.z) << "body " << b;
        }
    }
}

}  // namespace
}  // namespace rodsea
