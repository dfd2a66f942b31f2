#pragma once
// The contact search of the data-parallel step (kernels.hpp says what every kernel promises):
// a Verlet list of sphere pairs, built from a cell list when the spheres may have moved half its
// skin and kept for hundreds of steps in between, from which each step's touching pairs and
// plate overlaps become contacts. Each sphere takes places for its contacts from a cursor, so
// the list comes in no particular order, and no scan is needed; each contact's key says where it
// stands in the CPU's list (body contacts by (sphere i, sphere j), then plate contacts in sphere
// order, base before lid), and whatever reads contacts in order sorts them by key first. The Verlet
// list holds every touching pair whenever it is built, so the contacts are the CPU's, contact
// for contact, whatever the list's age.
#include <cstdint>

#include "rodsea/engine/parallel/arrays.hpp"
#include "rodsea/engine/parallel/atomics.hpp"
#include "rodsea/engine/parallel/island_kernels.hpp"
#include "rodsea/engine/parallel/system_run.hpp"
#include "rodsea/engine/physics/contact_geometry.hpp"
#include "rodsea/math/nan_as_infinity.hpp"

namespace rodsea::parallel {

// visit(j) for each sphere of the nine cells around sphere i's own (each cell once where the
// grid is less than three cells across), in i's system's grid.
template <class Visit>
RODSEA_HD void for_each_sphere_around(const Vec3& p, const CellList& cells,
                                      const SystemGrid& system_grid, const PeriodicBox2D& box,
                                      Visit&& visit) {
    const CellGrid& grid = system_grid.grid;
    const std::uint32_t cx = grid.column_of(p.x, box.lx), cy = grid.row_of(p.y, box.ly);
    const int x_from = grid.nx >= 3 ? -1 : 0, x_to = grid.nx >= 2 ? 1 : 0;
    const int y_from = grid.ny >= 3 ? -1 : 0, y_to = grid.ny >= 2 ? 1 : 0;
    for (int dy = y_from; dy <= y_to; ++dy) {
        const std::uint32_t row = (cy + grid.ny + static_cast<std::uint32_t>(dy)) % grid.ny;
        for (int dx = x_from; dx <= x_to; ++dx) {
            const std::uint32_t column = (cx + grid.nx + static_cast<std::uint32_t>(dx)) % grid.nx;
            const std::uint32_t c = system_grid.first_cell + row * grid.nx + column;
            const std::uint32_t* held = cells.slots(c);
            for (std::uint32_t m = 0, n = cells.held(c); m < n; ++m)
                visit(held[m]);
        }
    }
}

// Whether spheres at d = p_i − p_j (minimum image) with radii r_i, r_j touch: exactly when
// physics::sphere_sphere_contact makes a contact of them, so that the count and the list agree.
RODSEA_HD inline bool spheres_touch(const Vec3& d, double r_i, double r_j) {
    const double reach = r_i + r_j;
    const double d2 = norm2(d);
    return d2 < reach * reach && d2 != 0.0;
}

// Where a contact stands in the CPU's list: body contacts by (sphere i, partner j > i), then
// plate contacts by sphere, base before lid.
RODSEA_HD inline std::uint64_t body_contact_key(std::uint32_t i, std::uint32_t j) {
    return (std::uint64_t{i} << 32) | j;
}
RODSEA_HD inline std::uint64_t plate_contact_key(std::uint32_t i, bool lid) {
    return (std::uint64_t{1} << 63) | (std::uint64_t{i} << 1) | (lid ? 1u : 0u);
}

// Stage 3, per sphere: when the list is rebuilt, sphere i's partners (spheres j > i of other
// bodies whose discs come within r_i + r_j + skin; the CPU's VerletPairList criterion) found in
// the cells around it and kept ascending; then its contacts with the partners it touches and
// the plates it overlaps, with the pair's coefficients, at places taken from the step's cursor,
// each keyed and each body contact joining its two bodies' islands (union–find); each contact's
// overlap over its smaller radius joins the system's deepest. Contacts that would not fit are
// not written (the tail, CloseContactList, says so and the run is taken again). One kernel for
// both the counting and the writing: a kernel of its own for the few spheres with contacts
// costs more in its launch than the registers it frees buy back (docs/performance.md).
struct FindContacts {
    SphereArrays spheres;
    BodyArrays bodies;
    SpeciesArrays species;
    Systems systems;
    CellList cells;
    NeighbourList neighbours;
    Contact* contacts;
    std::uint64_t* key;
    std::uint32_t capacity;
    std::uint32_t* parent;  // the islands' forest (kernels.hpp: BodyScratch)
    double gross_overlap_fraction;
    RunStatus* status;

