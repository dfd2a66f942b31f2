#pragma once
// The data-parallel step, the GPU backend's algorithm: each stage a kernel, one object per kernel
// whose operator()(i) does element i (a body, a sphere, a contact) and calls the per-element
// physics of engine/physics/. An executor runs it for every i: a CUDA launch, or a host loop
// (parallel_backend.hpp), so the device's algorithm is tested on any machine.
//
// No element's result depends on the order in which elements run: each writes only its own
// outputs, and where elements would share a body (the impulses) one thread sweeps the whole
// island those bodies belong to. Sums and maxima are taken afterwards by the executor's
// reductions, and orders by stable sorts, so a trajectory is the same bit for bit on every run of
// one build on one device.
//
// The kernels step many independent systems at once (Systems): each element reads its own
// system's step (box, plates, noise, solver settings). Nothing a system's elements compute
// depends on the other systems, so a system steps to the same bits in an ensemble as alone.
#include <cstdint>

#include "rodsea/engine/parallel/arrays.hpp"
#include "rodsea/engine/parallel/atomics.hpp"
#include "rodsea/engine/physics/contact_geometry.hpp"
#include "rodsea/engine/physics/free_flight.hpp"
#include "rodsea/engine/physics/impulse.hpp"
#include "rodsea/engine/physics/island_sweep.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"
#include "rodsea/engine/physics/sphere_placement.hpp"
#include "rodsea/engine/physics/step_context.hpp"
#include "rodsea/math/nan_as_infinity.hpp"
#include "rodsea/random.hpp"

namespace rodsea::parallel {

// Stage 1, per body: free flight, and the squared speeds in the plane that bound how far its
// spheres move (the step's max_planar_speed).
struct FlyBodies {
    BodyArrays bodies;
    SpeciesArrays species;
    Systems systems;
    double* drift2;
    double* turn2;

    RODSEA_HD void operator()(std::uint32_t i) const {
        const StepContext& step = systems.context[systems.of_body[i]];
        const std::uint32_t k = bodies.species[i];
        const physics::Rotor& rotor = species.rotor[k];
        const physics::PlanarSpeed2 s = physics::planar_speed2(
            bodies.velocity[i], bodies.orientation[i], bodies.spin[i], rotor, species.reach2[k]);
        drift2[i] = s.drift2;
        turn2[i] = s.turn2;
        physics::fly_freely(bodies.position[i], bodies.velocity[i], bodies.orientation[i],
                            bodies.spin[i], rotor, step.dt, step.gravity, step.drop(), step.box);
    }
};

// Stage 2, per body: the world centres of its spheres.
struct PlaceSpheres {
    BodyArrays bodies;
    SpeciesArrays species;
    SphereArrays spheres;

    RODSEA_HD void operator()(std::uint32_t i) const {
        const std::uint32_t k = bodies.species[i];
        const std::uint32_t first = spheres.first_of[i];
        physics::place_spheres(spheres.position + first,
                               species.sphere_offset + species.first_sphere[k],
                               spheres.first_of[i + 1] - first, bodies.position[i],
                               bodies.orientation[i], species.sphere_axis[k]);
    }
};

// Stage 3a, per sphere: its cell, as a key for the sort that builds the cell list.
struct KeySpheresByCell {
    SphereArrays spheres;
    Systems systems;
    std::uint32_t* key;
    std::uint32_t* sphere;

    RODSEA_HD void operator()(std::uint32_t s) const {
        const std::uint32_t system = systems.of_sphere(spheres, s);
        const SystemGrid& g = systems.grid[system];
        const PeriodicBox2D& box = systems.context[system].box;
        const Vec3& p = spheres.position[s];
        key[s] =
            g.first_cell + g.grid.row_of(p.y, box.ly) * g.grid.nx + g.grid.column_of(p.x, box.lx);
        sphere[s] = s;
    }
};

// out[i] = values[at[i]]: a few entries of a long array, to copy to the host.
struct GatherAt {
    const std::uint32_t* values;
    const std::uint32_t* at;
    std::uint32_t* out;

    RODSEA_HD void operator()(std::uint32_t i) const { out[i] = values[at[i]]; }
};

// Per element of a sorted key array: where each key's run begins and ends (start[key] .. end[key]);
// keys that do not occur keep the values they were filled with (start = end: empty).
struct MarkRuns {
    const std::uint32_t* key;
    std::uint32_t count;
    std::uint32_t* start;
    std::uint32_t* end;

