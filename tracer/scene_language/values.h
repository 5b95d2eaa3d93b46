// What an identifier can hold while a scene is parsed: POV-Ray's identifier types. Numbers
// (float, vector or colour as 1..5-term expressions) and strings by value; arrays, macros,
// functions, splines, open files and every scene item (objects, textures, cameras, ...) by
// shared pointer, so that a declared item is stored once however often it is used.
#pragma once

#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "tracer/scene_language/lexer.h"
#include "tracer/scene_language/transform.h"

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

// POV-Ray keeps values of five terms (colours) in single precision wherever it stores them (an
// identifier, a macro parameter, an array element, a pigment): such a value as stored, rounded
// to float term by term. Values inside an expression stay in double precision.
Numeric as_stored(Numeric value);

// Scene items, defined by the scene description (scene_description.h and the headers it
// includes); values hold them by pointer.
struct ObjectNode;
struct Texture;
struct Pigment;
struct Normal;
struct Finish;
struct Interior;
struct Media;
struct TextureAndInterior;
struct Camera;
struct Fog;
struct Rainbow;
struct SkySphere;
struct BlendMap;
struct Pattern;
class UserFunction;
struct Spline;
struct Array;
struct Macro;
struct FileHandle;

// Pattern-based items of the same C++ type are told apart by a tag, as POV-Ray's identifier
// types tell them apart (a density is a pigment-like pattern, a density_map a pigment_map).
template <typename T, int Tag>
struct Tagged {
    std::shared_ptr<const T> item;
};

using ObjectRef = std::shared_ptr<const ObjectNode>;
using TextureRef = std::shared_ptr<const Texture>;
using PigmentRef = std::shared_ptr<const Pigment>;
using NormalRef = std::shared_ptr<const Normal>;
using FinishRef = std::shared_ptr<const Finish>;
using InteriorRef = std::shared_ptr<const Interior>;
using MediaRef = std::shared_ptr<const Media>;
using MaterialRef = std::shared_ptr<const TextureAndInterior>;
using CameraRef = std::shared_ptr<const Camera>;
using FogRef = std::shared_ptr<const Fog>;
using RainbowRef = std::shared_ptr<const Rainbow>;
using SkySphereRef = std::shared_ptr<const SkySphere>;
using FunctionRef = std::shared_ptr<const UserFunction>;
using SplineRef = std::shared_ptr<const Spline>;
using ArrayRef = std::shared_ptr<Array>;
using MacroRef = std::shared_ptr<const Macro>;
using FileRef = std::shared_ptr<FileHandle>;
using DensityRef = Tagged<Pigment, 0>;
using ColourMapRef = Tagged<BlendMap, 1>;
using PigmentMapRef = Tagged<BlendMap, 2>;
using NormalMapRef = Tagged<BlendMap, 3>;
using SlopeMapRef = Tagged<BlendMap, 4>;
using TextureMapRef = Tagged<BlendMap, 5>;
using DensityMapRef = Tagged<BlendMap, 6>;

struct TransformValue {
    Matrix4 matrix;
};

// std::monostate: an array element not yet assigned.
using Value = std::variant<std::monostate, Numeric, std::string, ArrayRef, MacroRef, FunctionRef,
                           SplineRef, FileRef, TransformValue, ObjectRef, TextureRef, PigmentRef,
                           NormalRef, FinishRef, InteriorRef, MediaRef, MaterialRef, CameraRef,
                           FogRef, RainbowRef, SkySphereRef, DensityRef, ColourMapRef,
                           PigmentMapRef, NormalMapRef, SlopeMapRef, TextureMapRef, DensityMapRef>;

// An identifier's value as stored (as_stored for numbers).
Value as_stored(Value value);

// "a float", "a vector", "a texture", ... for messages.
std::string type_name(const Value& value);

// An array of up to five dimensions, stored flat in row-major order. Its elements share one
// type, fixed by the first element assigned (as in POV-Ray).
struct Array {
    std::vector<int> sizes;
    std::vector<Value> elements;
    size_t element_type = 0;  // Value::index() of its elements; 0 until one is assigned
    int element_terms = 0;    // numbers: 1 float, 2 to 4 vector, 5 colour (each its own type)

    // Why `value` cannot be an element of this array ("colours, found a float"), or "" if it can.
    std::string mismatch(const Value& value) const;
    // Element `index` becomes `value` (as stored); the first assignment fixes the type.
    void assign(size_t index, Value value);
};

// `#macro NAME(PARAMS) BODY #end`: the body's tokens [body_start, body_end) of `file`, the
// #end at body_end.
struct Macro {
    NameId name = 0;
    std::vector<NameId> parameters;
    std::shared_ptr<const SourceFile> file;
    size_t body_start = 0, body_end = 0;
    Token defined_at;
};

// A file opened by #fopen.
struct FileHandle {
    std::string path;
    bool writing = false;
    std::FILE* stream = nullptr;
    std::shared_ptr<SourceFile> read_tokens;  // read mode: the file's tokens
    size_t read_position = 0;
    ~FileHandle();
};

// What an identifier names: its value, and for `#declare deprecated` the warning to give.
struct SymbolEntry {
    Value value;
    std::string deprecation;  // empty: not deprecated
    bool warn_once = false, warned = false;
};
using SymbolRef = std::shared_ptr<SymbolEntry>;

}  // namespace rayset::tracer
