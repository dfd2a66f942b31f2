#pragma once
// One trajectory frame as the analysis sees it: in-plane centres wrapped into the box, the
// in-plane axis angle θ (thick → thin for polar rods, docs/model.md §4), velocity, spin about z and
// species. Built once per frame, so that no observable redoes the quaternion → angle work.
#include <cstdint>
#include <string>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/math/periodic_box.hpp"

namespace rodsea {

// What the analysis needs to know about a species of the run.
struct SpeciesInfo {
    std::string name;
    BodyKind kind = BodyKind::polar_rod;
    double length = 0.0;         // mm, the body's largest extent (ℓ for rods, σ_b for beads)
    long long count = 0;         // bodies
    double area_fraction = 0.0;  // projected area of all its bodies / box area
};

struct AnalysisFrame {
    std::size_t index = 0;  // frame number in the trajectory
    double time = 0.0;      // s
    std::int64_t step = 0;
    PeriodicBox2D box;                   // mm
    std::vector<Vec3> position;          // mm, x and y wrapped into [0, L)
    std::vector<double> theta;           // rad, in (−π, π]
    std::vector<Vec3> velocity;          // mm/s
    std::vector<double> spin_z;          // rad/s, ω_z: the in-plane turning rate
    std::vector<std::uint32_t> species;  // index into the run's species

    std::size_t size() const { return position.size(); }
};

AnalysisFrame make_analysis_frame(const BodyState& bodies, const PeriodicBox2D& box,
                                  std::size_t index, double time, std::int64_t step);

}  // namespace rodsea
