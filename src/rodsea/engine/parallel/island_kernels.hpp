#pragma once
// The impulses of the data-parallel step (kernels.hpp says what every kernel promises): the
// contacts joined into islands (bodies linked by body–body contacts; a plate joins nothing),
// each island's contacts gathered and put in list order, and each island swept by one thread
// with the CPU's own sweep (physics/island_sweep.hpp). In a shaken monolayer islands are small:
// 72 % hold one contact and none more than 14 at φ_a = 0.78 (docs/performance.md), so one
// thread per island is enough, and each island gets exactly the impulses it gets on the CPU.
#include <cstdint>

#include "rodsea/engine/parallel/arrays.hpp"
#include "rodsea/engine/parallel/atomics.hpp"
#include "rodsea/engine/parallel/system_run.hpp"
#include "rodsea/engine/physics/island_sweep.hpp"

namespace rodsea::parallel {

// The root of body b's island as far as the hooks so far go.
RODSEA_HD inline std::uint32_t island_root(const std::uint32_t* parent, std::uint32_t b) {
    for (std::uint32_t up = load_shared(parent + b); up != b; up = load_shared(parent + b))
        b = up;
    return b;
}

// Per body contact: joins its two bodies' islands, the larger root under the smaller. Roots
// only ever point to smaller bodies, so whatever order the hooks run in, every island ends with
// its smallest body as its root: the partition and its labels are the same on every run. (Free
// flight set every body's parent to itself.)
struct HookIslands {
    const Contact* contacts;
    std::uint32_t* parent;

    RODSEA_HD void operator()(std::uint32_t k) const {
        const Contact& c = contacts[k];
        for (;;) {
            const std::uint32_t a = island_root(parent, c.a), b = island_root(parent, c.b);
            if (a == b) return;
            const std::uint32_t low = a < b ? a : b, high = a < b ? b : a;
            if (compare_and_swap(parent + high, high, low)) return;  // else another hook won
        }
    }
};

// Per contact, once every hook is in: its island (its first body's root), counted at the root,
// with its rank there (in no particular order: the sweep sorts its island's contacts).
struct KeyContactsByIsland {
    const Contact* contacts;
    const std::uint32_t* parent;
    std::uint32_t* island_count;  // per body: contacts of the island it is the root of
    std::uint32_t* key;
    std::uint32_t* rank;

    RODSEA_HD void operator()(std::uint32_t k) const {
        const std::uint32_t root = island_root(parent, contacts[k].a);
        key[k] = root;
        rank[k] = atomic_add(island_count + root, 1u);
    }
};

// Per contact, after the exclusive scan of the islands' counts: into its island's place.
struct GatherIslands {
    const std::uint32_t* key;
    const std::uint32_t* rank;
    const std::uint32_t* island_start;
    std::uint32_t* order;

    RODSEA_HD void operator()(std::uint32_t k) const { order[island_start[key[k]] + rank[k]] = k; }
};

// What physics::sweep_island reads and writes of the bodies.
struct IslandBodies {
    BodyArrays bodies;
    const double* inverse_mass;
    const Mat3* inverse_inertia;

    RODSEA_HD Vec3& velocity(std::uint32_t b) const { return bodies.velocity[b]; }
    RODSEA_HD Vec3& spin(std::uint32_t b) const { return bodies.spin[b]; }
    RODSEA_HD double inv_mass(std::uint32_t b) const { return inverse_mass[b]; }
    RODSEA_HD const Mat3& inv_inertia(std::uint32_t b) const { return inverse_inertia[b]; }
};

// Per body: if it is an island's root, its island's contacts in list order (a handful, sorted
// in place), swept with its system's sweep cap; what the sweep counted joins the system's step.
// Each plate impulse's approach speed is kept for the noise (the fastest per contact).
struct SweepIslands {
    const Contact* contacts;
    const std::uint32_t* island_count;
    const std::uint32_t* island_start;
    std::uint32_t* order;
    IslandBodies bodies;
    Systems systems;
    int* last_changed;
    double* hit_speed;

    RODSEA_HD void operator()(std::uint32_t root) const {
        const std::uint32_t count = island_count[root];
        const std::uint32_t system = systems.of_body[root];
        // A halted system's bodies keep the counts of the step it stopped at.
        if (count == 0 || systems.halted(system)) return;
        std::uint32_t* own = order + island_start[root];
        for (std::uint32_t i = 1; i < count; ++i) {
            const std::uint32_t k = own[i];
            std::uint32_t at = i;
            for (; at > 0 && own[at - 1] > k; --at)
                own[at] = own[at - 1];
            own[at] = k;
        }
        const StepContext& step = systems.context[system];
        IslandBodies b = bodies;
        const physics::IslandSweep s = physics::sweep_island(
            contacts, own, count, b, last_changed, Vec3{0.0, 0.0, step.plates.velocity_z},
            step.approach_tolerance, step.max_sweeps, [this](std::uint32_t k, double approach) {
                if (approach > hit_speed[k]) hit_speed[k] = approach;
            });
        StepCounts& tally = systems.counts[system];
        atomic_max(&tally.sweeps, static_cast<std::uint64_t>(s.sweeps));
        atomic_add(&tally.impulses, s.impulses);
        if (s.body_collisions > 0) atomic_add(&tally.body_collisions, s.body_collisions);
        if (s.plate_collisions > 0) atomic_add(&tally.plate_collisions, s.plate_collisions);
        if (s.unresolved > 0) atomic_add(&tally.unresolved, s.unresolved);
    }
};

}  // namespace rodsea::parallel
