// Objects as written, before they reach the scene: a tree of shapes, unions and lights, each
// node with its own transform (applied after its children's) and modifiers. Declared objects
// are shared; `object { ID ... }` copies the node before changing it. add_to_scene flattens a
// tree into world-space instances and lights.
#pragma once

#include <memory>
#include <vector>

#include "tracer/scene_language/scene_description.h"
#include "tracer/scene_language/values.h"

namespace rayset::tracer {

struct ObjectNode {
    enum class Kind { shape, union_of, light } kind = Kind::shape;
    Shape shape;
    std::vector<ObjectRef> children;
    LightSource light;  // in the node's own coordinates
    Matrix4 transform;
    ObjectAppearance appearance;  // what this node's own modifiers give
    bool no_shadow = false, no_image = false, no_reflection = false, hollow = false;
    SourceLocation location;
};

}  // namespace rayset::tracer
