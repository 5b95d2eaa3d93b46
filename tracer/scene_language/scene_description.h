// The scene as the parser hands it to the renderer: a plain description with every POV-Ray
// rule already applied (camera vectors resolved, transforms composed into one object-to-world
// matrix per instance, textures inherited through unions, lights in world coordinates).
//
// Frame: POV-Ray's own (left-handed, y up), coordinates as the file writes them. Lengths in
// the scene's unit (GlobalSettings::length_unit, mm by default). Colours are POV-Ray's
// numbers as written (linear; assumed_gamma is recorded, not applied).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "tracer/scene_language/transform.h"

namespace rayset::tracer {

struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;
    std::string str() const;  // "file:line:column"
};

struct Rgb {
    double red = 0, green = 0, blue = 0;
};

// POV-Ray's five-component colour: filter and transmit are the fractions of light passing
// through, filtered by the colour or not.
struct Colour {
    double red = 0, green = 0, blue = 0, filter = 0, transmit = 0;
    Rgb rgb() const { return {red, green, blue}; }
};

// Only uniform colour pigments are in the subset.
struct Pigment {
    Colour colour;  // POV-Ray's default pigment is black
};

// POV-Ray 3.7 finish keywords with POV-Ray's defaults.
struct Finish {
    Rgb ambient{0.1, 0.1, 0.1};
    Rgb emission{0, 0, 0};
    double diffuse = 0.6;
    double brilliance = 1.0;
    double specular = 0;
    double roughness = 0.05;
    double phong = 0;
    double phong_size = 40;
    double metallic = 0;
    Rgb reflection_min{0, 0, 0};  // `reflection X` sets both; `reflection { min, max }` each
    Rgb reflection_max{0, 0, 0};
    bool reflection_fresnel = false;
    double reflection_falloff = 1;
    bool conserve_energy = false;
};

struct Texture {
    Pigment pigment;
    Finish finish;
};

struct Interior {
    double ior = 1.0;
};

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
    bool textured = false;       // false: no texture anywhere up the tree (POV-Ray: black)
    Texture texture;
    bool has_interior = false;
    Interior interior;
    bool no_shadow = false, no_image = false, no_reflection = false, hollow = false;
    SourceLocation location;     // where the shape's keyword is
};

struct LightSource {
    Vec3 position;
    Rgb colour{1, 1, 1};
    bool spotlight = false;
    Vec3 point_at{0, 0, 1};
    double radius = 30, falloff = 45, tightness = 0;  // degrees, POV-Ray's defaults
    bool area_light = false;
    Vec3 axis1, axis2;          // full edge vectors of the area light
    int size1 = 1, size2 = 1;   // lights along each axis
    int adaptive = 0;
    bool jitter = false, circular = false, orient = false;
    double fade_distance = 0, fade_power = 0;  // 0: no fading
    bool shadowless = false;
    SourceLocation location;
};

// Perspective camera, resolved as POV-Ray 3.7 does (angle, then look_at, then transforms):
// the ray through image coordinates (s, t) in [0, 1]^2, s to the right and t downward, has the
// direction `direction + (s - 0.5) * right + (0.5 - t) * up` from `location`. The lengths of
// right and up set the aspect ratio and field of view; a right vector toward -x mirrors the
// image as in POV-Ray.
struct Camera {
    Vec3 location{0, 0, 0};
    Vec3 direction{0, 0, 1};
    Vec3 up{0, 1, 0};
    Vec3 right{1.33, 0, 0};
    Vec3 sky{0, 1, 0};
    double angle = 0;  // horizontal field of view in degrees when given, else 0
};

// Extension: an illuminance map on a parallelogram.
struct IlluminanceReceiver {
    std::string name;  // from `name "..."`, else "receiver<N>"
    Vec3 corner, edge1, edge2;  // world coordinates; cells run along edge1 (nx) and edge2 (ny)
    int nx = 1, ny = 1;
    SourceLocation location;
};

// Extension: a measured ray file placed in the scene.
struct RaySource {
    std::string path;         // absolute, canonical
    Matrix4 source_to_world;  // ray-file coordinates to scene coordinates
    SourceLocation location;
};

struct GlobalSettings {
    double assumed_gamma = 1.0;
    Rgb ambient_light{1, 1, 1};
    int max_trace_level = 5;
    // POV-Ray's radiosity block, recorded key by key (a path tracer computes indirect light
    // itself; the renderer decides what, if anything, to take from it).
    bool radiosity = false;
    std::map<std::string, std::vector<double>> radiosity_settings;
    // Our keys.
    std::string length_unit = "mm";  // mm, cm, m, in, ft
    double millimetres_per_unit = 1.0;
    std::string integrator = "path";  // "path" or "bidirectional"
    bool spectral = false;            // bidirectional: spectral transport (`spectral on`)
    int passes = 0;                   // 0: the renderer's default
    double time_limit = 0;            // seconds; 0: no limit
};

struct SceneDescription {
    double version = 3.7;  // from #version, last seen
    bool has_camera = false;
    Camera camera;
    std::vector<ObjectInstance> objects;
    std::vector<LightSource> lights;
    std::vector<IlluminanceReceiver> receivers;
    std::vector<RaySource> ray_sources;
    GlobalSettings global;
    Colour background;  // black unless `background { ... }`
    std::vector<std::string> files;  // every file read, main file first
};

}  // namespace rayset::tracer