    RODSEA_HD void operator()(std::uint32_t k) const {
        if (k == 0 || key[k] != key[k - 1]) start[key[k]] = k;
        if (k + 1 == count || key[k + 1] != key[k]) end[key[k]] = k + 1;
    }
};

// visit(contact, j) for each sphere j > i of another body that overlaps sphere i: the contact
// as the CPU's search makes it (d = p_i − p_j, minimum image; normal from j's body into i's),
// without its coefficients. Partners are looked for in i's cell and the eight around it, in i's
// system's grid.
template <class Visit>
RODSEA_HD void for_each_touching_partner(std::uint32_t i, const SphereArrays& spheres,
                                         const BodyArrays& bodies, const CellList& cells,
                                         const SystemGrid& system_grid, const PeriodicBox2D& box,
                                         Visit&& visit) {
    const CellGrid& grid = system_grid.grid;
    const Vec3 p = spheres.position[i];
    const std::uint32_t bi = spheres.body[i];
    const double ri = spheres.radius[i];
    const std::uint32_t cx = grid.column_of(p.x, box.lx), cy = grid.row_of(p.y, box.ly);
    // With fewer than three cells across, the offsets −1 and +1 name one cell twice (or the cell
    // itself): look at each distinct cell once.
    const int x_from = grid.nx >= 3 ? -1 : 0, x_to = grid.nx >= 2 ? 1 : 0;
    const int y_from = grid.ny >= 3 ? -1 : 0, y_to = grid.ny >= 2 ? 1 : 0;
    for (int dy = y_from; dy <= y_to; ++dy) {
        const std::uint32_t row = (cy + grid.ny + static_cast<std::uint32_t>(dy)) % grid.ny;
        for (int dx = x_from; dx <= x_to; ++dx) {
            const std::uint32_t column = (cx + grid.nx + static_cast<std::uint32_t>(dx)) % grid.nx;
            const std::uint32_t c = system_grid.first_cell + row * grid.nx + column;
            for (std::uint32_t m = cells.start[c]; m < cells.end[c]; ++m) {
                const std::uint32_t j = cells.sorted_sphere[m];
                const std::uint32_t bj = spheres.body[j];
                if (j <= i || bj == bi) continue;
                Contact contact;
                if (physics::sphere_sphere_contact(
                        box.minimum_image(p - spheres.position[j]), bi, p, ri, bodies.position[bi],
                        bj, spheres.position[j], spheres.radius[j], bodies.position[bj], contact))
                    visit(contact, j);
            }
        }
    }
}

// Stage 3b, per sphere: how many contacts it starts, with other spheres (j > i) and with the
// plates; their exclusive sums place each sphere's contacts in the list.
struct CountContacts {
    SphereArrays spheres;
    BodyArrays bodies;
    CellList cells;
    Systems systems;
    std::uint32_t* body_count;
    std::uint32_t* plate_count;

    RODSEA_HD void operator()(std::uint32_t i) const {
        const std::uint32_t system = systems.of_sphere(spheres, i);
        const StepContext& step = systems.context[system];
        std::uint32_t n = 0;
        for_each_touching_partner(i, spheres, bodies, cells, systems.grid[system], step.box,
                                  [&n](const Contact&, std::uint32_t) { ++n; });
        body_count[i] = n;
        const physics::PlateOverlaps o =
            physics::plate_overlaps(spheres.position[i].z, spheres.radius[i], step.plates);
        plate_count[i] = (o.base > 0.0 ? 1u : 0u) + (o.lid > 0.0 ? 1u : 0u);
    }
};

// Stage 3c, per sphere: writes its contacts where the counts put them: body contacts first, by
// sphere and then by partner sphere, then plate contacts in sphere order (base before lid): the
// CPU's list, contact for contact. `depth` takes each one's overlap over the smaller radius.
struct WriteContacts {
    SphereArrays spheres;
    BodyArrays bodies;
    SpeciesArrays species;
    CellList cells;
    Systems systems;
    const std::uint32_t* body_offset;
    const std::uint32_t* plate_offset;
    std::uint32_t body_contacts;  // where the plate contacts begin
    Contact* contacts;
    double* depth;
    std::uint32_t* partner;  // scratch: each body contact's sphere j

