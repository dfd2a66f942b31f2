#include "rodsea/engine/contact_search.hpp"

#include <algorithm>
#include <cmath>

namespace rodsea {

ContactSearchStats find_contacts(const SphereTable& spheres, const BodyState& bodies,
                                 const EngineParameters& params, const PlateState& plates,
                                 PeriodicCellList2D& cells, std::vector<Contact>& out) {
    out.clear();
    ContactSearchStats stats;
    const PeriodicBox2D box{params.box.lx, params.box.ly};
    double max_radius = 0.0;
    for (const Species& s : params.species)
        max_radius = std::max(max_radius, s.shape.max_radius);

    cells.build(spheres.position, spheres.radius, spheres.body, box, 2.0 * max_radius);
    cells.for_each_pair_within([&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
        const std::uint32_t bi = spheres.body[i], bj = spheres.body[j];
        const double reach = spheres.radius[i] + spheres.radius[j];
        const double d2 = norm2(d);
        if (d2 >= reach * reach || d2 == 0.0) return;
        const double dist = std::sqrt(d2);
        Contact c;
        c.a = bi;
        c.b = bj;
        c.normal = d / dist;
        c.overlap = reach - dist;
        c.arm_a = (spheres.position[i] - bodies.position[bi]) -
                  (spheres.radius[i] - 0.5 * c.overlap) * c.normal;
        c.arm_b = (spheres.position[j] - bodies.position[bj]) +
                  (spheres.radius[j] - 0.5 * c.overlap) * c.normal;
        const ContactCoefficients& k =
            params.pair_coefficients(bodies.species[bi], bodies.species[bj]);
        c.friction = k.friction;
        c.restitution = k.restitution;
        stats.max_overlap_fraction = std::max(
            stats.max_overlap_fraction, c.overlap / std::min(spheres.radius[i], spheres.radius[j]));
        out.push_back(c);
    });
    stats.body_contacts = out.size();

    const auto add_plate_contact = [&](size_t s, bool base, double overlap) {
        const std::uint32_t b = spheres.body[s];
        const double r = spheres.radius[s];
        const ContactCoefficients& k = params.species[bodies.species[b]].plate;
        Contact c;
        c.a = b;
        c.b = base ? kBasePlate : kLidPlate;
        c.normal = {0.0, 0.0, base ? 1.0 : -1.0};
        c.overlap = overlap;
        c.arm_a = (spheres.position[s] - bodies.position[b]) - (r - 0.5 * overlap) * c.normal;
        c.friction = k.friction;
        c.restitution = k.restitution;
        stats.max_overlap_fraction = std::max(stats.max_overlap_fraction, overlap / r);
        out.push_back(c);
    };
    for (size_t s = 0; s < spheres.size(); ++s) {
        const double z = spheres.position[s].z, r = spheres.radius[s];
        const double below = plates.base_z - (z - r), above = (z + r) - plates.lid_z;
        if (below > 0.0) add_plate_contact(s, true, below);
        if (above > 0.0) add_plate_contact(s, false, above);
    }
    stats.plate_contacts = out.size() - stats.body_contacts;
    return stats;
}

}  // namespace rodsea
