#include "rodsea/builder/initial_state.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "rodsea/builder/compression.hpp"
#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/lattice.hpp"
#include "rodsea/builder/monte_carlo.hpp"
#include "rodsea/builder/mosaic.hpp"
#include "rodsea/builder/placement.hpp"
#include "rodsea/builder/random_insertion.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/error.hpp"
#include "rodsea/neighbors/periodic_grid.hpp"
#include "rodsea/random.hpp"

namespace rodsea {

namespace {

// The lattice keeps discs twice as far apart as the Monte Carlo must: the difference is free room
// for the first moves in the densest packings and absorbs the round-off of lattice positions.
// Each µm costs: with 10 µm, beads at φ = 0.80 + polar rods at 0.05 fit in the 252 mm box with
// 0.6 % of its height to spare and in almost no box of 40–120 mm; with 5 µm in most boxes above
// 75 mm (docs/builder.md).
constexpr double kLatticeClearance = 2.0 * kBuildClearance;  // mm
constexpr double kMonteCarloClearance = kBuildClearance;     // mm

// Independent random streams: the lattice start does not depend on the number of sweeps.
constexpr std::uint64_t kLatticeStream = 0x6C61747469636531ULL;
constexpr std::uint64_t kMonteCarloStream = 0x6D6F6E7465636172ULL;
constexpr std::uint64_t kVelocityStream = 0x76656C6F63697479ULL;
constexpr std::uint64_t kInsertionStream = 0x696E736572746564ULL;
constexpr std::uint64_t kCompressionStream = 0x636F6D7072657373ULL;
constexpr std::uint64_t kMosaicStream = 0x6D6F7361696373ULL;

// Random insertion is tried up to a total area fraction of 0.50 (plus the rounding of counts),
// with at most 100 attempts per body on average before the lattice takes over. Measured in the
// 252 mm box (docs/builder.md): beads or 1 mm rods at 0.45 + polar rods at 0.05 need 36–50
// attempts per body; 2.5 mm rods at the same total need ~650 and fall back to the lattice after
// ~1 s of trying, 4.5 mm rods already at 0.35 + 0.05.
constexpr double kInsertionLimit = 0.505;
// Below this area fraction random insertion places every body (half the limit above, where it
// still succeeds for the paper's mixtures): a system whose lattice fallback does not fit (one
// row per species, so thousands of tiny species) is still feasible.
constexpr double kSureInsertion = 0.25;
constexpr double kInsertionAttemptsPerBody = 100.0;

// The overlap relaxations stop early once the largest overlap stops halving (stall_iterations), so
// this cap only bounds the slow convergence just below jamming: 2.5 mm rods at 0.75 + polar rods
// at 0.05 need ~3500 iterations.
constexpr int kRelaxationIterations = 6000;

std::vector<Footprint> footprints(const EngineParameters& params) {
    std::vector<Footprint> feet;
    for (const Species& s : params.species)
        feet.push_back(footprint_of(s.shape));
    return feet;
}

std::string counts_text(const EngineParameters& params, const std::vector<long long>& counts) {
    std::string text;
    for (size_t s = 0; s < counts.size() && s < params.species.size(); ++s)
        text += (s ? ", " : "") + std::to_string(counts[s]) + " " + params.species[s].name;
    return text;
}

double area_fraction(const EngineParameters& params, const std::vector<long long>& counts) {
    double area = 0.0;
    for (size_t s = 0; s < counts.size(); ++s)
        area += static_cast<double>(counts[s]) * params.species[s].shape.projected_area;
    return area / (params.box.lx * params.box.ly);
}

// The engine's state from the planar one: each body flat on the base at t = 0 (resting_height),
// its centre of mass placed off the geometric centre where the shape has it, and the small random
// velocities and spins that break the mirror symmetry of a still packing. Bodies grouped by species
// in the parameters' order, each group in lattice or insertion order (neighbours close in memory on
// a lattice).
BodyState lay_on_base(const EngineParameters& params, const std::vector<Footprint>& feet,
                      const PlanarBodies& planar, SplitMix64& rng) {
    std::vector<std::uint32_t> order(planar.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return planar.species[a] < planar.species[b];
    });
    BodyState state;
    for (const std::uint32_t b : order) {
        const std::uint32_t s = planar.species[b];
        const Quat q = flat_orientation(planar.angle[b]);
        const double z = resting_height(params.species[s].shape, q, params.drive);
        const Vec3 centre_from_com = rotate(q, Vec3{feet[s].centre_offset, 0.0, 0.0});
        const Vec3 x{PeriodicBox2D::wrap(planar.x[b] - centre_from_com.x, params.box.lx),
                     PeriodicBox2D::wrap(planar.y[b] - centre_from_com.y, params.box.ly), z};
        const Vec3 v{rng.uniform(-kStartSpeed, kStartSpeed), rng.uniform(-kStartSpeed, kStartSpeed),
                     0.0};
        const Vec3 w{rng.uniform(-kStartSpin, kStartSpin), rng.uniform(-kStartSpin, kStartSpin),
                     rng.uniform(-kStartSpin, kStartSpin)};
        state.add(s, x, q, v, w);
    }
    return state;
}

// Smallest gap in the plane between spheres of two bodies, from the finished state alone (an
// independent check of the Monte Carlo grid). Pairs farther apart than `reach` are not looked
// at, so the result is at most reach − 2 r_max.
double smallest_gap(const EngineParameters& params, const BodyState& state, double reach) {
    std::vector<Vec3> centres;
    std::vector<double> radii;
    std::vector<std::uint32_t> owner;
    double max_radius = 0.0;
    for (std::uint32_t b = 0; b < state.size(); ++b) {
        const Shape& shape = params.species[state.species[b]].shape;
        for (size_t k = 0; k < shape.sphere_count(); ++k) {
            centres.push_back(state.position[b] + rotate(state.orientation[b], shape.offsets[k]));
            radii.push_back(shape.radii[k]);
            owner.push_back(b);
            max_radius = std::max(max_radius, shape.radii[k]);
        }
    }
    const double cutoff = 2.0 * max_radius + reach;
    double gap = reach;
    if (centres.empty()) return gap;
    PeriodicGrid2D grid;
    grid.build(centres, PeriodicBox2D{params.box.lx, params.box.ly}, cutoff);
    grid.for_each_pair_within(cutoff, [&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
        if (owner[i] == owner[j]) return;
        gap = std::min(gap, std::hypot(d.x, d.y) - radii[i] - radii[j]);
    });
    return gap;
}

// The random starts, in order: insertion when dilute; for isotropic starts compression, then the
// mosaic with domains ever larger. False when none succeeded (the lattice is left). Each start has
// its own random stream, so a dilute start does not depend on the denser ones' code.
bool start_randomly(const EngineParameters& params, const std::vector<Footprint>& feet,
                    const std::vector<long long>& counts, const BuilderOptions& options,
                    std::uint64_t seed, PlanarBodies& planar, StartKind& kind, BuildReport& tried) {
    const double fraction = area_fraction(params, counts);
    if (fraction <= kInsertionLimit) {
        SplitMix64 rng(splitmix64(seed ^ kInsertionStream));
        const InsertionResult inserted =
            insert_randomly(params.species, feet, counts, params.box, kMonteCarloClearance,
                            options.orientation, kInsertionAttemptsPerBody, rng, planar);
        tried.insertion_attempts = inserted.attempts;
        kind = StartKind::insertion;
        if (inserted.complete) return true;
    }
    if (options.orientation == InitialOrientation::aligned) return false;

    SplitMix64 compression_rng(splitmix64(seed ^ kCompressionStream));
    CompressionOptions compression;
    compression.clearance = kMonteCarloClearance;
    compression.max_iterations = kRelaxationIterations;
    if (compression_probe_succeeds(params.species, feet, counts, params.box, options.orientation,
                                   compression, compression_rng)) {
        const CompressionResult compressed =
            compress_from_random(params.species, feet, counts, params.box, options.orientation,
                                 compression, compression_rng, planar);
        tried.relaxation_iterations += compressed.relaxation.iterations;
        kind = StartKind::compression;
        if (compressed.complete) return true;
    }
    tried.compression_jammed = true;

    SplitMix64 mosaic_rng(splitmix64(seed ^ kMosaicStream));
    MosaicOptions mosaic;
    mosaic.clearance = kMonteCarloClearance;
    mosaic.lattice_clearance = kLatticeClearance;
    mosaic.max_iterations = kRelaxationIterations;
    mosaic.guest_orientation = options.orientation;
    const double largest = std::max(params.box.lx, params.box.ly);
    mosaic.domain_size = std::min(options.domain_size, largest);
    for (;;) {
        const MosaicResult laid =
            mosaic_start(params.species, feet, counts, params.box, mosaic, mosaic_rng, planar);
        tried.relaxation_iterations += laid.relaxation.iterations;
        tried.domains = laid.domains;
        tried.domain_size = laid.domain_size;
        kind = StartKind::mosaic;
        if (laid.complete) return true;
        // Larger domains lose less room at their boundaries; one domain is the largest.
        if (laid.domains <= 1) return false;
        mosaic.domain_size = std::min(2.0 * mosaic.domain_size, largest);
    }
}

}  // namespace

