#pragma once
// Stage 5 of the step: the rotational noise of MODEL.md §3. Each polar rod that hit a plate in
// this step gets ω_z += ε |u_n| η, once per plate it hit, with |u_n| its largest approach speed
// against that plate in this step and η = ±1.
//
// η comes from a counter-based hash of (seed, step, body, plate), not from a stream: the kicks
// do not depend on the order in which contacts were resolved, so they stay the same whatever
// the thread count.
#include <cstdint>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/contact_resolution.hpp"

namespace rodsea {

double noise_sign(std::uint64_t seed, std::uint64_t step, std::uint32_t body, std::uint32_t plate);

// Returns the number of kicks given. Sorts `hits` in place. Large hit lists are split over
// `threads` OpenMP threads, by body: the same kicks on any number of threads.
size_t apply_plate_noise(std::vector<PlateHit>& hits, BodyState& bodies,
                         const std::vector<Species>& species, double epsilon, std::uint64_t seed,
                         std::uint64_t step, int threads = 1);

}  // namespace rodsea
