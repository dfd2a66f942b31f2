#pragma once
// The impulses of the data-parallel step (kernels.hpp says what every kernel promises): the
// contacts joined into islands (bodies linked by body–body contacts; a plate joins nothing) as
// they are found, each island's contacts listed at its root, and each island swept by one
// thread, its contacts in the CPU's order, with the CPU's own sweep
// (physics/island_sweep.hpp). In a shaken monolayer islands are small: 72 % hold one contact
// and none more than 14 at φ_a = 0.78 (docs/performance.md), so one thread per island is
// enough, and each island gets exactly the impulses it gets on the CPU.
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

// Joins bodies a's and b's islands, the larger root under the smaller. Roots only ever point to
// smaller bodies, so whatever order the joins run in, every island ends with its smallest body
// as its root: the partition and its labels are the same on every run. (Free flight set every
// body's parent to itself.)
RODSEA_HD inline void join_islands(std::uint32_t* parent, std::uint32_t a, std::uint32_t b) {
    for (;;) {
        const std::uint32_t ra = island_root(parent, a), rb = island_root(parent, b);
        if (ra == rb) return;
        const std::uint32_t low = ra < rb ? ra : rb, high = ra < rb ? rb : ra;
        if (compare_and_swap(parent + high, high, low)) return;  // else another join won
    }
}

// Stage 4, per contact, once every join is in: onto its island's list (its first body's root
// holds the list's head and count; the list's order varies from run to run: the sweep sorts it).
struct ListIslands {
    const Contact* contacts;
    const std::uint32_t* parent;
    std::uint32_t* island_count;  // per body: contacts of the island it is the root of
    std::uint32_t* island_head;   // per body: the last contact listed (kNoContact: none)
    std::uint32_t* next;          // per contact: the one listed before it

    RODSEA_HD void operator()(std::uint32_t k) const {
        const std::uint32_t root = island_root(parent, contacts[k].a);
        next[k] = atomic_exchange(island_head + root, k);
        atomic_add(island_count + root, 1u);
    }
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

// Stage 4b, per body: if it is an island's root, its island's contacts (a handful) copied from
// its list to places from the step's cursor and put in the CPU's order by their keys, swept with
// its system's sweep cap; what the sweep counted joins the system's step. Each body keeps the
// fastest approach among its plate impulses, for the noise.
struct SweepIslands {
    const Contact* contacts;
    const std::uint64_t* key;
    const std::uint32_t* island_count;
    const std::uint32_t* island_head;
    const std::uint32_t* next;
    std::uint32_t* order;  // room for every contact of the step
    IslandBodies bodies;
    Systems systems;
    int* last_changed;
    PlateHits* plate_hit;
    RunStatus* status;

    RODSEA_HD void operator()(std::uint32_t root) const {
        const std::uint32_t count = island_count[root];
        const std::uint32_t system = systems.of_body[root];
        // A halted system's bodies keep the counts of the step it stopped at.
        if (count == 0 || systems.halted(system)) return;
        std::uint32_t* own = order + atomic_add(&status->island_placed, count);
        std::uint32_t listed = island_head[root];
        for (std::uint32_t i = 0; i < count; ++i, listed = next[listed]) {
            const std::uint64_t at_key = key[listed];
            std::uint32_t at = i;
            for (; at > 0 && key[own[at - 1]] > at_key; --at)
                own[at] = own[at - 1];
            own[at] = listed;
        }
        const StepContext& step = systems.context[system];
        IslandBodies b = bodies;
        const physics::IslandSweep s = physics::sweep_island(
            contacts, own, count, b, last_changed, Vec3{0.0, 0.0, step.plates.velocity_z},
            step.approach_tolerance, step.max_sweeps, [this](std::uint32_t k, double approach) {
                const Contact& c = contacts[k];
                double& fastest = c.b == kLidPlate ? plate_hit[c.a].lid : plate_hit[c.a].base;
                if (approach > fastest) fastest = approach;
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
