// Shapes: sphere chains, exact projected areas, mass properties and the paper's counts.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rodsea/engine/parameters.hpp"
#include "rodsea/scenes/scenes.hpp"
#include "rodsea/shape/mass_properties.hpp"
#include "rodsea/shape/projected_area.hpp"
#include "rodsea/shape/shape.hpp"
#include "rodsea/shape/sphere_chain.hpp"

namespace rodsea {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(MassProperties, OneSphereMatchesAnalytic) {
    const double r = 0.4;
    const MassProperties mp = mass_properties({{{0.3, 0, 0}, r}});
    const double v = 4.0 / 3.0 * kPi * r * r * r;
    EXPECT_NEAR(mp.volume, v, 1e-14 * v);
    EXPECT_NEAR(mp.centre_of_mass.x, 0.3, 1e-14);
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(mp.inertia(k, k), 0.4 * v * r * r, 1e-14 * v);
}

TEST(MassProperties, TwoTouchingEqualSpheresMatchParallelAxis) {
    const double r = 0.5;
    const MassProperties mp = mass_properties({{{-r, 0, 0}, r}, {{r, 0, 0}, r}});
    const double v1 = 4.0 / 3.0 * kPi * r * r * r;
    EXPECT_NEAR(mp.volume, 2 * v1, 1e-13 * v1);
    EXPECT_NEAR(mp.centre_of_mass.x, 0.0, 1e-14);
    EXPECT_NEAR(mp.inertia(0, 0), 2 * 0.4 * v1 * r * r, 1e-13 * v1);
    EXPECT_NEAR(mp.inertia(1, 1), 2 * (0.4 * v1 * r * r + v1 * r * r), 1e-13 * v1);
    EXPECT_NEAR(mp.inertia(2, 2), mp.inertia(1, 1), 1e-13 * v1);
}

// Independent check of the piecewise-exact integration of an overlapping chain: a plain
// midpoint rule on ρ(x)² with 2·10⁵ slices (error ~1e-9 relative, far below the 1e-4 docs/model.md
// asks for).
TEST(MassProperties, PolarRodAgreesWithBruteForceIntegration) {
    const SphereList spheres = polar_rod_spheres({});
    const MassProperties mp = mass_properties(spheres);
    const int n = 200000;
    const double lo = -2.25, hi = 2.25, h = (hi - lo) / n;
    double v = 0, m1 = 0, ixx = 0, m2 = 0;
    for (int i = 0; i < n; ++i) {
        const double x = lo + (i + 0.5) * h;
        double r2 = 0;
        for (const Sphere& s : spheres)
            r2 = std::max(r2, s.radius * s.radius - (x - s.centre.x) * (x - s.centre.x));
        v += kPi * r2 * h;
        m1 += kPi * r2 * x * h;
        m2 += kPi * r2 * x * x * h;
        ixx += 0.5 * kPi * r2 * r2 * h;
    }
    const double xc = m1 / v;
    EXPECT_NEAR(mp.volume, v, 1e-7 * v);
    EXPECT_NEAR(mp.centre_of_mass.x, xc, 1e-7);
    EXPECT_NEAR(mp.inertia(0, 0), ixx, 1e-7 * ixx);
    EXPECT_NEAR(mp.inertia(1, 1), 0.5 * ixx + m2 - v * xc * xc, 1e-7 * mp.inertia(1, 1));
    // docs/model.md: the centre of mass sits ≈ 0.68 mm from the geometric centre, toward the thick
    // (−x) end.
    EXPECT_NEAR(mp.centre_of_mass.x, -0.68, 0.01);
}

TEST(ProjectedArea, TwoOverlappingDiscsMatchTheLensFormula) {
    const double r1 = 0.7, r2 = 0.4, d = 0.8;
    const double lens =
        r1 * r1 * std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1)) +
        r2 * r2 * std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2)) -
        0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2));
    const double expected = kPi * (r1 * r1 + r2 * r2) - lens;
    EXPECT_NEAR(projected_area({{{0, 0, 0}, r1}, {{d, 0, 0}, r2}}), expected, 1e-14);
    // Off-axis arrangement, contained disc and duplicate disc.
    EXPECT_NEAR(projected_area({{{0.1, 0.2, 0}, r1}, {{0.1 + d * 0.6, 0.2 + d * 0.8, 0}, r2}}),
                expected, 1e-14);
    EXPECT_NEAR(projected_area({{{0, 0, 0}, r1}, {{0.1, 0, 0}, 0.2}}), kPi * r1 * r1, 1e-14);
    EXPECT_NEAR(projected_area({{{0, 0, 0}, r1}, {{0, 0, 0}, r1}}), kPi * r1 * r1, 1e-14);
}