    RODSEA_HD void operator()(std::uint32_t i) const {
        const std::uint32_t system = systems.of_sphere(spheres, i);
        const StepContext& step = systems.context[system];
        const double ri = spheres.radius[i];
        const std::uint32_t first = body_offset[i];
        std::uint32_t at = first;
        for_each_touching_partner(i, spheres, bodies, cells, systems.grid[system], step.box,
                                  [&](Contact& c, std::uint32_t j) {
                                      const ContactCoefficients& k = species.pair_coefficients(
                                          bodies.species[c.a], bodies.species[c.b]);
                                      c.friction = k.friction;
                                      c.restitution = k.restitution;
                                      const double rj = spheres.radius[j];
                                      // Insertion by partner: the cells are visited in grid order,
                                      // the CPU's pairs in sphere order. A sphere has a handful of
                                      // partners.
                                      std::uint32_t slot = at++;
                                      for (; slot > first && partner[slot - 1] > j; --slot) {
                                          contacts[slot] = contacts[slot - 1];
                                          depth[slot] = depth[slot - 1];
                                          partner[slot] = partner[slot - 1];
                                      }
                                      contacts[slot] = c;
                                      depth[slot] =
                                          nan_as_infinity(c.overlap / (ri < rj ? ri : rj));
                                      partner[slot] = j;
                                  });
        const std::uint32_t b = spheres.body[i];
        const Vec3& p = spheres.position[i];
        const physics::PlateOverlaps o = physics::plate_overlaps(p.z, ri, step.plates);
        at = body_contacts + plate_offset[i];
        const ContactCoefficients& k = species.plate[bodies.species[b]];
        if (o.base > 0.0) {
            contacts[at] = physics::plate_contact(b, p, ri, bodies.position[b], true, o.base, k);
            depth[at++] = nan_as_infinity(o.base / ri);
        }
        if (o.lid > 0.0) {
            contacts[at] = physics::plate_contact(b, p, ri, bodies.position[b], false, o.lid, k);
            depth[at] = nan_as_infinity(o.lid / ri);
        }
    }
};

// Stage 4a, per body: inverse mass and world-frame inverse inertia for its orientation now.
struct WorldInverseInertia {
    BodyArrays bodies;
    SpeciesArrays species;
    double* inv_mass;
    Mat3* inv_inertia;

    RODSEA_HD void operator()(std::uint32_t i) const {
        const std::uint32_t k = bodies.species[i];
        inv_mass[i] = species.inverse_mass[k];
        inv_inertia[i] =
            physics::world_inverse_inertia(bodies.orientation[i], species.inverse_inertia[k]);
    }
};

// Stage 4b, per body: its own island to start with (union–find's forest).
struct InitIslands {
    std::uint32_t* parent;

    RODSEA_HD void operator()(std::uint32_t b) const { parent[b] = b; }
};

// The root of body b's island as far as the hooks so far go.
RODSEA_HD inline std::uint32_t island_root(const std::uint32_t* parent, std::uint32_t b) {
    for (std::uint32_t up = load_shared(parent + b); up != b; up = load_shared(parent + b))
        b = up;
    return b;
}

// Stage 4c, per body contact: joins its two bodies' islands, the larger root under the smaller.
// Roots only ever point to smaller bodies, so whatever order the hooks run in, every island ends
// with its smallest body as its root: the partition and its labels are the same on every run.
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

// Stage 4d, per body: points straight at its island's root, so that the contacts find it in one
// step. A body may be read by another element while it changes: it points to an ancestor before
// and to the root after, and either leads to the root.
struct CompressIslands {
    std::uint32_t* parent;

    RODSEA_HD void operator()(std::uint32_t b) const {
        store_shared(parent + b, island_root(parent, b));
    }
};

// Stage 4e, per contact: its island (its first body's root), the key of the stable sort that
// lists each island's contacts together, in list order.
struct KeyContactsByIsland {
    const Contact* contacts;
    const std::uint32_t* parent;
    std::uint32_t* key;
    std::uint32_t* contact;

