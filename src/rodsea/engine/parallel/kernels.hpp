#pragma once
// The data-parallel step, the GPU backend's algorithm: each stage a kernel, one object per kernel
// whose operator()(i) does element i (a body, a sphere, a contact) and calls the per-element
// physics of engine/physics/. An executor runs it for every i: a CUDA launch, or a host loop
// (parallel_backend.hpp), so the device's algorithm is tested on any machine.
//
// No element's result depends on the order in which elements run: each writes only its own
// outputs, and where elements share a body (the impulses) the contacts are coloured so that no
// two of one colour do. Sums and maxima are taken afterwards by the executor's reductions, and
// orders by stable sorts, so a trajectory is the same bit for bit on every run of one build on
// one device.
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
#include "rodsea/engine/physics/plate_noise.hpp"
#include "rodsea/engine/physics/sphere_placement.hpp"
#include "rodsea/engine/physics/step_context.hpp"
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

// visit(contact, r_j) for each sphere j > i of another body that overlaps sphere i: the contact
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
                    visit(contact, spheres.radius[j]);
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
                                  [&n](const Contact&, double) { ++n; });
        body_count[i] = n;
        const physics::PlateOverlaps o =
            physics::plate_overlaps(spheres.position[i].z, spheres.radius[i], step.plates);
        plate_count[i] = (o.base > 0.0 ? 1u : 0u) + (o.lid > 0.0 ? 1u : 0u);
    }
};

