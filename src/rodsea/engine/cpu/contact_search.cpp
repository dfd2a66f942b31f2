#include "rodsea/engine/cpu/contact_search.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/engine/cpu/detail/parallel.hpp"
#include "rodsea/engine/physics/contact_geometry.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/math/nan_as_infinity.hpp"

namespace rodsea::cpu {

namespace {

// What one search reads.
struct SearchInput {
    const SphereTable& spheres;
    BodyView bodies;
    const SpeciesTable& species;
    const physics::PlateState& plates;
};

}  // namespace

void ContactFinder::Depth::add(double overlap_fraction) {
    const double f = nan_as_infinity(overlap_fraction);
    deepest = std::max(deepest, f);
    if (f > kGrossOverlapFraction) ++gross;
}

namespace {

// The contact of listed spheres i < j (d = p_i − p_j, minimum image) if they touch, appended to
// `found`; `depth` takes its overlap over the smaller radius.
void add_body_contact(const SearchInput& in, std::uint32_t i, std::uint32_t j, const Vec3& d,
                      std::vector<Contact>& found, ContactFinder::Depth& depth) {
    const SphereTable& spheres = in.spheres;
    const std::uint32_t bi = spheres.body[i], bj = spheres.body[j];
    Contact c;
    if (!physics::sphere_sphere_contact(d, bi, spheres.position[i], spheres.radius[i],
                                        in.bodies.position[bi], bj, spheres.position[j],
                                        spheres.radius[j], in.bodies.position[bj], c))
        return;
    const ContactCoefficients& k =
        in.species.pair_coefficients(in.bodies.species[bi], in.bodies.species[bj]);
    c.friction = k.friction;
    c.restitution = k.restitution;
    depth.add(c.overlap / std::min(spheres.radius[i], spheres.radius[j]));
    found.push_back(c);
}

// The contacts of the listed sphere pairs [range) in list order, appended to `found`.
void find_body_contacts(const VerletPairList& pairs, const SearchInput& in, Chunk range,
                        std::vector<Contact>& found, ContactFinder::Depth& depth) {
    pairs.for_each_touching_pair(in.spheres.position, in.spheres.radius, range.begin, range.end,
                                 [&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
                                     add_body_contact(in, i, j, d, found, depth);
                                 });
}

// The contacts of body b's spheres with the base and the lid, in sphere order.
void find_plate_contacts_of(const SearchInput& in, size_t b, std::vector<Contact>& found,
                            ContactFinder::Depth& depth) {
    const SphereTable& spheres = in.spheres;
    // Whole bodies clear of both plates are most of them (a lone sphere is read directly). A NaN
    // height gives NaN bounds, which are searched; spheres of a NaN tilt have NaN heights and
    // touch nothing.
    if (spheres.first_of[b + 1] - spheres.first_of[b] > 1 &&
        spheres.lowest[b] >= in.plates.base_z && spheres.highest[b] <= in.plates.lid_z)
        return;
    for (size_t s = spheres.first_of[b]; s < spheres.first_of[b + 1]; ++s) {
        const double r = spheres.radius[s];
        const physics::PlateOverlaps o =
            physics::plate_overlaps(spheres.position[s].z, r, in.plates);
        for (const bool base : {true, false}) {
            const double overlap = base ? o.base : o.lid;
            if (!(overlap > 0.0)) continue;
            found.push_back(physics::plate_contact(
                static_cast<std::uint32_t>(b), spheres.position[s], r, in.bodies.position[b], base,
                overlap, in.species.plate[in.bodies.species[b]]));
            depth.add(overlap / r);
        }
    }
}

// The contacts of the spheres of bodies [range) with the base and the lid, in sphere order.
void find_plate_contacts(const SearchInput& in, Chunk range, std::vector<Contact>& found,
                         ContactFinder::Depth& depth) {
    for (size_t b = range.begin; b < range.end; ++b)
        find_plate_contacts_of(in, b, found, depth);
}

// The contacts of the bodies awake[range) (ascending): with each other, in the list's (i, j)
// order, appended to `pairs_found`, and with the plates, in sphere order, to `plates_found`. A
// pair with a coasting body is skipped: nothing touches a coasting body (coasting_backend.hpp).
void find_awake_contacts(const VerletPairList& pairs, const SearchInput& in,
                         std::span<const std::uint32_t> awake,
                         std::span<const std::uint8_t> coasting, Chunk range,
                         std::vector<Contact>& pairs_found, std::vector<Contact>& plates_found,
                         ContactFinder::Depth& depth) {
    const SphereTable& spheres = in.spheres;
    for (size_t k = range.begin; k < range.end; ++k) {
        const std::uint32_t b = awake[k];
        for (std::uint32_t i = spheres.first_of[b]; i < spheres.first_of[b + 1]; ++i) {
            // A sphere's row is a few pairs: tested one by one, with the sifting test of
            // for_each_touching_pair (a NaN distance is visited, for the contact test to see).
            const VerletPairList::Range row = pairs.row(i);
            const double r = spheres.radius[i];
            pairs.for_each_pair(
                spheres.position, row.begin, row.end,
                [&](std::uint32_t p, std::uint32_t j, const Vec3& d) {
                    const double reach = r + spheres.radius[j];
                    const double d2 = norm2(d);
                    if (d2 >= reach * reach || d2 == 0.0 || coasting[spheres.body[j]]) return;
                    add_body_contact(in, p, j, d, pairs_found, depth);
                });
        }
        find_plate_contacts_of(in, b, plates_found, depth);
    }
}

}  // namespace

ContactSearchStats ContactFinder::find(const SphereTable& spheres, BodyView bodies,
                                       const SpeciesTable& species, const StepContext& step,
                                       std::vector<Contact>& out, int threads, double travel) {
    pairs_.update(spheres.position, spheres.radius, spheres.body, step.box, travel, threads);
    const SearchInput in{spheres, bodies, species, step.plates};
    ContactSearchStats stats;
    if (threads <= 1) {  // straight into `out`: no copies
        out.clear();
        Depth depth;
        find_body_contacts(pairs_, in, {0, pairs_.size()}, out, depth);
        stats.body_contacts = out.size();
        find_plate_contacts(in, {0, bodies.size()}, out, depth);
        stats.plate_contacts = out.size() - stats.body_contacts;
        stats.max_overlap_fraction = depth.deepest;
        stats.gross_overlaps = depth.gross;
        return stats;
    }
    start_chunks(threads);
#pragma omp parallel num_threads(threads)
    {
        const int team = team_size(), t = thread_index();
        find_body_contacts(pairs_, in, chunk_of(pairs_.size(), t, team), body_chunks_[t],
                           depth_[t]);
        find_plate_contacts(in, chunk_of(bodies.size(), t, team), plate_chunks_[t], depth_[t]);
    }
    return gather_chunks(out);
}

ContactSearchStats ContactFinder::find_awake(const SphereTable& spheres, BodyView bodies,
                                             const SpeciesTable& species, const StepContext& step,
                                             std::span<const std::uint32_t> awake,
                                             std::span<const std::uint8_t> coasting,
                                             std::vector<Contact>& out, int threads,
                                             double travel) {
    pairs_.update(spheres.position, spheres.radius, spheres.body, step.box, travel, threads);
    const SearchInput in{spheres, bodies, species, step.plates};
    start_chunks(threads);
    if (threads <= 1) {
        find_awake_contacts(pairs_, in, awake, coasting, {0, awake.size()}, body_chunks_[0],
                            plate_chunks_[0], depth_[0]);
    } else {
#pragma omp parallel num_threads(threads)
        {
            const int team = team_size(), t = thread_index();
            find_awake_contacts(pairs_, in, awake, coasting, chunk_of(awake.size(), t, team),
                                body_chunks_[t], plate_chunks_[t], depth_[t]);
        }
    }
    // The order find() gives the same contacts in.
    return gather_chunks(out);
}

void ContactFinder::start_chunks(int threads) {
    const auto slots = static_cast<size_t>(std::max(threads, 1));
    body_chunks_.resize(slots);
    plate_chunks_.resize(slots);
    depth_.assign(slots, Depth{});
    for (size_t t = 0; t < slots; ++t) {  // a team smaller than asked leaves slots unfilled
        body_chunks_[t].clear();
        plate_chunks_[t].clear();
    }
}

ContactSearchStats ContactFinder::gather_chunks(std::vector<Contact>& out) const {
    // Body contacts then plate contacts, each in chunk order: the serial list.
    ContactSearchStats stats;
    stats.body_contacts = gather(body_chunks_, out, 0);
    stats.plate_contacts = gather(plate_chunks_, out, stats.body_contacts);
    for (const Depth& d : depth_) {
        stats.max_overlap_fraction = std::max(stats.max_overlap_fraction, d.deepest);
        stats.gross_overlaps += d.gross;
    }
    return stats;
}

size_t ContactFinder::gather(const std::vector<std::vector<Contact>>& chunks,
                             std::vector<Contact>& out, size_t at) {
    size_t total = 0;
    for (const std::vector<Contact>& c : chunks)
        total += c.size();
    out.resize(at + total);
    for (const std::vector<Contact>& c : chunks) {
        std::copy(c.begin(), c.end(), out.begin() + static_cast<std::ptrdiff_t>(at));
        at += c.size();
    }
    return total;
}

}  // namespace rodsea::cpu
