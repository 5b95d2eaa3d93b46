// Internal to render_scene.cpp and scene_geometry.cpp: what the renderer needs to turn an
// Embree hit back into an object, a point and normals, and to skip objects by POV-Ray's
// no_shadow / no_image / no_reflection modifiers.
#pragma once

#include <memory>
#include <vector>

#include <embree3/rtcore.h>

#include "tracer/render/parametric_mesh.h"
#include "tracer/render/render_scene.h"
#include "tracer/scene_language/shape_geometry.h"

namespace rayset::tracer {

enum ObjectFlag : uint8_t { kNoShadow = 1, kNoImage = 2, kNoReflection = 4 };

// Embree's context extended with the flags the ray skips (Embree hands the pointer back to
// filter and user-geometry callbacks).
struct TraceContext {
    RTCIntersectContext embree;
    uint8_t skip = 0;
};

// A primitive intersected by the renderer's own code (user_geometry.cpp), in double precision.
struct UserPrim {
    enum class Kind : uint8_t {
        sphere,  // world_to_local takes it to the unit sphere at the origin
        plane,   // dot(normal, p) = distance, world
        shape,   // a cylinder, cone, torus or disc through shape_geometry.h, in its own frame
        solid,   // CSG, clipped_by or inverse: a SolidTree in world coordinates (solids.h)
    } kind = Kind::sphere;
    int object = -1;
    Matrix4 world_to_local;  // sphere, shape
    Vec3 normal;             // plane
    double distance = 0;
    const Shape* shape = nullptr;      // shape: the description's, in object coordinates
    const SolidTree* solid = nullptr;  // solid
    const SolidTree* bound = nullptr;  // solid with bounded_by: rays that miss it skip the solid
    bool unbounded = false;            // solid: bounds as a plane's
    Vec3 lower, upper;                 // sphere, shape, bounded solid: world bounds
};

struct GeometryTables;

// One Embree leaf geometry: world triangles, a mesh prototype or the user primitives.
struct LeafTable {
    const GeometryTables* tables = nullptr;
    std::vector<int> prim_object;  // top-level triangles: object of each primitive
    std::vector<Vec3>
        prim_normal;  // triangles: unit normal (world, or object space for prototypes)
    std::shared_ptr<const TriangleMesh> mesh;  // prototypes: for interpolated normals
    std::vector<UserPrim> user_prims;
    float plane_extent = 1e6f;  // half-size of the box a plane's bounds span
    // A parametric's triangles (one geometry for each; primitive k is triangle k of the mesh):
    // the surface for shading normals, the container for its clipping.
    const ParametricShape* parametric = nullptr;
    std::shared_ptr<const ParametricMesh> parametric_mesh;
    int parametric_object = -1;
    Matrix4 world_to_object;
};

struct InstanceRecord {
    int object = -1;
    Matrix4 object_to_world, world_to_object;
    const LeafTable* prototype = nullptr;
};

struct GeometryTables {
    std::vector<std::unique_ptr<SolidTree>> solids;  // ownership
    // Solids whose parts may have materials of their own: object, and its parts by tree node
    // (Solid::parts).
    std::vector<std::pair<int, std::vector<const ObjectInstance*>>> solid_parts;
    std::vector<uint8_t> object_flags;               // per object
    std::vector<std::unique_ptr<LeafTable>> leaves;  // ownership
    std::vector<RTCScene> prototypes;                // released with the tables
    std::vector<const LeafTable*> leaf_of_geometry;  // top-level geomID -> leaf (or null)
    std::vector<int> instance_of_geometry;           // top-level geomID -> instances index (or -1)
    std::vector<InstanceRecord> instances;
    double extent = 1;  // size of the finite geometry's box
};

// Fills `scene` with the description's objects; returns the tables hits are resolved with.
std::unique_ptr<GeometryTables> build_geometry(RTCDevice device, RTCScene scene,
                                               const SceneDescription& description);
void add_user_geometry(RTCDevice device, RTCScene scene, GeometryTables& tables, LeafTable& leaf);
// Whether some surface of the scene may lie within `box`: false only when none does
// (box_clearance.cpp says how closely each kind of surface is tested).
bool surfaces_may_reach(const GeometryTables& tables, RTCScene scene, const Bounds3& box);
// Fills the hit's object, normal and shading normal from an Embree hit (point and t set).
void resolve_hit(const GeometryTables& tables, const RTCHit& embree_hit, SurfaceHit& hit);

}  // namespace rayset::tracer
