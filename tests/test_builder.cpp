// The system builder: exact counts, every body flat and resting on the base, no two bodies
// overlapping (checked here by brute force, independently of the builder's own grid), the dense
// packings of the paper reached, isotropy at low density, determinism, and refusals that name
// the species.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/initial_state.hpp"
#include "rodsea/builder/lattice.hpp"
#include "rodsea/builder/monte_carlo.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/math/periodic_box.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

struct Request {
    EngineParameters params;
    std::vector<long long> counts;
};

// Polar rods at φ_p with a medium (beads for medium_length 0, else apolar rods) at φ_a, in a
// square box of side `side` mm, counts from N = round(φ L² / A).
Request mixture(double phi_polar, double medium_length, double phi_medium, double side) {
    Request r;
    r.params.box = {side, side};
    r.params.species = {polar_rod_species(),
                        medium_length == 0.0 ? bead_species() : apolar_rod_species(medium_length)};
    for (const Species& s : r.params.species) {
        const double phi = s.kind == BodyKind::polar_rod ? phi_polar : phi_medium;
        r.counts.push_back(count_for_area_fraction(phi, r.params.box, s.shape));
    }
    return r;
}

struct Overlaps {
    double min_gap_3d = 1e9;          // smallest surface gap between spheres of two bodies, in 3D
    double min_gap_2d = 1e9;          // same between their great discs in the plane
    int close_pairs_across_seam = 0;  // pairs closer than 0.1 mm met through the periodic boundary
};

// Every pair of spheres of different bodies, by brute force with the minimum image.
Overlaps brute_force_gaps(const EngineParameters& params, const BodyState& bodies) {
    std::vector<Vec3> centre;
    std::vector<double> radius;
    std::vector<size_t> owner;
    for (size_t b = 0; b < bodies.size(); ++b) {
        const Shape& shape = params.species[bodies.species[b]].shape;
        for (size_t k = 0; k < shape.sphere_count(); ++k) {
            centre.push_back(bodies.position[b] + rotate(bodies.orientation[b], shape.offsets[k]));
            radius.push_back(shape.radii[k]);
            owner.push_back(b);
        }
    }
    const PeriodicBox2D box{params.box.lx, params.box.ly};
    Overlaps o;
    for (size_t i = 0; i < centre.size(); ++i) {
        for (size_t j = i + 1; j < centre.size(); ++j) {
            if (owner[i] == owner[j]) continue;
            const Vec3 raw = centre[i] - centre[j];
            const Vec3 d = box.minimum_image(raw);
            const double reach = radius[i] + radius[j];
            if (std::abs(d.x) > reach + 0.1 || std::abs(d.y) > reach + 0.1) continue;
            o.min_gap_3d = std::min(o.min_gap_3d, norm(d) - reach);
            const double gap_2d = std::hypot(d.x, d.y) - reach;
            o.min_gap_2d = std::min(o.min_gap_2d, gap_2d);
            if (gap_2d < 0.1 && (d.x != raw.x || d.y != raw.y)) ++o.close_pairs_across_seam;
        }
    }
    return o;
}

// The checks every built state must pass. `seam`: some close pairs must meet through the
// periodic boundary, so that the test sees it (dense states).
void expect_valid_start(const Request& r, const BodyState& bodies, bool seam = true) {
    ASSERT_EQ(bodies.size(), static_cast<size_t>(r.counts[0] + r.counts[1]));
    for (std::uint32_t s = 0; s < r.counts.size(); ++s) {
        EXPECT_EQ(std::count(bodies.species.begin(), bodies.species.end(), s), r.counts[s])
            << r.params.species[s].name;
    }
    const double base = physics::plate_state(r.params.drive.motion(), 0.0).base_z;
    for (size_t b = 0; b < bodies.size(); ++b) {
        const Vec3& x = bodies.position[b];
        EXPECT_TRUE(x.x >= 0.0 && x.x < r.params.box.lx && x.y >= 0.0 && x.y < r.params.box.ly)
            << "body " << b << " not wrapped";
        // Flat: the axis horizontal and the body z axis vertical (1e-12: round-off of a unit
        // quaternion's rotation).
        const Quat& q = bodies.orientation[b];
        EXPECT_NEAR(rotate(q, Vec3{1, 0, 0}).z, 0.0, 1e-12);
        EXPECT_NEAR(rotate(q, Vec3{0, 0, 1}).z, 1.0, 1e-12);
        // Resting: the lowest sphere 1 µm (resting_height's clearance) above the base at t = 0.
        const Shape& shape = r.params.species[bodies.species[b]].shape;
        double lowest = 1e9;
        for (size_t k = 0; k < shape.sphere_count(); ++k)
            lowest = std::min(lowest, x.z + rotate(q, shape.offsets[k]).z - shape.radii[k]);
        EXPECT_NEAR(lowest - base, 1e-3, 1e-12);
    }
    const Overlaps o = brute_force_gaps(r.params, bodies);
    std::printf(
        "[ measured ] smallest gap %.5f mm in the plane, %.5f mm in 3D; %d close pairs "
        "across the periodic boundary\n",
        o.min_gap_2d, o.min_gap_3d, o.close_pairs_across_seam);
    // The builder promises kBuildClearance between the discs in the plane; 1e-12 mm of slack
    // for the round-off between its disc positions and the ones recomputed here.
    EXPECT_GE(o.min_gap_2d, kBuildClearance - 1e-12);
    EXPECT_GE(o.min_gap_3d, o.min_gap_2d);  // discs apart in the plane: spheres apart in 3D
    if (seam) {
        EXPECT_GT(o.close_pairs_across_seam, 0);
    }
}

