#include "rodsea/engine/cpu/contact_resolution.hpp"

#include <algorithm>
#include <limits>

#include "rodsea/engine/physics/impulse.hpp"
#include "rodsea/engine/physics/island_sweep.hpp"

namespace rodsea::cpu {

void InverseInertia::update_for(const std::vector<Contact>& contacts, BodyView bodies,
                                const SpeciesTable& species) {
    inv_mass_.resize(bodies.size());
    inv_inertia_.resize(bodies.size());
    stamp_.resize(bodies.size(), 0);
    ++calls_;
    const auto need = [&](std::uint32_t b) {
        if (stamp_[b] == calls_) return;
        stamp_[b] = calls_;
        const std::uint32_t k = bodies.species[b];
        inv_mass_[b] = species.inverse_mass[k];
        inv_inertia_[b] =
            physics::world_inverse_inertia(bodies.orientation[b], species.inverse_inertia[k]);
    };
    for (const Contact& c : contacts) {
        need(c.a);
        if (!c.with_plate()) need(c.b);
    }
}

void ContactResolver::find_islands(const std::vector<Contact>& contacts, size_t bodies) {
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    parent_.resize(bodies);
    for (size_t b = 0; b < bodies; ++b)
        parent_[b] = static_cast<std::uint32_t>(b);
    const auto root = [&](std::uint32_t b) {
        while (parent_[b] != b) {
            parent_[b] = parent_[parent_[b]];  // path halving
            b = parent_[b];
        }
        return b;
    };
    for (const Contact& c : contacts) {
        if (c.with_plate()) continue;
        const std::uint32_t ra = root(c.a), rb = root(c.b);
        if (ra != rb) parent_[std::max(ra, rb)] = std::min(ra, rb);
    }
    // Number the islands in the order of their first contact, and sort the contacts by island
    // (stable: list order within each island).
    island_of_root_.assign(bodies, kNone);
    contact_island_.resize(contacts.size());
    island_start_.assign(1, 0);
    for (size_t k = 0; k < contacts.size(); ++k) {
        const std::uint32_t r = root(contacts[k].a);
        if (island_of_root_[r] == kNone) {
            island_of_root_[r] = static_cast<std::uint32_t>(island_start_.size() - 1);
            island_start_.push_back(0);
        }
        contact_island_[k] = island_of_root_[r];
        ++island_start_[island_of_root_[r] + 1];
    }
    island_count_ = island_start_.size() - 1;
    for (size_t i = 0; i < island_count_; ++i)
        island_start_[i + 1] += island_start_[i];
    island_contacts_.resize(contacts.size());
    island_cursor_.assign(island_start_.begin(), island_start_.end() - 1);
    for (size_t k = 0; k < contacts.size(); ++k)
        island_contacts_[island_cursor_[contact_island_[k]]++] = static_cast<std::uint32_t>(k);
}

namespace {

// The bodies as physics::sweep_island reads them: the state, and the inverse mass and inertia
// of the bodies in contact.
struct SweptBodies {
    BodyView bodies;
    const InverseInertia& inertia;

    Vec3& velocity(std::uint32_t b) const { return bodies.velocity[b]; }
    Vec3& spin(std::uint32_t b) const { return bodies.spin[b]; }
    double inv_mass(std::uint32_t b) const { return inertia.inv_mass(b); }
    const Mat3& inv_inertia(std::uint32_t b) const { return inertia.inv_inertia(b); }
};

}  // namespace

ResolutionStats ContactResolver::sweep_island(size_t island, const std::vector<Contact>& contacts,
                                              BodyView bodies, const InverseInertia& inertia,
                                              const StepContext& step,
                                              std::vector<PlateHit>& hits) {
    SweptBodies swept{bodies, inertia};
    const std::uint32_t first = island_start_[island];
    const physics::IslandSweep s = physics::sweep_island(
        contacts.data(), island_contacts_.data() + first, island_start_[island + 1] - first, swept,
        last_changed_.data(), Vec3{0.0, 0.0, step.plates.velocity_z}, step.approach_tolerance,
        step.max_sweeps, [&](std::uint32_t k, double approach) {
            hits.push_back({contacts[k].a, contacts[k].b, approach});
        });
    return {s.sweeps, s.impulses, s.body_collisions, s.plate_collisions, s.unresolved};
}

ResolutionStats ContactResolver::resolve(const std::vector<Contact>& contacts, BodyView bodies,
                                         const InverseInertia& inertia, const StepContext& step,
                                         std::vector<PlateHit>& hits, int threads) {
    last_changed_.assign(bodies.size(), 0);
    find_islands(contacts, bodies.size());
    ResolutionStats total;
    const auto add = [&total](const ResolutionStats& s) {
        total.sweeps = std::max(total.sweeps, s.sweeps);
        total.impulses += s.impulses;
        total.body_collisions += s.body_collisions;
        total.plate_collisions += s.plate_collisions;
        total.unresolved += s.unresolved;
    };
    if (threads <= 1) {
        for (size_t i = 0; i < island_count_; ++i)
            add(sweep_island(i, contacts, bodies, inertia, step, hits));
        return total;
    }
    // Each thread keeps its islands' hits apart and they are put back in island order, so that
    // `hits` is the same list on any number of threads.
    island_hits_.resize(island_count_);
    island_stats_.resize(island_count_);
    const auto n = static_cast<std::ptrdiff_t>(island_count_);
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        island_hits_[i].clear();
        island_stats_[i] =
            sweep_island(static_cast<size_t>(i), contacts, bodies, inertia, step, island_hits_[i]);
    }
    for (size_t i = 0; i < island_count_; ++i) {
        add(island_stats_[i]);
        hits.insert(hits.end(), island_hits_[i].begin(), island_hits_[i].end());
    }
    return total;
}

}  // namespace rodsea::cpu