    RODSEA_HD void operator()(std::uint32_t k) const {
        key[k] = island_root(parent, contacts[k].a);
        contact[k] = k;
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

// What an island's sweep found, written at the index of its first contact (zero elsewhere).
struct IslandTallies {
    double* sweeps;  // whole numbers, as doubles for the executor's maximum
    std::uint32_t* impulses;
    std::uint32_t* body_collisions;
    std::uint32_t* plate_collisions;
    std::uint32_t* unresolved;
    double* hit_speed;  // per plate contact: its fastest approach that got an impulse
};

// Stage 4f, per entry of the contacts sorted by island: the thread at an island's first entry
// sweeps the whole island (physics::sweep_island, the CPU backend's own sweep, in list order
// with its system's sweep cap), so each island gets exactly the impulses it gets on the CPU. In
// a shaken monolayer islands are small: 72 % hold one contact and none more than 14 at
// φ_a = 0.78 (docs/performance.md).
struct SweepIslands {
    const Contact* contacts;
    const std::uint32_t* key;    // island of each sorted entry
    const std::uint32_t* order;  // contacts sorted by island
    const std::uint32_t* island_end;
    IslandBodies bodies;
    Systems systems;
    int* last_changed;
    IslandTallies tallies;

    RODSEA_HD void operator()(std::uint32_t p) const {
        const std::uint32_t island = key[p];
        if (p > 0 && key[p - 1] == island) return;  // not the island's first entry
        const std::uint32_t k0 = order[p];
        const StepContext& step = systems.context[systems.of_body[contacts[k0].a]];
        IslandBodies b = bodies;
        const physics::IslandSweep s =
            physics::sweep_island(contacts, order + p, island_end[island] - p, b, last_changed,
                                  Vec3{0.0, 0.0, step.plates.velocity_z}, step.approach_tolerance,
                                  step.max_sweeps, [this](std::uint32_t k, double approach) {
                                      if (approach > tallies.hit_speed[k])
                                          tallies.hit_speed[k] = approach;
                                  });
        tallies.sweeps[k0] = s.sweeps;
        tallies.impulses[k0] = s.impulses;
        tallies.body_collisions[k0] = s.body_collisions;
        tallies.plate_collisions[k0] = s.plate_collisions;
        tallies.unresolved[k0] = s.unresolved;
    }
};

// Stage 4g, per body: out of the plates by its deepest overlap (plate_projection.hpp says why).
// The overlaps are those the contacts were found with: the spheres have not moved since.
struct ProjectOutOfPlates {
    BodyArrays bodies;
    SphereArrays spheres;
    Systems systems;

    RODSEA_HD void operator()(std::uint32_t b) const {
        const physics::PlateState& plates = systems.context[systems.of_body[b]].plates;
        double base = 0.0, lid = 0.0;
        const std::uint32_t first = spheres.first_of[b], last = spheres.first_of[b + 1];
        for (std::uint32_t s = first; s < last; ++s) {
            const physics::PlateOverlaps o =
                physics::plate_overlaps(spheres.position[s].z, spheres.radius[s], plates);
            if (o.base > base) base = o.base;
            if (o.lid > lid) lid = o.lid;
        }
        if ((base > 0.0) == (lid > 0.0)) return;  // free, or wedged between both plates
        const double dz = base > 0.0 ? base : -lid;
        bodies.position[b].z += dz;
        for (std::uint32_t s = first; s < last; ++s)
            spheres.position[s].z += dz;
    }
};

// Stage 5, per body: a polar body's spin kick for each plate it hit this step (MODEL.md §3), the
// lid's before the base's as on the CPU, with the fastest approach that got an impulse. A body's
// plate contacts are together in the list (its spheres' plate contacts). The noise hashes the
// body's index in its own system. No kick at ε = 0 (the CPU's rule: a kick of ±0 would still
// change the sign of a zero spin).
struct KickPolarBodies {
    BodyArrays bodies;
    SpeciesArrays species;
    SphereArrays spheres;
    const Contact* contacts;
    const std::uint32_t* plate_offset;  // per sphere, from the plate contacts' scan
    std::uint32_t body_contacts, contact_count;
    const double* hit_speed;
    Systems systems;
    std::uint32_t* kicks;

    RODSEA_HD void operator()(std::uint32_t b) const {
        kicks[b] = 0;
        const std::uint32_t system = systems.of_body[b];
        const StepContext& step = systems.context[system];
        if (step.noise_epsilon == 0.0 || !species.polar[bodies.species[b]]) return;
        const std::uint32_t own = b - systems.first_body[system];
        const std::uint32_t last_sphere = spheres.first_of[b + 1];
        const std::uint32_t first = body_contacts + plate_offset[spheres.first_of[b]];
        const std::uint32_t end =
            last_sphere < spheres.count ? body_contacts + plate_offset[last_sphere] : contact_count;
        double lid = 0.0, base = 0.0;
        for (std::uint32_t k = first; k < end; ++k) {
            if (contacts[k].b == kLidPlate && hit_speed[k] > lid) lid = hit_speed[k];
            if (contacts[k].b == kBasePlate && hit_speed[k] > base) base = hit_speed[k];
        }
        if (lid > 0.0) {
            bodies.spin[b].z += step.noise_epsilon * lid *
                                physics::noise_sign(step.seed, step.step, own, kLidPlate);
            ++kicks[b];
        }
        if (base > 0.0) {
            bodies.spin[b].z += step.noise_epsilon * base *
                                physics::noise_sign(step.seed, step.step, own, kBasePlate);
            ++kicks[b];
        }
    }
};

}  // namespace rodsea::parallel
