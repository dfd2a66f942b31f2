#pragma once
// The collision impulse of MODEL.md §3 (Stronge / Keller): restitution on the normal relative
// velocity and Coulomb friction, sticking when the cone allows it, sliding otherwise.
#include "rodsea/math/mat3.hpp"

namespace rodsea {

// K such that an impulse P on body a (−P on body b) changes the relative contact velocity by
// K P. A plate is body b with inv_mass_b = 0 and a zero inverse inertia.
Mat3 collision_matrix(double inv_mass_a, const Mat3& inv_inertia_a, const Vec3& arm_a,
                      double inv_mass_b, const Mat3& inv_inertia_b, const Vec3& arm_b);

struct Impulse {
    Vec3 p;  // on body a
    bool sticking = false;
};

// u: relative contact velocity (a − b) before the collision, approaching (u·n < 0);
// n: unit normal from b into a. Stick trial P* = K⁻¹(−e u_n n − u), accepted inside the
// friction cone; otherwise P = j (n − μ t̂) with t̂ the direction of the tangential slip and
// j = −(1+e) u_n / nᵀK(n − μ t̂).
Impulse stronge_impulse(const Vec3& u, const Vec3& n, const Mat3& k, double friction,
                        double restitution);

}  // namespace rodsea
