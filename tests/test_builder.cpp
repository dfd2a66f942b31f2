// The system builder: exact counts, every body flat and resting on the base, no two bodies
// overlapping (checked independently of the builder, builder_checks.hpp), the lattice start,
// isotropy at low density, determinism, and refusals that name the species. The dense isotropic
// starts are tested with their segregation in test_dense_starts.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "builder_checks.hpp"
#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/initial_state.hpp"
#include "rodsea/builder/lattice.hpp"
#include "rodsea/builder/monte_carlo.hpp"
#include "rodsea/builder/overlap_relaxation.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/math/periodic_box.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

using namespace test;

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
        // Isotropic starts this dense are random packings (compression); aligned ones are the
        // lattice (polar rods all along +x, apolar rods ±x at random as in any lattice start).
        options.orientation = InitialOrientation::aligned;
        BuildReport report;
        const BodyState bodies = build_initial_state(r.params, r.counts, options, 4, &report);
        EXPECT_EQ(report.start, StartKind::lattice);
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

TEST(BuilderLowDensity, IsotropicAndUniform) {
    // φ_p = 0.05 + φ_a = 0.10 (ℓ_a = 2.5 mm) in a 120 mm box: 181 polar and 1053 apolar rods.
    const Request r = mixture(0.05, 2.5, 0.10, 120.0);
    BuildReport report;
    const BodyState bodies = build_initial_state(r.params, r.counts, {}, 5, &report);
    expect_valid_start(r, bodies);
    EXPECT_EQ(report.start, StartKind::insertion);  // random insertion suffices this dilute
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
    MonteCarloOptions options;
    options.sweeps = 50;
    const MonteCarloResult mc = randomise(planar, feet, r.params.box, options, rng);
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
        EXPECT_EQ(report.start, phi > 0.5 ? StartKind::lattice : StartKind::insertion);
        EXPECT_EQ(orientational_order(bodies, 0, 1), 1.0) << "phi " << phi;
        EXPECT_NEAR(orientational_order(bodies, 1, 2), 1.0, 1e-15) << "phi " << phi;
        for (size_t b = 0; b < bodies.size(); ++b) {
            if (bodies.species[b] == 0) {
                EXPECT_EQ(in_plane_angle(bodies.orientation[b]), 0.0);
            }
        }
    }
}

TEST(BuilderPolarAligned, PolarRodsAlongPlusXInAnIsotropicMediumAtEveryDensity) {
    // Insertion, compression and the mosaic (φ_a = 0.80 in the 38 mm box, the screening study's
    // dense point): P = 1 exactly for the polar rods, and a medium at the chance level of its
    // independent directions, S < 3/√N.
    for (const double phi : {0.10, 0.70, 0.80}) {
        const Request r = mixture(0.05, 2.5, phi, 37.8);
        BuilderOptions options;
        options.orientation = InitialOrientation::polar_aligned;
        BuildReport report;
        const BodyState bodies = build_initial_state(r.params, r.counts, options, 4, &report);
        std::printf("[ measured ] phi %.2f: %s; medium S %.3f (N %lld)\n", phi,
                    describe_start(report).c_str(), orientational_order(bodies, 1, 2), r.counts[1]);
        EXPECT_EQ(report.start, phi < 0.5    ? StartKind::insertion
                                : phi < 0.75 ? StartKind::compression
                                             : StartKind::mosaic);
        EXPECT_EQ(orientational_order(bodies, 0, 1), 1.0) << "phi " << phi;
        EXPECT_LT(orientational_order(bodies, 1, 2),
                  3.0 / std::sqrt(static_cast<double>(r.counts[1])))
            << "phi " << phi;
        expect_valid_start(r, bodies, phi > 0.5);  // dilute: no pairs across the seam
    }
}

