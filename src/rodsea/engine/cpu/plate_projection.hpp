#pragma once
// Stage 4b of the CPU step: move each body that sank into a plate back out of it, after the
// impulses.
//
// Time-driven stepping lets a sphere pressed against an accelerating plate sink by about
// ½ (a + g) dt² each step; the impulses stop the approach but nothing undoes the depth, so over a
// contact lasting a few milliseconds it adds up to ~(a + g) T dt / 2 (≈ 0.1 µm at dt = 1.25 µs).
// That is small, but the polar rod's ratchet speed near the default gap changes by 0.23 mm/s per
// µm of gap, and without this stage its speed never converged in dt (docs/model.md). Moving the
// body by its deepest plate overlap, along the plate's normal, leaves every plate contact just
// touching. Bodies that touch both plates are left alone: no vertical move frees them.
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
