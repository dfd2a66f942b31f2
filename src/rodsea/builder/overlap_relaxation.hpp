#pragma once
// Pushes overlapping flat bodies apart: the discs of different bodies repel with a harmonic
// overlap energy ½ (σ − d)², σ = r_i + r_j + 2 × clearance, which FIRE (Bitzek et al., PRL 97
// 170201 (2006), with the semi-implicit Euler of Guénolé et al., Comput. Mater. Sci. 175 109584
// (2020)) minimises over the bodies' positions and angles. Below jamming the minimum has no
// overlap, and it is reached in hundreds to thousands of iterations whatever the start: the
// standard way to make dense random packings (O'Hern et al., PRE 68 011306 (2003)).
#include <cstdint>

#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/planar_bodies.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

struct OverlapRelaxationOptions {
    double clearance = 0.0025;  // the gap every disc pair must end up with at least, mm
    int max_iterations = 20000;
    // Gives up when the largest overlap has not halved over this many iterations (0: never).
    // Below jamming it halves every few hundred iterations to the end; above, it stalls within
    // a thousand at a few percent of a diameter (docs/builder.md).
    int stall_iterations = 1000;
    bool rotate = true;  // false keeps every angle (the aligned start)
};

struct OverlapRelaxationResult {
    bool converged = false;  // every gap at least the clearance
    bool stalled = false;    // gave up early: the overlaps stopped shrinking
    int iterations = 0;
    int list_builds = 0;           // of the pair list
    double largest_overlap = 0.0;  // of the discs at the end (negative: their smallest gap), mm
};

// Moves and turns `bodies` until every disc of one body is at least the
// clearance from every disc of another, in the plane with the minimum image, or gives up after
// the iterations allowed or once it stalls (above jamming; then the result is not converged).
// Positions are wrapped into the box at the end.
OverlapRelaxationResult relax_overlaps(PlanarBodies& bodies, const std::vector<Footprint>& feet,
                                       const Box& box, const OverlapRelaxationOptions& options);

}  // namespace rodsea
