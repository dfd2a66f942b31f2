#pragma once
// The data-parallel step, the GPU backend's algorithm: each stage a kernel, one object per kernel
// whose operator()(i) does element i (a body, a sphere, a contact, a system) and calls the
// per-element physics of engine/physics/. An executor runs it for every i: a CUDA launch, or a
// host loop (parallel_backend.hpp), so the device's algorithm is tested on any machine. This
// file: the stages over bodies and systems; contact_kernels.hpp and island_kernels.hpp the rest;
// parallel_ensemble.hpp puts them in order.
//
// No element's result depends on the order in which elements run: each writes only its own
// outputs; where elements would share a body (the impulses) one thread sweeps the whole island
// those bodies belong to; a system's counts are integer sums and maxima (system_run.hpp); and
// what atomics place in no particular order is sorted before it is read. A trajectory is the
// same bit for bit on every run of one build on one device.
//
// The kernels step many independent systems at once (Systems): each element reads its own
// system's step (box, plates, noise, solver settings). Nothing a system's elements compute
// depends on the other systems, so a system steps to the same bits in an ensemble as alone. A
// system that blew up earlier in the run (Systems::halted) is left as it was.
#include <cstdint>

#include "rodsea/engine/parallel/arrays.hpp"
#include "rodsea/engine/parallel/atomics.hpp"
#include "rodsea/engine/parallel/system_run.hpp"
#include "rodsea/engine/physics/contact_geometry.hpp"
#include "rodsea/engine/physics/free_flight.hpp"
#include "rodsea/engine/physics/impulse.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"
#include "rodsea/engine/physics/sphere_placement.hpp"
#include "rodsea/engine/physics/step_context.hpp"

namespace rodsea::parallel {

// What the resolution needs of each body, written by free flight: the island forest, lists and
// sweep marks cleared, the inverse mass and world-frame inverse inertia for the orientation the
// contacts see, no plate hit yet.
struct BodyScratch {
    std::uint32_t* parent;        // union–find forest of the islands
    std::uint32_t* island_count;  // contacts of the island whose root this body is
    std::uint32_t* island_head;   // the first of them in the island's list (kNoContact: none)
    int* last_changed;            // sweep_island's marks
    double* inv_mass;
    Mat3* inv_inertia;
    PlateHits* plate_hit;
};

// Stage 1, per body: free flight; its squared in-plane speeds join the system's maxima (the
// step's max_planar_speed, and the neighbour list's bound on how far spheres moved). Also clears
// the cell list's counts, a few cells per body, for this step's build if it has one.
struct FlyBodies {
    BodyArrays bodies;
    SpeciesArrays species;
    Systems systems;
    BodyScratch scratch;
    CellList cells;

    RODSEA_HD void operator()(std::uint32_t i) const {
        for (std::uint32_t c = i; c < cells.cells; c += bodies.count)
            cells.count[c] = 0;
        const std::uint32_t system = systems.of_body[i];
        if (systems.halted(system)) return;
        const StepContext& step = systems.context[system];
        const std::uint32_t k = bodies.species[i];
        const physics::Rotor& rotor = species.rotor[k];
        const physics::PlanarSpeed2 s = physics::planar_speed2(
            bodies.velocity[i], bodies.orientation[i], bodies.spin[i], rotor, species.reach2[k]);
        StepCounts& counts = systems.counts[system];
        atomic_max_of(&counts.drift2_bits, s.drift2);
        atomic_max_of(&counts.turn2_bits, s.turn2);
        physics::fly_freely(bodies.position[i], bodies.velocity[i], bodies.orientation[i],
                            bodies.spin[i], rotor, step.dt, step.gravity, step.drop(), step.box);
        scratch.parent[i] = i;
        scratch.island_count[i] = 0;
        scratch.island_head[i] = kNoContact;
        scratch.last_changed[i] = 0;
        scratch.inv_mass[i] = species.inverse_mass[k];
        scratch.inv_inertia[i] =
            physics::world_inverse_inertia(bodies.orientation[i], species.inverse_inertia[k]);
        scratch.plate_hit[i] = PlateHits{};
    }
};

// Stage 1's tail, once every body has flown: whether this step builds the neighbour list anew.
// Each system's spheres have moved at most `travel` in the plane since the last build (the bound
// of each step's fastest body, summed, as the CPU's VerletPairList sums it); past half the skin a
// pair could have come within reach unlisted. The list is shared by every system, so any one
// rebuilds it. Also opens the step's lists of contacts and moves the run on to its next step's
// contexts (the step's are read by now).
struct DecideRebuild {
    Systems systems;
    double* travel;  // per system, mm
    RunStatus* status;
    double half_skin;

