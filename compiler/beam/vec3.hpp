#pragma once
// Small fixed-size vector algebra for the beam integrals (3-vectors, 3x3 matrices).
#include <array>

namespace yamsc::beam {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<std::array<double, 3>, 3>;

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 operator*(double s, const Vec3& a) {
    return {s * a[0], s * a[1], s * a[2]};
}
inline double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Vec3 unit(int axis) {
    Vec3 e{0, 0, 0};
    e[static_cast<std::size_t>(axis)] = 1;
    return e;
}

/// skew(a) b = a x b
inline Mat3 skew(const Vec3& a) {
    return {{{0, -a[2], a[1]}, {a[2], 0, -a[0]}, {-a[1], a[0], 0}}};
}
inline Mat3 operator*(const Mat3& a, const Mat3& b) {
    Mat3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
    return c;
}
inline Mat3 operator+(const Mat3& a, const Mat3& b) {
    Mat3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) c[i][j] = a[i][j] + b[i][j];
    return c;
}
inline Mat3 operator*(double s, const Mat3& a) {
    Mat3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) c[i][j] = s * a[i][j];
    return c;
}
/// Row vector a^T M.
inline Vec3 row_times(const Vec3& a, const Mat3& m) {
    Vec3 r{0, 0, 0};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[j] += a[i] * m[i][j];
    return r;
}

} // namespace yamsc::beam
