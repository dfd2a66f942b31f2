#pragma once
// The collision impulse of docs/model.md §3 (Stronge / Keller): restitution on the normal relative
// velocity and Coulomb friction, sticking when the cone allows it, sliding otherwise.
#include <cmath>

#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/mat3.hpp"
#include "rodsea/math/quat.hpp"

namespace rodsea::physics {

// R I⁻¹ Rᵀ: the world-frame inverse inertia of a body with orientation q and inverse principal
// moments `inverse`.
RODSEA_HD inline Mat3 world_inverse_inertia(const Quat& q, const Vec3& inverse) {
    const Mat3 r = to_matrix(q);
    return r * Mat3::diagonal(inverse) * transpose(r);
}

// K such that an impulse P on body a (−P on body b) changes the relative contact velocity by
// K P. A plate is body b with inv_mass_b = 0 and a zero inverse inertia.
RODSEA_HD inline Mat3 collision_matrix(double inv_mass_a, const Mat3& inv_inertia_a,
                                       const Vec3& arm_a, double inv_mass_b,
                                       const Mat3& inv_inertia_b, const Vec3& arm_b) {
    const Mat3 ra = Mat3::skew(arm_a), rb = Mat3::skew(arm_b);
    return (inv_mass_a + inv_mass_b) * Mat3::identity() - ra * inv_inertia_a * ra -
           rb * inv_inertia_b * rb;
}

struct Impulse {
    Vec3 p;  // on body a
    bool sticking = false;
};

// u: relative contact velocity (a − b) before the collision, approaching (u·n < 0);
// n: unit normal from b into a. Stick trial P* = K⁻¹(−e u_n n − u), accepted inside the
// friction cone; otherwise P = j (n − μ t̂) with t̂ the direction of the tangential slip and
// j = −(1+e) u_n / nᵀK(n − μ t̂).
RODSEA_HD inline Impulse stronge_impulse(const Vec3& u, const Vec3& n, const Mat3& k,
                                         double friction, double restitution) {
    const double un = dot(u, n);
    const Vec3 stick = solve(k, -restitution * un * n - u);
    const double pn = dot(stick, n);
    const Vec3 pt = stick - pn * n;
    if (norm(pt) <= friction * pn) return {stick, true};

    // Sliding: friction opposes the slip. With no slip before the collision the slip that
    // develops is the one the sticking impulse would have had to stop: opposite to P*_t. A slip
    // at round-off level (u along n but for ~1e-16 |u|) has no meaningful direction: treat it
    // as none.
    const Vec3 ut = u - un * n;
    const double ut_norm = norm(ut);
    const Vec3 slip = ut_norm > 1e-12 * std::abs(un) ? ut / ut_norm : -pt / norm(pt);
    const Vec3 direction = n - friction * slip;
    const double denominator = dot(n, k * direction);
    if (!(denominator > 0.0)) {
        // Friction so strong that sliding would pull the bodies together (Painlevé-like):
        // fall back to a frictionless impulse rather than inject energy.
        return {(-(1.0 + restitution) * un / dot(n, k * n)) * n, false};
    }
    return {(-(1.0 + restitution) * un / denominator) * direction, false};
}

// The velocity of the point at `arm` from the centre of mass of a body moving at v, spinning at ω.
RODSEA_HD inline Vec3 point_velocity(const Vec3& v, const Vec3& w, const Vec3& arm) {
    return v + cross(w, arm);
}

}  // namespace rodsea::physics
