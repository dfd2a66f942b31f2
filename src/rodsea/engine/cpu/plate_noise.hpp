#pragma once
// Stage 5 of the CPU step: the rotational noise of docs/model.md §3. Each polar rod that hit a
// plate in this step gets physics::apply_plate_noise (ω_z += or = ε |u_n| η by the step's noise
// mode), with |u_n| its largest approach speed against each plate it hit in this step.
#include <cstdint>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/cpu/contact_resolution.hpp"
#include "rodsea/engine/physics/step_context.hpp"
#include "rodsea/engine/species_table.hpp"

namespace rodsea::cpu {

// Returns the number of kicks given. Sorts `hits` in place. Large hit lists are split over
// `threads` OpenMP threads, by body: the same kicks on any number of threads.
size_t apply_plate_noise(std::vector<PlateHit>& hits, BodyView bodies, const SpeciesTable& species,
                         const StepContext& step, int threads);

}  // namespace rodsea::cpu
