// Clarberg's equal-area octahedral map in double precision, with the fold of the square's edges.
#include "lightmodel/direction_map.h"

#include <algorithm>
#include <cmath>

namespace rayset::lightmodel {

Vec2 direction_to_square(Vec3 w) {
    const double ax = std::abs(w.x), ay = std::abs(w.y), az = std::abs(w.z);
    // r = sqrt(1 - |z|), written so that it keeps full precision near the poles where 1 - |z|
    // would cancel.
    const double r = std::sqrt((ax * ax + ay * ay) / (1 + az));
    // Fraction of the quadrant's angle, 0 on the x axis and 1 on the y axis.
    const double phi = (ax == 0 && ay == 0) ? 0 : std::atan2(ay, ax) * (2 / kPi);
    double v = phi * r;
    double u = r - v;
    if (w.z < 0) {  // fold the lower hemisphere out into the corner triangle
        std::swap(u, v);
        u = 1 - u;
        v = 1 - v;
    }
    // Explicit sign tests rather than copysign, so that -0.0 components do not flip a point.
    if (w.x < 0) u = -u;
    if (w.y < 0) v = -v;
    return {std::clamp(0.5 * (u + 1), 0.0, 1.0), std::clamp(0.5 * (v + 1), 0.0, 1.0)};
}

Vec3 square_to_direction(Vec2 p) {
    const double u = 2 * std::clamp(p.x, 0.0, 1.0) - 1;
    const double v = 2 * std::clamp(p.y, 0.0, 1.0) - 1;
    const double au = std::abs(u), av = std::abs(v);
    // Signed distance from the diamond |u| + |v| = 1 (the equator): positive inside (z > 0).
    const double signed_distance = 1 - (au + av);
    const double r = 1 - std::abs(signed_distance);
    // The fold (|u|, |v|) -> (1 - |v|, 1 - |u|) keeps |v| - |u|, so one formula serves both
    // hemispheres.
    const double phi = (r == 0 ? 1 : (av - au) / r + 1) * (kPi / 4);
    const double z = signed_distance < 0 ? -(1 - r * r) : 1 - r * r;
    const double sin_theta = r * std::sqrt(std::max(0.0, 2 - r * r));
    const double x = std::cos(phi) * sin_theta, y = std::sin(phi) * sin_theta;
    return {u < 0 ? -x : x, v < 0 ? -y : y, z};
}

Vec2 wrap_square(Vec2 p) {
    if (p.x < 0) {
        p = {-p.x, 1 - p.y};
    } else if (p.x > 1) {
        p = {2 - p.x, 1 - p.y};
    }
    if (p.y < 0) {
        p = {1 - p.x, -p.y};
    } else if (p.y > 1) {
        p = {1 - p.x, 2 - p.y};
    }
    return p;
}

CellIndex wrap_cell(CellIndex c, int n) {
    if (c.i < 0) {
        c = {-1 - c.i, n - 1 - c.j};
    } else if (c.i >= n) {
        c = {2 * n - 1 - c.i, n - 1 - c.j};
    }
    if (c.j < 0) {
        c = {n - 1 - c.i, -1 - c.j};
    } else if (c.j >= n) {
        c = {n - 1 - c.i, 2 * n - 1 - c.j};
    }
    return c;
}

}  // namespace rayset::lightmodel
