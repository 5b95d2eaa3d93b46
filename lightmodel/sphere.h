// One sphere of the source body: centre and radius in mm, single precision because that is what
// Embree's sphere points (RTC_FORMAT_FLOAT4 x y z r) and the model file store.
#pragma once

#include "core/geometry.h"

#include <cmath>

namespace rayset::lightmodel {

struct Sphere {
    float x = 0, y = 0, z = 0, r = 0;
};

inline Vec3 centre_of(const Sphere& s) { return {s.x, s.y, s.z}; }

// Where the line origin + t dir (dir unit) crosses the ball, in double precision: t0 <= t1,
// false when it misses.
inline bool line_ball(const Sphere& s, Vec3 origin, Vec3 dir, double& t0, double& t1) {
    const Vec3 oc = centre_of(s) - origin;
    const double tc = dot(oc, dir);
    const Vec3 perp = oc - tc * dir;  // not |oc|^2 - tc^2, which cancels far from the ball
    const double disc = double(s.r) * s.r - dot(perp, perp);
    if (disc < 0) return false;
    const double half = std::sqrt(disc);
    t0 = tc - half, t1 = tc + half;
    return true;
}

}  // namespace rayset::lightmodel
