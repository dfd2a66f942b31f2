#include "rodsea/shape/shape.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/error.hpp"
#include "rodsea/shape/mass_properties.hpp"
#include "rodsea/shape/projected_area.hpp"

namespace rodsea {

namespace {

// Rotation matrix (proper) to quaternion, Shepperd's method.
Quat quat_from_matrix(const Mat3& r) {
    const double tr = r(0, 0) + r(1, 1) + r(2, 2);
    Quat q;
    if (tr > 0.0) {
        const double s = 2.0 * std::sqrt(1.0 + tr);
        q = {0.25 * s, (r(2, 1) - r(1, 2)) / s, (r(0, 2) - r(2, 0)) / s, (r(1, 0) - r(0, 1)) / s};
    } else if (r(0, 0) > r(1, 1) && r(0, 0) > r(2, 2)) {
        const double s = 2.0 * std::sqrt(1.0 + r(0, 0) - r(1, 1) - r(2, 2));
        q = {(r(2, 1) - r(1, 2)) / s, 0.25 * s, (r(0, 1) + r(1, 0)) / s, (r(0, 2) + r(2, 0)) / s};
    } else if (r(1, 1) > r(2, 2)) {
        const double s = 2.0 * std::sqrt(1.0 + r(1, 1) - r(0, 0) - r(2, 2));
        q = {(r(0, 2) - r(2, 0)) / s, (r(0, 1) + r(1, 0)) / s, 0.25 * s, (r(1, 2) + r(2, 1)) / s};
    } else {
        const double s = 2.0 * std::sqrt(1.0 + r(2, 2) - r(0, 0) - r(1, 1));
        q = {(r(1, 0) - r(0, 1)) / s, (r(0, 2) + r(2, 0)) / s, (r(1, 2) + r(2, 1)) / s, 0.25 * s};
    }
    return normalized(q);
}

}  // namespace

SymmetricEigen symmetric_eigen(const Mat3& input) {
    // Cyclic Jacobi: a handful of sweeps reach round-off for 3x3.
    Mat3 a = input;
    Mat3 v = Mat3::identity();
    for (int sweep = 0; sweep < 50; ++sweep) {
        const double off = a(0, 1) * a(0, 1) + a(0, 2) * a(0, 2) + a(1, 2) * a(1, 2);
        const double scale = a(0, 0) * a(0, 0) + a(1, 1) * a(1, 1) + a(2, 2) * a(2, 2);
        if (off <= 1e-32 * scale) break;
        for (int p = 0; p < 2; ++p) {
            for (int q = p + 1; q < 3; ++q) {
                if (a(p, q) == 0.0) continue;
                const double theta = (a(q, q) - a(p, p)) / (2.0 * a(p, q));
                const double t =
                    (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                Mat3 j = Mat3::identity();
                j(p, p) = c;
                j(q, q) = c;
                j(p, q) = s;
                j(q, p) = -s;
                a = transpose(j) * a * j;
                v = v * j;
            }
        }
    }
    if (determinant(v) < 0.0) {
        for (int r = 0; r < 3; ++r)
            v(r, 2) = -v(r, 2);
    }
    return {{a(0, 0), a(1, 1), a(2, 2)}, v};
}

Shape make_shape(const SphereList& spheres, double mass, const std::string& name) {
    require_positive(name + ".mass", mass, "mass units");
    const MassProperties mp = mass_properties(spheres);
    const SymmetricEigen eig = symmetric_eigen(mp.inertia);
    const Mat3 to_body = transpose(eig.rotation);

    Shape shape;
    shape.mass = mass;
    shape.volume = mp.volume;
    shape.principal_inertia = (mass / mp.volume) * eig.values;
    shape.com_in_definition_frame = mp.centre_of_mass;
    shape.definition_to_body = quat_from_matrix(to_body);
    shape.projected_area = projected_area(spheres);
    for (const Sphere& s : spheres) {
        shape.offsets.push_back(to_body * (s.centre - mp.centre_of_mass));
        shape.radii.push_back(s.radius);
        shape.max_radius = std::max(shape.max_radius, s.radius);
    }
    for (size_t i = 0; i < spheres.size(); ++i)
        for (size_t j = i; j < spheres.size(); ++j)
            shape.extent = std::max(shape.extent, norm(spheres[i].centre - spheres[j].centre) +
                                                      spheres[i].radius + spheres[j].radius);
    return shape;
}

}  // namespace rodsea
