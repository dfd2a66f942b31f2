#pragma once
// The rotational noise of polar rods (docs/model.md §3), one rule for every executor: the sign η =
// ±1 of a kick and what a step's plate collisions do to a polar body's ω_z, under either reading of
// the paper's rule.
#include <cstdint>

#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/math/hostdevice.hpp"
#include "rodsea/random.hpp"

namespace rodsea::physics {

// How a plate collision's kick meets the spin the rod already has. The paper's SI "imposes"
// ω_z = ε v_rel η at each plate collision (set); the first model specification read it as a kick
// added to ω_z (add). docs/model.md says which the evidence chose.
enum class NoiseMode : std::uint8_t { add, set };

// η from a counter-based hash of (seed, step, body, plate) rather than a stream: the kicks do not
// depend on the order in which contacts were resolved, nor on the executor.
RODSEA_HD inline double noise_sign(std::uint64_t seed, std::uint64_t step, std::uint32_t body,
                                   std::uint32_t plate) {
    std::uint64_t h = splitmix64(seed);
    h = splitmix64(h ^ step);
    h = splitmix64(h ^ ((static_cast<std::uint64_t>(body) << 1) | (plate == kBasePlate ? 0 : 1)));
    return (h >> 63) ? 1.0 : -1.0;
}

// A polar body's collisions with the plates in one step: the fastest approach |u_n| (mm/s)
// among the impulses each plate gave it, 0 where it gave none.
struct PlateApproach {
    double base = 0.0;
    double lid = 0.0;
};

// Applies this step's noise to `spin_z` (rad/s) and returns the number of plate collisions that
// did (0, 1 or 2). Each plate hit contributes ε |u_n| η, the lid's before the base's (the order
// fixes the rounding). add: the contributions join ω_z. set: ω_z becomes their sum, so one hit
// leaves exactly ε |u_n| η, and at ε = 0 a hit stops the spin about z; two plates hit in one step
// are two simultaneous impositions, which add. A body that hit no plate keeps its spin. Under
// add, ε = 0 leaves the spin untouched (a kick of ±0 would still flip the sign of a zero spin).
RODSEA_HD inline int apply_plate_noise(double& spin_z, NoiseMode mode, double epsilon,
                                       std::uint64_t seed, std::uint64_t step, std::uint32_t body,
                                       PlateApproach hit) {
    const int hits = (hit.lid > 0.0 ? 1 : 0) + (hit.base > 0.0 ? 1 : 0);
    if (hits == 0 || (mode == NoiseMode::add && epsilon == 0.0)) return 0;
    double spin = mode == NoiseMode::set ? 0.0 : spin_z;
    if (hit.lid > 0.0) spin += epsilon * hit.lid * noise_sign(seed, step, body, kLidPlate);
    if (hit.base > 0.0) spin += epsilon * hit.base * noise_sign(seed, step, body, kBasePlate);
    spin_z = spin;
    return hits;
}

}  // namespace rodsea::physics
