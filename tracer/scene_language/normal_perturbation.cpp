// normal { } patterns as shading-normal perturbations (normal_perturbation.h).
#include "tracer/scene_language/normal_perturbation.h"

#include <cmath>

#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/image_mapping.h"
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
// `value_at(world point, value)` gives the value.
template <class ValueAt>
bool world_gradient(ValueAt&& value_at, Vec3 point, double h, const Matrix4& to_world,
                    Vec3& gradient) {
    const double c = 1 / std::sqrt(3.0);
    const Vec3 corners[4] = {{c, c, c}, {c, -c, -c}, {-c, c, -c}, {-c, -c, c}};
    double centre = 0;
    if (!value_at(point, centre)) return false;
    Vec3 in_pattern;
    for (const Vec3& t : corners) {
        double value = 0;
        if (!value_at(point + h * to_world.vector(t), value)) return false;
        in_pattern = in_pattern + (value - centre) * t;
    }
    gradient = to_world.normal((0.75 / h) * in_pattern);
    return true;
}

// bump_map's tilt before its size: the slope of the plane through the image's heights at the
// point and one pixel below it to either side, along the pattern's x and y (per pixel, not per
// unit: POV-Ray's tilt is the same on an image of any size and any even scale), turned into
// the world as normals are. Read back from POV-Ray's renders of ramp, step and single-dot
// images lit from either side (a dot tilts its own pixel and the two diagonally above it, as
// this plane does): the normal leans by bump_size times that slope, of the file's numbers (no
// gamma), for map_type 0.
bool bump_map_slope(const Pattern& pattern, Vec3 point, const Matrix4& to_world, Vec3& slope) {
    if (!pattern.image || !pattern.image->pixels || pattern.image->use_index ||
        pattern.image->map_type != 0 || !pattern_space_point(pattern, point))
        return false;
    const ImageMap& image = *pattern.image;
    double u = 0, v = 0;
    if (!image_coordinates(image, point, u, v)) {  // beyond a `once` image: no tilt
        slope = {};
        return true;
    }
    const Vec3 dx{1.0 / image.pixels->width, 0, 0}, dy{0, 1.0 / image.pixels->height, 0};
    double here = 0, below_left = 0, below_right = 0;
    if (!image_height(image, point, here) || !image_height(image, point - dx - dy, below_left) ||
        !image_height(image, point + dx - dy, below_right))
        return false;
    slope =
        to_world.normal({(below_right - below_left) / 2, here - (below_left + below_right) / 2, 0});
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
    if (pattern.kind == PatternKind::bump_map) {
        if (!bump_map_slope(pattern, point, to_world, gradient)) return false;
        delta = (-normal.amount * across) * gradient;
        return true;
    }
    auto value_at = [&](Vec3 p, double& value) { return evaluate_pattern(pattern, p, value); };
    if (!world_gradient(value_at, point, normal.accuracy, to_world, gradient)) return false;
    delta = (-2.0 / 15 * normal.amount * across) * gradient;
    return true;
}

bool normal_is_evaluable(const Normal& normal) {
    Vec3 delta;
    return normal_perturbation(normal, {0.31, -0.72, 1.13}, {0, 1, 0}, delta);
}

}  // namespace rayset::tracer
