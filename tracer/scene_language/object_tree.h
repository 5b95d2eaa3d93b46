// Objects as written, before they reach the scene: a tree of shapes, CSG, lights and light
// groups, each node with its own transform (applied after its children's) and modifiers.
// Declared objects are shared; `object { ID ... }` copies the node before changing it.
// add_to_scene flattens a tree into world-space instances and lights.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "tracer/scene_language/scene_description.h"
#include "tracer/scene_language/values.h"

namespace rayset::tracer {

// POV-Ray's bounding box of a node, kept as POV-Ray keeps it while the node's transforms are
// applied one by one (object_geometry.cpp): min_extent and max_extent read it.
struct ParseBounds {
    bool known = false;     // false: a shape whose box is not computed here
    bool infinite = false;  // planes, lights, and what contains them: +-1e10
    Vec3 minimum, maximum;  // in the coordinates of the node's parent
    // A sphere moved only by translate, rotate and uniform scale keeps a tight box (POV-Ray
    // moves its centre and radius); from its first other transform on, its box is the box of
    // the sphere it was then, carried through the transforms since (`sphere_transform`).
    bool sphere_transformed = false;
    Vec3 sphere_centre;
    double sphere_radius = 0;
    Matrix4 sphere_transform;
};

struct ObjectNode {
    enum class Kind { shape, csg, light, light_group } kind = Kind::shape;
    Shape shape;  // shape; csg: a CsgShape with no children (they are `children`)
    std::vector<ObjectRef> children;  // csg, light_group: objects and lights in writing order
    LightSource light;  // light, in the node's own coordinates (projected_through left empty)
    bool global_lights = false;  // light_group

    Matrix4 transform;
    ObjectAppearance appearance;  // what this node's own modifiers give
    bool no_shadow = false, no_image = false, no_reflection = false, no_radiosity = false;
    bool double_illuminate = false, inverse = false, uv_mapping = false, cutaway_textures = false;
    std::optional<bool> hollow;                  // unset: as its enclosing CSG
    std::optional<double> radiosity_importance;  // unset: as its enclosing CSG, else 1
    ObjectPhotons photons;
    bool photons_given = false;  // a photons block or no_shadow: else as its enclosing CSG
    // Objects attached to this node, in its parent's coordinates: they take the transforms
    // that follow them in the node (clipped_by, bounded_by; for a light its looks_like and
    // projected_through objects).
    std::vector<ObjectRef> clipped_by, bounded_by;
    ObjectRef looks_like, projected_through;

    ParseBounds bounds;
    SourceLocation location;
};

}  // namespace rayset::tracer
