// Objects rendered as solids: CSG kept whole (merge, intersection, difference, a union that
// could not be split), quadrics and polynomials (poly, cubic, quartic), and any object with
// clipped_by, bounded_by or inverse. Each is one SolidTree (scene_language/shape_geometry.h) in
// world coordinates, intersected exactly by the renderer's user geometry; a part with a texture
// or interior of its own shows it where its surface is the solid's (POV-Ray's rule without
// cutaway_textures, which is refused).
//
// bounded_by is what POV-Ray 3.7 makes of it: kept only for an object it cannot bound itself
// (an unbounded one: a plane or inverse among its parts; POV-Ray's Remove_Bounds, on by
// default, drops the others), and then a ray is tested against the object only if it meets
// the bounding objects or starts inside them; the object's bounds are theirs.
#pragma once

#include <optional>

#include "tracer/scene_language/scene_description.h"
#include "tracer/scene_language/shape_geometry.h"

namespace rayset::tracer {

bool is_solid(const ObjectInstance& object);

// The box that holds a shape in its own coordinates (sphere, box, cylinder, cone, torus, disc,
// triangle, mesh, an isosurface's or parametric's container, ...); false for the unbounded ones
// (plane, ...).
bool local_box(const Shape& shape, Vec3& lower, Vec3& upper);

struct Solid {
    SolidTree tree;                  // points into the object's shapes
    std::optional<SolidTree> bound;  // bounded_by of an unbounded object: the bounding objects
    // By tree node: the part a shape node is (ShapeHit::part), null for other nodes and clips.
    std::vector<const ObjectInstance*> parts;
    bool bounded = true;  // false: the box below is not known (a plane among the parts)
    Vec3 lower, upper;    // world
};

// The solid of `object` (is_solid). Refuses (Error, "not supported: ... at FILE:LINE:COLUMN")
// parts whose shape the tree cannot intersect or tell the inside of, and cutaway_textures.
Solid solid_of(const ObjectInstance& object);

}  // namespace rayset::tracer