// A few hundred steps of the engine from the built state: accepted, and overlaps stay small.
void expect_runs(const Request& r, const BodyState& bodies) {
    Simulation sim(r.params, bodies);
    sim.run(300);
    std::printf("[ measured ] 300 steps: largest overlap %.4f of the smaller radius\n",
                sim.totals().max_overlap_fraction);
    // Same bound as DenseMonolayer: relative speeds below ~220 mm/s give at most 1.1 µm of
    // overlap per 5 µs step, 0.55 % of the smallest radius; ten steps of accumulation allowed.
    EXPECT_LT(sim.totals().max_overlap_fraction, 0.055);
    EXPECT_EQ(sim.totals().unresolved, 0u);
}

TEST(BuilderLattice, BeadRowsFormTheHexagonalLattice) {
    // Rows of discs of diameter d + c half a pitch apart touch when their spacing is
    // sqrt((d + c)² − (p/2)²): the hexagonal lattice for p = d + c.
    const Footprint bead = footprint_of(bead_species().shape);
    const double c = 0.01, pitch = 0.85;
    EXPECT_NEAR(stacked_row_spacing(bead, pitch, 0.5 * pitch, c),
                std::sqrt(0.81 * 0.81 - 0.25 * pitch * pitch), 1e-12);
    EXPECT_NEAR(stacked_row_spacing(bead, pitch, 0.0, c), 0.81, 1e-12);  // in register
}

TEST(BuilderLattice, TaperedRodRowsInterlock) {
    // Apolar rods taper from 0.8 to 0.4 mm: half a pitch apart, a thick middle faces two thin
    // ends, so rows sit closer than the 0.8 mm width (for a linear taper the two half-width
    // profiles add to ~0.6 mm) but no closer than a middle over thin ends allows.
    const Footprint rod = footprint_of(apolar_rod_species(2.5).shape);
    const double pitch = 2.52, c = 0.01;
    const double spacing = stacked_row_spacing(rod, pitch, 0.5 * pitch, c);
    EXPECT_LT(spacing, 0.6);
    EXPECT_GT(spacing, 0.5);
    // In register the widest discs meet head on.
    EXPECT_NEAR(stacked_row_spacing(rod, pitch, 0.0, c), 0.8 + c, 1e-12);
    // The polar rod's head/tail is random: its rows need more than a one-way taper would.
    const Footprint polar = footprint_of(polar_rod_species().shape);
    EXPECT_GT(stacked_row_spacing(polar, 4.6, 2.3, c), 0.5 * (1.375 + 0.4) + c);
    EXPECT_LT(stacked_row_spacing(polar, 4.6, 2.3, c), 1.375 + c);
}

TEST(BuilderLattice, OneBodyPerRowInANarrowBox) {
    // A 9 mm box holds one 4.5 mm rod per row: half-pitch shifted rows then slot into each
    // other's gaps end to end, and rows two apart (in register again) set the spacing. Also the
    // periodic seam between the last and the first row, with an even and an odd number of rows.
    // Rows 0.69 mm apart for polar rods (half their in-register spacing), 0.4025 for apolar
    // ones: 12 polar rods, or 22 or 21 apolar rods (odd: the seam in register), fill the 9 mm.
    for (const std::vector<long long>& counts :
         std::vector<std::vector<long long>>{{12, 0}, {0, 22}, {0, 21}}) {
        Request r = mixture(0.0, 4.5, 0.0, 9.0);
        r.counts = counts;
        BuilderOptions options;
        options.randomisation_sweeps = 0;  // the lattice itself
        const BodyState bodies = build_initial_state(r.params, r.counts, options, 4);
        // Polar rods two rows apart sit 1.5 mm apart at best: no pair closer than 0.1 mm.
        expect_valid_start(r, bodies, counts[0] == 0);
    }
}

