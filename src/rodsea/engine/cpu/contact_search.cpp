#include "rodsea/engine/cpu/contact_search.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/engine/cpu/detail/parallel.hpp"
#include "rodsea/engine/physics/contact_geometry.hpp"

namespace rodsea::cpu {

ContactSearchStats ContactFinder::find(const SphereTable& spheres, BodyView bodies,
                                       const SpeciesTable& species, const StepContext& step,
                                       std::vector<Contact>& out, int threads, double travel) {
    ContactSearchStats stats;
    pairs_.update(spheres.position, spheres.radius, spheres.body, step.box, travel);
    const auto slots = static_cast<size_t>(std::max(threads, 1));
    body_chunks_.resize(slots);
    plate_chunks_.resize(slots);
    max_overlap_.assign(slots, 0.0);

    const auto find_body_contacts = [&](Chunk range, std::vector<Contact>& found, double& deepest) {
        pairs_.for_each_pair(
            spheres.position, range.begin, range.end,
            [&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
                const std::uint32_t bi = spheres.body[i], bj = spheres.body[j];
                Contact c;
                if (!physics::sphere_sphere_contact(d, bi, spheres.position[i], spheres.radius[i],
                                                    bodies.position[bi], bj, spheres.position[j],
                                                    spheres.radius[j], bodies.position[bj], c))
                    return;
                const ContactCoefficients& k =
                    species.pair_coefficients(bodies.species[bi], bodies.species[bj]);
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
            found.push_back(physics::plate_contact(b, spheres.position[s], r, bodies.position[b],
                                                   base, overlap,
                                                   species.plate[bodies.species[b]]));
            deepest = std::max(deepest, overlap / r);
        };
        for (size_t s = range.begin; s < range.end; ++s) {
            const physics::PlateOverlaps o =
                physics::plate_overlaps(spheres.position[s].z, spheres.radius[s], step.plates);
            if (o.base > 0.0) add(s, true, o.base);
            if (o.lid > 0.0) add(s, false, o.lid);
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

}  // namespace rodsea::cpu
