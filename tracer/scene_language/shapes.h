// The objects of a scene as the renderer receives them: one instance per shape, in object
// coordinates with its object-to-world transform and its appearance. Every POV-Ray 3.7 shape
// has its description here, with POV-Ray's defaults; CSG other than a plain union keeps its
// children as a tree (CsgShape). Plain data; the grammar that fills it is
// grammar_objects.cpp and the grammar_shapes*.cpp files.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "tracer/scene_language/appearance.h"
#include "tracer/scene_language/source_location.h"
#include "tracer/scene_language/values.h"

namespace rayset::tracer {

struct TextOutline;  // text_outline.h
// What the crossings of every ray with a shape need, made once when the shape is read
// (prepare_shape, shape_geometry.h).
struct LatheProfile;
struct SorProfile;
struct SweepSegments;
struct PolygonPlane;

// A 2-D point: lathe and sor (radius x, height y), prism (x, z written as x, y), uv vectors.
struct Vec2 {
    double x = 0, y = 0;
};

// ---------------------------------------------------------------- finite solids

struct SphereShape {
    Vec3 centre;
    double radius = 1;  // as written; POV-Ray accepts 0 and negative radii
};
struct BoxShape {
    Vec3 minimum, maximum;  // corners sorted per axis, as POV-Ray does
};
// Closed by flat caps unless `open`.
struct CylinderShape {
    Vec3 base, cap;  // centres of the two ends (never equal)
    double radius = 1;
    bool open = false;
};
struct ConeShape {
    Vec3 base, cap;  // centres of the two ends (never equal)
    double base_radius = 1, cap_radius = 0;
    bool open = false;
};
// Centred at the origin in the x-z plane, the y axis through its hole.
struct TorusShape {
    double major_radius = 1;    // centre of the hole to the middle of the rim
    double minor_radius = 0.5;  // radius of the rim's cross-section
    bool sturm = false;
};
// A bottom sphere at the origin and a top sphere centred on its top, joined smoothly.
struct OvusShape {
    double bottom_radius = 1, top_radius = 0.5;
    bool sturm = false;
};
// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1, inside the box -1..1.
struct SuperellipsoidShape {
    double east_west = 1;    // e
    double north_south = 1;  // n
};

// One component of a blob: its field is strength * (1 - (d / radius)^2)^2 within `radius` of
// its centre (sphere) or of its axis segment (cylinder, hemispherical ends).
struct BlobComponent {
    enum class Kind { sphere, cylinder } kind = Kind::sphere;
    Vec3 centre;  // sphere: its centre; cylinder: the first end
    Vec3 end;     // cylinder: the second end
    double radius = 1;
    double strength = 1;
    Matrix4 transform;            // the component's own transforms, into the blob's coordinates
    ObjectAppearance appearance;  // its own texture, pigment, normal, finish (no interior)
    SourceLocation location;
};
struct BlobShape {
    std::vector<BlobComponent> components;
    double threshold = 1;  // the field value of the surface
    bool sturm = false;
    bool hierarchy = true;
};

// A height field's samples: column i at x = i / (columns - 1), row j at z = j / (rows - 1) (the
// image's bottom row at z = 0), each cell two triangles split along its diagonal from
// (i, j + 1) to (i + 1, j), as POV-Ray splits them (its trace of a field of one raised corner).
struct HeightGrid {
    int columns = 0, rows = 0;
    std::vector<double> heights;  // row by row from z = 0
    double at(int column, int row) const {
        return heights[size_t(row) * size_t(columns) + size_t(column)];
    }
};

// The unit square x, z in [0, 1] with heights y in [0, 1] from an image or a function.
struct HeightFieldShape {
    // From an image: its type keyword (gif, tga, pot, png, pgm, ppm, jpeg, tiff, sys, exr, hdr,
    // iff, bmp), empty when not written (POV-Ray then reads it as its output file type, PNG
    // unless set otherwise), and its path, absolute and canonical. Not read while parsing.
    std::string image_type;
    std::string image_path;
    double image_gamma = 0;      // `gamma G` after the file name; 0: not given (linear data)
    bool image_srgb = false;     // `gamma srgb`
    bool premultiplied = false;  // `premultiplied [BOOL]`
    // From `function W, H { ... }`: f(x, y) sampled on a W x H grid over [0, 1]^2.
    FunctionRef function;
    int function_width = 0, function_height = 0;
    // The heights, read from the image while parsing (POV-Ray's rules: heights_from_image).
    std::shared_ptr<const HeightGrid> grid;
    bool smooth = false;     // interpolated normals
    double water_level = 0;  // heights below it are left out
    bool hierarchy = true;
};

// Where an isosurface or parametric is looked for: a box (default -1..1) or a sphere.
struct ContainedBy {
    enum class Kind { box, sphere } kind = Kind::box;
    Vec3 minimum{-1, -1, -1}, maximum{1, 1, 1};  // box, corners sorted
    Vec3 centre;                                 // sphere
    double radius = 1;
};

// The surface f(x, y, z) = threshold.
struct IsosurfaceShape {
    FunctionRef function;
    ContainedBy contained_by;
    double threshold = 0;
    double accuracy = 0.001;
    double max_gradient = 1.1;
    bool evaluate = false;                    // dynamic max_gradient with the three values below
    std::array<double, 3> evaluate_values{};  // P0 (minimum), P1 (over-estimate), P2 (attenuation)
    bool open = false;                        // no surface where the container cuts it
    int max_trace = 1;                        // intersections found per ray
    bool all_intersections = false;           // every intersection (max_trace unlimited)
};

// The surface <fx(u, v), fy(u, v), fz(u, v)> over the uv rectangle.
struct ParametricShape {
    std::array<FunctionRef, 3> functions;
    Vec2 uv_minimum, uv_maximum;  // <u1, v1>, <u2, v2>
    ContainedBy contained_by;
    double max_gradient = 1.1;
    double accuracy = 0.001;
    int precompute_depth = 0;               // 0: no precompute
    std::array<bool, 3> precompute_axes{};  // x, y, z ranges precomputed
};

// A 3-D slice of a 4-D julia set: h <- f(h) + parameter.
struct JuliaFractalShape {
    std::array<double, 4> parameter{};
    enum class Algebra { quaternion, hypercomplex } algebra = Algebra::quaternion;
    // The orbit's function, by POV-Ray's keyword (quaternion: only sqr and cube).
    // clang-format off
    enum class Function { sqr, cube, exp, reciprocal, sin, asin, sinh, asinh, cos, acos, cosh,
                          acosh, tan, atan, tanh, atanh, ln, pwr };
    // clang-format on
    Function function = Function::sqr;
    Vec2 power;  // pwr(x, y): the complex exponent x + iy
    int max_iteration = 20;
    double precision = 20;                           // values below 1 act as 1
    std::array<double, 4> slice_normal{0, 0, 0, 1};  // its fourth term is never 0
    double slice_distance = 0;
};

enum class SplineKind { linear, quadratic, cubic, bezier };

// A 2-D curve (radius x, height y) turned about the y axis.
struct LatheShape {
    SplineKind spline = SplineKind::linear;
    std::vector<Vec2> points;  // as many as the spline kind needs (checked)
    bool sturm = false;
    std::shared_ptr<const LatheProfile> profile;  // prepare_shape
};
// Closed 2-D curves in the x-z plane (points hold x, z) swept along y from height1 to height2
// (conic: scaled down toward the origin, height1 and height2 then scale the curve).
struct PrismShape {
    SplineKind spline = SplineKind::linear;
    bool conic_sweep = false;
    double height1 = 0, height2 = 1;
    std::vector<Vec2> points;  // a linear spline's last sub-prism closed, as POV-Ray does
    bool open = false;
    bool sturm = false;
};
// Radius as a function of height (x = radius, y = height), turned about the y axis; the first
// and last points only set the slopes.
struct SorShape {
    std::vector<Vec2> points;
    bool open = false;
    bool sturm = false;
    std::shared_ptr<const SorProfile> profile;  // prepare_shape
};
struct SphereSweepShape {
    enum class Kind { linear_spline, b_spline, cubic_spline } kind = Kind::linear_spline;
    struct Sphere {
        Vec3 centre;
        double radius = 1;
    };
    std::vector<Sphere> spheres;
    double tolerance = 1e-6;                        // depth tolerance of the intersection tests
    std::shared_ptr<const SweepSegments> segments;  // prepare_shape
};
// Extruded text: the baseline along x from the origin, thickness along +z.
struct TextShape {
    std::string font_path;   // ttf/ttc file, absolute and canonical; empty for a built-in font
    int internal_font = -1;  // `internal N`: POV-Ray's built-in font N (0..3; others act as 0)
    std::string text;
    double thickness = 1;
    Vec3 offset;                                 // extra spacing added after each character
    std::shared_ptr<const TextOutline> outline;  // of a ttf font (text_outline.h)
};

// ---------------------------------------------------------------- patches

// A Bezier patch of 4 x 4 control points (rows of four).
struct BicubicPatchShape {
    int type = 0;  // 0: control points kept; 1: pre-subdivided
    double flatness = 0;
    int u_steps = 0, v_steps = 0;
    std::vector<Vec3> points = std::vector<Vec3>(16);  // 4 x 4, on the heap: patches are rare
    // The uv coordinates of the corners points[0], [3], [15], [12] (uv_vectors).
    std::array<Vec2, 4> corner_uvs{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
};
// Points p with dot(normal, p - centre) = 0 and hole_radius <= |p - centre| <= radius.
struct DiscShape {
    Vec3 centre;
    Vec3 normal{0, 1, 0};  // normalised when not zero
    double radius = 1;
    double hole_radius = 0;
};
struct TriangleShape {
    Vec3 a, b, c;
};
struct SmoothTriangleShape {
    Vec3 a, b, c;
    Vec3 normal_a, normal_b, normal_c;  // as written, interpolated across the triangle
};
// Sub-polygons in one plane; each closes when its first point repeats, the last one is closed
// as POV-Ray does. Where an even number of them overlap there is a hole.
struct PolygonShape {
    std::vector<Vec3> points;
    std::shared_ptr<const PolygonPlane> plane;  // prepare_shape
};

struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> faces;
    std::vector<Vec3> normals;  // smooth triangles and mesh2 normal_vectors
    // Per face: its normals; empty when normals (if any) follow `faces`. A face of a mesh that
    // mixes flat and smooth triangles has {-1, -1, -1} (flat).
    std::vector<std::array<int, 3>> normal_faces;
    std::vector<Vec2> uvs;                     // uv_vectors
    std::vector<std::array<int, 3>> uv_faces;  // per face; empty when uvs follow `faces`
    // Per-triangle textures: `textures` holds them (texture_list of mesh2, the texture
    // identifiers of mesh); per face three indices into it (one repeated thrice for a single
    // texture, three for interpolation between the corners), or {-1, -1, -1} for the mesh's own.
    std::vector<TextureRef> textures;
    std::vector<std::array<int, 3>> face_textures;  // empty: no face has its own texture
    bool has_inside_vector = false;  // solid (for CSG and inside) along `inside_vector`
    Vec3 inside_vector;
};
// One mesh statement shared by every instance that `object { ID }` makes of it: instances
// of the same mesh hold the same pointer, which is how the renderer finds instancing.
struct MeshShape {
    std::shared_ptr<const TriangleMesh> mesh;
    bool hierarchy = true;
};
// Extension `mesh_file { "file.obj" }`: path resolved and checked to exist; loaded later.
struct MeshFileShape {
    std::string path;    // absolute, canonical
    std::string format;  // "obj" or "ply", from the extension
};

// ---------------------------------------------------------------- infinite solids

// Points p with dot(normal, p) = distance; normal of unit length (POV-Ray normalises it and
// keeps the distance as given). Inside is the side the normal points away from.
struct PlaneShape {
    Vec3 normal{0, 1, 0};
    double distance = 0;
};
// poly, cubic, quartic and polynomial: sum of coefficient * x^i y^j z^k = 0, the coefficients
// in POV-Ray's term order for the order (x^order first, the constant last), (order + 1)(order
// + 2)(order + 3) / 6 of them. Inside where the sum is negative.
struct PolynomialShape {
    int order = 2;  // 2..35 (cubic: 3, quartic: 4)
    std::vector<double> coefficients;
    bool sturm = false;
};
// A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0; inside where negative.
struct QuadricShape {
    Vec3 squares;         // A, B, C
    Vec3 mixed;           // D (xy), E (xz), F (yz)
    Vec3 linear;          // G, H, I
    double constant = 0;  // J
};

// ---------------------------------------------------------------- CSG

struct ObjectInstance;

// merge, intersection and difference, and a union that cannot be split into its children (it
// has clipped_by, bounded_by or inverse, or it is inside one of the others). The children
// are instances like the scene's, in world coordinates; difference subtracts the second and
// later children from the first.
struct CsgShape {
    enum class Operation {
        union_of,
        merge,
        intersection,
        difference
    } operation = Operation::union_of;
    std::vector<ObjectInstance> children;
    bool split_union = true;  // union: photons shot at each child (`split_union off`: at the whole)
};

using Shape =
    std::variant<SphereShape, BoxShape, PlaneShape, TriangleShape, MeshShape, MeshFileShape,
                 CylinderShape, ConeShape, TorusShape, OvusShape, SuperellipsoidShape, BlobShape,
                 HeightFieldShape, IsosurfaceShape, ParametricShape, JuliaFractalShape, LatheShape,
                 PrismShape, SorShape, SphereSweepShape, TextShape, BicubicPatchShape, DiscShape,
                 SmoothTriangleShape, PolygonShape, PolynomialShape, QuadricShape, CsgShape>;

// The keyword that writes a shape ("sphere", "union", "mesh2" is "mesh" ...), for messages.
const char* shape_keyword(const Shape& shape);

// ---------------------------------------------------------------- instances

// A light_group: its objects are lit by its lights (and its enclosing groups' lights), and by
// the scene's other lights only with global_lights; its lights light nothing else.
struct LightGroup {
    std::shared_ptr<const LightGroup> parent;  // the enclosing group, null at the top
    bool global_lights = false;
    SourceLocation location;
};

// An object's photons { } block: how POV-Ray's photon mapping treats it.
struct ObjectPhotons {
    bool target = false;            // photons are shot at it
    double spacing_multiplier = 1;  // `target S`: photon spacing times S
    bool refraction = false, reflection = false;
    bool collect = true;        // photons are stored on it
    bool pass_through = false;  // photons pass unaffected (set by no_shadow too)
};

struct ObjectInstance {
    Shape shape;                  // in object coordinates
    Matrix4 object_to_world;      // every transform of the object and its enclosing objects
    ObjectAppearance appearance;  // its own, else inherited from its enclosing CSG
    // Inherited from enclosing CSG (set there, set here).
    bool no_shadow = false, no_image = false, no_reflection = false, no_radiosity = false;
    bool double_illuminate = false;
    bool hollow = false;      // its own `hollow [on|off]`, else its enclosing CSG's, else off
    bool inverse = false;     // inside and outside swapped (its own only)
    bool uv_mapping = false;  // textures mapped by the surface's uv coordinates
    bool cutaway_textures =
        false;  // intersection, difference: cut faces keep the cutters' textures
    ObjectPhotons photons;
    double radiosity_importance = 1;  // radiosity { importance }: its own, else its CSG's, else 1
    // Cut to the inside of all of these (clipped_by), and declared to lie inside all of these
    // (bounded_by); world coordinates, no textures.
    std::vector<ObjectInstance> clipped_by, bounded_by;
    std::shared_ptr<const LightGroup> light_group;  // null: lit by the scene's lights
    int looks_like_of = -1;   // looks_like object of this light (index into the lights), or -1
    SourceLocation location;  // where the shape's keyword is
};

}  // namespace rayset::tracer
