// Small sampling helpers the integrator and materials share: a shading frame, cosine-weighted
// hemisphere directions, Phong-lobe directions and the power heuristic (Veach 1997).
#pragma once

#include <algorithm>
#include <cmath>

#include "converters/analytic/analytic_geometry.h"

namespace rayset::tracer {

// An orthonormal frame around a unit normal: local (x, y, z) with z the normal.
struct Frame {
    Vec3 s, t, n;
    explicit Frame(Vec3 normal) : n(normal) { orthonormal_basis(normal, s, t); }
    Vec3 to_world(Vec3 v) const { return v.x * s + v.y * t + v.z * n; }
};

// Cosine-weighted direction about +z (pdf cos(theta) / pi), Malley's method.
// The angle in single precision: the uniforms are floats already, and sinf/cosf cost half of
// the double versions on the renderer's hottest path.
inline Vec3 cosine_hemisphere(double u1, double u2) {
    const double r = std::sqrt(u1);
    const float phi = 2 * float(kPi) * float(u2);
    return {r * double(std::cos(phi)), r * double(std::sin(phi)), std::sqrt(std::max(0.0, 1 - u1))};
}

// Uniform direction on the unit sphere (pdf 1 / (4 pi)).
inline Vec3 uniform_sphere(double u1, double u2) {
    const double z = 1 - 2 * u1, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Direction about +z with pdf (n + 1) / (2 pi) cos^n(alpha).
inline Vec3 phong_lobe(double exponent, double u1, double u2) {
    const double cos_alpha = std::pow(u1, 1 / (exponent + 1));
    const double sin_alpha = std::sqrt(std::max(0.0, 1 - cos_alpha * cos_alpha)),
                 phi = 2 * kPi * u2;
    return {sin_alpha * std::cos(phi), sin_alpha * std::sin(phi), cos_alpha};
}

inline double power_heuristic(double pdf_a, double pdf_b) {
    const double a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    return a + b > 0 ? a / (a + b) : 0;
}

inline Vec3 reflect(Vec3 wo, Vec3 n) { return 2 * dot(wo, n) * n - wo; }

}  // namespace rayset::tracer
