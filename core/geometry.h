// The basic geometry: pi, a double-precision vector and its operations, an orthonormal basis.
#pragma once

#include <cmath>

namespace rayset {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kRadiansPerDegree = kPi / 180;

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline bool is_zero(Vec3 a) { return a.x == 0 && a.y == 0 && a.z == 0; }
inline Vec3 normalized(Vec3 a) { return (1 / length(a)) * a; }

// Two unit vectors that complete `axis` (unit) to a right-handed orthonormal basis
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited"): no trigonometry, so it is
// bit-identical wherever IEEE arithmetic is.
// Inline: the path tracer builds one at every bounce, and rayset_core is compiled without
// link-time optimisation, so an out-of-line definition stays a call.
inline void orthonormal_basis(Vec3 axis, Vec3& u, Vec3& v) {
    const double sign = std::copysign(1.0, axis.z);
    const double a = -1 / (sign + axis.z);
    const double b = axis.x * axis.y * a;
    u = {1 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x};
    v = {b, sign + axis.y * axis.y * a, -axis.y};
}

}  // namespace rayset
