#pragma once
// Stages 4 and 5 of a CPU step, after the contact search, shared by CpuBackend and
// CoastingBackend: the impulses (and the projection out of the plates), then the plate noise;
// and the step's statistics from what each stage found.
#include <cstddef>
#include <vector>

#include "rodsea/engine/cpu/contact_resolution.hpp"
#include "rodsea/engine/cpu/contact_search.hpp"
#include "rodsea/engine/cpu/plate_projection.hpp"
#include "rodsea/engine/cpu/sphere_table.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea::cpu {

class ContactResponse {
  public:
    // Resolves `contacts` on `bodies`, moves bodies that sank into a plate out of it (with their
    // spheres), kicks the polar rods that hit a plate; each part timed into `profile`. Returns
    // the step's statistics: `found` and `fastest` (mm/s) from the stages before, `flown` the
    // bodies the step flew.
    StepStatistics respond(const std::vector<Contact>& contacts, BodyView bodies,
                           const SpeciesTable& species, SphereTable& spheres,
                           const StepContext& context, int threads, StageProfile& profile,
                           const ContactSearchStats& found, double fastest, std::size_t flown);

  private:
    // Scratch reused every step: no allocation in the steady state.
    InverseInertia inverse_inertia_;
    ContactResolver resolver_;
    std::vector<PlateHit> plate_hits_;
    PlateProjection plate_projection_;
};

}  // namespace rodsea::cpu
