#pragma once
// Stage 4b of the CPU step: move each body that sank into a plate back out of it, after the
// impulses, by physics::plate_push (which says why), from the depths of the step's plate
// contacts: the cost is the plate contacts', not the bodies'.
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/cpu/sphere_table.hpp"
#include "rodsea/engine/physics/contact.hpp"

namespace rodsea::cpu {

class PlateProjection {
  public:
    // Keeps `spheres` in step with the moved bodies. Costs the plate contacts, not the bodies.
    void apply(const std::vector<Contact>& contacts, BodyView bodies, SphereTable& spheres);

  private:
    // Deepest overlap of each body with the base and with the lid in this step (mm), zero between
    // steps: only the entries of `touched_` are set, and they are cleared again after use.
    std::vector<double> base_depth_;
    std::vector<double> lid_depth_;
    std::vector<std::uint32_t> touched_;  // bodies with a plate contact, each once
};

}  // namespace rodsea::cpu