// docs/model.md §2 gives the areas to 5 decimals; the construction must reproduce all of them.
TEST(ProjectedArea, ApolarRodsAndBeadsMatchModel) {
    const std::pair<double, double> expected[] = {
        {1.0, 0.56258}, {1.5, 0.80975}, {2.0, 1.08494}, {2.5, 1.36762}, {4.5, 2.51796}};
    for (const auto& [length, area] : expected) {
        const auto g = ApolarRodGeometry::with_length(length);
        EXPECT_EQ(g.sphere_count, static_cast<int>(std::lround(4 * length - 1)));
        EXPECT_NEAR(projected_area(apolar_rod_spheres(g)), area, 5e-6) << "l_a = " << length;
    }
    EXPECT_NEAR(projected_area(bead_spheres({})), 0.50265, 5e-6);
    EXPECT_NEAR(projected_area(polar_rod_spheres({})), 3.971, 5e-4);
}

struct TableS1Row {
    const char* name;
    double length;  // mm; 0.8 with one sphere = bead
    double phi_lo, phi_hi;
    long long n_lo, n_hi;
};

// The paper's Table S1 ends for L = 252 mm (docs/model.md §2).
TEST(Counts, ReproduceTableS1) {
    const Box box{252.0, 252.0};
    const TableS1Row rows[] = {
        {"l_a=1.0", 1.0, 0.05, 0.75, 5644, 84660}, {"l_a=1.5", 1.5, 0.05, 0.50, 3921, 39212},
        {"l_a=2.0", 2.0, 0.05, 0.50, 2927, 29266}, {"l_a=2.5", 2.5, 0.05, 0.80, 2322, 37147},
        {"l_a=4.5", 4.5, 0.05, 0.75, 1261, 18915},
    };
    for (const TableS1Row& row : rows) {
        const Shape shape = apolar_rod_species(row.length).shape;
        EXPECT_EQ(count_for_area_fraction(row.phi_lo, box, shape), row.n_lo) << row.name;
        EXPECT_EQ(count_for_area_fraction(row.phi_hi, box, shape), row.n_hi) << row.name;
    }
    const Shape bead = bead_species().shape;
    EXPECT_EQ(count_for_area_fraction(0.05, box, bead), 6317);
    EXPECT_EQ(count_for_area_fraction(0.80, box, bead), 101070);
    // The paper's polar counts (801, 3203) are within 0.2 % of the 13-sphere rod's.
    const Shape polar = polar_rod_species().shape;
    EXPECT_NEAR(static_cast<double>(count_for_area_fraction(0.05, box, polar)), 801.0, 0.002 * 801);
    EXPECT_NEAR(static_cast<double>(count_for_area_fraction(0.20, box, polar)), 3203.0,
                0.002 * 3203);
}

TEST(Shape, MassRatioAndInertiaScaleWithMass) {
    const Species polar = polar_rod_species();
    const Species apolar = apolar_rod_species(2.5);
    EXPECT_DOUBLE_EQ(apolar.shape.mass / polar.shape.mass, 0.20);
    const Shape heavy = make_shape(polar_rod_spheres({}), 3.0);
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(heavy.principal_inertia[k], 3.0 * polar.shape.principal_inertia[k],
                    1e-14 * heavy.principal_inertia[k]);
    // A rod is axisymmetric about its body x axis, which stays the rod axis.
    EXPECT_NEAR(polar.shape.principal_inertia.y, polar.shape.principal_inertia.z,
                1e-14 * polar.shape.principal_inertia.y);
    EXPECT_LT(polar.shape.principal_inertia.x, polar.shape.principal_inertia.y);
    // Spheres are stored relative to the centre of mass: the thick end is at −x.
    EXPECT_LT(polar.shape.offsets.front().x, 0.0);
    EXPECT_GT(polar.shape.radii.front(), polar.shape.radii.back());
    EXPECT_NEAR(polar.shape.extent, 4.5, 1e-12);
}

TEST(Shape, AsymmetricBodyIsStoredInItsPrincipalFrame) {
    const SphereList spheres = {{{0, 0, 0}, 0.3}, {{1.0, 0.2, 0}, 0.2}, {{0.1, 0.9, 0.3}, 0.25}};
    const Shape shape = make_shape(spheres, 2.0);
    // Rebuild the inertia tensor from the stored (principal-frame) offsets: it must be diagonal
    // with the stored moments, and the same rigid geometry as the input.
    const MassProperties mp = mass_properties(
        {{shape.offsets[0], 0.3}, {shape.offsets[1], 0.2}, {shape.offsets[2], 0.25}});
    const double scale = 2.0 / mp.volume;
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(scale * mp.inertia(i, i), shape.principal_inertia[i], 1e-12);
        for (int j = 0; j < 3; ++j) {
            if (i != j) {
                EXPECT_NEAR(mp.inertia(i, j), 0.0, 1e-12);
            }
        }
    }
    EXPECT_NEAR(norm(shape.offsets[1] - shape.offsets[2]),
                norm(spheres[1].centre - spheres[2].centre), 1e-12);
}

}  // namespace
}  // namespace rodsea
