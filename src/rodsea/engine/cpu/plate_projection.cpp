#include "rodsea/engine/cpu/plate_projection.hpp"

#include <algorithm>

#include "rodsea/engine/physics/contact_geometry.hpp"

namespace rodsea::cpu {

void PlateProjection::apply(const std::vector<Contact>& contacts, BodyView bodies,
                            SphereTable& spheres) {
    base_depth_.resize(bodies.size(), 0.0);
    lid_depth_.resize(bodies.size(), 0.0);
    touched_.clear();
    for (const Contact& c : contacts) {
        if (!c.with_plate()) continue;
        if (base_depth_[c.a] == 0.0 && lid_depth_[c.a] == 0.0) touched_.push_back(c.a);
        std::vector<double>& depth = c.b == kBasePlate ? base_depth_ : lid_depth_;
        depth[c.a] = std::max(depth[c.a], c.overlap);  // overlaps of found contacts are > 0
    }
    for (const std::uint32_t b : touched_) {
        const double dz = physics::plate_push(base_depth_[b], lid_depth_[b]);
        base_depth_[b] = lid_depth_[b] = 0.0;
        if (dz == 0.0) continue;  // wedged between both plates
        bodies.position[b].z += dz;
        for (std::uint32_t s = spheres.first_of[b]; s < spheres.first_of[b + 1]; ++s)
            spheres.position[s].z += dz;
        spheres.lowest[b] += dz;   // still bounds (a bead's are unused): the spheres moved by dz,
        spheres.highest[b] += dz;  // to a rounding within the bounds' margin
    }
}

}  // namespace rodsea::cpu
