// What the object grammar files share (internal to the scene-language library):
//   grammar_objects.cpp         dispatch, object { }, CSG, object modifiers, flattening
//   grammar_objects_lights.cpp  light_source, light_group
//   grammar_shapes.cpp          the shapes given by a few numbers (sphere ... quadric)
//   grammar_shapes_curves.cpp   lathe, prism, sor, sphere_sweep, polygon, bicubic_patch, text
//   grammar_shapes_fields.cpp   blob, height_field, isosurface, parametric, julia_fractal
//   grammar_shapes_meshes.cpp   mesh, mesh2, mesh_file
//   object_geometry.cpp         POV-Ray's bounding boxes, inside and trace at parse time
// Each parse_KEYWORD(parser, keyword) is called with the shape's keyword just taken and reads
// its block, modifiers and closing brace included.
#pragma once

#include <memory>
#include <string>

#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/object_tree.h"

namespace rayset::tracer {

using NodePtr = std::shared_ptr<ObjectNode>;

// A node of `kind` for the keyword just taken, located at it.
NodePtr new_node(Parser& p, const Token& keyword, ObjectNode::Kind kind = ObjectNode::Kind::shape);
// After a shape's own items: its bounding box, then the object modifiers up to the brace
// that closes `keyword`'s block opened at `open`.
void finish_shape(Parser& p, ObjectNode& node, const Token& keyword, const Token& open);
// The object modifiers up to the closing brace, then POV-Ray's bounding-box rules.
void parse_object_modifiers(Parser& p, ObjectNode& node, const Token& keyword, const Token& open);
bool parse_object_modifier(Parser& p, ObjectNode& node);
// A transform statement applied to the node, its attached objects and its bounding box;
// false (nothing read) when the next token is not a transform.
bool parse_node_transform(Parser& p, ObjectNode& node);
void transform_node(ObjectNode& node, const Matrix4& step, bool similarity);
// The keyword's enum value, or false for anything that is not a keyword.
bool keyword_of(const Token& token, Keyword& keyword);
// `COUNT` of a list of entries: a non-negative integer within ParseOptions::max_array_elements,
// checked before anything is allocated for it.
int parse_count(Parser& p, const std::string& what);
// A 2-D vector (uv vector): a float or a vector of two terms, as POV-Ray's UV vectors.
Vec2 parse_vec2(Parser& p, const std::string& what);

// ---- lights (grammar_objects_lights.cpp)
ObjectRef parse_light_source(Parser& p, const Token& keyword);
ObjectRef parse_light_group(Parser& p, const Token& keyword);

// ---- shapes
ObjectRef parse_sphere(Parser& p, const Token& keyword);
ObjectRef parse_box(Parser& p, const Token& keyword);
ObjectRef parse_cylinder(Parser& p, const Token& keyword);
ObjectRef parse_cone(Parser& p, const Token& keyword);
ObjectRef parse_torus(Parser& p, const Token& keyword);
ObjectRef parse_ovus(Parser& p, const Token& keyword);
ObjectRef parse_superellipsoid(Parser& p, const Token& keyword);
ObjectRef parse_plane(Parser& p, const Token& keyword);
ObjectRef parse_disc(Parser& p, const Token& keyword);
ObjectRef parse_triangle(Parser& p, const Token& keyword);
ObjectRef parse_smooth_triangle(Parser& p, const Token& keyword);
ObjectRef parse_poly(Parser& p, const Token& keyword);  // poly, cubic, quartic
ObjectRef parse_polynomial(Parser& p, const Token& keyword);
ObjectRef parse_quadric(Parser& p, const Token& keyword);
ObjectRef parse_lathe(Parser& p, const Token& keyword);
ObjectRef parse_prism(Parser& p, const Token& keyword);
ObjectRef parse_sor(Parser& p, const Token& keyword);
ObjectRef parse_sphere_sweep(Parser& p, const Token& keyword);
ObjectRef parse_polygon(Parser& p, const Token& keyword);
ObjectRef parse_bicubic_patch(Parser& p, const Token& keyword);
ObjectRef parse_text(Parser& p, const Token& keyword);
ObjectRef parse_blob(Parser& p, const Token& keyword);
ObjectRef parse_height_field(Parser& p, const Token& keyword);
ObjectRef parse_isosurface(Parser& p, const Token& keyword);
ObjectRef parse_parametric(Parser& p, const Token& keyword);
ObjectRef parse_julia_fractal(Parser& p, const Token& keyword);
ObjectRef parse_mesh(Parser& p, const Token& keyword);
ObjectRef parse_mesh2(Parser& p, const Token& keyword);
ObjectRef parse_mesh_file(Parser& p, const Token& keyword);
// contained_by { box { ... } | sphere { ... } } after `contained_by` was taken.
ContainedBy parse_contained_by(Parser& p, const Token& keyword);

// ---- bounding boxes (object_geometry.cpp)
// The box of a shape node from its shape and transform (unknown for the shapes it does not
// cover), of a CSG or light-group node from its children.
void compute_shape_bounds(ObjectNode& node);
void compute_csg_bounds(ObjectNode& node);
void transform_bounds(ObjectNode& node, const Matrix4& step, bool similarity);
// POV-Ray's rule at the end of an object's modifiers: the smallest of its own box, the box of
// its clipped_by objects and the box of its bounded_by objects.
void apply_bounding_rules(ObjectNode& node);

}  // namespace rayset::tracer
