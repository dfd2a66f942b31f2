#pragma once
// Every sphere of every body, in body order: which body it belongs to, its radius, and its world
// centre (recomputed after each free flight). Body b owns spheres first_of[b] .. first_of[b+1]−1,
// in the order of its shape's spheres.
#include <cstdint>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

struct SphereTable {
    std::vector<std::uint32_t> body;
    std::vector<double> radius;           // mm
    std::vector<Vec3> position;           // world, mm; x, y not wrapped
    std::vector<std::uint32_t> first_of;  // first sphere of each body, plus one past the end

    void assign(const BodyState& bodies, const std::vector<Species>& species);
    void update_positions(const BodyState& bodies, const std::vector<Species>& species,
                          int threads = 1);
    size_t size() const { return body.size(); }

  private:
    // Per species: the principal axis that all its sphere centres lie on (every rod and bead),
    // or -1. Their world centres are then x + s u, with u one column of the rotation.
    std::vector<int> species_axis_;
};

}  // namespace rodsea