TEST(BuilderLattice, BeadRowsStretchWhenThereIsRoom) {
    // At φ_a = 0.5 the densest bead rows would leave every bead 2.5 µm from its row neighbours
    // and all the room between rows; the build stretches the bead pitch by λ until λ times the
    // rows' height reaches the box (room shared between x and y). Rods keep the densest pitch.
    for (const double length : {0.0, 2.5}) {
        const Request r = mixture(0.05, length, 0.50, 60.0);
        std::vector<Footprint> feet;
        for (const Species& s : r.params.species)
            feet.push_back(footprint_of(s.shape));
        const LatticePlan dense =
            plan_lattice(r.params.species, feet, r.counts, r.params.box, 0.005);
        const LatticePlan spread =
            spread_lattice(r.params.species, feet, r.counts, r.params.box, 0.005);
        ASSERT_TRUE(spread.fits);
        EXPECT_EQ(spread.species[0].sites_per_row, dense.species[0].sites_per_row);  // polar
        if (length == 0.0) {
            EXPECT_GT(spread.pitch_scale, 1.2);
            EXPECT_LE(spread.pitch_scale * spread.height, r.params.box.ly);
            EXPECT_LT(spread.species[1].sites_per_row, dense.species[1].sites_per_row);
        } else {
            EXPECT_EQ(spread.species[1].sites_per_row, dense.species[1].sites_per_row);
        }
    }
}

TEST(BuilderDense, BeadsAtEightyPercentWithPolarRods) {
    // φ_a = 0.80 beads + φ_p = 0.05 polar rods, the densest bead medium of Table S1. 64 mm: a
    // box whose row rounding leaves room (docs/builder.md lists which sides do).
    const Request r = mixture(0.05, 0.0, 0.80, 64.0);
    BuildReport report;
    const BodyState bodies = build_initial_state(r.params, r.counts, {}, 11, &report);
    expect_valid_start(r, bodies);
    EXPECT_TRUE(report.lattice_start);
    std::printf("[ measured ] S %.3f / %.3f, P %.3f (polar / beads), acceptance %.2f\n",
                report.nematic_order[0], report.nematic_order[1], report.polar_order[0],
                report.acceptance);
    EXPECT_EQ(report.sweeps, BuilderOptions{}.randomisation_sweeps);
    EXPECT_GE(report.min_gap, kBuildClearance - 1e-12);
    EXPECT_LE(report.row_height, r.params.box.ly);
    expect_runs(r, bodies);
}

TEST(BuilderDense, ApolarRodsAtEightyPercentWithPolarRods) {
    // ℓ_a = 2.5 mm (9 spheres) at φ_a = 0.80 + φ_p = 0.05: the densest rod medium of Table S1.
    const Request r = mixture(0.05, 2.5, 0.80, 50.0);
    BuildReport report;
    const BodyState bodies = build_initial_state(r.params, r.counts, {}, 12, &report);
    expect_valid_start(r, bodies);
    EXPECT_TRUE(report.lattice_start);
    std::printf("[ measured ] S %.3f / %.3f, P %.3f (polar / apolar), acceptance %.2f\n",
                report.nematic_order[0], report.nematic_order[1], report.polar_order[0],
                report.acceptance);
    // Random head/tail: P of the polar rods is a sum of ±1 over N rods, |P| ≲ 3/√N.
    EXPECT_LT(report.polar_order[0], 3.0 / std::sqrt(static_cast<double>(r.counts[0])));
    expect_runs(r, bodies);
}

