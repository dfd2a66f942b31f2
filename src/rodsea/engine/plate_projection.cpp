#include "rodsea/engine/plate_projection.hpp"

#include <algorithm>

namespace rodsea {

size_t PlateProjection::apply(const std::vector<Contact>& contacts, BodyState& bodies,
                              SphereTable& spheres) {
    const size_t n = bodies.size();
    base_depth_.assign(n, 0.0);
    lid_depth_.assign(n, 0.0);
    bool any = false;
    for (const Contact& c : contacts) {
        if (!c.with_plate()) continue;
        std::vector<double>& depth = c.b == kBasePlate ? base_depth_ : lid_depth_;
        depth[c.a] = std::max(depth[c.a], c.overlap);
        any = true;
    }
    if (!any) return 0;

    size_t moved = 0;
    for (size_t b = 0; b < n; ++b) {
        const double base = base_depth_[b], lid = lid_depth_[b];
        if ((base > 0.0) == (lid > 0.0)) continue;  // free, or wedged between both plates
        const double dz = base > 0.0 ? base : -lid;
        bodies.position[b].z += dz;
        for (std::uint32_t s = spheres.first_of[b]; s < spheres.first_of[b + 1]; ++s)
            spheres.position[s].z += dz;
        ++moved;
    }
    return moved;
}

}  // namespace rodsea