    RODSEA_HD void operator()(std::uint32_t) const {
        bool rebuild = status->force_rebuild != 0;
        for (std::uint32_t m = 0; m < systems.count; ++m) {
            if (systems.halted(m)) continue;
            const StepCounts& c = systems.counts[m];
            travel[m] += (std::sqrt(from_ordered_bits(c.drift2_bits)) +
                          std::sqrt(from_ordered_bits(c.turn2_bits))) *
                         systems.context[m].dt;
            if (!(travel[m] <= half_skin)) rebuild = true;
        }
        status->rebuild = rebuild ? 1u : 0u;
        status->force_rebuild = 0;
        if (rebuild) {
            for (std::uint32_t m = 0; m < systems.count; ++m)
                travel[m] = 0.0;
            ++status->builds;
        }
        status->placed = 0;
        status->island_placed = 0;
        ++status->step;
    }
};

// Stage 2, per sphere: its centre in the world; when the list is rebuilt, into its cell.
struct PlaceSpheres {
    BodyArrays bodies;
    SpeciesArrays species;
    SphereArrays spheres;
    Systems systems;
    CellList cells;
    RunStatus* status;

    RODSEA_HD void operator()(std::uint32_t s) const {
        const std::uint32_t b = spheres.body[s];
        const std::uint32_t system = systems.of_body[b];
        if (!systems.halted(system)) {
            const std::uint32_t k = bodies.species[b];
            const std::uint32_t local = s - spheres.first_of[b];
            physics::place_spheres(
                spheres.position + s, species.sphere_offset + species.first_sphere[k] + local, 1,
                bodies.position[b], bodies.orientation[b], species.sphere_axis[k]);
        }
        if (status->rebuild == 0) return;
        const SystemGrid& g = systems.grid[system];
        const PeriodicBox2D& box = systems.context[system].box;
        const Vec3& p = spheres.position[s];
        const std::uint32_t cell =
            g.first_cell + g.grid.row_of(p.y, box.ly) * g.grid.nx + g.grid.column_of(p.x, box.lx);
        const std::uint32_t rank = atomic_add(cells.count + cell, 1u);
        if (rank < cells.room)
            cells.slots(cell)[rank] = s;
        else
            atomic_max(&status->needed_cell_room, std::uint64_t{rank} + 1);
    }
};

// Stage 5, per body: out of the plates by its deepest overlap (physics::plate_push says why),
// and a polar body's noise for the plates it hit this step (docs/model.md §3; the one rule of
// physics::apply_plate_noise, as on the CPU), with the fastest approach that got an impulse (the
// sweeps kept it). The overlaps are those the contacts were found with: the spheres have not
// moved since. The noise hashes the body's index in its own system.
struct ProjectAndKick {
    BodyArrays bodies;
    SpeciesArrays species;
    SphereArrays spheres;
    Systems systems;
    const PlateHits* plate_hit;

    RODSEA_HD void operator()(std::uint32_t b) const {
        const std::uint32_t system = systems.of_body[b];
        if (systems.halted(system)) return;
        const StepContext& step = systems.context[system];
        const std::uint32_t first = spheres.first_of[b], last = spheres.first_of[b + 1];
        double base = 0.0, lid = 0.0;
        for (std::uint32_t s = first; s < last; ++s) {
            const physics::PlateOverlaps o =
                physics::plate_overlaps(spheres.position[s].z, spheres.radius[s], step.plates);
            if (o.base > base) base = o.base;
            if (o.lid > lid) lid = o.lid;
        }
        if (const double dz = physics::plate_push(base, lid); dz != 0.0) {
            bodies.position[b].z += dz;
            for (std::uint32_t s = first; s < last; ++s)
                spheres.position[s].z += dz;
        }
        if (!species.polar[bodies.species[b]]) return;
        const int kicks = physics::apply_plate_noise(bodies.spin[b].z, step.noise_mode,
                                                     step.noise_epsilon, step.seed, step.step,
                                                     b - systems.first_body[system], plate_hit[b]);
        if (kicks > 0)
            atomic_add(&systems.counts[system].noise_kicks, static_cast<std::uint64_t>(kicks));
    }
};

// Stage 5's tail, per system, once every body is out of the plates and kicked: the step's counts
// become its statistics (a system that crossed its bounds stops), and the next step of the run
// reads its context.
struct EndStep {
    SystemRun* run;
    StepCounts* counts;
    const HaltBounds* halt;
    StepContext* current;        // the step being taken, per system
    const StepContext* planned;  // the run's, step by step, system by system
    const RunStatus* status;
    std::uint32_t systems;

    RODSEA_HD void operator()(std::uint32_t m) const {
        if (run[m].halted == 0) run[m].end_step(counts[m], halt[m]);
        if (status->step < status->steps) current[m] = planned[status->step * systems + m];
    }
};

// Before a run, per system: its first step's context, its run and counts cleared; and the
// run's shared words.
struct BeginRun {
    StepContext* current;
    const StepContext* planned;
    SystemRun* run;
    StepCounts* counts;
    RunStatus* status;
    std::uint32_t steps;
    bool force_rebuild;

    RODSEA_HD void operator()(std::uint32_t m) const {
        current[m] = planned[m];
        run[m] = SystemRun{};
        counts[m] = StepCounts{};
        if (m != 0) return;
        status->step = 0;
        status->steps = steps;
        status->needed_slots = 0;
        status->needed_contacts = 0;
        status->needed_cell_room = 0;
        if (force_rebuild) status->force_rebuild = 1;
    }
};

}  // namespace rodsea::parallel
