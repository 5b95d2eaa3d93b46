// Geometry of the analytic test sources: a double-precision vector and the exact irradiance
// that uniform Lambertian polygons and disks produce at any point and receiver orientation.
//
// Units: lengths in mm, radiance in W/(mm^2 sr), irradiance in W/mm^2 (multiply by 1e6 for
// W/m^2). A receiver normal points into the half-space the receiver collects light from.
#pragma once

#include <cmath>
#include <vector>

namespace rayset::analytic {

inline constexpr double kPi = 3.14159265358979323846;

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(Vec3 a) { return (1 / length(a)) * a; }

// Two unit vectors that complete `axis` (unit) to a right-handed orthonormal basis
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited"): no trigonometry, so it is
// bit-identical wherever IEEE arithmetic is.
void orthonormal_basis(Vec3 axis, Vec3& u, Vec3& v);

// Irradiance at `point` on a receiver with unit `normal` from a simple planar polygon (convex or
// not) of uniform Lambertian `radiance` that emits from one side only: the side from which its
// vertices run counter-clockwise. Exact (Lambert's contour formula, see
// docs/synthetic-sources.md), after clipping the polygon to the receiver's front half-space
// (the zero-width bridges clipping leaves in a non-convex polygon cancel in the contour sum).
double polygon_irradiance(double radiance, const std::vector<Vec3>& vertices, Vec3 point, Vec3 normal);

// Irradiance from a one-sided Lambertian disk of `radius` centred at `centre` that emits into
// the half-space its unit `axis` points to. Exact closed form of the contour integral, also
// when the receiver's plane cuts the disk.
double disk_irradiance(double radiance, Vec3 centre, Vec3 axis, double radius, Vec3 point, Vec3 normal);

}  // namespace rayset::analytic
