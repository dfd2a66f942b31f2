#include "rodsea/engine/free_flight.hpp"

#include <algorithm>
#include <array>
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

// Quat::from_axis_angle without the library sin and cos for the small angles of one step (a
// body spinning at 100 rad/s turns by 1e-4 rad in 1.25 µs): their Taylor series, cut where the
// first omitted term is below 1e-17 relative, cost a few multiplications against ~20 ns per call.
// Larger angles fall back to the library.
Quat axis_angle(const Vec3& unit_axis, double angle) {
    const double h = 0.5 * angle, h2 = h * h;
    if (h2 > 4e-4) return Quat::from_axis_angle(unit_axis, angle);  // |h| > 0.02
    // |h| <= 0.02: sin's next term h⁹/9! and cos's h¹⁰/10! are < 1e-17 of the result.
    constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0;
    constexpr double k2 = 0.5, k12 = 1.0 / 12.0, k30 = 1.0 / 30.0, k56 = 1.0 / 56.0;
    const double s = h * (1.0 - h2 * k6 * (1.0 - h2 * k20 * (1.0 - h2 * k42)));
    const double c = 1.0 - h2 * k2 * (1.0 - h2 * k12 * (1.0 - h2 * k30 * (1.0 - h2 * k56)));
    return {c, unit_axis.x * s, unit_axis.y * s, unit_axis.z * s};
}

Quat unit(const Quat& q) {
    const double inv = 1.0 / std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w * inv, q.x * inv, q.y * inv, q.z * inv};
}

// What torque-free rotation needs of a species' moments, worked out once per species and call:
// a step then costs no division but one (the norm of L). Free flight was half of the step's time
// before, most of it in divisions.
struct Rotor {
    Vec3 inertia;   // principal moments
    Vec3 inverse;   // their inverses
    int axis = -1;  // the distinct moment of an axisymmetric body (x for a sphere), else -1
    double inverse_transverse = 0.0;  // 1 / I_t
    double spin_rate = 0.0;           // 1 / I_a − 1 / I_t
    double largest_inverse = 0.0;
};

// An upper bound on |ω| over a torque-free step: |ω| itself for a symmetric body (regular
// precession keeps it), |L| / I_min otherwise (|L| is kept, ω = I⁻¹ L in the body frame).
double spin_bound(const Rotor& rotor, const Quat& q, const Vec3& spin) {
    if (rotor.axis >= 0) return norm(spin);
    const Vec3 w = rotate(conjugate(q), spin);
    const Vec3& i = rotor.inertia;
    return norm(Vec3{i.x * w.x, i.y * w.y, i.z * w.z}) * rotor.largest_inverse;
}

Rotor make_rotor(const Vec3& inertia) {
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
    if (r.axis >= 0) {
        const int t = r.axis == 0 ? 1 : 0;
        r.inverse_transverse = r.inverse[t];
        r.spin_rate = r.inverse[r.axis] - r.inverse[t];
    }
    return r;
}

// Exact flow of H_k = L_k² / 2I_k: the body turns about its own axis k by L_k h / I_k.
void principal_subflow(Quat& q, Vec3& l_body, int k, double inverse_k, double h) {
    const double angle = l_body[k] * h * inverse_k;
    q = q * axis_angle(unit_axis(k), angle);
    // The world vector L is fixed, so its body components turn the other way.
    l_body = rotate(axis_angle(unit_axis(k), -angle), l_body);
}

void rotate_free(Quat& q, Vec3& spin, const Rotor& rotor, double dt) {
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

}  // namespace

void rotate_free(Quat& q, Vec3& spin, const Vec3& inertia, double dt) {
    rotate_free(q, spin, make_rotor(inertia), dt);
}

double advance_free_flight(BodyState& bodies, const std::vector<Species>& species, const Box& box,
                           double gravity, double dt, int threads) {
    // Per species: its rotor and the farthest sphere centre from its centre of mass (mm). On the
    // stack for the few species a run has, so that a step allocates nothing.
    struct Motion {
        Rotor rotor;
        double reach = 0.0;
    };
    constexpr size_t kFewSpecies = 8;
    std::array<Motion, kFewSpecies> few;
    std::vector<Motion> many(species.size() > kFewSpecies ? species.size() : 0);
    Motion* motion = many.empty() ? few.data() : many.data();
    for (size_t k = 0; k < species.size(); ++k) {
        motion[k].rotor = make_rotor(species[k].shape.principal_inertia);
        for (const Vec3& offset : species[k].shape.offsets)
            motion[k].reach = std::max(motion[k].reach, norm(offset));
    }

    const double drop = 0.5 * gravity * dt * dt;
    const auto n = static_cast<std::ptrdiff_t>(bodies.size());
    double fastest = 0.0;  // mm/s, in the plane
    // clang-format off
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1) \
    reduction(max : fastest)
    // clang-format on
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        Vec3& x = bodies.position[i];
        Vec3& v = bodies.velocity[i];
        Vec3& w = bodies.spin[i];
        const std::uint32_t k = bodies.species[i];
        // Gravity does not act in the plane: v_xy and the bound on |ω| bound every sphere
        // centre's speed in the plane during this step.
        const double spin = spin_bound(motion[k].rotor, bodies.orientation[i], w);
        fastest = std::max(fastest, std::sqrt(v.x * v.x + v.y * v.y) + spin * motion[k].reach);
        x += dt * v;
        x.z -= drop;
        v.z -= gravity * dt;
        x.x = PeriodicBox2D::wrap(x.x, box.lx);
        x.y = PeriodicBox2D::wrap(x.y, box.ly);
        rotate_free(bodies.orientation[i], w, motion[k].rotor, dt);
    }
    return fastest;
}

}  // namespace rodsea
