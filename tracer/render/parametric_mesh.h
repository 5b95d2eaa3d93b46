// A parametric surface as the renderer draws it: triangles over a grid in (u, v), refined until
// they follow the surface within kParametricTolerance of its size, clipped by its container at
// the hit (scene_geometry.cpp). POV-Ray 3.7's rules, read back from its renders and trace():
// the surface is (fx, fy, fz)(u, v, 0) over the rectangle between the two uv corners (in
// either order); its normal is cross(dP/du, dP/dv), whichever side the ray comes from; only
// what lies inside contained_by is seen, and without contained_by that is the box -1..1.
// max_gradient, accuracy and precompute steer POV-Ray's search for the surface along a ray and
// do not change the surface: here they are not used (POV-Ray misses or adds pieces where
// max_gradient is below the functions' gradient; the surface is drawn whole here).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "tracer/scene_language/shapes.h"

namespace rayset::tracer {

// Between a cell's corners, at the middle of its edges, its centre and its triangles'
// centroids, the surface lies within this fraction of its size (the largest side of the box
// around the surface's part inside its container, in its own coordinates) from the triangles'
// points of the same (u, v).
constexpr double kParametricTolerance = 1e-4;

struct ParametricMesh {
    std::vector<Vec3> points;  // the surface's own coordinates
    std::vector<Vec2> uvs;     // (u, v) of each point
    // Wound so that cross(b - a, c - a) points along cross(dP/du, dP/dv).
    std::vector<std::array<unsigned, 3>> triangles;
    // Per triangle: whether part of it may lie outside the container (the rest lie inside).
    std::vector<bool> straddles;
    double tolerance = 0;  // the distance the triangles keep to the surface at the samples
};

// The surface's point at (u, v).
Vec3 parametric_point(const ParametricShape& shape, double u, double v);
// cross(dP/du, dP/dv) at (u, v) by central differences; not normalised (zero where the
// surface is degenerate, as at a sphere's poles).
Vec3 parametric_normal(const ParametricShape& shape, double u, double v);
// Whether `p` is inside the container (box or sphere, boundary included).
bool container_holds(const ContainedBy& container, Vec3 p);
// The triangles of the surface's part that may lie inside its container. Throws Error ("not
// supported: ... at `where`") when the functions are not finite over the rectangle, or when
// a million triangles do not follow them within the tolerance (a jump in a function).
ParametricMesh tessellate_parametric(const ParametricShape& shape, const std::string& where);

}  // namespace rayset::tracer
