#pragma once
// A body coasts when nothing can touch it for a while: between its collisions its motion is
// exact and analytic (a parabola under gravity, the torque-free rotation of rigid_rotation.hpp),
// so it can be left alone for many steps and then flown to the step it is needed at in one jump.
// Here: that jump, and the first step at which a coasting body might reach a plate.
// docs/performance.md ("Coasting") gives the scheme; engine/cpu/coasting_backend.hpp runs it.
#include <cmath>
#include <cstdint>

#include "rodsea/engine/physics/free_flight.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/math/hostdevice.hpp"

namespace rodsea::physics {

// Flies a body `steps` steps of dt in one jump: the same parabola and precession as that many
// calls of fly_freely, to round-off (one step of dt is exactly fly_freely's step).
RODSEA_HD inline void fly_for(Vec3& x, Vec3& v, Quat& q, Vec3& w, const Rotor& rotor,
                              std::uint64_t steps, double dt, double gravity, PeriodicBox2D box) {
    const double tau = static_cast<double>(steps) * dt;
    fly_freely(x, v, q, w, rotor, tau, gravity, 0.5 * gravity * tau * tau, box);
}

// What the plate bound needs of a body at the start of its coast (step s₀).
struct CoastStart {
    double z = 0.0;   // centre of mass height, mm
    double vz = 0.0;  // its vertical velocity, mm/s
    // How far its lowest sphere bottom lies below the centre and its highest top above it, mm.
    double below = 0.0, above = 0.0;
    // A bound on how fast `below` and `above` can grow while it coasts, mm/s: every sphere centre
    // at distance ≤ reach from the centre turns about it at a rate ≤ the body's spin.
    double tilt_rate = 0.0;
};

// The margin the bound keeps from a plate, mm: far above the rounding of the heights (10⁻¹⁶ of
// millimetres) and of the jump against the bound's own arithmetic, far below any overlap that
// matters (a contact is an overlap > 0; the gap between bodies' spheres and the plates is
// tenths of a millimetre).
inline constexpr double kCoastMargin = 1e-9;

// The first step after `start` at whose end a body coasting from `start` might touch a plate, at
// most `start + horizon`.
//
// Why it is a bound: its lowest sphere bottom at time τ after the start is at least
//   z(τ) − below − tilt_rate τ,   z(τ) = z + vz τ − g τ²/2,
// since each sphere's height above the centre changes at most at reach × |spin|, and the jump
// flies exactly that z(τ); the base is at A cos Ωt, the lid w above it (plate_state, as the
// step's context computes them). A step whose lower gap (bottom − base) and upper gap (lid − top)
// both exceed the margin has no plate contact. From a step k whose gap g exceeds the margin by
// Δ, the gap closes at most at V = |vz(τ_k)| + g τ_look + tilt_rate + AΩ over the next
// kLookSteps steps, so the steps before k + Δ / (V dt) cannot touch: the scan jumps there (at
// least one step, at most kLookSteps) and looks again. It stops at the first step it cannot
// clear. A NaN anywhere clears nothing: the body wakes at once.
inline constexpr std::uint64_t kLookSteps = 512;

RODSEA_HD inline std::uint64_t first_plate_step(const CoastStart& c, std::uint64_t start,
                                                std::uint64_t horizon, double dt, double gravity,
                                                const PlateMotion& plates) {
    const double plate_speed = plates.amplitude * plates.angular_frequency;
    const double look = static_cast<double>(kLookSteps) * dt;
    std::uint64_t k = 1;
    while (k < horizon) {
        const double tau = static_cast<double>(k) * dt;
        const double z = c.z + c.vz * tau - 0.5 * gravity * tau * tau;
        const double grown = c.tilt_rate * tau;
        const PlateState p = plate_state(plates, static_cast<double>(start + k) * dt);
        const double lower = (z - c.below - grown) - p.base_z;
        const double upper = p.lid_z - (z + c.above + grown);
        const double spare = (lower < upper ? lower : upper) - kCoastMargin;
        if (!(spare > 0.0)) return start + k;
        const double closing =
            std::abs(c.vz - gravity * tau) + gravity * look + c.tilt_rate + plate_speed;
        const double clear = spare / (closing * dt);
        std::uint64_t skip = 1;
        if (clear >= static_cast<double>(kLookSteps))
            skip = kLookSteps;
        else if (clear >= 1.0)
            skip = static_cast<std::uint64_t>(clear);
        k += skip;
    }
    return start + horizon;
}

}  // namespace rodsea::physics
