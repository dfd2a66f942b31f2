#pragma once
// Unit quaternion for body orientation: world = rotate(q, body).
#include <cmath>

#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/mat3.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

struct Quat {
    double w = 1.0, x = 0.0, y = 0.0, z = 0.0;

    RODSEA_HD static Quat from_axis_angle(const Vec3& unit_axis, double angle) {
        const double s = std::sin(0.5 * angle);
        return {std::cos(0.5 * angle), unit_axis.x * s, unit_axis.y * s, unit_axis.z * s};
    }
    RODSEA_HD constexpr Vec3 vec() const { return {x, y, z}; }
};

RODSEA_HD constexpr Quat operator*(const Quat& p, const Quat& q) {
    return {p.w * q.w - p.x * q.x - p.y * q.y - p.z * q.z,
            p.w * q.x + p.x * q.w + p.y * q.z - p.z * q.y,
            p.w * q.y - p.x * q.z + p.y * q.w + p.z * q.x,
            p.w * q.z + p.x * q.y - p.y * q.x + p.z * q.w};
}
RODSEA_HD constexpr bool operator==(const Quat& p, const Quat& q) {
    return p.w == q.w && p.x == q.x && p.y == q.y && p.z == q.z;
}
RODSEA_HD constexpr Quat conjugate(const Quat& q) {
    return {q.w, -q.x, -q.y, -q.z};
}

RODSEA_HD inline Quat normalized(const Quat& q) {
    const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// Column k of q's rotation matrix R (R v = q v q*): the world direction of body axis k.
RODSEA_HD constexpr Vec3 rotated_axis(const Quat& q, int k) {
    switch (k) {
        case 0:
            return {1 - 2 * (q.y * q.y + q.z * q.z), 2 * (q.x * q.y + q.w * q.z),
                    2 * (q.x * q.z - q.w * q.y)};
        case 1:
            return {2 * (q.x * q.y - q.w * q.z), 1 - 2 * (q.x * q.x + q.z * q.z),
                    2 * (q.y * q.z + q.w * q.x)};
        default:
            return {2 * (q.x * q.z + q.w * q.y), 2 * (q.y * q.z - q.w * q.x),
                    1 - 2 * (q.x * q.x + q.y * q.y)};
    }
}

// Rotation matrix R with R v = q v q*, column by column.
RODSEA_HD constexpr Mat3 to_matrix(const Quat& q) {
    Mat3 m;
    for (int k = 0; k < 3; ++k) {
        const Vec3 c = rotated_axis(q, k);
        m(0, k) = c.x;
        m(1, k) = c.y;
        m(2, k) = c.z;
    }
    return m;
}

RODSEA_HD constexpr Vec3 rotate(const Quat& q, const Vec3& v) {
    // v + 2 w (u x v) + 2 u x (u x v), u = vector part: cheaper than building R.
    const Vec3 u = q.vec();
    const Vec3 t = 2.0 * cross(u, v);
    return v + q.w * t + cross(u, t);
}

}  // namespace rodsea
