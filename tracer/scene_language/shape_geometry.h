// Exact geometry of the simple shapes in their own coordinates, the crossings of a line with
// their surface and whether a point is inside, and of CSG solids made of them (SolidTree). The
// language's trace and inside (object_geometry.cpp) and the renderer's analytic shapes and CSG
// use them.
//
// Covered: sphere, box, cylinder, cone, torus, plane, disc, triangle, mesh (inside with an
// inside_vector; hits of flat triangles), quadric, polynomial (poly, cubic, quartic: the
// polynomial along the line, its real roots bisected within Cauchy's bound), superellipsoid,
// isosurface and blob (the implicit function sampled in 256 steps across the box, container or
// bounds, sign changes bisected; an isosurface capped by its container), linear prism, lathe
// (its profile's pieces as POV-Ray draws them, each turned: a sextic along the line), sor (r^2 a
// cubic in the height: a cubic along the line), sphere_sweep of each spline kind (the union of
// its spheres, segment by segment: where along the line the spheres' entries and exits are
// least and greatest over the segment's parameter, from a polynomial's roots; normals from the
// sphere that gives the hit), polygon (even-odd over its loops),
// julia_fractal (the set as its orbits' escape within max_iteration steps says, sampled in 256
// steps across its ball of radius 2 and bisected; slices w = const only) and height_field of an
// image (its triangles, cell by cell along the line: height_field_geometry.cpp).
#pragma once

#include <vector>

#include "tracer/scene_language/shapes.h"

namespace rayset::tracer {

struct ShapeHit {
    double t;       // along the line o + t d, in units of |d|
    Vec3 normal;    // outward, not normalised
    int part = -1;  // SolidTree::hits: the shape node it lies on
};

// Where the line o + t d crosses the triangle a, b, c: t, and the hit's weights u of b and v of
// c (a's is 1 - u - v); false when it does not.
bool triangle_crossing(Vec3 a, Vec3 b, Vec3 c, Vec3 o, Vec3 d, double& t, double& u, double& v);
// Makes what the crossings of every ray need once, when the shape is read: a lathe's and a
// sor's profile pieces, a sphere_sweep's segments, a polygon's plane. The functions below take
// shapes so prepared (the parser prepares every shape it reads).
void prepare_shape(Shape& shape);
// Every crossing of the line o + t d (any t, unsorted) with the shape's surface; false when the
// shape is not covered here.
bool shape_hits(const Shape& shape, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits);
// The box around a blob's positive components (its own coordinates); false when it has none.
bool blob_bounds(const BlobShape& blob, Vec3& lower, Vec3& upper);
// The box around a lathe: its profile's reach and heights.
void lathe_bounds(const LatheShape& lathe, Vec3& lower, Vec3& upper);
// Whether a julia_fractal is cut by a hyperplane w = const (the one slice covered here).
bool julia_default_slice(const JuliaFractalShape& julia);
// The box around a surface of revolution.
void sor_bounds(const SorShape& sor, Vec3& lower, Vec3& upper);
// The box around a sphere_sweep: per axis the reach of each segment's spheres.
void sphere_sweep_bounds(const SphereSweepShape& sweep, Vec3& lower, Vec3& upper);
// A height field's lowest and highest sample, and (shape_hits and shape_inside of a field with
// its grid) its crossings and inside.
void height_field_range(const HeightGrid& grid, double& lowest, double& highest);
void height_field_hits(const HeightFieldShape& field, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits);
bool height_field_inside(const HeightFieldShape& field, Vec3 p);
// Whether `p` is inside the shape (POV-Ray's inside: a plane's or disc's side against their
// normal, a mesh by the parity of crossings along its inside_vector); false when not covered.
bool shape_inside(const Shape& shape, Vec3 p, bool& inside);

// A solid as CSG makes it from shapes: union, merge, intersection and difference (the second
// and later children subtracted from the first), inverse and clipped_by, every node in one
// frame (world coordinates for the renderer; a parse-time object's parent's coordinates).
// Nodes are added parent first, so the root is node 0; a shape keeps a pointer to the Shape.
class SolidTree {
public:
    enum class Kind { shape, union_of, merge, intersection, difference };

    // A shape seen through `frame_to_local` (the inverse of its transform into the frame).
    int add_shape(const Shape& shape, const Matrix4& frame_to_local, bool inverse);
    int add_csg(CsgShape::Operation operation, bool inverse);
    void add_child(int parent, int child) { nodes_[size_t(parent)].children.push_back(child); }
    // `node` is cut to the inside of the solid rooted at `clip` (clipped_by).
    void add_clip(int node, int clip) { nodes_[size_t(node)].clips.push_back(clip); }

    // Every crossing of the line o + t d with the solid's surface as CSG keeps it (unsorted),
    // normals outward in the frame, not normalised; false when a shape is not covered by
    // shape_hits.
    bool hits(Vec3 o, Vec3 d, std::vector<ShapeHit>& out) const { return hits_of(0, o, d, out); }
    // Whether `p` is inside the solid; false when a shape is not covered by shape_inside.
    bool inside(Vec3 p, bool& in) const { return inside_of(0, p, in); }

private:
    struct Node {
        Kind kind = Kind::shape;
        const Shape* shape = nullptr;
        Matrix4 frame_to_local;
        bool inverse = false;
        std::vector<int> children, clips;
    };
    bool hits_of(int node, Vec3 o, Vec3 d, std::vector<ShapeHit>& out) const;
    bool inside_of(int node, Vec3 p, bool& in) const;
    // Whether a hit of child `from` at p is on the surface of the CSG `node`.
    bool keeps(const Node& node, size_t from, Vec3 p, bool& keep) const;
    std::vector<Node> nodes_;
};

}  // namespace rayset::tracer