    RODSEA_HD void operator()(std::uint32_t i) const {
        const std::uint32_t system = systems.of_sphere(spheres, i);
        const StepContext& step = systems.context[system];
        const Vec3 p = spheres.position[i];
        const double r_i = spheres.radius[i];
        if (status->rebuild != 0) build(i, p, r_i, system, step.box);
        if (systems.halted(system)) return;
        std::uint32_t touching = 0;
        const std::uint32_t listed = neighbours.count[i];
        for (std::uint32_t k = 0; k < listed; ++k) {
            const std::uint32_t j = neighbours.slot[k * neighbours.stride + i];
            if (spheres_touch(step.box.minimum_image(p - spheres.position[j]), r_i,
                              spheres.radius[j]))
                ++touching;
        }
        const physics::PlateOverlaps o = physics::plate_overlaps(p.z, r_i, step.plates);
        const std::uint32_t plates = (o.base > 0.0 ? 1u : 0u) + (o.lid > 0.0 ? 1u : 0u);
        const std::uint32_t found = touching + plates;
        if (found == 0) return;
        std::uint32_t at = atomic_add(&status->placed, found);
        if (std::uint64_t{at} + found > capacity) return;

        StepCounts& tally = systems.counts[system];
        const std::uint32_t b_i = spheres.body[i];
        double deepest = 0.0;
        std::uint64_t gross = 0;
        const auto depth = [&](double overlap_fraction) {
            const double d = nan_as_infinity(overlap_fraction);
            if (d > deepest) deepest = d;
            if (d > gross_overlap_fraction) ++gross;
        };
        for (std::uint32_t k = 0; k < listed && touching > 0; ++k) {
            const std::uint32_t j = neighbours.slot[k * neighbours.stride + i];
            const Vec3 d = step.box.minimum_image(p - spheres.position[j]);
            if (!spheres_touch(d, r_i, spheres.radius[j])) continue;
            const std::uint32_t b_j = spheres.body[j];
            Contact c;
            physics::sphere_sphere_contact(d, b_i, p, r_i, bodies.position[b_i], b_j,
                                           spheres.position[j], spheres.radius[j],
                                           bodies.position[b_j], c);
            const ContactCoefficients& coefficients =
                species.pair_coefficients(bodies.species[b_i], bodies.species[b_j]);
            c.friction = coefficients.friction;
            c.restitution = coefficients.restitution;
            const double r_j = spheres.radius[j];
            depth(c.overlap / (r_i < r_j ? r_i : r_j));
            key[at] = body_contact_key(i, j);
            contacts[at++] = c;
            join_islands(parent, b_i, b_j);
        }
        const ContactCoefficients& k = species.plate[bodies.species[b_i]];
        if (o.base > 0.0) {
            depth(o.base / r_i);
            key[at] = plate_contact_key(i, false);
            contacts[at++] =
                physics::plate_contact(b_i, p, r_i, bodies.position[b_i], true, o.base, k);
        }
        if (o.lid > 0.0) {
            depth(o.lid / r_i);
            key[at] = plate_contact_key(i, true);
            contacts[at] =
                physics::plate_contact(b_i, p, r_i, bodies.position[b_i], false, o.lid, k);
        }
        if (touching > 0) atomic_add(&tally.body_contacts, std::uint64_t{touching});
        if (plates > 0) atomic_add(&tally.plate_contacts, std::uint64_t{plates});
        atomic_max_of(&tally.overlap_bits, deepest);
        if (gross > 0) atomic_add(&tally.gross, gross);
    }

  private:
    RODSEA_HD void build(std::uint32_t i, const Vec3& p, double r_i, std::uint32_t system,
                         const PeriodicBox2D& box) const {
        const std::uint32_t body = spheres.body[i];
        const double half_skin = 0.5 * neighbours.skin;
        const double reach_i = r_i + half_skin;
        const std::uint32_t room = neighbours.capacity, stride = neighbours.stride;
        std::uint32_t n = 0;
        for_each_sphere_around(p, cells, systems.grid[system], box, [&](std::uint32_t j) {
            if (j <= i || spheres.body[j] == body) return;
            const Vec3 d = box.minimum_image(p - spheres.position[j]);
            const double reach = reach_i + (spheres.radius[j] + half_skin);
            if (!(d.x * d.x + d.y * d.y < reach * reach)) return;
            // Kept ascending: the cells come in no particular order, a sphere has a handful.
            if (n < room) {
                std::uint32_t at = n;
                for (; at > 0 && neighbours.slot[(at - 1) * stride + i] > j; --at)
                    neighbours.slot[at * stride + i] = neighbours.slot[(at - 1) * stride + i];
                neighbours.slot[at * stride + i] = j;
            }
            ++n;
        });
        neighbours.count[i] = n < room ? n : room;
        if (n > room) atomic_max(&status->needed_slots, n);
    }
};

// Stage 3's tail, once every sphere has placed its contacts: how many the step has, or 0 and the
// room needed when they did not all fit.
struct CloseContactList {
    RunStatus* status;
    std::uint32_t capacity;

    RODSEA_HD void operator()(std::uint32_t) const {
        const std::uint32_t placed = status->placed;
        const bool fits = placed <= capacity;
        status->contacts = fits ? placed : 0u;
        if (!fits) atomic_max(&status->needed_contacts, placed);
    }
};

}  // namespace rodsea::parallel
