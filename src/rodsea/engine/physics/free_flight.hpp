#pragma once
// Free flight of one body for dt: an exact parabola under gravity and torque-free rotation.
#include "rodsea/engine/physics/rigid_rotation.hpp"
#include "rodsea/engine/physics/step_context.hpp"
#include "rodsea/math/hostdevice.hpp"

namespace rodsea::physics {

// Moves a body by one step, x and y wrapped into the box. Before moving, raises `drift2` to the
// body's squared speed in the plane and `turn2` to a bound on the squared speed of its spheres
// about its centre (`reach2`: its farthest sphere centre's squared distance): the sum of the
// roots of the largest over all bodies bounds how far any sphere moves in the plane this step,
// which tells the Verlet list when to look. Gravity does not act in the plane. `drop` is
// step.drop(), worked out once for all bodies.
RODSEA_HD inline void fly_freely(Vec3& x, Vec3& v, Quat& q, Vec3& w, const Rotor& rotor,
                                 double reach2, const StepContext& step, double drop,
                                 double& drift2, double& turn2) {
    const double planar2 = v.x * v.x + v.y * v.y;
    const double spin2 = spin_bound2(rotor, q, w) * reach2;
    drift2 = drift2 < planar2 ? planar2 : drift2;  // std::max, which device code lacks
    turn2 = turn2 < spin2 ? spin2 : turn2;
    x += step.dt * v;
    x.z -= drop;
    v.z -= step.gravity * step.dt;
    x.x = PeriodicBox2D::wrap(x.x, step.box.lx);
    x.y = PeriodicBox2D::wrap(x.y, step.box.ly);
    rotate_free(q, w, rotor, step.dt);
}

}  // namespace rodsea::physics
