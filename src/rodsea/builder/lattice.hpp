#pragma once
// The lattice start: rows of bodies along x, one species per row, the rows of each species spread
// evenly among the others. In a row the pitch is the body's extent plus a clearance; two adjacent
// rows of one species are shifted by half a pitch so that tapered rods interlock (and beads form
// the hexagonal lattice), and their spacing is computed from the actual discs. This reaches the
// dense packings (area fractions up to ~0.85) that random insertion cannot.
#include <cstdint>
#include <string>
#include <vector>

#include "rodsea/builder/builder_options.hpp"
#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/planar_bodies.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/random.hpp"

namespace rodsea {

// Smallest distance in y between two parallel rows of the same footprint, the upper row shifted
// by `shift` along x, both with lattice `pitch`, that keeps every disc of one row at least
// `clearance` from every disc of the other, for every combination of head/tail of the bodies
// (the lattice randomises it). Exact for the discs, not an estimate from the outline.
double stacked_row_spacing(const Footprint& f, double pitch, double shift, double clearance);

struct SpeciesRows {
    long long count = 0;           // bodies
    long long sites_per_row = 0;   // lattice sites in one row, floor(L_x / (extent + clearance))
    long long rows = 0;            // ceil(count / sites_per_row)
    double pitch = 0.0;            // L_x / sites_per_row, mm
    double stacked_spacing = 0.0;  // between two adjacent rows of this species, mm
    double height = 0.0;  // mm of the box's height its rows take (half of each gap to another)
};

struct LatticeRow {
    std::uint32_t species = 0;
    long long count = 0;         // bodies in the row (the rest of its sites stay empty)
    bool continues_run = false;  // the row below is the same species: shift by half a pitch
    double gap_after = 0.0;      // required distance to the next row up (periodically), mm
};

struct LatticePlan {
    std::vector<SpeciesRows> species;
    std::vector<LatticeRow> rows;  // bottom to top
    double height = 0.0;           // sum of the rows' gaps: must be <= L_y
    double pitch_scale = 1.0;      // beads' in-row pitch over the smallest one (extent + clearance)
    bool fits = true;
    std::string message;  // why not, when !fits
};

// Deterministic (no random numbers). With pitch_scale 1 the densest rows: what check_packing
// decides on. pitch_scale stretches the rows of bodies without an axis (see spread_lattice).
LatticePlan plan_lattice(const std::vector<Species>& species, const std::vector<Footprint>& feet,
                         const std::vector<long long>& counts, const Box& box, double clearance,
                         double pitch_scale = 1.0);

// The plan the build uses: the in-row pitch of beads (bodies without an axis) stretched by a
// common scale λ until the rows' height times λ reaches L_y, so that their free room is shared
// between x (gaps in the rows) and y (gaps between rows). Rows packed end to end trap each bead
// between its row neighbours, and the Monte Carlo, whose steps are isotropic, then only rattles
// it: at φ_a = 0.5 the beads moved 0.08 mm in 50 sweeps unstretched, 0.45 mm stretched. Rods
// keep the densest pitch: what they need to turn is room across their axis, between the rows
// (stretching them too left S of the rods higher after the sweeps, e.g. 0.55 instead of 0.24
// for ℓ_a = 1.5 mm at 0.50). Fits whenever plan_lattice(…, 1) does (λ = 1 at worst).
LatticePlan spread_lattice(const std::vector<Species>& species, const std::vector<Footprint>& feet,
                           const std::vector<long long>& counts, const Box& box, double clearance);

// Places the bodies of a plan that fits: a random height for the first row, a random x phase per
// run of rows of one species, vacancies spread evenly along each row, head/tail of every rod
// random (isotropic) or polar rods along +x (aligned). Spare height is shared equally by the gaps.
// A body with no axis (a bead) gets a random angle, or 0 when aligned.
PlanarBodies place_lattice(const LatticePlan& plan, const std::vector<Species>& species,
                           const std::vector<Footprint>& feet, const Box& box,
                           InitialOrientation orientation, SplitMix64& rng);

}  // namespace rodsea