namespace {

// Sparse enough, with every body well inside the box (no body meets its own periodic image).
bool insertion_is_sure(const EngineParameters& params, const std::vector<long long>& counts) {
    const double half_side = 0.5 * std::min(params.box.lx, params.box.ly);
    for (std::size_t s = 0; s < counts.size(); ++s)
        if (counts[s] > 0 && params.species[s].shape.extent > half_side) return false;
    return area_fraction(params, counts) <= kSureInsertion;
}

}  // namespace

PackingCheck check_packing(const EngineParameters& params, const std::vector<long long>& counts) {
    if (counts.size() != params.species.size()) {
        return {false, std::to_string(counts.size()) + " counts for " +
                           std::to_string(params.species.size()) + " species"};
    }
    if (!(params.box.lx > 0.0) || !(params.box.ly > 0.0) || !std::isfinite(params.box.lx) ||
        !std::isfinite(params.box.ly)) {
        return {false, "the box (" + format_number(params.box.lx) + " x " +
                           format_number(params.box.ly) + " mm) offers no area"};
    }
    const LatticePlan plan =
        plan_lattice(params.species, footprints(params), counts, params.box, kLatticeClearance);
    if (!plan.fits && insertion_is_sure(params, counts)) return {true, ""};
    return {plan.fits, plan.message};
}

