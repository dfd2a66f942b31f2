#pragma once
// Torque-free rotation of a rigid body for one time step: world angular momentum L is kept
// exactly. Axisymmetric bodies (every rod) follow the exact solution, regular precession, and
// spheres (every bead) turn about their constant ω; asymmetric bodies use the symmetric splitting
// into the exact rotations about the three principal axes (energy error O(dt²), bounded).
#include <algorithm>
#include <cmath>

#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/quat.hpp"

namespace rodsea::physics {

// cos h and sin(h) / h from h² by their Taylor series, for the small angles of one step (a body
// spinning at 100 rad/s turns by 1e-4 rad in 1.25 µs): a few multiplications against ~20 ns for
// the library's sin and cos. Valid for h² <= kSeriesLimit (|h| <= 0.02), where the first omitted
// terms, h¹⁰/10! and h¹⁰/11!, are < 1e-17 of the result.
inline constexpr double kSeriesLimit = 4e-4;
struct HalfAngle {
    double cos, sinc;
};
RODSEA_HD inline HalfAngle half_angle_series(double h2) {
    constexpr double k2 = 0.5, k12 = 1.0 / 12.0, k30 = 1.0 / 30.0, k56 = 1.0 / 56.0;
    constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0, k72 = 1.0 / 72.0;
    return {1.0 - h2 * k2 * (1.0 - h2 * k12 * (1.0 - h2 * k30 * (1.0 - h2 * k56))),
            1.0 - h2 * k6 * (1.0 - h2 * k20 * (1.0 - h2 * k42 * (1.0 - h2 * k72)))};
}

// Quat::from_axis_angle, by the series where the angle is small enough.
RODSEA_HD inline Quat axis_angle(const Vec3& unit_axis, double angle) {
    const double h = 0.5 * angle, h2 = h * h;
    if (h2 > kSeriesLimit) return Quat::from_axis_angle(unit_axis, angle);
    const HalfAngle a = half_angle_series(h2);
    const double s = h * a.sinc;
    return {a.cos, unit_axis.x * s, unit_axis.y * s, unit_axis.z * s};
}

RODSEA_HD inline Vec3 unit_axis(int k) {
    return k == 0 ? Vec3{1, 0, 0} : (k == 1 ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
}

// q · (c, s e_K): a turn about body axis K, without the products with zero.
template <int K>
RODSEA_HD Quat turned_about_body_axis(const Quat& q, double c, double s) {
    if constexpr (K == 0)
        return {q.w * c - q.x * s, q.w * s + q.x * c, q.y * c + q.z * s, q.z * c - q.y * s};
    else if constexpr (K == 1)
        return {q.w * c - q.y * s, q.x * c - q.z * s, q.w * s + q.y * c, q.x * s + q.z * c};
    else
        return {q.w * c - q.z * s, q.x * c + q.y * s, q.y * c - q.x * s, q.w * s + q.z * c};
}

RODSEA_HD inline Quat unit(const Quat& q) {
    const double inv = 1.0 / std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w * inv, q.x * inv, q.y * inv, q.z * inv};
}

// A product of unit quaternions back onto the unit sphere: it is off by round-off only, so one
// Newton step for 1/|q| is as accurate there as the square root and division it replaces.
RODSEA_HD inline Quat renormalised(const Quat& q) {
    const double n2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    const double inv = std::abs(n2 - 1.0) < 1e-8 ? 0.5 * (3.0 - n2) : 1.0 / std::sqrt(n2);
    return {q.w * inv, q.x * inv, q.y * inv, q.z * inv};
}

// What torque-free rotation needs of a body's principal moments, worked out once per species:
// a step then costs no division but one (the norm of L).
struct Rotor {
    Vec3 inertia;   // principal moments
    Vec3 inverse;   // their inverses
    int axis = -1;  // the distinct moment of an axisymmetric body (x for a sphere), else -1
    bool isotropic = false;           // all three moments equal (a sphere): ω itself is kept
    double inverse_transverse = 0.0;  // 1 / I_t
    double spin_rate = 0.0;           // 1 / I_a − 1 / I_t
    double largest_inverse = 0.0;
};

// Moments closer than this, relative, are equal.
inline constexpr double kSameMoment = 1e-12;

inline Rotor make_rotor(const Vec3& inertia) {
    const auto same = [](double a, double b) {
        return std::abs(a - b) <= kSameMoment * std::max(a, b);
    };
    Rotor r;
    r.inertia = inertia;
    r.inverse = {1.0 / inertia.x, 1.0 / inertia.y, 1.0 / inertia.z};
    r.largest_inverse = std::max({r.inverse.x, r.inverse.y, r.inverse.z});
    if (same(inertia.y, inertia.z))
        r.axis = 0;
    else if (same(inertia.x, inertia.z))
        r.axis = 1;
    else if (same(inertia.x, inertia.y))
        r.axis = 2;
    r.isotropic = same(inertia.x, inertia.y) && same(inertia.y, inertia.z);
    if (r.axis >= 0) {
        const int t = r.axis == 0 ? 1 : 0;
        r.inverse_transverse = r.inverse[t];
        r.spin_rate = r.inverse[r.axis] - r.inverse[t];
    }
    return r;
}

// An upper bound on |ω|² over a torque-free step: |ω|² itself for a symmetric body (regular
// precession keeps it), (|L| / I_min)² otherwise (|L| is kept, ω = I⁻¹ L in the body frame).
RODSEA_HD inline double spin_bound2(const Rotor& rotor, const Quat& q, const Vec3& spin) {
    if (rotor.axis >= 0) return norm2(spin);
    const Vec3 w = rotate(conjugate(q), spin);
    const Vec3& i = rotor.inertia;
    return norm2(Vec3{i.x * w.x, i.y * w.y, i.z * w.z}) * rotor.largest_inverse *
           rotor.largest_inverse;
}

// Exact flow of H_k = L_k² / 2I_k: the body turns about its own axis k by L_k h / I_k.
RODSEA_HD inline void principal_subflow(Quat& q, Vec3& l_body, int k, double inverse_k, double h) {
    const double angle = l_body[k] * h * inverse_k;
    q = q * axis_angle(unit_axis(k), angle);
    // The world vector L is fixed, so its body components turn the other way.
    l_body = rotate(axis_angle(unit_axis(k), -angle), l_body);
}

// Any body, with the library's sin, cos, square roots and divisions.
RODSEA_HD inline void rotate_general(Quat& q, Vec3& spin, const Rotor& rotor, double dt) {
    const Vec3 w_body = rotate(conjugate(q), spin);
    const Vec3& i = rotor.inertia;
    const Vec3 l_body{i.x * w_body.x, i.y * w_body.y, i.z * w_body.z};
    const Vec3 l_world = rotate(q, l_body);
    const double l2 = norm2(l_world);
    if (l2 == 0.0) return;
    const double l = std::sqrt(l2);

    if (rotor.axis >= 0) {
        // H = L²/2I_t + L_a²/2 (1/I_a − 1/I_t): two commuting exact flows, precession about L
        // and spin about the symmetry axis.
        q = axis_angle((1.0 / l) * l_world, l * dt * rotor.inverse_transverse) * q;
        q = q * axis_angle(unit_axis(rotor.axis), l_body[rotor.axis] * rotor.spin_rate * dt);
    } else {
        Vec3 lb = l_body;
        principal_subflow(q, lb, 0, rotor.inverse.x, 0.5 * dt);
        principal_subflow(q, lb, 1, rotor.inverse.y, 0.5 * dt);
        principal_subflow(q, lb, 2, rotor.inverse.z, dt);
        principal_subflow(q, lb, 1, rotor.inverse.y, 0.5 * dt);
        principal_subflow(q, lb, 0, rotor.inverse.x, 0.5 * dt);
    }
    q = unit(q);
    const Vec3 lb = rotate(conjugate(q), l_world);
    const Vec3& inv = rotor.inverse;
    spin = rotate(q, Vec3{lb.x * inv.x, lb.y * inv.y, lb.z * inv.z});
}

// The same regular precession as rotate_general for an axisymmetric body with symmetry axis K
// (every rod, and a bead too large a turn for rotate_isotropic: rotate_general's square roots,
// divisions and quaternion rotations were over 60 % of the step). The precession about L by φ = |L|
// dt / I_t is the quaternion (cos(φ/2), L sin(φ/2) / |L|), and both entries are even series in |L|
// dt / 2I_t: no square root of |L|², no division by it. ω = L / I_t + (1/I_a − 1/I_t) L_a u follows
// from L and the new axis u without rotating back into the body frame. Returns false, changing
// nothing, when an angle is too large for the series; rotate_general then does it.
template <int K>
RODSEA_HD bool rotate_symmetric(Quat& q, Vec3& spin, const Rotor& rotor, double dt) {
    const Vec3 u = rotated_axis(q, K);
    const double axial_spin = dot(spin, u);
    const double transverse = rotor.inertia[K == 0 ? 1 : 0];
    const double axial_momentum = rotor.inertia[K] * axial_spin;  // L·u, kept exactly
    const Vec3 l = transverse * spin + (axial_momentum - transverse * axial_spin) * u;
    const double beta = 0.5 * dt * rotor.inverse_transverse;  // φ/2 = β |L|
    const double precession2 = norm2(l) * beta * beta;        // (φ/2)²
    const double half_spin = 0.5 * axial_momentum * rotor.spin_rate * dt;
    if (precession2 > kSeriesLimit || half_spin * half_spin > kSeriesLimit) return false;
    const HalfAngle p = half_angle_series(precession2);
    const HalfAngle a = half_angle_series(half_spin * half_spin);
    const double p_scale = beta * p.sinc;
    const Quat precession{p.cos, p_scale * l.x, p_scale * l.y, p_scale * l.z};
    const Quat turned = turned_about_body_axis<K>(precession * q, a.cos, half_spin * a.sinc);
    q = renormalised(turned);
    spin = rotor.inverse_transverse * l + (rotor.spin_rate * axial_momentum) * rotated_axis(q, K);
    return true;
}

// A sphere (every bead): L = I ω, so ω itself is kept and the body turns about it by |ω| dt, the
// quaternion (cos(φ/2), ω sin(φ/2) / |ω|), by the series where the angle is small (one step).
// Half the work of rotate_symmetric, which free flight of a bead medium spends most of its step
// on, and ω is kept to the bit rather than recomputed from L, also over a coast's long jump
// (physics/coasting.hpp), where the library's sin and cos take the large angle.
RODSEA_HD inline void rotate_isotropic(Quat& q, const Vec3& spin, double dt) {
    const double beta = 0.5 * dt;                    // φ/2 = β |ω|
    const double turn2 = norm2(spin) * beta * beta;  // (φ/2)²
    if (turn2 > kSeriesLimit) {
        const double half = std::sqrt(turn2), scale = beta * std::sin(half) / half;
        q = unit(Quat{std::cos(half), scale * spin.x, scale * spin.y, scale * spin.z} * q);
        return;
    }
    const HalfAngle h = half_angle_series(turn2);
    const double scale = beta * h.sinc;
    q = renormalised(Quat{h.cos, scale * spin.x, scale * spin.y, scale * spin.z} * q);
}

// One step of torque-free rotation: the fast path where it applies, the general one otherwise.
RODSEA_HD inline void rotate_free(Quat& q, Vec3& spin, const Rotor& rotor, double dt) {
    if (rotor.isotropic) {
        rotate_isotropic(q, spin, dt);
        return;
    }
    switch (rotor.axis) {
        case 0:
            if (rotate_symmetric<0>(q, spin, rotor, dt)) return;
            break;
        case 1:
            if (rotate_symmetric<1>(q, spin, rotor, dt)) return;
            break;
        case 2:
            if (rotate_symmetric<2>(q, spin, rotor, dt)) return;
            break;
        default:
            break;
    }
    rotate_general(q, spin, rotor, dt);
}

}  // namespace rodsea::physics
