// The sphere table's world centres: for a body whose spheres lie on one principal axis (every rod
// and bead) they are x + s u, u one column of the rotation, which must equal the general
// x + R · offset to the last bit (the products with zero offset components add ±0), and any other
// body keeps the general product.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rodsea/engine/cpu/contact_search.hpp"
#include "rodsea/engine/cpu/sphere_table.hpp"
#include "rodsea/engine/physics/contact_geometry.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

// Three spheres on no common axis: the general path of every stage.
Species bent_species() {
    return {"bent",
            BodyKind::bead,
            make_shape({{{0, 0, 0}, 0.3}, {{1.0, 0.2, 0}, 0.2}, {{0.1, 0.9, 0.3}, 0.25}}, 1.0),
            {0.0, 0.3}};
}

TEST(SphereTable, SpheresOnAnAxisAreWhereTheRotationMatrixPutsThem) {
    EngineParameters params;
    params.species = {polar_rod_species(), apolar_rod_species(2.5), bead_species(), bent_species()};
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

// The plate search skips whole bodies whose bounds on their lowest sphere bottom and highest top
// (from the centre and the tilt) lie between the plates. The bounds must hold for every sphere as
// rounded, and the search must find exactly what a scan of every sphere finds: the same contacts,
// in sphere order, with the same overlaps to the bit, on one thread and two, in a layer whose
// bodies (rods, tapered rods, beads and a shape off any axis) are thrown at every height and tilt
// so that some poke through the base, some through the lid, some through both, and many through
// neither.
TEST(PlateSearch, SkipsBodiesClearOfThePlatesAndFindsWhatAScanOfEverySphereFinds) {
    EngineParameters params;
    params.box = {40.0, 40.0};
    params.species = {polar_rod_species(), apolar_rod_species(4.5), bead_species(), bent_species()};
    const StepContext step = step_context(params, 0);
    const physics::PlateState& plates = step.plates;
    BodyState bodies;
    SplitMix64 rng(5);
    for (std::uint32_t b = 0; b < 600; ++b) {
        const Vec3 axis{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-0.3, 0.3)};
        bodies.add(b % 4,
                   {rng.uniform(0, 40), rng.uniform(0, 40),
                    rng.uniform(plates.base_z - 0.3, plates.lid_z + 0.3)},
                   Quat::from_axis_angle(normalized(axis), rng.uniform(-3.2, 3.2)));
    }
    // Rods lying flat, as most do in a layer, at heights that leave some clear of both plates.
    for (std::uint32_t b = 0; b < 200; ++b)
        bodies.add(b % 2,
                   {rng.uniform(0, 40), rng.uniform(0, 40),
                    rng.uniform(plates.base_z + 0.3, plates.lid_z - 0.3)},
                   Quat::from_axis_angle({0.0, 0.0, 1.0}, rng.uniform(-3.2, 3.2)));
    // Flat rods whose thick middle's bottom or top is at a plate, and an ulp either side: the
    // margin, not luck, must keep them searched.
    const std::vector<double>& radii = params.species[1].shape.radii;
    const double r = *std::max_element(radii.begin(), radii.end());
    for (const double z : {plates.base_z + r, plates.lid_z - r})
        for (const double toward : {-1.0, 1.0}) {
            bodies.add(1, {1.0, 1.0, z}, Quat{});
            bodies.add(1, {1.0, 1.0, std::nextafter(z, toward * 1e9)}, Quat{});
        }
    const SpeciesTable species = SpeciesTable::from(params);
    cpu::SphereTable spheres;
    spheres.assign(bodies.species, species);
    spheres.update_positions(bodies.view(), species, 1);

    std::vector<Contact> expected;
    for (std::size_t s = 0; s < spheres.size(); ++s) {
        const physics::PlateOverlaps o =
            physics::plate_overlaps(spheres.position[s].z, spheres.radius[s], plates);
        const std::uint32_t b = spheres.body[s];
        const ContactCoefficients& k = species.plate[bodies.species[b]];
        if (o.base > 0.0)
            expected.push_back(physics::plate_contact(b, spheres.position[s], spheres.radius[s],
                                                      bodies.position[b], true, o.base, k));
        if (o.lid > 0.0)
            expected.push_back(physics::plate_contact(b, spheres.position[s], spheres.radius[s],
                                                      bodies.position[b], false, o.lid, k));
    }
    // The outline: the tapered polar rod's two ends, the apolar rod's two ends and thick middle,
    // the bead (unused: a lone sphere is read directly), the bent shape's bounding sphere. A
    // bound on a rod is its extreme sphere to the slack and the margin (2 × 17 × 10⁻⁹ × 2.05 mm
    // = 7×10⁻⁸ mm for the 4.5 mm rod, the widest, and 10⁻¹² of the heights): within 10⁻⁷ mm. On
    // the bent shape, a bound.
    EXPECT_EQ(species.first_outline, (std::vector<std::uint32_t>{0, 2, 5, 6, 7}));
    std::size_t clear = 0, base_and_lid = 0;
    for (std::uint32_t b = 0; b < bodies.size(); ++b) {
        if (bodies.species[b] == 2) continue;  // a bead is read directly: no bounds
        double low = spheres.lowest[b] + 1.0, high = spheres.highest[b] - 1.0;
        for (std::uint32_t s = spheres.first_of[b]; s < spheres.first_of[b + 1]; ++s) {
            ASSERT_LE(spheres.lowest[b], spheres.position[s].z - spheres.radius[s]) << b;
            ASSERT_GE(spheres.highest[b], spheres.position[s].z + spheres.radius[s]) << b;
            low = std::min(low, spheres.position[s].z - spheres.radius[s]);
            high = std::max(high, spheres.position[s].z + spheres.radius[s]);
        }
        if (bodies.species[b] != 3) {
            EXPECT_NEAR(spheres.lowest[b], low, 1e-7) << b;
            EXPECT_NEAR(spheres.highest[b], high, 1e-7) << b;
        }
        clear += spheres.lowest[b] >= plates.base_z && spheres.highest[b] <= plates.lid_z;
        base_and_lid += spheres.lowest[b] < plates.base_z && spheres.highest[b] > plates.lid_z;
    }
    ASSERT_GT(clear, 50u);        // the skip is taken (how often in a layer: the benchmarks)
    ASSERT_GT(base_and_lid, 0u);  // and a tilted rod spans the gap
    ASSERT_GT(expected.size(), 300u);

    for (int threads = 1; threads <= 2; ++threads) {
        cpu::ContactFinder finder;
        std::vector<Contact> found;
        const cpu::ContactSearchStats stats =
            finder.find(spheres, bodies.view(), species, step, found, threads);
        ASSERT_EQ(stats.plate_contacts, expected.size()) << threads << " threads";
        for (std::size_t i = 0; i < expected.size(); ++i) {
            const Contact& c = found[stats.body_contacts + i];
            const Contact& e = expected[i];
            ASSERT_EQ(c.a, e.a) << i;
            ASSERT_EQ(c.b, e.b) << i;
            ASSERT_EQ(c.overlap, e.overlap) << i;
            ASSERT_EQ(c.arm_a.x, e.arm_a.x) << i;
            ASSERT_EQ(c.arm_a.z, e.arm_a.z) << i;
        }
    }
}

}  // namespace
}  // namespace rodsea
