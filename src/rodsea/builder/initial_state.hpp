#pragma once
// The system builder: from counts per species to an initial state with every body lying flat on
// the base, no two bodies overlapping, random positions and orientations.
#include <cstdint>
#include <string>
#include <vector>

#include "rodsea/builder/builder_options.hpp"
#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

// Whether the counts can be packed at all, decided before any work: `ok` false comes with a
// message that names the species, the area it needs and the area the box offers.
struct PackingCheck {
    bool ok = true;
    std::string message;
};
PackingCheck check_packing(const EngineParameters& params, const std::vector<long long>& counts);

// Every two bodies of a built state are at least this far apart in the plane (mm): far enough that
// no contact exists at t = 0, close enough that the lattice start reaches φ ≈ 0.85.
inline constexpr double kBuildClearance = 0.0025;

// How the bodies were first placed, before the Monte Carlo sweeps (docs/builder.md):
//   insertion    random sequential insertion (dilute);
//   compression  random insertion of shrunk bodies, grown back and their overlaps relaxed (dense,
//                below the jamming of random packings);
//   mosaic       the medium in domains of random direction, the others inserted at random (denser);
//   lattice      rows along x (aligned starts, or when nothing else fits).
enum class StartKind { insertion, compression, mosaic, lattice };
const char* to_string(StartKind kind);

struct BuildReport {
    StartKind start = StartKind::lattice;
    double seconds = 0.0;     // wall time of the build
    int sweeps = 0;           // randomisation sweeps done
    double acceptance = 0.0;  // fraction of accepted Monte Carlo moves
    double min_gap = 0.0;  // smallest in-plane gap between spheres of two bodies, mm (at most 0.01)
    std::vector<double> nematic_order;     // S per species after randomisation
    std::vector<double> polar_order;       // P per species after randomisation
    std::uint64_t insertion_attempts = 0;  // random placements tried (0 if not tried)
    int relaxation_iterations = 0;         // of the overlap relaxation(s), summed
    bool compression_jammed = false;       // compression was tried and could not relax
    int domains = 0;                       // of the mosaic start
    double domain_size = 0.0;              // of the mosaic start, mm
    double row_height = 0.0;               // mm of the box's height the lattice rows need
    double pitch_scale = 1.0;              // lattice pitch over the densest pitch (spread_lattice)
    std::vector<double> translation_step;  // Monte Carlo step per species at the end, mm
    std::vector<double> rotation_step;     // Monte Carlo turn per species at the end, rad
};

// One line: how the start was built and what it cost.
std::string describe_start(const BuildReport& report);

// What the build will try, in order, for these counts and options, without building (for `rodsea
// info`): which starts depends on the area fraction, and whether compression jams is found out
// only by trying.
std::string planned_start(const EngineParameters& params, const std::vector<long long>& counts,
                          const BuilderOptions& options);

// Throws InvalidParameter (key "species") when check_packing fails.
BodyState build_initial_state(const EngineParameters& params, const std::vector<long long>& counts,
                              const BuilderOptions& options, std::uint64_t seed,
                              BuildReport* report = nullptr);

}  // namespace rodsea