// Order parameters of isotropic angles: N P² and N S² are asymptotically exponential with mean
// 1 for N independent uniform angles, so P, S > 3/√N has probability e⁻⁹ ≈ 1e-4. Hard-body
// correlations at φ = 0.15 are short-ranged and do not change the scaling.
void expect_isotropic(const BodyState& bodies, std::uint32_t species, long long n) {
    const double bound = 3.0 / std::sqrt(static_cast<double>(n));
    std::printf("[ measured ] species %u: P %.3f, S %.3f, bound 3/sqrt(N) = %.3f\n", species,
                orientational_order(bodies, species, 1), orientational_order(bodies, species, 2),
                bound);
    EXPECT_LT(orientational_order(bodies, species, 1), bound) << "P of species " << species;
    EXPECT_LT(orientational_order(bodies, species, 2), bound) << "S of species " << species;
}

// Occupancy of a k × k grid of coarse cells: chi² = Σ (n_i − n/k²)² / (n/k²). For Poisson
// counts its mean is k² − 1 and its standard deviation sqrt(2 (k² − 1)); hard bodies are
// sub-Poissonian, so mean + 5 σ is a generous upper bound for a uniform state, while rows or
// clumps of the size of a cell give chi² of order n.
double coarse_cell_chi2(const BodyState& bodies, const Box& box, int k) {
    std::vector<int> cells(static_cast<size_t>(k * k), 0);
    for (const Vec3& x : bodies.position) {
        const int cx = std::min(k - 1, static_cast<int>(x.x / box.lx * k));
        const int cy = std::min(k - 1, static_cast<int>(x.y / box.ly * k));
        ++cells[static_cast<size_t>(cy * k + cx)];
    }
    const double expected = static_cast<double>(bodies.size()) / (k * k);
    double chi2 = 0.0;
    for (const int n : cells)
        chi2 += (n - expected) * (n - expected) / expected;
    std::printf("[ measured ] chi2 of %d x %d cells: %.1f\n", k, k, chi2);
    return chi2;
}

TEST(BuilderLowDensity, IsotropicAndUniform) {
    // φ_p = 0.05 + φ_a = 0.10 (ℓ_a = 2.5 mm) in a 120 mm box: 181 polar and 1053 apolar rods.
    const Request r = mixture(0.05, 2.5, 0.10, 120.0);
    BuildReport report;
    const BodyState bodies = build_initial_state(r.params, r.counts, {}, 5, &report);
    expect_valid_start(r, bodies);
    EXPECT_FALSE(report.lattice_start);  // random insertion suffices this dilute
    expect_isotropic(bodies, 0, r.counts[0]);
    expect_isotropic(bodies, 1, r.counts[1]);
    const int k = 6;
    EXPECT_LT(coarse_cell_chi2(bodies, r.params.box, k), (k * k - 1) + 5 * std::sqrt(2.0 * 35));
    expect_runs(r, bodies);
}

TEST(BuilderLowDensity, MonteCarloForgetsTheLattice) {
    // The lattice path on its own, at the same low density: 50 sweeps must erase the rows
    // (all along x, evenly spaced in y) in orientation and in position.
    const Request r = mixture(0.05, 2.5, 0.10, 120.0);
    std::vector<Footprint> feet;
    for (const Species& s : r.params.species)
        feet.push_back(footprint_of(s.shape));
    const LatticePlan plan = spread_lattice(r.params.species, feet, r.counts, r.params.box, 0.005);
    ASSERT_TRUE(plan.fits);
    SplitMix64 rng(3);
    PlanarBodies planar = place_lattice(plan, r.params.species, feet, r.params.box,
                                        InitialOrientation::isotropic, rng);
    const PlanarBodies lattice = planar;
    const MonteCarloResult mc = randomise(planar, feet, r.params.box, {0.0025, 50, true}, rng);
    EXPECT_EQ(mc.sweeps, 50);
    BodyState bodies;  // angles and centres are all the order parameters need
    for (std::uint32_t b = 0; b < planar.size(); ++b)
        bodies.add(planar.species[b], {planar.x[b], planar.y[b], 0.0},
                   flat_orientation(planar.angle[b]));
    expect_isotropic(bodies, 0, r.counts[0]);
    expect_isotropic(bodies, 1, r.counts[1]);
    EXPECT_LT(coarse_cell_chi2(bodies, r.params.box, 6), 35 + 5 * std::sqrt(2.0 * 35));
    // The rows' density modulation (wavevector q = 2π / a, a the row spacing) survives random
    // displacements of rms σ per coordinate as exp(−q² σ² / 2): for σ > a that is < 3e-9, the
    // rows are gone. Displacements with the minimum image.
    const PeriodicBox2D box{r.params.box.lx, r.params.box.ly};
    double msd = 0.0;
    for (size_t b = 0; b < planar.size(); ++b) {
        const Vec3 d =
            box.minimum_image({planar.x[b] - lattice.x[b], planar.y[b] - lattice.y[b], 0.0});
        msd += d.x * d.x + d.y * d.y;
    }
    const double sigma = std::sqrt(msd / (2.0 * static_cast<double>(planar.size())));
    const double row_spacing = r.params.box.ly / static_cast<double>(plan.rows.size());
    std::printf("[ measured ] rms displacement per coordinate %.1f mm, row spacing %.1f mm\n",
                sigma, row_spacing);
    EXPECT_GT(sigma, row_spacing);
    // The steps grew to jumps of half the box and turns of ±π, as they should when dilute.
    EXPECT_EQ(mc.rotation_step[1], std::numbers::pi);
}