TEST(BuilderDeterminism, SameSeedSameStateOtherSeedOther) {
    // Each start: insertion, compression, mosaic (the lattice: BuilderAligned is exact).
    const std::vector<std::pair<double, StartKind>> cases{
        {0.20, StartKind::insertion}, {0.60, StartKind::compression}, {0.80, StartKind::mosaic}};
    for (const auto& [phi, kind] : cases) {
        const Request r = mixture(0.05, 2.5, phi, 30.0);
        const auto hash = [&](std::uint64_t seed) {
            BuildReport report;
            const BodyState bodies = build_initial_state(r.params, r.counts, {}, seed, &report);
            EXPECT_EQ(report.start, kind) << "phi " << phi;
            return Simulation(r.params, bodies).state_hash();
        };
        EXPECT_EQ(hash(7), hash(7)) << "phi " << phi;
        EXPECT_NE(hash(7), hash(8)) << "phi " << phi;
    }
}

// Two discs of one body each, d apart in x in a 20 mm box, relaxed.
PlanarBodies two_beads(double d) {
    PlanarBodies b;
    b.add(0, 10.0, 10.0, 0.0);
    b.add(0, 10.0 + d, 10.0, 0.0);
    return b;
}

TEST(OverlapRelaxation, PartsTwoDiscsAlongTheirLineOfCentresAboutTheirMidpoint) {
    // Equal and opposite forces on equal masses: FIRE keeps the total velocity zero (its mixing
    // adds a multiple of the total force, also zero), so the midpoint stays where it was, and
    // the discs move along x only. The end: a gap of at least the clearance.
    const std::vector<Footprint> feet{footprint_of(bead_species().shape)};
    const Box box{20.0, 20.0};
    PlanarBodies b = two_beads(0.3);  // 0.8 mm beads overlapping by 0.5 mm
    OverlapRelaxationOptions options;
    const OverlapRelaxationResult r = relax_overlaps(b, feet, box, options);
    EXPECT_TRUE(r.converged);
    EXPECT_FALSE(r.stalled);
    const double gap = (b.x[1] - b.x[0]) - 0.8;
    std::printf("[ measured ] %d iterations, gap %.6f mm\n", r.iterations, gap);
    EXPECT_GE(gap, options.clearance);
    // It stops at the first iteration with the gap: FIRE's momentum carries the discs past the
    // energy's zero (twice the clearance) by at most one step of a speed the 0.5 mm overlap's
    // energy bounds, far less than that overlap.
    EXPECT_LT(gap, 0.5);
    EXPECT_NEAR(0.5 * (b.x[0] + b.x[1]), 10.15, 1e-12);
    EXPECT_EQ(b.y[0], 10.0);
    EXPECT_EQ(b.y[1], 10.0);
}

TEST(OverlapRelaxation, LeavesAClearPackingAlone) {
    const std::vector<Footprint> feet{footprint_of(bead_species().shape)};
    PlanarBodies b = two_beads(1.0);
    const PlanarBodies before = b;
    const OverlapRelaxationResult r = relax_overlaps(b, feet, {20.0, 20.0}, {});
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(b.x, before.x);
    EXPECT_EQ(b.y, before.y);
}

TEST(OverlapRelaxation, StallsWhenTheBodiesCannotFit) {
    // Beads at an area fraction of 0.95, beyond the hexagonal close packing (π/√12 ≈ 0.907):
    // no configuration is free of overlaps, and the relaxation must say so early (the largest
    // overlap stops halving) rather than run to its iteration cap.
    const Species bead = bead_species();
    const std::vector<Footprint> feet{footprint_of(bead.shape)};
    const Box box{10.0, 10.0};
    const long long n = count_for_area_fraction(0.95, box, bead.shape);
    SplitMix64 rng(5);
    PlanarBodies b;
    for (long long i = 0; i < n; ++i)
        b.add(0, rng.uniform(0.0, box.lx), rng.uniform(0.0, box.ly), 0.0);
    OverlapRelaxationOptions options;
    options.max_iterations = 20000;
    const OverlapRelaxationResult r = relax_overlaps(b, feet, box, options);
    std::printf("[ measured ] %lld beads: stalled after %d iterations at an overlap of %.3f mm\n",
                n, r.iterations, r.largest_overlap);
    EXPECT_FALSE(r.converged);
    EXPECT_TRUE(r.stalled);
    EXPECT_LT(r.iterations, options.max_iterations / 4);
    EXPECT_GT(r.largest_overlap, 0.01);  // a hundredth of a millimetre: not round-off
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
