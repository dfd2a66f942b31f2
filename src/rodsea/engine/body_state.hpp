#pragma once
// The hot per-body state, one contiguous array per quantity (structure of arrays): this is all
// the time step reads and writes for bodies. Shapes and names live with the species.
#include <cstdint>
#include <span>
#include <vector>

#include "rodsea/math/quat.hpp"

namespace rodsea {

// The state's arrays as spans: what the stages take, whoever owns the memory.
struct BodyView {
    std::span<const std::uint32_t> species;
    std::span<Vec3> position;
    std::span<Quat> orientation;
    std::span<Vec3> velocity;
    std::span<Vec3> spin;

    std::size_t size() const { return species.size(); }
};

struct BodyState {
    std::vector<std::uint32_t> species;  // index into EngineParameters::species
    std::vector<Vec3> position;          // centre of mass, mm; x, y wrapped into [0, L)
    std::vector<Quat> orientation;       // body (principal) frame -> world
    std::vector<Vec3> velocity;          // mm/s
    std::vector<Vec3> spin;              // angular velocity ω in the world frame, rad/s

    std::size_t size() const { return species.size(); }

    void add(std::uint32_t species_index, const Vec3& x, const Quat& q, const Vec3& v = {},
             const Vec3& w = {}) {
        species.push_back(species_index);
        position.push_back(x);
        orientation.push_back(q);
        velocity.push_back(v);
        spin.push_back(w);
    }

    BodyView view() { return {species, position, orientation, velocity, spin}; }
};

}  // namespace rodsea
