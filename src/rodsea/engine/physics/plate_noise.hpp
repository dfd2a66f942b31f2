#pragma once
// The sign η = ±1 of the rotational noise kick (MODEL.md §3), from a counter-based hash of
// (seed, step, body, plate) rather than a stream: the kicks do not depend on the order in which
// contacts were resolved, nor on the executor.
#include <cstdint>

#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/math/hostdevice.hpp"
#include "rodsea/random.hpp"

namespace rodsea::physics {

RODSEA_HD inline double noise_sign(std::uint64_t seed, std::uint64_t step, std::uint32_t body,
                                   std::uint32_t plate) {
    std::uint64_t h = splitmix64(seed);
    h = splitmix64(h ^ step);
    h = splitmix64(h ^ ((static_cast<std::uint64_t>(body) << 1) | (plate == kBasePlate ? 0 : 1)));
    return (h >> 63) ? 1.0 : -1.0;
}

}  // namespace rodsea::physics
