#pragma once
// The contact search of the data-parallel step (kernels.hpp says what every kernel promises):
// a Verlet list of sphere pairs, built from a cell list when the spheres may have moved half its
// skin and kept for hundreds of steps in between, from which each step's touching pairs are
// counted, placed by a scan and written. The list holds every touching pair whenever it is
// built, and each sphere's partners ascending, so the contact list is the CPU's, contact for
// contact and in the same order, whatever the list's age: body contacts by (sphere i, sphere j),
// then plate contacts in sphere order (base before lid).
#include <cstdint>

#include "rodsea/engine/parallel/arrays.hpp"
#include "rodsea/engine/parallel/atomics.hpp"
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
            for (std::uint32_t m = cells.start[c]; m < cells.start[c + 1]; ++m)
                visit(cells.sphere[m]);
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

// Stage 4, per sphere: when the list is rebuilt, sphere i's partners (spheres j > i of other
// bodies whose discs come within r_i + r_j + skin; the CPU's VerletPairList criterion) found in
// the cells around it and kept ascending; then how many of its partners it touches, and how
// many plates. The two counts share one word (body contacts high, plate contacts low) so that
// one scan places both.
struct ListAndCountContacts {
    SphereArrays spheres;
    Systems systems;
    CellList cells;
    NeighbourList neighbours;
    std::uint64_t* counts;
    RunStatus* status;

    RODSEA_HD void operator()(std::uint32_t i) const {
        const std::uint32_t system = systems.of_sphere(spheres, i);
        const StepContext& step = systems.context[system];
        const Vec3 p = spheres.position[i];
        const double r_i = spheres.radius[i];
        if (status->rebuild != 0) build(i, p, r_i, system, step.box);
        if (systems.halted(system)) {
            counts[i] = 0;
            return;
        }
        std::uint64_t touching = 0;
        const std::uint32_t listed = neighbours.count[i];
        for (std::uint32_t k = 0; k < listed; ++k) {
            const std::uint32_t j = neighbours.slot[k * neighbours.stride + i];
            if (spheres_touch(step.box.minimum_image(p - spheres.position[j]), r_i,
                              spheres.radius[j]))
                ++touching;
        }
        const physics::PlateOverlaps o = physics::plate_overlaps(p.z, r_i, step.plates);
        counts[i] = (touching << 32) | ((o.base > 0.0 ? 1u : 0u) + (o.lid > 0.0 ? 1u : 0u));
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

// Stage 4b, per sphere, after the exclusive scan of the counts: writes its contacts where the
// scan puts them (body contacts first, every system's, then plate contacts), with the pair's
// coefficients; each contact's overlap over its smaller radius joins the system's deepest, and
// its plate hit speed starts at 0. The last sphere also writes how many there are, or 0 and the
// room needed when they do not fit.
struct WriteContacts {
    SphereArrays spheres;
    BodyArrays bodies;
    SpeciesArrays species;
    Systems systems;
    NeighbourList neighbours;
    const std::uint64_t* counts;
    const std::uint64_t* offsets;
    Contact* contacts;
    double* hit_speed;
    std::uint32_t capacity;
    double gross_overlap_fraction;
    RunStatus* status;

    RODSEA_HD void operator()(std::uint32_t i) const {
        const std::uint32_t last = spheres.count - 1;
        const std::uint64_t total = offsets[last] + counts[last];
        const auto body_total = static_cast<std::uint32_t>(total >> 32);
        const std::uint64_t all = body_total + (total & 0xffffffffu);
        const bool fits = all <= capacity;
        if (i == last) {
            status->body_contacts = fits ? body_total : 0u;
            status->contacts = fits ? static_cast<std::uint32_t>(all) : 0u;
            if (!fits) atomic_max(&status->needed_contacts, all);
        }
        const std::uint64_t count = counts[i];
        if (count == 0 || !fits) return;
        const std::uint32_t system = systems.of_sphere(spheres, i);
        const StepContext& step = systems.context[system];
        StepCounts& tally = systems.counts[system];
        const Vec3 p = spheres.position[i];
        const double r_i = spheres.radius[i];
        const std::uint32_t b_i = spheres.body[i];
        double deepest = 0.0;
        std::uint64_t gross = 0;
        const auto depth = [&](double overlap_fraction) {
            const double d = nan_as_infinity(overlap_fraction);
            if (d > deepest) deepest = d;
            if (d > gross_overlap_fraction) ++gross;
        };
        auto at = static_cast<std::uint32_t>(offsets[i] >> 32);
        const std::uint32_t listed = neighbours.count[i];
        for (std::uint32_t k = 0; k < listed; ++k) {
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
            hit_speed[at] = 0.0;
            contacts[at++] = c;
        }
        at = body_total + static_cast<std::uint32_t>(offsets[i] & 0xffffffffu);
        const physics::PlateOverlaps o = physics::plate_overlaps(p.z, r_i, step.plates);
        const ContactCoefficients& k = species.plate[bodies.species[b_i]];
        if (o.base > 0.0) {
            depth(o.base / r_i);
            hit_speed[at] = 0.0;
            contacts[at++] =
                physics::plate_contact(b_i, p, r_i, bodies.position[b_i], true, o.base, k);
        }
        if (o.lid > 0.0) {
            depth(o.lid / r_i);
            hit_speed[at] = 0.0;
            contacts[at] =
                physics::plate_contact(b_i, p, r_i, bodies.position[b_i], false, o.lid, k);
        }
        atomic_add(&tally.body_contacts, count >> 32);
        atomic_add(&tally.plate_contacts, count & 0xffffffffu);
        atomic_max_of(&tally.overlap_bits, deepest);
        if (gross > 0) atomic_add(&tally.gross, gross);
    }
};

}  // namespace rodsea::parallel
