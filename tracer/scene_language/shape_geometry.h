// Exact geometry of the simple shapes in their own coordinates: the crossings of a line with
// their surface and whether a point is inside. The parse-time trace and inside of the language
// (object_geometry.cpp) and the renderer's analytic shapes use them.
//
// Covered: sphere, box, cylinder, cone, torus, plane, disc, triangle, mesh (inside with an
// inside_vector; hits of flat triangles), quadric, polynomial (inside only) and linear prism
// (inside only).
#pragma once

#include <vector>

#include "tracer/scene_language/shapes.h"

namespace rayset::tracer {

struct ShapeHit {
    double t;     // along the line o + t d, in units of |d|
    Vec3 normal;  // outward, not normalised
};

// Every crossing of the line o + t d (any t, unsorted) with the shape's surface; false when the
// shape is not covered here.
bool shape_hits(const Shape& shape, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits);
// Whether `p` is inside the shape (POV-Ray's inside: a plane's or disc's side against their
// normal, a mesh by the parity of crossings along its inside_vector); false when not covered.
bool shape_inside(const Shape& shape, Vec3 p, bool& inside);

}  // namespace rayset::tracer
