#include "rodsea/engine/contact_search.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/engine/parallel.hpp"

namespace rodsea {

ContactSearchStats ContactFinder::find(const SphereTable& spheres, const BodyState& bodies,
                                       const EngineParameters& params, const PlateState& plates,
                                       std::vector<Contact>& out, int threads, double travel) {
    ContactSearchStats stats;
    const PeriodicBox2D box{params.box.lx, params.box.ly};
    pairs_.update(spheres.position, spheres.radius, spheres.body, box, travel);
    const auto slots = static_cast<size_t>(std::max(threads, 1));
    body_chunks_.resize(slots);
    plate_chunks_.resize(slots);
    max_overlap_.assign(slots, 0.0);

    const auto find_body_contacts = [&](Chunk range, std::vector<Contact>& found, double& deepest) {
        pairs_.for_each_pair(
            spheres.position, range.begin, range.end,
            [&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
                const double reach = spheres.radius[i] + spheres.radius[j];
                const double d2 = norm2(d);
                if (d2 >= reach * reach || d2 == 0.0) return;
                const std::uint32_t bi = spheres.body[i], bj = spheres.body[j];
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
                deepest =
                    std::max(deepest, c.overlap / std::min(spheres.radius[i], spheres.radius[j]));
                found.push_back(c);
            });
    };
    const auto find_plate_contacts = [&](Chunk range, std::vector<Contact>& found,
                                         double& deepest) {
        const auto add = [&](size_t s, bool base, double overlap) {
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
            deepest = std::max(deepest, overlap / r);
            found.push_back(c);
        };
        for (size_t s = range.begin; s < range.end; ++s) {
            const double z = spheres.position[s].z, r = spheres.radius[s];
            const double below = plates.base_z - (z - r), above = (z + r) - plates.lid_z;
            if (below > 0.0) add(s, true, below);
            if (above > 0.0) add(s, false, above);
        }
    };

    if (slots == 1) {  // straight into `out`: no copies
        out.clear();
        find_body_contacts({0, pairs_.size()}, out, max_overlap_[0]);
        stats.body_contacts = out.size();
        find_plate_contacts({0, spheres.size()}, out, max_overlap_[0]);
        stats.plate_contacts = out.size() - stats.body_contacts;
        stats.max_overlap_fraction = max_overlap_[0];
        return stats;
    }

    size_t body_total = 0, plate_total = 0;
#pragma omp parallel num_threads(threads)
    {
        const int team = team_size(), t = thread_index();
        std::vector<Contact>& body = body_chunks_[t];
        std::vector<Contact>& plate = plate_chunks_[t];
        body.clear();
        plate.clear();
        find_body_contacts(chunk_of(pairs_.size(), t, team), body, max_overlap_[t]);
        find_plate_contacts(chunk_of(spheres.size(), t, team), plate, max_overlap_[t]);
#pragma omp barrier
#pragma omp single
        {
            for (int u = 0; u < team; ++u) {
                body_total += body_chunks_[u].size();
                plate_total += plate_chunks_[u].size();
            }
            out.resize(body_total + plate_total);
        }  // implicit barrier: every thread sees the totals and the resized list
        size_t body_at = 0, plate_at = body_total;
        for (int u = 0; u < t; ++u) {
            body_at += body_chunks_[u].size();
            plate_at += plate_chunks_[u].size();
        }
        std::copy(body.begin(), body.end(), out.begin() + static_cast<std::ptrdiff_t>(body_at));
        std::copy(plate.begin(), plate.end(), out.begin() + static_cast<std::ptrdiff_t>(plate_at));
    }
    stats.body_contacts = body_total;
    stats.plate_contacts = plate_total;
    stats.max_overlap_fraction = *std::max_element(max_overlap_.begin(), max_overlap_.end());
    return stats;
}

}  // namespace rodsea
