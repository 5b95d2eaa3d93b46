// Whether a scene's surfaces may reach into a box (scene_geometry.h): conservative, exact enough
// for what surrounds a light source in a room. Triangles count where their box overlaps the box
// and their plane passes between its corners; planes where they pass between its corners;
// other primitives by their world bounds; unbounded solids always.
#include <algorithm>

#include "core/bounds.h"
#include "tracer/render/scene_geometry.h"

namespace rayset::tracer {

namespace {

// Whether the plane dot(normal, p) = offset passes between the box's corners (or touches).
bool straddles(const Bounds3& box, Vec3 normal, double offset) {
    bool below = false, above = false;
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner{i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                          i & 4 ? box.hi.z : box.lo.z};
        const double side = dot(normal, corner) - offset;
        below |= side <= 0, above |= side >= 0;
    }
    return below && above;
}

bool may_meet_triangle(const Bounds3& box, Vec3 a, Vec3 b, Vec3 c) {
    Bounds3 triangle;
    triangle.add(a), triangle.add(b), triangle.add(c);
    const Vec3 normal = cross(b - a, c - a);
    return box.overlaps(triangle) && straddles(box, normal, dot(normal, a));
}

bool user_prims_may_meet(const LeafTable& leaf, const Bounds3& box) {
    for (const UserPrim& prim : leaf.user_prims) {
        switch (prim.kind) {
            case UserPrim::Kind::plane:
                if (straddles(box, prim.normal, prim.distance)) return true;
                break;
            case UserPrim::Kind::solid:
                if (prim.unbounded || box.overlaps({prim.lower, prim.upper})) return true;
                break;
            case UserPrim::Kind::sphere:
            case UserPrim::Kind::shape:
                if (box.overlaps({prim.lower, prim.upper})) return true;
                break;
        }
    }
    return false;
}

// The triangles as Embree holds them (three floats a vertex, three indices a triangle).
bool triangles_may_meet(RTCGeometry geometry, size_t count, const Bounds3& box) {
    const auto* vertex =
        static_cast<const float*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, 0));
    const auto* index =
        static_cast<const unsigned*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_INDEX, 0));
    auto at = [&](unsigned i) { return Vec3{vertex[3 * i], vertex[3 * i + 1], vertex[3 * i + 2]}; };
    for (size_t k = 0; k < count; ++k)
        if (may_meet_triangle(box, at(index[3 * k]), at(index[3 * k + 1]), at(index[3 * k + 2])))
            return true;
    return false;
}

bool instance_may_meet(const InstanceRecord& instance, const Bounds3& box) {
    const TriangleMesh& mesh = *instance.prototype->mesh;
    const Matrix4& m = instance.object_to_world;
    for (const auto& f : mesh.faces)
        if (may_meet_triangle(box, m.point(mesh.vertices[size_t(f[0])]),
                              m.point(mesh.vertices[size_t(f[1])]),
                              m.point(mesh.vertices[size_t(f[2])])))
            return true;
    return false;
}

}  // namespace

bool surfaces_may_reach(const GeometryTables& tables, RTCScene scene, const Bounds3& box) {
    for (size_t id = 0; id < tables.leaf_of_geometry.size(); ++id) {
        const LeafTable* leaf = tables.leaf_of_geometry[id];
        const int instance = tables.instance_of_geometry[id];
        if (instance >= 0) {
            if (instance_may_meet(tables.instances[size_t(instance)], box)) return true;
        } else if (!leaf) {
            continue;  // an identifier Embree did not give out
        } else if (!leaf->user_prims.empty()) {
            if (user_prims_may_meet(*leaf, box)) return true;
        } else if (triangles_may_meet(rtcGetGeometry(scene, unsigned(id)), leaf->prim_normal.size(),
                                      box)) {
            return true;
        }
    }
    return false;
}

}  // namespace rayset::tracer