// Stage 3c, per sphere: writes its contacts where the counts put them: body contacts first, in
// sphere order, then plate contacts in sphere order (base before lid), like the CPU's list;
// `depth` takes each one's overlap over the smaller radius.
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

    RODSEA_HD void operator()(std::uint32_t i) const {
        const std::uint32_t system = systems.of_sphere(spheres, i);
        const StepContext& step = systems.context[system];
        const double ri = spheres.radius[i];
        std::uint32_t at = body_offset[i];
        for_each_touching_partner(
            i, spheres, bodies, cells, systems.grid[system], step.box, [&](Contact& c, double rj) {
                const ContactCoefficients& k =
                    species.pair_coefficients(bodies.species[c.a], bodies.species[c.b]);
                c.friction = k.friction;
                c.restitution = k.restitution;
                depth[at] = c.overlap / (ri < rj ? ri : rj);
                contacts[at++] = c;
            });
        const std::uint32_t b = spheres.body[i];
        const Vec3& p = spheres.position[i];
        const physics::PlateOverlaps o = physics::plate_overlaps(p.z, ri, step.plates);
        at = body_contacts + plate_offset[i];
        const ContactCoefficients& k = species.plate[bodies.species[b]];
        if (o.base > 0.0) {
            contacts[at] = physics::plate_contact(b, p, ri, bodies.position[b], true, o.base, k);
            depth[at++] = o.base / ri;
        }
        if (o.lid > 0.0) {
            contacts[at] = physics::plate_contact(b, p, ri, bodies.position[b], false, o.lid, k);
            depth[at] = o.lid / ri;
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

// Stage 4b, per contact: its (body, contact) incidences, for a sort by body. Body contacts
// [0, B) take slots 2k and 2k + 1, plate contacts k >= B one slot, 2B + (k − B).
struct ListIncidences {
    const Contact* contacts;
    std::uint32_t body_contacts;
    std::uint32_t* body;
    std::uint32_t* contact;

    RODSEA_HD void operator()(std::uint32_t k) const {
        const Contact& c = contacts[k];
        if (k < body_contacts) {
            body[2 * k] = c.a;
            contact[2 * k] = k;
            body[2 * k + 1] = c.b;
            contact[2 * k + 1] = k;
        } else {
            const std::uint32_t at = body_contacts + k;  // 2B + (k − B)
            body[at] = c.a;
            contact[at] = k;
        }
    }
};

// Per contact: its index within its own system's list (body contacts, then plate contacts, as
// that system alone would list them), which ranks it in the colouring: a system's colours then do
// not depend on the systems beside it.
struct RankContactsInTheirSystem {
    const Contact* contacts;
    Systems systems;
    std::uint32_t body_contacts;  // of every system
    std::uint32_t* rank;

    RODSEA_HD void operator()(std::uint32_t k) const {
        const ContactRange& r = systems.contacts[systems.of_body[contacts[k].a]];
        rank[k] = k < body_contacts ? k - r.body_first : r.body_count + (k - r.plate_first);
    }
};

// The contacts that share a body with contact k (k itself excluded; a contact that shares both
// bodies is visited twice).
template <class Visit>
RODSEA_HD void for_each_neighbour(std::uint32_t k, const Contact& c, const Incidence& incidence,
                                  Visit&& visit) {
    for (std::uint32_t m = incidence.start[c.a]; m < incidence.end[c.a]; ++m)
        if (incidence.contact[m] != k) visit(incidence.contact[m]);
    if (c.with_plate()) return;
    for (std::uint32_t m = incidence.start[c.b]; m < incidence.end[c.b]; ++m)
        if (incidence.contact[m] != k) visit(incidence.contact[m]);
}

// Whether a contact of rank r1 goes before one of rank r2 (RankContactsInTheirSystem) in the
// colouring: by a hash of the rank, so that runs of neighbouring contacts (often consecutive in
// the list) do not form long chains of decreasing priority, each of which costs a round.
RODSEA_HD inline bool outranks(std::uint32_t r1, std::uint32_t r2) {
    const std::uint64_t h1 = splitmix64(r1), h2 = splitmix64(r2);
    return h1 != h2 ? h1 > h2 : r1 > r2;
}

RODSEA_HD inline int lowest_clear_bit(std::uint64_t used) {
#if defined(__CUDA_ARCH__)
    return __ffsll(static_cast<long long>(~used)) - 1;
#else
    return __builtin_ctzll(~used);
#endif
}

// Stage 4c, one round of the colouring (Jones–Plassmann), per contact: an uncoloured contact
// that outranks every neighbour that was uncoloured when the round began takes the smallest
// colour none of its coloured neighbours has. Contacts of one colour then share no body and are
// resolved at once. `coloured_in` is the round that coloured each contact, −1 before: a
// neighbour coloured in this very round outranks the contact (it was a local maximum), so reading
// it before or after its write gives the same decision, and colours are only read from earlier
// rounds. Sets `waiting` while a contact is left for a later round.
struct ColourRound {
    const Contact* contacts;
    const std::uint32_t* rank;
    Incidence incidence;
    int round;
    int* colour;
    int* coloured_in;
    int* waiting;

    RODSEA_HD void operator()(std::uint32_t k) const {
        if (coloured_in[k] >= 0) return;  // only this element writes its own mark
        const Contact& c = contacts[k];
        bool waits = false;
        for_each_neighbour(k, c, incidence, [&](std::uint32_t n) {
            const int r = load_shared(coloured_in + n);
            if ((r < 0 || r == round) && outranks(rank[n], rank[k])) waits = true;
        });
        if (waits) {
            store_shared(waiting, 1);
            return;
        }
        for (int window = 0;; window += 64) {  // colours [window, window + 64) at a time
            std::uint64_t used = 0;
            for_each_neighbour(k, c, incidence, [&](std::uint32_t n) {
                const int r = load_shared(coloured_in + n);
                if (r < 0 || r >= round) return;  // no colour yet (or not one this may read)
                const int slot = colour[n] - window;
                if (slot >= 0 && slot < 64) used |= std::uint64_t{1} << slot;
            });
            if (~used != 0) {
                colour[k] = window + lowest_clear_bit(used);
                break;
            }
        }
        store_shared(coloured_in + k, round);
    }
};

// Per contact: its colour as the key of the sort that groups the contacts colour by colour.
struct KeyContactsByColour {
    const int* colour;
    std::uint32_t* key;
    std::uint32_t* contact;

    RODSEA_HD void operator()(std::uint32_t k) const {
        key[k] = static_cast<std::uint32_t>(colour[k]);
        contact[k] = k;
    }
};

// The relative velocity (a − b) at a contact's point; a plate moves at `plate_velocity`.
RODSEA_HD inline Vec3 contact_relative_velocity(const Contact& c, const BodyArrays& bodies,
                                                const Vec3& plate_velocity) {
    const Vec3 va = physics::point_velocity(bodies.velocity[c.a], bodies.spin[c.a], c.arm_a);
    return c.with_plate()
               ? va - plate_velocity
               : va - physics::point_velocity(bodies.velocity[c.b], bodies.spin[c.b], c.arm_b);
}

// Stage 4d, per contact of one colour, in sweep `sweep` (from 1): the impulse on the contact if
// it approaches, as the CPU's Gauss–Seidel sweep gives it, skipping contacts whose bodies got no
// impulse since the contact was last looked at (none since sweep − 1 began). Colours are swept in
// order, so this is Gauss–Seidel in colour order. Each impulse is tallied on its contact.
struct SweepColour {
    const Contact* contacts;
    const std::uint32_t* order;  // contacts sorted by colour
    std::uint32_t first;         // this colour's first entry in `order`
    BodyArrays bodies;
    const double* inv_mass;
    const Mat3* inv_inertia;
    Systems systems;
    int sweep;
    int* last_changed;  // per body: the last sweep that gave it an impulse
    ContactTallies tallies;
    int* any_impulse;  // per system

    RODSEA_HD void operator()(std::uint32_t index) const {
        const std::uint32_t k = order[first + index];
        const Contact& c = contacts[k];
        const std::uint32_t system = systems.of_body[c.a];
        const StepContext& step = systems.context[system];
        if (sweep > step.max_sweeps) return;  // this system's cap (another's may be higher)
        const bool plate = c.with_plate();
        const int changed =
            plate ? last_changed[c.a]
                  : (last_changed[c.a] > last_changed[c.b] ? last_changed[c.a] : last_changed[c.b]);
        if (sweep > 1 && changed < sweep - 1) return;  // nothing moved since the last look

        const Vec3 u = contact_relative_velocity(c, bodies, {0.0, 0.0, step.plates.velocity_z});
        const double un = dot(u, c.normal);
        if (un >= -step.approach_tolerance) return;

        const Mat3 k_matrix =
            plate ? physics::collision_matrix(inv_mass[c.a], inv_inertia[c.a], c.arm_a, 0.0,
                                              Mat3::zero(), {})
                  : physics::collision_matrix(inv_mass[c.a], inv_inertia[c.a], c.arm_a,
                                              inv_mass[c.b], inv_inertia[c.b], c.arm_b);
        const physics::Impulse impulse =
            physics::stronge_impulse(u, c.normal, k_matrix, c.friction, c.restitution);
        bodies.velocity[c.a] += inv_mass[c.a] * impulse.p;
        bodies.spin[c.a] += inv_inertia[c.a] * cross(c.arm_a, impulse.p);
        last_changed[c.a] = sweep;
        if (plate) {
            if (-un > tallies.hit_speed[k]) tallies.hit_speed[k] = -un;
        } else {
            bodies.velocity[c.b] -= inv_mass[c.b] * impulse.p;
            bodies.spin[c.b] -= inv_inertia[c.b] * cross(c.arm_b, impulse.p);
            last_changed[c.b] = sweep;
        }
        ++tallies.impulses[k];
        if (-un > kCollisionSpeed) ++tallies.collisions[k];
        store_shared(any_impulse + system, 1);
    }
};

// Per contact, after the last sweep: 1 where it still approaches.
struct FlagApproaching {
    const Contact* contacts;
    BodyArrays bodies;
    Systems systems;
    std::uint32_t* approaching;

    RODSEA_HD void operator()(std::uint32_t k) const {
        const Contact& c = contacts[k];
        const StepContext& step = systems.context[systems.of_body[c.a]];
        const Vec3 u = contact_relative_velocity(c, bodies, {0.0, 0.0, step.plates.velocity_z});
        approaching[k] = dot(u, c.normal) < -step.approach_tolerance ? 1u : 0u;
    }
};

// Stage 4e, per body: out of the plates by its deepest overlap (plate_projection.hpp says why).
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
// lid's before the base's as on the CPU, with the fastest approach that got an impulse. The noise
// hashes the body's index in its own system. No kick at ε = 0 (the CPU's rule: a kick of ±0
// would still change the sign of a zero spin).
struct KickPolarBodies {
    BodyArrays bodies;
    SpeciesArrays species;
    const Contact* contacts;
    Incidence incidence;
    const double* hit_speed;
    Systems systems;
    std::uint32_t* kicks;

    RODSEA_HD void operator()(std::uint32_t b) const {
        kicks[b] = 0;
        const std::uint32_t system = systems.of_body[b];
        const StepContext& step = systems.context[system];
        if (step.noise_epsilon == 0.0 || !species.polar[bodies.species[b]]) return;
        const std::uint32_t own = b - systems.first_body[system];
        double lid = 0.0, base = 0.0;
        for (std::uint32_t m = incidence.start[b]; m < incidence.end[b]; ++m) {
            const std::uint32_t k = incidence.contact[m];
            const std::uint32_t plate = contacts[k].b;
            if (plate == kLidPlate && hit_speed[k] > lid) lid = hit_speed[k];
            if (plate == kBasePlate && hit_speed[k] > base) base = hit_speed[k];
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
