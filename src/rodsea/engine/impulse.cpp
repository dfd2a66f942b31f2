#include "rodsea/engine/impulse.hpp"

#include <cmath>

namespace rodsea {

Mat3 collision_matrix(double inv_mass_a, const Mat3& inv_inertia_a, const Vec3& arm_a,
                      double inv_mass_b, const Mat3& inv_inertia_b, const Vec3& arm_b) {
    const Mat3 ra = Mat3::skew(arm_a), rb = Mat3::skew(arm_b);
    return (inv_mass_a + inv_mass_b) * Mat3::identity() - ra * inv_inertia_a * ra -
           rb * inv_inertia_b * rb;
}

Impulse stronge_impulse(const Vec3& u, const Vec3& n, const Mat3& k, double friction,
                        double restitution) {
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

}  // namespace rodsea
