#include "rodsea/shape/mass_properties.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "rodsea/error.hpp"

namespace rodsea {

namespace {

constexpr double kPi = std::numbers::pi;

bool all_on_x_axis(const SphereList& spheres) {
    return std::all_of(spheres.begin(), spheres.end(),
                       [](const Sphere& s) { return s.centre.y == 0.0 && s.centre.z == 0.0; });
}

bool pairwise_disjoint(const SphereList& spheres) {
    for (size_t i = 0; i < spheres.size(); ++i)
        for (size_t j = i + 1; j < spheres.size(); ++j)
            if (norm(spheres[i].centre - spheres[j].centre) < spheres[i].radius + spheres[j].radius)
                return false;
    return true;
}

// Solid of revolution about x with radius ρ(x) = max_i sqrt(r_i² − (x − x_i)²). Between
// consecutive breakpoints (sphere ends and pairwise crossings of the profiles) one sphere
// dominates, so ρ² is a quadratic there and every integrand below is a polynomial of degree ≤ 4:
// a 3-point Gauss–Legendre rule per piece is exact.
MassProperties axial_chain(const SphereList& spheres) {
    std::vector<double> breaks;
    for (const Sphere& s : spheres) {
        breaks.push_back(s.centre.x - s.radius);
        breaks.push_back(s.centre.x + s.radius);
    }
    for (size_t i = 0; i < spheres.size(); ++i) {
        for (size_t j = i + 1; j < spheres.size(); ++j) {
            const double xi = spheres[i].centre.x, xj = spheres[j].centre.x;
            if (xi == xj) continue;
            const double ri = spheres[i].radius, rj = spheres[j].radius;
            breaks.push_back((ri * ri - rj * rj + xj * xj - xi * xi) / (2.0 * (xj - xi)));
        }
    }
    std::sort(breaks.begin(), breaks.end());

    const double gx[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
    const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

    double vol = 0.0, first = 0.0, second = 0.0, disc_axial = 0.0;
    for (size_t k = 0; k + 1 < breaks.size(); ++k) {
        const double a = breaks[k], b = breaks[k + 1];
        if (b <= a) continue;
        // The dominant sphere on (a, b), chosen at the midpoint, gives the exact quadratic.
        const double mid = 0.5 * (a + b);
        const Sphere* dom = nullptr;
        double best = 0.0;
        for (const Sphere& s : spheres) {
            const double h2 = s.radius * s.radius - (mid - s.centre.x) * (mid - s.centre.x);
            if (h2 > best) best = h2, dom = &s;
        }
        if (dom == nullptr) continue;  // a gap between disjoint spheres
        const double half = 0.5 * (b - a);
        for (int q = 0; q < 3; ++q) {
            const double x = mid + half * gx[q];
            const double r2 = dom->radius * dom->radius - (x - dom->centre.x) * (x - dom->centre.x);
            const double w = gw[q] * half;
            vol += w * kPi * r2;
            first += w * kPi * r2 * x;
            second += w * kPi * r2 * x * x;
            disc_axial += w * 0.5 * kPi * r2 * r2;  // thin disc about its axis: ½ m ρ²
        }
    }
    MassProperties mp;
    mp.volume = vol;
    const double xc = first / vol;
    mp.centre_of_mass = {xc, 0.0, 0.0};
    // A thin disc about a diameter has ¼ m ρ², half its axial moment.
    const double transverse = 0.5 * disc_axial + second - vol * xc * xc;
    mp.inertia = Mat3::diagonal({disc_axial, transverse, transverse});
    return mp;
}

MassProperties disjoint_spheres(const SphereList& spheres) {
    MassProperties mp;
    Vec3 first;
    for (const Sphere& s : spheres) {
        const double v = 4.0 / 3.0 * kPi * s.radius * s.radius * s.radius;
        mp.volume += v;
        first += v * s.centre;
    }
    mp.centre_of_mass = first / mp.volume;
    for (const Sphere& s : spheres) {
        const double v = 4.0 / 3.0 * kPi * s.radius * s.radius * s.radius;
        const Vec3 d = s.centre - mp.centre_of_mass;
        // Own moment ⅖ m r² plus the parallel-axis term m (|d|² 𝟙 − d dᵀ).
        mp.inertia = mp.inertia +
                     (0.4 * v * s.radius * s.radius + v * norm2(d)) * Mat3::identity() -
                     v * Mat3::outer(d, d);
    }
    return mp;
}

}  // namespace

MassProperties mass_properties(const SphereList& spheres) {
    if (spheres.empty()) throw InvalidParameter("shape.spheres", "0 spheres", ">= 1 sphere");
    for (const Sphere& s : spheres)
        require_positive("shape.sphere_radius", s.radius, "mm");
    if (all_on_x_axis(spheres)) return axial_chain(spheres);
    if (pairwise_disjoint(spheres)) return disjoint_spheres(spheres);
    throw InvalidParameter("shape.spheres", "overlapping spheres off the body x axis",
                           "a chain along the body x axis, or spheres that do not overlap");
}

}  // namespace rodsea
