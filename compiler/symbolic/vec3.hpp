#pragma once
// Small fixed-size vector and matrix algebra over GiNaC expressions. Products
// build shared DAG nodes; GiNaC's automatic evaluation drops the zeros.
#include <ginac/ginac.h>

#include <array>

namespace yamsc::symbolic {

struct Vec3 {
    std::array<GiNaC::ex, 3> c{0, 0, 0};
    const GiNaC::ex& operator[](std::size_t i) const { return c[i]; }
    GiNaC::ex& operator[](std::size_t i) { return c[i]; }
};

/// Row-major 3x3; for a frame's orientation the columns are its axes in ground.
struct Mat3 {
    std::array<std::array<GiNaC::ex, 3>, 3> m{};
    static Mat3 identity() {
        Mat3 r;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) r.m[i][j] = i == j ? 1 : 0;
        return r;
    }
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
    return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}
inline Vec3 operator-(const Vec3& a) {
    return {{-a[0], -a[1], -a[2]}};
}
inline Vec3 operator*(const GiNaC::ex& s, const Vec3& a) {
    return {{s * a[0], s * a[1], s * a[2]}};
}
inline GiNaC::ex dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline Vec3 operator*(const Mat3& A, const Vec3& v) {
    Vec3 r;
    for (std::size_t i = 0; i < 3; ++i)
        r[i] = A.m[i][0] * v[0] + A.m[i][1] * v[1] + A.m[i][2] * v[2];
    return r;
}
/// Aᵀ v: components in a frame's axes of a vector given in ground.
inline Vec3 transpose_times(const Mat3& A, const Vec3& v) {
    Vec3 r;
    for (std::size_t i = 0; i < 3; ++i)
        r[i] = A.m[0][i] * v[0] + A.m[1][i] * v[1] + A.m[2][i] * v[2];
    return r;
}
inline Mat3 operator*(const Mat3& A, const Mat3& B) {
    Mat3 r;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            r.m[i][j] = A.m[i][0] * B.m[0][j] + A.m[i][1] * B.m[1][j] + A.m[i][2] * B.m[2][j];
    return r;
}

} // namespace yamsc::symbolic
