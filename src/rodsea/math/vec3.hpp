#pragma once
// Plain 3-vector of doubles. Trivially copyable so that arrays of it are contiguous and are
// copied to a GPU as they are.
#include <cmath>

#include "rodsea/math/hostdevice.hpp"

namespace rodsea {

struct Vec3 {
    double x = 0.0, y = 0.0, z = 0.0;

    constexpr Vec3() = default;
    RODSEA_HD constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

    RODSEA_HD constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    RODSEA_HD constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    RODSEA_HD constexpr Vec3& operator+=(const Vec3& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    RODSEA_HD constexpr Vec3& operator-=(const Vec3& o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    RODSEA_HD constexpr Vec3& operator*=(double s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
};

RODSEA_HD constexpr Vec3 operator+(Vec3 a, const Vec3& b) {
    return a += b;
}
RODSEA_HD constexpr Vec3 operator-(Vec3 a, const Vec3& b) {
    return a -= b;
}
RODSEA_HD constexpr Vec3 operator-(const Vec3& a) {
    return {-a.x, -a.y, -a.z};
}
RODSEA_HD constexpr Vec3 operator*(Vec3 a, double s) {
    return a *= s;
}
RODSEA_HD constexpr Vec3 operator*(double s, Vec3 a) {
    return a *= s;
}
RODSEA_HD constexpr Vec3 operator/(const Vec3& a, double s) {
    return {a.x / s, a.y / s, a.z / s};
}
RODSEA_HD constexpr bool operator==(const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

RODSEA_HD constexpr double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
RODSEA_HD constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
RODSEA_HD constexpr double norm2(const Vec3& a) {
    return dot(a, a);
}
RODSEA_HD inline double norm(const Vec3& a) {
    return std::sqrt(norm2(a));
}
RODSEA_HD inline Vec3 normalized(const Vec3& a) {
    return a / norm(a);
}

}  // namespace rodsea