BodyState build_initial_state(const EngineParameters& params, const std::vector<long long>& counts,
                              const BuilderOptions& options, std::uint64_t seed,
                              BuildReport* report) {
    const auto start = std::chrono::steady_clock::now();
    if (counts.size() != params.species.size()) {
        throw InvalidParameter("counts", std::to_string(counts.size()) + " values",
                               std::to_string(params.species.size()) + " (one per species)");
    }
    require_positive("box.lx", params.box.lx, "mm");
    require_positive("box.ly", params.box.ly, "mm");
    require_in_closed_range("builder.randomisation_sweeps", options.randomisation_sweeps, 0,
                            100000);
    const std::vector<Footprint> feet = footprints(params);
    const LatticePlan plan =
        spread_lattice(params.species, feet, counts, params.box, kLatticeClearance);
    if (!plan.fits && !insertion_is_sure(params, counts)) {
        throw InvalidParameter("species", counts_text(params, counts),
                               "counts whose lattice start fits in the box", plan.message);
    }
    validate(params);

    // A polar-aligned start keeps its polar rods' angles through every relaxation and sweep: to
    // those stages, a polar rod does not turn.
    std::vector<Footprint> turning = feet;
    if (options.orientation == InitialOrientation::polar_aligned)
        for (size_t s = 0; s < params.species.size(); ++s)
            if (params.species[s].kind == BodyKind::polar_rod) turning[s].rotatable = false;

    // 1. Start: the first of insertion, compression, mosaic and lattice that succeeds.
    PlanarBodies planar;
    StartKind kind = StartKind::lattice;
    BuildReport attempts;
    if (start_randomly(params, turning, counts, options, seed, planar, kind, attempts) == false) {
        if (!plan.fits)
            throw InvalidParameter("species", counts_text(params, counts),
                                   "counts that random insertion or a lattice can place",
                                   "random insertion failed and " + plan.message);
        SplitMix64 rng(splitmix64(seed ^ kLatticeStream));
        planar = place_lattice(plan, params.species, feet, params.box, options.orientation, rng);
    }

    // 2. Randomise in the plane.
    SplitMix64 mc_rng(splitmix64(seed ^ kMonteCarloStream));
    MonteCarloOptions mc;
    mc.clearance = kMonteCarloClearance;
    mc.sweeps = options.randomisation_sweeps;
    mc.rotate = options.orientation != InitialOrientation::aligned;
    const MonteCarloResult randomised = randomise(planar, turning, params.box, mc, mc_rng);

    // 3. Onto the base, and check the result independently.
    SplitMix64 velocity_rng(splitmix64(seed ^ kVelocityStream));
    BodyState state = lay_on_base(params, feet, planar, velocity_rng);
    const double gap = smallest_gap(params, state, 2.0 * kLatticeClearance);
    if (gap < 0.0) {
        throw std::logic_error("builder: two bodies overlap by " + format_number(-gap) +
                               " mm after randomisation");
    }

    if (report) {
        *report = attempts;
        report->start = kind;
        report->sweeps = randomised.sweeps;
        report->acceptance = randomised.attempted == 0
                                 ? 0.0
                                 : static_cast<double>(randomised.accepted) /
                                       static_cast<double>(randomised.attempted);
        report->min_gap = gap;
        report->row_height = plan.height;
        report->pitch_scale = plan.pitch_scale;
        report->translation_step = randomised.translation_step;
        report->rotation_step = randomised.rotation_step;
        report->nematic_order.clear();
        report->polar_order.clear();
        for (std::uint32_t s = 0; s < params.species.size(); ++s) {
            report->nematic_order.push_back(orientational_order(state, s, 2));
            report->polar_order.push_back(orientational_order(state, s, 1));
        }
        report->seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return state;
}

const char* to_string(StartKind kind) {
    switch (kind) {
        case StartKind::insertion:
            return "insertion";
        case StartKind::compression:
            return "compression";
        case StartKind::mosaic:
            return "mosaic";
        case StartKind::lattice:
            return "lattice";
    }
    return "?";
}

std::string describe_start(const BuildReport& r) {
    std::string text;
    switch (r.start) {
        case StartKind::insertion:
            text = "random insertion (" + std::to_string(r.insertion_attempts) + " placements)";
            break;
        case StartKind::compression:
            text =
                "compression: shrunk bodies inserted at random, grown back, overlaps relaxed in " +
                std::to_string(r.relaxation_iterations) + " iterations";
            break;
        case StartKind::mosaic:
            text = "mosaic: random compression jams; the medium ";
            text += r.domains == 1
                        ? std::string("as one domain at a random angle")
                        : "in " + std::to_string(r.domains) + " domains of " +
                              format_number(r.domain_size) + " mm at evenly spaced directions";
            text += ", the other species at random (" + std::to_string(r.relaxation_iterations) +
                    " relaxation iterations)";
            break;
        case StartKind::lattice:
            text = "lattice: rows along x";
            if (r.compression_jammed) text += " (random compression and every mosaic jammed)";
            break;
    }
    return text;
}

std::string planned_start(const EngineParameters& params, const std::vector<long long>& counts,
                          const BuilderOptions& options) {
    const double fraction = area_fraction(params, counts);
    const bool aligned = options.orientation == InitialOrientation::aligned;
    if (fraction <= kInsertionLimit)
        return "random insertion (area fraction <= " + format_number(kInsertionLimit) +
               (aligned ? "; rows along x if it fails)" : ")");
    if (aligned) return "lattice: rows along x (aligned start above area fraction 0.505)";
    return "compression: shrunk bodies inserted at random, grown back, overlaps relaxed; if the "
           "random packing jams (above area fraction ~0.75-0.84, docs/builder.md), a mosaic of " +
           format_number(options.domain_size) +
           " mm domains of the medium at evenly spaced directions with the other species at "
           "random" +
           (options.orientation == InitialOrientation::polar_aligned
                ? std::string("; the polar rods along +x")
                : std::string());
}

}  // namespace rodsea
