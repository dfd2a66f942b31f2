#pragma once
// Free flight of one body for dt: an exact parabola under gravity and torque-free rotation.
#include "rodsea/engine/physics/rigid_rotation.hpp"
#include "rodsea/engine/physics/step_context.hpp"
#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/nan_as_infinity.hpp"

namespace rodsea::physics {

// Squared speeds in the plane during one step of free flight (mm²/s²): of the centre of mass,
// and a bound for the spheres about it (`reach2`: the farthest sphere centre's squared distance
// from the centre). The sum of the roots of the largest over all bodies bounds how far any sphere
// moves in the plane in the step, which tells the Verlet list when to look. Gravity does not act
// in the plane, so they hold for the whole step.
struct PlanarSpeed2 {
    double drift2 = 0.0;
    double turn2 = 0.0;
};
RODSEA_HD inline PlanarSpeed2 planar_speed2(const Vec3& v, const Quat& q, const Vec3& w,
                                            const Rotor& rotor, double reach2) {
    return {nan_as_infinity(v.x * v.x + v.y * v.y),
            nan_as_infinity(spin_bound2(rotor, q, w) * reach2)};
}

// Moves a body by one step, x and y wrapped into the box. The step's numbers come by value
// (`drop` is StepContext::drop()): stores to the bodies cannot alias them, so a loop over bodies
// keeps them in registers.
RODSEA_HD inline void fly_freely(Vec3& x, Vec3& v, Quat& q, Vec3& w, const Rotor& rotor, double dt,
                                 double gravity, double drop, PeriodicBox2D box) {
    x += dt * v;
    x.z -= drop;
    v.z -= gravity * dt;
    x.x = PeriodicBox2D::wrap(x.x, box.lx);
    x.y = PeriodicBox2D::wrap(x.y, box.ly);
    rotate_free(q, w, rotor, dt);
}

}  // namespace rodsea::physics
