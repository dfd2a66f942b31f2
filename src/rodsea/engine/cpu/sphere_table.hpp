#pragma once
// Stage 2 of the CPU step: every sphere of every body, in body order: which body it belongs to,
// its radius, and its world centre, recomputed after each free flight. Body b owns spheres
// first_of[b] .. first_of[b+1]−1, in the order of its shape's spheres.
#include <cstdint>
#include <span>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea::cpu {

struct SphereTable {
    std::vector<std::uint32_t> body;
    std::vector<double> radius;           // mm
    std::vector<Vec3> position;           // world, mm; x, y not wrapped
    std::vector<std::uint32_t> first_of;  // first sphere of each body, plus one past the end
    // Per body, bounds below its lowest sphere bottom min(z − r) and above its highest top
    // max(z + r), mm, as `position` rounds them: a body whose spheres cannot touch a plate is
    // skipped whole by the plate search, which otherwise reads every sphere every step. Set by
    // update_positions (for unit quaternions, as free flight leaves them) for bodies of more
    // than one sphere, and moved with the spheres by the plate projection.
    std::vector<double> lowest, highest;

    void assign(std::span<const std::uint32_t> body_species, const SpeciesTable& species);
    void update_positions(BodyView bodies, const SpeciesTable& species, int threads);
    // The same for the bodies listed only.
    void update_positions_of(std::span<const std::uint32_t> list, BodyView bodies,
                             const SpeciesTable& species, int threads);
    // Body b's sphere centres for the pose (x, q), its height bounds left as they were.
    void place(std::uint32_t b, std::uint32_t species_index, const Vec3& x, const Quat& q,
               const SpeciesTable& species);
    std::size_t size() const { return body.size(); }
    SphereView view() const { return {body, radius, position, first_of}; }
};

}  // namespace rodsea::cpu
