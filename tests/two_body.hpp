#pragma once
// Two free bodies far from both plates, no gravity, fixed plates: the setting for checking one
// collision against conservation laws. dt is tiny so that the free flight before contact search
// moves the bodies by ~1e-7 mm: the collision happens where the test put it.
#include "rodsea/engine/simulation.hpp"

namespace rodsea::testing {

struct BodySpec {
    Vec3 position;
    Quat orientation;
    Vec3 velocity;
    Vec3 spin;
};

inline Simulation two_body_simulation(const Species& a, const Species& b, const BodySpec& sa,
                                      const BodySpec& sb, ContactCoefficients body_body,
                                      const BackendOptions& options = {}) {
    EngineParameters p;
    p.box = {40.0, 40.0};
    p.drive.gamma = 0.0;
    p.drive.gravity = 0.0;
    p.drive.gap = 20.0;
    p.dt = 1e-9;
    p.species = {a, b};
    p.body_body = body_body;
    BodyState bodies;
    bodies.add(0, sa.position, sa.orientation, sa.velocity, sa.spin);
    bodies.add(1, sb.position, sb.orientation, sb.velocity, sb.spin);
    return Simulation(p, bodies, options);
}

// Relative velocity of a contact's two points along its normal (a − b).
inline double normal_relative_velocity(const Simulation& sim, const Contact& c) {
    const BodyState& s = sim.bodies();
    const Vec3 u = (s.velocity[c.a] + cross(s.spin[c.a], c.arm_a)) -
                   (s.velocity[c.b] + cross(s.spin[c.b], c.arm_b));
    return dot(u, c.normal);
}

}  // namespace rodsea::testing
