// The body's Embree scene and its union-of-balls queries (see sphere_body.h).
#include "lightmodel/sphere_body.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace rayset::lightmodel {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

void throw_on_error(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("SphereBody: Embree error ") +
                                 std::to_string(int(error)) + " in " + what);
}

RTCRayHit make_rayhit(Vec3 origin, Vec3 dir, double tmax) {
    RTCRayHit rh{};
    rh.ray.org_x = float(origin.x), rh.ray.org_y = float(origin.y), rh.ray.org_z = float(origin.z);
    rh.ray.dir_x = float(dir.x), rh.ray.dir_y = float(dir.y), rh.ray.dir_z = float(dir.z);
    rh.ray.tnear = 0;
    rh.ray.tfar = tmax < double(std::numeric_limits<float>::max()) ? float(tmax) : kInfinity;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

// The context of crossed_spheres(): Embree hands it to the filter, which records every ball
// the segment meets (tested again exactly in double) and rejects the hit so traversal goes on.
struct CrossingContext {
    RTCIntersectContext context;  // first member: Embree sees a plain RTCIntersectContext
    const std::vector<Sphere>* spheres;
    Vec3 origin, dir;
    double tmax;
    std::vector<uint32_t>* out;
};

void record_crossing(const RTCFilterFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto* c = reinterpret_cast<const CrossingContext*>(args->context);
    const uint32_t prim = RTCHitN_primID(args->hit, args->N, 0);
    const Sphere& s = (*c->spheres)[prim];
    const Vec3 centre = centre_of(s);
    const double t = std::clamp(dot(centre - c->origin, c->dir), 0.0, c->tmax);
    const Vec3 closest = c->origin + t * c->dir - centre;
    if (dot(closest, closest) <= double(s.r) * s.r) c->out->push_back(prim);
    args->valid[0] = 0;
}

// occluded()'s filter, with a CrossingContext: a hit counts where the segment enters that ball
// in double precision too (intersect()'s test of its nearest hit); others are passed over.
void confirm_entry(const RTCFilterFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto* c = reinterpret_cast<const CrossingContext*>(args->context);
    const uint32_t prim = RTCHitN_primID(args->hit, args->N, 0);
    double t0, t1;
    if (!(line_ball((*c->spheres)[prim], c->origin, c->dir, t0, t1) && t0 >= 0 && t0 <= c->tmax))
        args->valid[0] = 0;
}

// The context of inside(): a ray from the point finds the exit of every ball holding it within
// twice the largest radius; the filter tests containment exactly and keeps traversing until
// one holds the point.
struct InsideContext {
    RTCIntersectContext context;
    const std::vector<Sphere>* spheres;
    Vec3 p;
    bool inside;
};

void record_inside(const RTCFilterFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* c = reinterpret_cast<InsideContext*>(args->context);
    const Sphere& s = (*c->spheres)[RTCHitN_primID(args->hit, args->N, 0)];
    const Vec3 d = c->p - centre_of(s);
    if (dot(d, d) < double(s.r) * s.r)
        c->inside = true;  // accepted: shortens the ray, ends sooner
    else
        args->valid[0] = 0;
}

}  // namespace

SphereBody::SphereBody(std::vector<Sphere> spheres, RTCDevice device)
    : spheres_(std::move(spheres)) {
    for (const Sphere& s : spheres_) {
        if (!(s.r >= 0) || !std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z) ||
            !std::isfinite(s.r))
            throw std::invalid_argument(
                "SphereBody: a sphere with a non-finite centre or negative radius");
        bounds_.extend(centre_of(s) - Vec3{s.r, s.r, s.r});
        bounds_.extend(centre_of(s) + Vec3{s.r, s.r, s.r});
        max_radius_ = std::max(max_radius_, s.r);
    }
    if (device) {
        rtcRetainDevice(device);
        device_ = device;
    } else {
        device_ = rtcNewDevice(nullptr);
        if (!device_) throw std::runtime_error("SphereBody: cannot create an Embree device");
    }
    // Robust traversal: the light-sampling pdf needs every ball a segment meets, grazing ones too.
    scene_ = rtcNewScene(device_);
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    if (!spheres_.empty()) {
        // Embree reads the balls from spheres_ itself: the ball a hit names is then in cache
        // when intersect() recomputes it in double.
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                   spheres_.data(), 0, sizeof(Sphere), spheres_.size());
        throw_on_error(device_, "sharing the sphere buffer");
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene_);
    throw_on_error(device_, "building the sphere scene");
}

