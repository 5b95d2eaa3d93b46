// What an identifier can hold while a scene is parsed: numbers (float, vector or colour as
// POV-Ray's 1..5-term expressions), strings, objects (a tree that becomes instances when it
// reaches the scene), textures, pigments, finishes, interiors, transforms and cameras.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

// POV-Ray's "express": up to five terms; a float has one. Binary operators promote the shorter
// operand: a float repeats into every term, a vector pads with zeros.
struct Numeric {
    std::array<double, 5> v{};
    int terms = 1;

    static Numeric scalar(double value) { return Numeric{{value, 0, 0, 0, 0}, 1}; }
    static Numeric vector3(Vec3 a) { return Numeric{{a.x, a.y, a.z, 0, 0}, 3}; }
    Numeric promoted(int to_terms) const;
    Vec3 vec3() const { return {v[0], v[1], v[2]}; }
};

struct ObjectNode;
using ObjectRef = std::shared_ptr<const ObjectNode>;

// An object as written: a shape, a union of children or a light, with its own transform (applied
// after the children's) and modifiers. Declared objects are shared; `object { ID ... }` copies
// the node before changing it.
struct ObjectNode {
    enum class Kind { shape, union_of, light } kind = Kind::shape;
    Shape shape;
    std::vector<ObjectRef> children;
    LightSource light;  // in the node's own coordinates
    Matrix4 transform;
    std::optional<Texture> texture;
    std::optional<Interior> interior;
    bool no_shadow = false, no_image = false, no_reflection = false, hollow = false;
    SourceLocation location;
};

struct TransformValue {
    Matrix4 matrix;
};

using Value = std::variant<Numeric, std::string, ObjectRef, Texture, Pigment, Finish, Interior, TransformValue, Camera>;

// "a float", "a vector", "a texture", ... for messages.
std::string type_name(const Value& value);

}  // namespace rayset::tracer
