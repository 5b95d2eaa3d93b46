// Axis-aligned boxes that grow to hold points: bounds of shapes, meshes and sample sets.
#pragma once

#include <algorithm>

#include "core/geometry.h"

namespace rayset {

// Empty (lo above hi) until the first point is added.
struct Bounds3 {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void add(Vec3 p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    Bounds3 grown(double by) const { return {lo - Vec3{by, by, by}, hi + Vec3{by, by, by}}; }
    bool overlaps(const Bounds3& o) const {
        return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y &&
               lo.z <= o.hi.z && o.lo.z <= hi.z;
    }
    double largest_side() const { return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}); }
    // The box both hold (empty when they do not overlap).
    Bounds3 overlap(const Bounds3& o) const {
        return {{std::max(lo.x, o.lo.x), std::max(lo.y, o.lo.y), std::max(lo.z, o.lo.z)},
                {std::min(hi.x, o.hi.x), std::min(hi.y, o.hi.y), std::min(hi.z, o.hi.z)}};
    }
};

}  // namespace rayset