TEST(BuilderAligned, PolarRodsAllPointAlongPlusX) {
    // Dilute (random insertion) and dense (lattice): P = 1 exactly for the polar rods, S = 1
    // for the apolar ones.
    for (const double phi : {0.10, 0.70}) {
        const Request r = mixture(0.05, 2.5, phi, 50.0);
        BuilderOptions options;
        options.orientation = InitialOrientation::aligned;
        BuildReport report;
        const BodyState bodies = build_initial_state(r.params, r.counts, options, 2, &report);
        EXPECT_EQ(report.lattice_start, phi > 0.5);
        EXPECT_EQ(orientational_order(bodies, 0, 1), 1.0) << "phi " << phi;
        EXPECT_NEAR(orientational_order(bodies, 1, 2), 1.0, 1e-15) << "phi " << phi;
        for (size_t b = 0; b < bodies.size(); ++b) {
            if (bodies.species[b] == 0) {
                EXPECT_EQ(in_plane_angle(bodies.orientation[b]), 0.0);
            }
        }
    }
}

TEST(BuilderDeterminism, SameSeedSameStateOtherSeedOther) {
    for (const double phi : {0.20, 0.60}) {  // the random-insertion path and the lattice path
        const Request r = mixture(0.05, 2.5, phi, 30.0);
        const auto hash = [&](std::uint64_t seed) {
            return Simulation(r.params, build_initial_state(r.params, r.counts, {}, seed))
                .state_hash();
        };
        EXPECT_EQ(hash(7), hash(7)) << "phi " << phi;
        EXPECT_NE(hash(7), hash(8)) << "phi " << phi;
    }
}

void expect_refused(const Request& r, const std::vector<std::string>& named) {
    const PackingCheck check = check_packing(r.params, r.counts);
    EXPECT_FALSE(check.ok);
    std::printf("[ measured ] %s\n", check.message.c_str());
    for (const std::string& name : named)
        EXPECT_NE(check.message.find(name), std::string::npos) << check.message;
    try {
        build_initial_state(r.params, r.counts, {}, 1);
        ADD_FAILURE() << "built an impossible packing";
    } catch (const InvalidParameter& e) {
        EXPECT_EQ(e.name(), "species");
        for (const std::string& name : named)
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
}

TEST(BuilderRefuses, ImpossiblePackingsNamingTheSpecies) {
    // Beads at φ = 0.95: beyond the hexagonal packing (π / √12 ≈ 0.907).
    Request beads = mixture(0.0, 0.0, 0.95, 40.0);
    expect_refused(beads, {"bead", "mm^2", "box.ly"});
    // Each species fits alone, not together: 0.20 polar rods + 0.70 beads.
    const Request both = mixture(0.20, 0.0, 0.70, 40.0);
    EXPECT_TRUE(check_packing(both.params, {both.counts[0], 0}).ok);
    EXPECT_TRUE(check_packing(both.params, {0, both.counts[1]}).ok);
    expect_refused(both, {"bead", "polar_rod"});
    // A polar rod (4.5 mm) longer than the box.
    Request tiny = mixture(0.05, 0.0, 0.0, 4.0);
    tiny.counts = {1, 0};
    expect_refused(tiny, {"polar_rod", "4.5"});
}

TEST(BuilderRefuses, CountsThatDoNotMatchTheSpecies) {
    const Request r = mixture(0.05, 0.0, 0.10, 40.0);
    EXPECT_FALSE(check_packing(r.params, {1}).ok);
    try {
        build_initial_state(r.params, {1}, {}, 1);
        ADD_FAILURE() << "built with one count for two species";
    } catch (const InvalidParameter& e) {
        EXPECT_EQ(e.name(), "counts");
    }
}

}  // namespace
}  // namespace rodsea
