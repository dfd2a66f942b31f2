#pragma once
// The checks every state passes before rodsea uses it, wherever it comes from: a fresh start, a
// checkpoint being resumed, a trajectory frame being analysed or drawn. One layer, so that a
// value read from a file meets the same rules as one built from a config, and so that the
// run-time guard (a step that blows up) and the resume check agree on what "impossible" is.
//
// The bounds, documented in docs/running.md ("What rodsea guarantees"):
//   - every number finite; species indices in range; x, y inside the periodic box;
//   - orientations unit quaternions (within kQuaternionTolerance of the origin's precision);
//   - every sphere between the plates at the state's time: exactly for a fresh start, within
//     kGrossOverlapFraction of its radius for a state the engine produced (bodies rest on the
//     plates with small overlaps that the impulses remove);
//   - no two spheres of different bodies overlapping by more than kGrossOverlapFraction of the
//     smaller radius (checked on resume; the engine's own overlaps stay below a few per cent);
//   - in-plane speeds below planar_speed_bound(): faster, a sphere crosses more than a quarter
//     of the smallest radius in one step and contacts are no longer resolved.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea {

// Half a radius: an order of magnitude above the deepest overlap the validation runs ever saw
// (a few per cent, docs/validation.md), and well short of bodies passing through each other.
inline constexpr double kGrossOverlapFraction = 0.5;

enum class StateOrigin {
    fresh,         // built for a new run (t = 0): spheres strictly between the plates
    resumed,       // a checkpoint, double precision, as the engine left it
    stored_frame,  // a trajectory frame, single precision
};

// What is wrong with one body: which field, its value (with unit) and what is allowed.
struct StateProblem {
    std::size_t body = 0;
    std::string field;  // "species", "position", "position.z", "orientation", "velocity", ...
    std::string value;
    std::string allowed;
    std::string detail;  // optional: why (which sphere, which plate)
};

// The first problem of `bodies` at time `time` (s; where the plates are), or none. Checks
// values body by body (O(N)); not the overlaps between bodies.
std::optional<StateProblem> find_state_problem(const EngineParameters& params,
                                               const BodyState& bodies, double time,
                                               StateOrigin origin);

// The first pair of spheres of different bodies that overlap by more than kGrossOverlapFraction
// of the smaller radius (minimum image in x and y), reported on the first body of the pair.
std::optional<StateProblem> find_gross_overlap(const EngineParameters& params,
                                               const BodyState& bodies);

// The species of a stored state's bodies (a checkpoint's, a trajectory's) against the counts its
// config asks for, species by species: a flipped bit or an edited array changes them. The first
// species whose count differs, described, or none.
std::optional<std::string> find_species_count_problem(const std::vector<std::uint32_t>& species,
                                                      const std::vector<long long>& counts);

// The fastest in-plane sphere speed the time step resolves (mm/s): a quarter of the smallest
// sphere radius per step. ~80 m/s at the defaults, 1500× the plates' peak speed.
double planar_speed_bound(const EngineParameters& params);

// A step that blew up: what crossed its bound, by how much, and what to change.
struct BlowUp {
    std::string what;  // "the largest in-plane speed", "the largest overlap", ...
    std::string value;
    std::string bound;
    std::string advice;
};

// Checks one step's statistics against the bounds (values that are not finite cross them), as
// BlowUpBounds::crossed_by does, and says which crossed.
// O(1): the statistics come from the step itself.
std::optional<BlowUp> detect_blow_up(const BlowUpBounds& bounds, const StepStatistics& step);

// Thrown by Simulation::step after a step that blew up; the state is then meaningless.
class BlowUpError : public std::runtime_error {
  public:
    BlowUpError(BlowUp what, std::uint64_t step, double time);
    const BlowUp& blow_up() const { return blow_up_; }
    std::uint64_t step() const { return step_; }

  private:
    BlowUp blow_up_;
    std::uint64_t step_;
};

}  // namespace rodsea
