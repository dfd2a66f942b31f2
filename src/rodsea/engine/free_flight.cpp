#include "rodsea/engine/free_flight.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/neighbors/periodic_cell_list.hpp"

namespace rodsea {

namespace {

constexpr double kSameMoment = 1e-12;  // relative: moments closer than this are equal

bool same(double a, double b) {
    return std::abs(a - b) <= kSameMoment * std::max(a, b);
}

Vec3 unit_axis(int k) {
    return k == 0 ? Vec3{1, 0, 0} : (k == 1 ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
}

// Rotates q by angle about a world axis (left) — used for the precession about L.
Quat rotate_about_world(const Quat& q, const Vec3& axis, double angle) {
    return Quat::from_axis_angle(axis, angle) * q;
}

// Exact flow of H_k = L_k² / 2I_k: the body turns about its own axis k by L_k h / I_k.
void principal_subflow(Quat& q, Vec3& l_body, int k, double inertia_k, double h) {
    const double angle = l_body[k] * h / inertia_k;
    q = q * Quat::from_axis_angle(unit_axis(k), angle);
    // The world vector L is fixed, so its body components turn the other way.
    l_body = rotate(Quat::from_axis_angle(unit_axis(k), -angle), l_body);
}

}  // namespace

void rotate_free(Quat& q, Vec3& spin, const Vec3& inertia, double dt) {
    const Vec3 w_body = rotate(conjugate(q), spin);
    const Vec3 l_body{inertia.x * w_body.x, inertia.y * w_body.y, inertia.z * w_body.z};
    const Vec3 l_world = rotate(q, l_body);
    const double l = norm(l_world);
    if (l == 0.0) return;

    // Index of the distinct moment for an axisymmetric body (x for a sphere, where the second
    // flow below has zero rate), -1 if none.
    int axis = -1;
    if (same(inertia.y, inertia.z))
        axis = 0;
    else if (same(inertia.x, inertia.z))
        axis = 1;
    else if (same(inertia.x, inertia.y))
        axis = 2;

    if (axis >= 0) {
        // H = L²/2I_t + L_a²/2 (1/I_a − 1/I_t): two commuting exact flows, precession about L
        // and spin about the symmetry axis.
        const int t = axis == 0 ? 1 : 0;
        const double i_a = inertia[axis], i_t = inertia[t];
        q = rotate_about_world(q, l_world / l, l * dt / i_t);
        q = q * Quat::from_axis_angle(unit_axis(axis), l_body[axis] * (1.0 / i_a - 1.0 / i_t) * dt);
    } else {
        Vec3 lb = l_body;
        principal_subflow(q, lb, 0, inertia.x, 0.5 * dt);
        principal_subflow(q, lb, 1, inertia.y, 0.5 * dt);
        principal_subflow(q, lb, 2, inertia.z, dt);
        principal_subflow(q, lb, 1, inertia.y, 0.5 * dt);
        principal_subflow(q, lb, 0, inertia.x, 0.5 * dt);
    }
    q = normalized(q);
    const Vec3 lb = rotate(conjugate(q), l_world);
    spin = rotate(q, Vec3{lb.x / inertia.x, lb.y / inertia.y, lb.z / inertia.z});
}

void advance_free_flight(BodyState& bodies, const std::vector<Species>& species, const Box& box,
                         double gravity, double dt) {
    const double drop = 0.5 * gravity * dt * dt;
    for (size_t i = 0; i < bodies.size(); ++i) {
        Vec3& x = bodies.position[i];
        Vec3& v = bodies.velocity[i];
        x += dt * v;
        x.z -= drop;
        v.z -= gravity * dt;
        x.x = PeriodicBox2D::wrap(x.x, box.lx);
        x.y = PeriodicBox2D::wrap(x.y, box.ly);
        rotate_free(bodies.orientation[i], bodies.spin[i],
                    species[bodies.species[i]].shape.principal_inertia, dt);
    }
}

}  // namespace rodsea
