#pragma once
// 3x3 matrix, row-major. Used for inertia tensors and the collision matrix K.
#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

struct Mat3 {
    double a[9]{};  // a[3*row + col]; a plain array, so that device code can index it

    RODSEA_HD static constexpr Mat3 zero() { return {}; }
    RODSEA_HD static constexpr Mat3 identity() { return diagonal({1.0, 1.0, 1.0}); }
    RODSEA_HD static constexpr Mat3 diagonal(const Vec3& d) {
        Mat3 m;
        m(0, 0) = d.x;
        m(1, 1) = d.y;
        m(2, 2) = d.z;
        return m;
    }
    // [v]x, the matrix with [v]x w = v x w.
    RODSEA_HD static constexpr Mat3 skew(const Vec3& v) {
        Mat3 m;
        m(0, 1) = -v.z;
        m(0, 2) = v.y;
        m(1, 0) = v.z;
        m(1, 2) = -v.x;
        m(2, 0) = -v.y;
        m(2, 1) = v.x;
        return m;
    }
    RODSEA_HD static constexpr Mat3 outer(const Vec3& u, const Vec3& v) {
        Mat3 m;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                m(i, j) = u[i] * v[j];
        return m;
    }

    RODSEA_HD constexpr double operator()(int r, int c) const { return a[3 * r + c]; }
    RODSEA_HD constexpr double& operator()(int r, int c) { return a[3 * r + c]; }
    RODSEA_HD constexpr Vec3 row(int r) const { return {a[3 * r], a[3 * r + 1], a[3 * r + 2]}; }
    RODSEA_HD constexpr Vec3 col(int c) const { return {a[c], a[3 + c], a[6 + c]}; }
};

RODSEA_HD constexpr Vec3 operator*(const Mat3& m, const Vec3& v) {
    return {dot(m.row(0), v), dot(m.row(1), v), dot(m.row(2), v)};
}
RODSEA_HD constexpr Mat3 operator*(const Mat3& p, const Mat3& q) {
    Mat3 m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m(i, j) = dot(p.row(i), q.col(j));
    return m;
}
RODSEA_HD constexpr Mat3 operator+(Mat3 p, const Mat3& q) {
    for (int i = 0; i < 9; ++i)
        p.a[i] += q.a[i];
    return p;
}
RODSEA_HD constexpr Mat3 operator-(Mat3 p, const Mat3& q) {
    for (int i = 0; i < 9; ++i)
        p.a[i] -= q.a[i];
    return p;
}
RODSEA_HD constexpr Mat3 operator*(double s, Mat3 p) {
    for (double& x : p.a)
        x *= s;
    return p;
}
RODSEA_HD constexpr Mat3 transpose(const Mat3& m) {
    Mat3 t;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            t(i, j) = m(j, i);
    return t;
}
RODSEA_HD constexpr double determinant(const Mat3& m) {
    return dot(m.row(0), cross(m.row(1), m.row(2)));
}

// Solves m x = b by Cramer's rule; m must be non-singular (K is positive definite).
RODSEA_HD constexpr Vec3 solve(const Mat3& m, const Vec3& b) {
    const Vec3 c0 = m.col(0), c1 = m.col(1), c2 = m.col(2);
    const double det = dot(c0, cross(c1, c2));
    return {dot(b, cross(c1, c2)) / det, dot(c0, cross(b, c2)) / det, dot(c0, cross(c1, b)) / det};
}

}  // namespace rodsea
