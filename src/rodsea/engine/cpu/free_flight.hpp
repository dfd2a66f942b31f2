#pragma once
// Stage 1 of the CPU step: every body moves freely for dt (physics::fly_freely). Bodies are
// independent: split over OpenMP threads, with the same result for any count.
#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/physics/step_context.hpp"
#include "rodsea/engine/species_table.hpp"

namespace rodsea::cpu {

// Returns an upper bound on the speed in the plane (mm/s) of any sphere centre during the step,
// which tells the Verlet list when its spheres may have moved far enough to need a check.
double advance_free_flight(BodyView bodies, const SpeciesTable& species, const StepContext& step,
                           int threads);

}  // namespace rodsea::cpu
