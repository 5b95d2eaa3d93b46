// Embree user geometry, intersected in double precision: spheres (ellipsoids under any
// transform), planes, the shapes that shape_geometry.h intersects exactly (cylinder, cone,
// torus, disc) in their own coordinates, and solids (CSG, clipped_by, inverse; solids.h) in
// world coordinates. An unbounded solid's bounds are a plane's. A plane's bounds are a box of
// half-size LeafTable::plane_extent around the origin (10^5 times the reach of the scene's
// geometry, camera, lights and receivers from the origin): beyond it the plane is not found.
#include <algorithm>
#include <cmath>
#include <limits>

#include "tracer/render/scene_geometry.h"
#include "tracer/scene_language/shape_geometry.h"

namespace rayset::tracer {

namespace {

bool skipped(const LeafTable& leaf, const UserPrim& prim, const RTCIntersectContext* context) {
    const auto* trace = reinterpret_cast<const TraceContext*>(context);
    return (leaf.tables->object_flags[prim.object] & trace->skip) != 0;
}

bool plane_hit(const UserPrim& prim, Vec3 o, Vec3 d, double t_near, double t_far, double& t) {
    const double denom = dot(prim.normal, d);
    if (denom == 0) return false;
    t = (prim.distance - dot(prim.normal, o)) / denom;
    return t > t_near && t < t_far;
}

bool sphere_hit(const UserPrim& prim, Vec3 o, Vec3 d, double t_near, double t_far, double& t) {
    const Vec3 lo = prim.world_to_local.point(o), ld = prim.world_to_local.vector(d);
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

// The nearest crossing in (t_near, t_far), its normal in world coordinates (not normalised).
// The line is taken into the shape's coordinates by an affine map, which keeps t.
bool shape_hit(const UserPrim& prim, Vec3 o, Vec3 d, double t_near, double t_far, double& t,
               Vec3& normal) {
    thread_local std::vector<ShapeHit> hits;
    hits.clear();
    shape_hits(*prim.shape, prim.world_to_local.point(o), prim.world_to_local.vector(d), hits);
    const ShapeHit* nearest = nullptr;
    for (const ShapeHit& h : hits)
        if (h.t > t_near && h.t < t_far && (!nearest || h.t < nearest->t)) nearest = &h;
    if (!nearest) return false;
    t = nearest->t;
    // Normals go back through the transpose of world -> local (the inverse transpose of
    // local -> world).
    const Matrix4& m = prim.world_to_local;
    const Vec3 n = nearest->normal;
    normal = {m(0, 0) * n.x + m(1, 0) * n.y + m(2, 0) * n.z,
              m(0, 1) * n.x + m(1, 1) * n.y + m(2, 1) * n.z,
              m(0, 2) * n.x + m(1, 2) * n.y + m(2, 2) * n.z};
    return true;
}

// POV-Ray's bounded_by: a ray is tested against the object only if it starts inside the
// bounding objects or meets them ahead of it.
bool meets_bound(const SolidTree& bound, Vec3 o, Vec3 d) {
    bool inside = false;
    if (bound.inside(o, inside) && inside) return true;
    thread_local std::vector<ShapeHit> hits;
    hits.clear();
    bound.hits(o, d, hits);
    return std::any_of(hits.begin(), hits.end(), [](const ShapeHit& h) { return h.t > 0; });
}

bool solid_hit(const UserPrim& prim, Vec3 o, Vec3 d, double t_near, double t_far, double& t,
               Vec3& normal, int& part) {
    if (prim.bound && !meets_bound(*prim.bound, o, d)) return false;
    thread_local std::vector<ShapeHit> hits;
    hits.clear();
    prim.solid->hits(o, d, hits);
    const ShapeHit* nearest = nullptr;
    for (const ShapeHit& h : hits)
        if (h.t > t_near && h.t < t_far && (!nearest || h.t < nearest->t)) nearest = &h;
    if (!nearest) return false;
    t = nearest->t, normal = nearest->normal, part = nearest->part;
    return true;
}

bool user_hit(const UserPrim& prim, Vec3 o, Vec3 d, double t_near, double t_far, double& t,
              Vec3& normal, int& part) {
    switch (prim.kind) {
        case UserPrim::Kind::plane: return plane_hit(prim, o, d, t_near, t_far, t);
        case UserPrim::Kind::sphere: return sphere_hit(prim, o, d, t_near, t_far, t);
        case UserPrim::Kind::shape: return shape_hit(prim, o, d, t_near, t_far, t, normal);
        case UserPrim::Kind::solid: return solid_hit(prim, o, d, t_near, t_far, t, normal, part);
    }
    return false;
}

void user_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* leaf = static_cast<const LeafTable*>(args->geometryUserPtr);
    const UserPrim& prim = leaf->user_prims[args->primID];
    RTCBounds& b = *args->bounds_o;
    if (prim.kind != UserPrim::Kind::plane && !prim.unbounded) {
        b.lower_x = std::nextafter(float(prim.lower.x), -1e30f);
        b.lower_y = std::nextafter(float(prim.lower.y), -1e30f);
        b.lower_z = std::nextafter(float(prim.lower.z), -1e30f);
        b.upper_x = std::nextafter(float(prim.upper.x), 1e30f);
        b.upper_y = std::nextafter(float(prim.upper.y), 1e30f);
        b.upper_z = std::nextafter(float(prim.upper.z), 1e30f);
        return;
    }
    const float r = leaf->plane_extent;
    b.lower_x = b.lower_y = b.lower_z = -r;
    b.upper_x = b.upper_y = b.upper_z = r;
    if (prim.kind != UserPrim::Kind::plane) return;
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

void user_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto* leaf = static_cast<const LeafTable*>(args->geometryUserPtr);
    const UserPrim& prim = leaf->user_prims[args->primID];
    if (skipped(*leaf, prim, args->context)) return;
    auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);
    RTCRay& ray = rayhit->ray;
    const Vec3 o{ray.org_x, ray.org_y, ray.org_z}, d{ray.dir_x, ray.dir_y, ray.dir_z};
    double t = 0;
    Vec3 normal{};  // spheres and planes: resolve_hit computes it in double
    int part = 0;   // solids: the tree node hit, kept in u (exact in float below 2^24)
    if (!user_hit(prim, o, d, ray.tnear, ray.tfar, t, normal, part)) return;
    ray.tfar = float(t);
    RTCHit& hit = rayhit->hit;
    hit.u = float(part), hit.v = 0;
    hit.Ng_x = float(normal.x), hit.Ng_y = float(normal.y), hit.Ng_z = float(normal.z);
    hit.primID = args->primID;
    hit.geomID = args->geomID;
    hit.instID[0] = args->context->instID[0];
}

void user_occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto* leaf = static_cast<const LeafTable*>(args->geometryUserPtr);
    const UserPrim& prim = leaf->user_prims[args->primID];
    if (skipped(*leaf, prim, args->context)) return;
    auto* ray = reinterpret_cast<RTCRay*>(args->ray);
    const Vec3 o{ray->org_x, ray->org_y, ray->org_z}, d{ray->dir_x, ray->dir_y, ray->dir_z};
    double t = 0;
    Vec3 normal;
    int part = 0;
    if (user_hit(prim, o, d, ray->tnear, ray->tfar, t, normal, part))
        ray->tfar = -std::numeric_limits<float>::infinity();
}

}  // namespace

void add_user_geometry(RTCDevice device, RTCScene scene, GeometryTables& tables, LeafTable& leaf) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(leaf.user_prims.size()));
    rtcSetGeometryUserData(geometry, &leaf);
    rtcSetGeometryBoundsFunction(geometry, user_bounds, &leaf);
    rtcSetGeometryIntersectFunction(geometry, user_intersect);
    rtcSetGeometryOccludedFunction(geometry, user_occluded);
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
