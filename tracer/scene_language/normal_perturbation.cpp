// normal { } patterns as shading-normal perturbations (normal_perturbation.h).
#include "tracer/scene_language/normal_perturbation.h"

#include <cmath>

#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/noise.h"

namespace rayset::tracer {
namespace {

// Patterns POV-Ray perturbs with a noise vector rather than down their slope.
bool tilts_by_noise(PatternKind kind) {
    return kind == PatternKind::bumps || kind == PatternKind::dents ||
           kind == PatternKind::wrinkles;
}

// Patterns with a perturbation of their own that is not rendered (their slope is not what
// POV-Ray shows).
bool has_unrendered_perturbation(PatternKind kind) {
    return kind == PatternKind::ripples || kind == PatternKind::waves ||
           kind == PatternKind::quilted || kind == PatternKind::facets ||
           kind == PatternKind::average;
}

// The noise vector in the pattern's space, per unit bump size.
Vec3 noise_tilt(const Pattern& pattern, Vec3 p) {
    constexpr double kBumps = 1.0, kDents = 1.0, kWrinkles = 0.55, kWrinklesBias = 0.42;
    switch (pattern.kind) {
        case PatternKind::bumps: return kBumps * vector_noise(p);
        case PatternKind::dents:
            return (kDents * std::pow(solid_noise(p, pattern.noise_generator), 3)) *
                   vector_noise(p);
        default:
            return kWrinkles * vector_turbulence(p, 10, 0.5, 2) +
                   Vec3{kWrinklesBias, kWrinklesBias, kWrinklesBias};
    }
}

// The pattern's gradient at `point` (world) from its values at the corners of a regular
// tetrahedron of radius h in the pattern's space around it (POV-Ray's step is in pattern
// units: a pattern scaled up is differenced over a wider step):
// sum_i (v(p + h t_i) - v(p)) t_i = (4/3) h grad(v) for unit corners t_i.
bool world_gradient(const Pattern& pattern, Vec3 point, double h, const Matrix4& to_world,
                    Vec3& gradient) {
    const double c = 1 / std::sqrt(3.0);
    const Vec3 corners[4] = {{c, c, c}, {c, -c, -c}, {-c, c, -c}, {-c, -c, c}};
    double centre = 0;
    if (!evaluate_pattern(pattern, point, centre)) return false;
    Vec3 in_pattern;
    for (const Vec3& t : corners) {
        double value = 0;
        if (!evaluate_pattern(pattern, point + h * to_world.vector(t), value)) return false;
        in_pattern = in_pattern + (value - centre) * t;
    }
    gradient = to_world.normal((0.75 / h) * in_pattern);
    return true;
}

}  // namespace

bool normal_perturbation(const Normal& normal, Vec3 point, Vec3 n, Vec3& delta) {
    const Pattern& pattern = *normal.pattern;
    delta = {};
    if (pattern.kind == PatternKind::plain) return true;
    // Block patterns take a list of normals; maps of normals or slopes are not rendered.
    if (normal.map || list_size(pattern.kind) > 0 || has_unrendered_perturbation(pattern.kind))
        return false;
    const Matrix4 to_world = pattern_to_world(pattern);
    const double across = normal.no_bump_scale ? 1.0 : length(to_world.transpose_vector(n));
    if (tilts_by_noise(pattern.kind)) {
        Vec3 p = point;
        if (!pattern_space_point(pattern, p)) return false;
        delta = (normal.amount * across) * to_world.normal(noise_tilt(pattern, p));
        return true;
    }
    Vec3 gradient;
    if (!world_gradient(pattern, point, normal.accuracy, to_world, gradient)) return false;
    delta = (-2.0 / 15 * normal.amount * across) * gradient;
    return true;
}

bool normal_is_evaluable(const Normal& normal) {
    Vec3 delta;
    return normal_perturbation(normal, {0.31, -0.72, 1.13}, {0, 1, 0}, delta);
}

}  // namespace rayset::tracer
