// Spheres (ellipsoids under any transform) and planes as Embree user geometry, intersected in
// double precision. A plane's bounds are a box of half-size LeafTable::plane_extent around
// the origin (10^5 times the reach of the scene's geometry, camera, lights and receivers from
// the origin): beyond it the plane is not found.
#include <algorithm>
#include <cmath>
#include <limits>

#include "tracer/render/scene_geometry.h"

namespace rayset::tracer {

namespace {

bool skipped(const LeafTable& leaf, const QuadricPrim& prim, const RTCIntersectContext* context) {
    const auto* trace = reinterpret_cast<const TraceContext*>(context);
    return (leaf.tables->object_flags[prim.object] & trace->skip) != 0;
}

// First root of the ray with the primitive in (t_near, t_far); false if none.
bool quadric_hit(const QuadricPrim& prim, Vec3 o, Vec3 d, double t_near, double t_far, double& t) {
    if (!prim.sphere) {
        const double denom = dot(prim.normal, d);
        if (denom == 0) return false;
        t = (prim.distance - dot(prim.normal, o)) / denom;
        return t > t_near && t < t_far;
    }
    const Vec3 lo = prim.world_to_unit.point(o), ld = prim.world_to_unit.vector(d);
    const double a = dot(ld, ld), b = dot(lo, ld), c = dot(lo, lo) - 1;
    const double discriminant = b * b - a * c;
    if (discriminant < 0) return false;
    const double root = std::sqrt(discriminant);
    // Numerically stable pair of roots.
    const double q = b >= 0 ? -(b + root) : -(b - root);
    double t0 = q / a, t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_near && t0 < t_far) return t = t0, true;
    if (t1 > t_near && t1 < t_far) return t = t1, true;
    return false;
}

void quadric_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* leaf = static_cast<const LeafTable*>(args->geometryUserPtr);
    const QuadricPrim& prim = leaf->quadrics[args->primID];
    RTCBounds& b = *args->bounds_o;
    const float r = leaf->plane_extent;
    b.lower_x = b.lower_y = b.lower_z = -r;
    b.upper_x = b.upper_y = b.upper_z = r;
    if (prim.sphere) {
        const Matrix4 unit_to_world = prim.world_to_unit.inverse();
        b.lower_x = b.lower_y = b.lower_z = std::numeric_limits<float>::max();
        b.upper_x = b.upper_y = b.upper_z = -std::numeric_limits<float>::max();
        for (int i = 0; i < 8; ++i) {
            const Vec3 p =
                unit_to_world.point({i & 1 ? 1. : -1., i & 2 ? 1. : -1., i & 4 ? 1. : -1.});
            b.lower_x = std::min(b.lower_x, std::nextafter(float(p.x), -1e30f));
            b.lower_y = std::min(b.lower_y, std::nextafter(float(p.y), -1e30f));
            b.lower_z = std::min(b.lower_z, std::nextafter(float(p.z), -1e30f));
            b.upper_x = std::max(b.upper_x, std::nextafter(float(p.x), 1e30f));
            b.upper_y = std::max(b.upper_y, std::nextafter(float(p.y), 1e30f));
            b.upper_z = std::max(b.upper_z, std::nextafter(float(p.z), 1e30f));
        }
        return;
    }
    // An axis-aligned plane gets a thin box, so rays parallel to it skip the test.
    const Vec3 n = prim.normal;
    const float margin = 1e-4f * float(leaf->tables->extent);
    auto thin = [&](double component, float& lower, float& upper) {
        if (std::abs(component) < 1 - 1e-12) return;
        const float at = float(prim.distance / component);
        lower = at - margin - std::abs(at) * 1e-6f;
        upper = at + margin + std::abs(at) * 1e-6f;
    };
    thin(n.x, b.lower_x, b.upper_x);
    thin(n.y, b.lower_y, b.upper_y);
    thin(n.z, b.lower_z, b.upper_z);
}

void quadric_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto* leaf = static_cast<const LeafTable*>(args->geometryUserPtr);
    const QuadricPrim& prim = leaf->quadrics[args->primID];
    if (skipped(*leaf, prim, args->context)) return;
    auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);
    RTCRay& ray = rayhit->ray;
    const Vec3 o{ray.org_x, ray.org_y, ray.org_z}, d{ray.dir_x, ray.dir_y, ray.dir_z};
    double t = 0;
    if (!quadric_hit(prim, o, d, ray.tnear, ray.tfar, t)) return;
    ray.tfar = float(t);
    RTCHit& hit = rayhit->hit;
    hit.u = hit.v = 0;
    hit.Ng_x = hit.Ng_y = hit.Ng_z = 0;  // resolve_hit computes the normal in double
    hit.primID = args->primID;
    hit.geomID = args->geomID;
    hit.instID[0] = args->context->instID[0];
}

void quadric_occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto* leaf = static_cast<const LeafTable*>(args->geometryUserPtr);
    const QuadricPrim& prim = leaf->quadrics[args->primID];
    if (skipped(*leaf, prim, args->context)) return;
    auto* ray = reinterpret_cast<RTCRay*>(args->ray);
    const Vec3 o{ray->org_x, ray->org_y, ray->org_z}, d{ray->dir_x, ray->dir_y, ray->dir_z};
    double t = 0;
    if (quadric_hit(prim, o, d, ray->tnear, ray->tfar, t))
        ray->tfar = -std::numeric_limits<float>::infinity();
}

}  // namespace

void add_quadric_geometry(RTCDevice device, RTCScene scene, GeometryTables& tables,
                          LeafTable& leaf) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(leaf.quadrics.size()));
    rtcSetGeometryUserData(geometry, &leaf);
    rtcSetGeometryBoundsFunction(geometry, quadric_bounds, &leaf);
    rtcSetGeometryIntersectFunction(geometry, quadric_intersect);
    rtcSetGeometryOccludedFunction(geometry, quadric_occluded);
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    if (tables.leaf_of_geometry.size() <= id) {
        tables.leaf_of_geometry.resize(id + 1, nullptr);
        tables.instance_of_geometry.resize(id + 1, -1);
    }
    tables.leaf_of_geometry[id] = &leaf;
}

}  // namespace rayset::tracer
