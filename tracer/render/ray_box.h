// A ray against an axis-aligned box: the quick test that lets most rays skip lights they
// cannot meet.
#pragma once

#include <algorithm>
#include <cmath>

#include "tracer/render/rgb.h"

namespace rayset::tracer {

// Slab test of the ray (origin, unit direction) in [0, t_max] against the box [low, high]
// (widened by widen_box: the box of coplanar rectangles is flat).
inline bool ray_crosses_box(Vec3 origin, Vec3 direction, double t_max, Vec3 low, Vec3 high) {
    double t0 = 0, t1 = t_max;
    const double o[3] = {origin.x, origin.y, origin.z},
                 d[3] = {direction.x, direction.y, direction.z};
    const double lo[3] = {low.x, low.y, low.z}, hi[3] = {high.x, high.y, high.z};
    // A ray outside a slab and heading away from it misses the box: decided by signs alone,
    // before any division. For a unit direction the slab test below says the same (both its
    // distances are negative), so this changes no outcome, only what those rays cost. A NaN
    // t_max makes the slab test reject nothing: then neither does this.
    bool away = false;
    for (int k = 0; k < 3; ++k) away |= (o[k] < lo[k] && d[k] < 0) | (o[k] > hi[k] && d[k] > 0);
    if (away && !std::isnan(t_max)) return false;
    for (int k = 0; k < 3; ++k) {
        const double inverse = 1 / d[k];
        double near = (lo[k] - o[k]) * inverse, far = (hi[k] - o[k]) * inverse;
        if (near > far) std::swap(near, far);
        if (std::isnan(near)) {  // parallel to the slab: inside it or not
            if (o[k] < lo[k] || o[k] > hi[k]) return false;
            continue;
        }
        t0 = std::max(t0, near), t1 = std::min(t1, far);
        if (t0 > t1) return false;
    }
    return true;
}

// Where the ray (origin, unit direction) enters the box [low, high]: 0 when the origin is in
// it; meaningful only for a ray that meets the box.
inline double box_entry(Vec3 origin, Vec3 direction, Vec3 low, Vec3 high) {
    const double o[3] = {origin.x, origin.y, origin.z},
                 d[3] = {direction.x, direction.y, direction.z};
    const double lo[3] = {low.x, low.y, low.z}, hi[3] = {high.x, high.y, high.z};
    double t0 = 0;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0) continue;  // parallel to the slab, and inside it since the ray meets the box
        const double near = std::min((lo[k] - o[k]) / d[k], (hi[k] - o[k]) / d[k]);
        t0 = std::max(t0, near);
    }
    return t0;
}

inline bool box_holds(Vec3 p, Vec3 low, Vec3 high) {
    return p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y && p.z >= low.z &&
           p.z <= high.z;
}

// Widens a box by a small relative margin, so that rounding never lets a ray miss what it holds.
inline void widen_box(Vec3& low, Vec3& high) {
    for (int k = 0; k < 3; ++k) {
        double& lo = k == 0 ? low.x : k == 1 ? low.y : low.z;
        double& hi = k == 0 ? high.x : k == 1 ? high.y : high.z;
        const double margin = 1e-9 * (std::abs(lo) + std::abs(hi) + (hi - lo)) + 1e-300;
        lo -= margin, hi += margin;
    }
}

}  // namespace rayset::tracer
