#pragma once
// The isotropic start for packings denser than random ones can be. Above the jamming fraction of
// a random quench (compression.hpp; for polar rods at 0.05 with 2.5 mm rods at ~0.75–0.80, 4.5 mm
// rods at ~0.65, beads at ~0.75–0.80, docs/builder.md) hard rods must align locally to fit, and
// beads must crystallise. So the medium (the species of the largest total area, the host) is laid
// out as a mosaic: the box is cut into Voronoi cells about jittered grid points, and each cell is
// filled with the densest rows of the host (the lattice start's pitch and row spacing,
// lattice.hpp) turned to a random direction, every rod with random head/tail. The other species
// (the guests: the polar rods) are inserted first at uniformly random positions and angles. The
// host sites are taken in random order and kept if they clear the guests and the sites kept
// before; a random choice of the host's count of them stays (the rest are vacancies spread through
// the domains), and when too few cleared, clashing sites are added back and the overlaps pushed
// apart (overlap_relaxation.hpp). The guests are thus random and isotropic; the host's directors
// are evenly spaced over π and dealt to the domains so that their area-weighted Q tensors cancel,
// which leaves S near chance even with the few domains of a small box. A host without an axis
// (beads) is one domain: boundaries between crystals only cost room.
#include <cstdint>
#include <vector>

#include "rodsea/builder/builder_options.hpp"
#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/overlap_relaxation.hpp"
#include "rodsea/builder/planar_bodies.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/random.hpp"

namespace rodsea {

struct MosaicOptions {
    double clearance = 0.0025;         // between bodies at the end, mm
    double lattice_clearance = 0.005;  // between bodies in a domain's rows, mm
    double domain_size = 10.0;         // mm: the box is cut into about (L / size)² domains
    int max_iterations = 4000;         // of the overlap relaxation, when one is needed
    // isotropic, or polar_aligned: the guests' polar rods along +x.
    InitialOrientation guest_orientation = InitialOrientation::isotropic;
};

struct MosaicResult {
    bool complete = false;
    std::uint32_t host = 0;  // the species laid out in domains
    int domains = 0;
    double domain_size = 0.0;            // used, mm: the box's side for a host without an axis
    long long sites = 0;                 // host sites inside the domains
    long long clashes = 0;               // sites dropped: on a guest or across a boundary
    bool relaxed = false;                // too few clear sites: clashing ones were relaxed
    std::uint64_t guest_attempts = 0;    // random placements of the guests
    OverlapRelaxationResult relaxation;  // when relaxed
};

// Fills `bodies` (replacing what they held) with the counts of each species. Incomplete when the
// guests do not fit at random or the relaxation fails; `bodies` then must not be used.
MosaicResult mosaic_start(const std::vector<Species>& species, const std::vector<Footprint>& feet,
                          const std::vector<long long>& counts, const Box& box,
                          const MosaicOptions& options, SplitMix64& rng, PlanarBodies& bodies);

}  // namespace rodsea
