// The objects of a scene as the renderer receives them: one instance per shape, in object
// coordinates with its object-to-world transform and its appearance. Plain data; the grammar
// that fills it is grammar_objects.cpp.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "tracer/scene_language/appearance.h"
#include "tracer/scene_language/source_location.h"

namespace rayset::tracer {

struct SphereShape {
    Vec3 centre;
    double radius = 1;
};
struct BoxShape {
    Vec3 minimum, maximum;  // corners sorted per axis, as POV-Ray does
};
// Points p with dot(normal, p) = distance; normal of unit length (POV-Ray normalises it and
// keeps the distance as given). Inside is the side the normal points away from.
struct PlaneShape {
    Vec3 normal{0, 1, 0};
    double distance = 0;
};
struct TriangleShape {
    Vec3 a, b, c;
};
struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> faces;
    std::vector<Vec3> normals;                      // mesh2 normal_vectors, may be empty
    std::vector<std::array<int, 3>> normal_faces;   // per face; empty: use `faces`
};
// One mesh statement shared by every instance that `object { ID }` makes of it: instances
// of the same mesh hold the same pointer, which is how the renderer finds instancing.
struct MeshShape {
    std::shared_ptr<const TriangleMesh> mesh;
};
// Extension `mesh_file { "file.obj" }`: path resolved and checked to exist; loaded later.
struct MeshFileShape {
    std::string path;    // absolute, canonical
    std::string format;  // "obj" or "ply", from the extension
};
using Shape = std::variant<SphereShape, BoxShape, PlaneShape, TriangleShape, MeshShape, MeshFileShape>;

struct ObjectInstance {
    Shape shape;                 // in object coordinates
    Matrix4 object_to_world;     // every transform of the object and its enclosing unions
    ObjectAppearance appearance;  // its own, else inherited from its unions
    bool no_shadow = false, no_image = false, no_reflection = false, hollow = false;
    SourceLocation location;     // where the shape's keyword is
};

}  // namespace rayset::tracer
