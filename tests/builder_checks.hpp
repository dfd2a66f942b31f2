#pragma once
// What every built initial state must satisfy, shared by the builder's tests: exact counts,
// bodies flat on the base and wrapped into the box, no two bodies closer than the build clearance
// (found independently of the builder), a few hundred engine steps without trouble, and the
// statistics of isotropic angles and uniform positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/math/periodic_box.hpp"
#include "rodsea/neighbors/periodic_grid.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea::test {

struct Request {
    EngineParameters params;
    std::vector<long long> counts;
};

// Polar rods at φ_p with a medium (beads for medium_length 0, else apolar rods) at φ_a, in a
// square box of side `side` mm, counts from N = round(φ L² / A).
inline Request mixture(double phi_polar, double medium_length, double phi_medium, double side) {
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

// Every pair of spheres of different bodies closer than 0.1 mm, found with the engine's neighbour
// grid (independent of the builder's DiscGrid and of its overlap relaxation), with the minimum
// image.
inline Overlaps sphere_gaps(const EngineParameters& params, const BodyState& bodies) {
    std::vector<Vec3> centre;
    std::vector<double> radius;
    std::vector<size_t> owner;
    double widest = 0.0;
    for (size_t b = 0; b < bodies.size(); ++b) {
        const Shape& shape = params.species[bodies.species[b]].shape;
        for (size_t k = 0; k < shape.sphere_count(); ++k) {
            centre.push_back(bodies.position[b] + rotate(bodies.orientation[b], shape.offsets[k]));
            radius.push_back(shape.radii[k]);
            owner.push_back(b);
            widest = std::max(widest, shape.radii[k]);
        }
    }
    const PeriodicBox2D box{params.box.lx, params.box.ly};
    const double cutoff = 2.0 * widest + 0.1;
    PeriodicGrid2D grid;
    grid.build(centre, box, cutoff);
    Overlaps o;
    grid.for_each_pair_within(cutoff, [&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
        if (owner[i] == owner[j]) return;
        const double reach = radius[i] + radius[j];
        o.min_gap_3d = std::min(o.min_gap_3d, norm(d) - reach);
        const double gap_2d = std::hypot(d.x, d.y) - reach;
        o.min_gap_2d = std::min(o.min_gap_2d, gap_2d);
        const Vec3 raw = centre[i] - centre[j];
        if (gap_2d < 0.1 && (std::abs(raw.x - d.x) > 1.0 || std::abs(raw.y - d.y) > 1.0))
            ++o.close_pairs_across_seam;
    });
    return o;
}

// The checks every built state must pass. `seam`: some close pairs must meet through the
// periodic boundary, so that the test sees it (dense states).
inline void expect_valid_start(const Request& r, const BodyState& bodies, bool seam = true) {
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
    const Overlaps o = sphere_gaps(r.params, bodies);
    std::printf(
        "[ measured ] smallest gap %.5f mm in the plane, %.5f mm in 3D; %d close pairs "
        "across the periodic boundary\n",
        o.min_gap_2d, o.min_gap_3d, o.close_pairs_across_seam);
    // The builder promises kBuildClearance between the discs in the plane; 1e-12 mm of slack
    // for the round-off between its disc positions and the ones recomputed here.
    EXPECT_GE(o.min_gap_2d, kBuildClearance - 1e-12);
    // Discs apart in the plane: spheres apart in 3D (to the round-off of the two distances).
    EXPECT_GE(o.min_gap_3d, o.min_gap_2d - 1e-12);
    if (seam) {
        EXPECT_GT(o.close_pairs_across_seam, 0);
    }
}

// A few hundred steps of the engine from the built state: accepted, and overlaps stay small.
inline void expect_runs(const Request& r, const BodyState& bodies) {
    Simulation sim(r.params, bodies);
    sim.run(300);
    std::printf("[ measured ] 300 steps: largest overlap %.4f of the smaller radius\n",
                sim.totals().max_overlap_fraction);
    // Same bound as DenseMonolayer: relative speeds below ~220 mm/s give at most 1.1 µm of
    // overlap per 5 µs step, 0.55 % of the smallest radius; ten steps of accumulation allowed.
    EXPECT_LT(sim.totals().max_overlap_fraction, 0.055);
    EXPECT_EQ(sim.totals().unresolved, 0u);
}

// Order parameters of isotropic angles: N P² and N S² are asymptotically exponential with mean
// 1 for N independent uniform angles, so P, S > 3/√N has probability e⁻⁹ ≈ 1e-4. Hard-body
// correlations at φ = 0.15 are short-ranged and do not change the scaling.
inline void expect_isotropic(const BodyState& bodies, std::uint32_t species, long long n) {
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
inline double coarse_cell_chi2(const BodyState& bodies, const Box& box, int k) {
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

}  // namespace rodsea::test