SphereBody::~SphereBody() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
}

bool SphereBody::inside(Vec3 p) const {
    if (!bounds_.contains(p)) return false;  // also when there are no spheres
    InsideContext c;
    rtcInitIntersectContext(&c.context);
    c.context.filter = record_inside;
    c.spheres = &spheres_;
    c.p = p;
    c.inside = false;
    RTCRayHit rh = make_rayhit(p, {0, 0, 1}, 2.0 * max_radius_);
    rtcIntersect1(scene_, &c.context, &rh);
    return c.inside;
}

bool SphereBody::hit_from(uint32_t sphere, Vec3 origin, Vec3 dir, double t, BodyHit& hit) const {
    const Sphere& s = spheres_[sphere];
    hit.t = t;
    hit.point = origin + t * dir;
    hit.normal = (1.0 / s.r) * (hit.point - centre_of(s));
    hit.sphere = sphere;
    return true;
}

bool SphereBody::intersect(Vec3 origin, Vec3 dir, double tmax, BodyHit& hit) const {
    if (spheres_.empty() || inside(origin)) return entry_after_inside(origin, dir, tmax, hit);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh = make_rayhit(origin, dir, tmax);
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    double t0, t1;
    // From outside the first crossing is an entry; where float and double disagree about that
    // (an origin within rounding of a surface) the exact path decides.
    if (line_ball(spheres_[rh.hit.primID], origin, dir, t0, t1) && t0 >= 0 && t0 <= tmax)
        return hit_from(rh.hit.primID, origin, dir, t0, hit);
    return entry_after_inside(origin, dir, tmax, hit);
}

// The exact path: the balls along the segment as intervals of t, merged from t = 0 on; the first
// interval that starts after the merged stretch holding the origin is the entry.
bool SphereBody::entry_after_inside(Vec3 origin, Vec3 dir, double tmax, BodyHit& hit) const {
    std::vector<uint32_t> crossed;
    crossed_spheres(origin, dir, tmax, crossed);
    struct Interval {
        double t0, t1;
        uint32_t sphere;
    };
    std::vector<Interval> intervals;
    intervals.reserve(crossed.size());
    for (uint32_t i : crossed) {
        double t0, t1;
        if (line_ball(spheres_[i], origin, dir, t0, t1)) intervals.push_back({t0, t1, i});
    }
    std::sort(intervals.begin(), intervals.end(),
              [](const Interval& a, const Interval& b) { return a.t0 < b.t0; });
    double reach = 0;
    for (const Interval& in : intervals) {
        if (in.t0 > reach) return in.t0 <= tmax && hit_from(in.sphere, origin, dir, in.t0, hit);
        reach = std::max(reach, in.t1);
    }
    return false;
}

bool SphereBody::occluded(Vec3 origin, Vec3 dir, double tmax) const {
    if (spheres_.empty()) return false;
    if (inside(origin)) {
        BodyHit hit;
        return entry_after_inside(origin, dir, tmax, hit);
    }
    CrossingContext c;
    rtcInitIntersectContext(&c.context);
    c.context.filter = confirm_entry;
    c.spheres = &spheres_;
    c.origin = origin, c.dir = dir, c.tmax = tmax;
    RTCRay ray = make_rayhit(origin, dir, tmax).ray;
    rtcOccluded1(scene_, &c.context, &ray);
    return ray.tfar < 0;  // Embree marks an occluded ray with tfar = -inf
}

void SphereBody::crossed_spheres(Vec3 origin, Vec3 dir, double tmax,
                                 std::vector<uint32_t>& out) const {
    out.clear();
    if (spheres_.empty()) return;
    CrossingContext c;
    rtcInitIntersectContext(&c.context);
    c.context.filter = record_crossing;
    c.spheres = &spheres_;
    c.origin = origin, c.dir = dir, c.tmax = tmax;
    c.out = &out;
    // A ball the segment meets has a surface crossing at t in [0, tmax + 2 r]: its exit.
    RTCRayHit rh = make_rayhit(origin, dir, tmax + 2.0 * max_radius_);
    rtcIntersect1(scene_, &c.context, &rh);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace rayset::lightmodel
