#pragma once
// What every stage of one step reads besides the state: built once per step (Box2D's
// b2StepContext), plain numbers only, so that a device takes it by value.
#include <cstdint>

#include "rodsea/engine/physics/plate_noise.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/periodic_box.hpp"

namespace rodsea {

struct StepContext {
    double dt = 0.0;       // s
    double gravity = 0.0;  // mm/s²
    PeriodicBox2D box;
    physics::PlateState plates;         // at the end of the step, where contacts are found
    physics::PlateMotion plate_motion;  // the drive: where the plates are at any step
    double approach_tolerance = 0.0;    // mm/s: slower normal approach counts as none
    int max_sweeps = 1;                 // impulse sweeps before contacts count as unresolved
    double noise_epsilon = 0.0;         // ε, 1/mm
    physics::NoiseMode noise_mode = physics::NoiseMode::add;
    std::uint64_t seed = 0;
    std::uint64_t step = 0;  // the number of the step being taken, from 1: the noise hashes it

    // How far gravity pulls a body down in dt from rest: ½ g dt² (mm).
    RODSEA_HD double drop() const { return 0.5 * gravity * dt * dt; }
};

}  // namespace rodsea
