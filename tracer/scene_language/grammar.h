// The grammar of POV-Ray's scene items, as free functions over the Parser's public API. Each
// `parse_X(parser, keyword)` is called with `keyword` just taken and reads the block after it.
//   grammar_objects.cpp     shapes, CSG, object modifiers, light sources; flattening
//   grammar_appearance.cpp  texture, material, object appearance modifiers, #default; with
//                           grammar_patterns, _images, _blend_maps, _pigments, _finish,
//                           _media.cpp (appearance_grammar.h) and pattern_evaluation.cpp
//   grammar_scene.cpp       the top-level statements that are not objects (the dispatcher),
//                           background; ray_source and illuminance_receiver
//   grammar_camera.cpp      camera
//   grammar_global_settings.cpp  global_settings
//   grammar_atmosphere.cpp  fog, rainbow, sky_sphere, atmospheric media
#pragma once

#include "tracer/scene_language/appearance.h"
#include "tracer/scene_language/parser.h"

namespace rayset::tracer {

// ---- objects
bool starts_object(Parser& parser, const Token& token);
ObjectRef parse_object(Parser& parser);  // the object keyword is the next token
// Flattens an object tree into the scene's instances and lights.
void add_to_scene(Parser& parser, const ObjectRef& object, const Token& at);
// Parse-time geometry of a declared object, for min_extent, max_extent, inside and trace
// (object space of the tree, its transforms applied). Each returns false when it cannot
// answer for this kind of object; the caller reports that as not supported.
bool object_bounding_box(const ObjectNode& object, Vec3& minimum, Vec3& maximum);
bool object_inside(const ObjectNode& object, Vec3 point, bool& inside);
bool object_trace(const ObjectNode& object, Vec3 origin, Vec3 direction, Vec3& hit, Vec3& normal,
                  bool& found);

// ---- appearance
// An object modifier about appearance (texture, pigment, normal, finish, interior,
// interior_texture, material), read into `appearance`; false (nothing read) when the next token
// starts none. A second texture is layered over the first, as in POV-Ray.
bool parse_appearance_modifier(Parser& parser, ObjectAppearance& appearance);
// What an object inside a union ends up with: what it lacks, the union's. Both in the same
// coordinates (transform_appearance in appearance.h moves an object's appearance with it).
void inherit_appearance(ObjectAppearance& inner, const ObjectAppearance& outer);
// What an object added to the scene inherits when neither it nor its unions give a texture:
// the #default texture of that moment (POV-Ray attaches it then, not when the object is
// declared), in world coordinates.
ObjectAppearance scene_default_appearance(Parser& parser);
// `above` layered over `below` (#declare T = texture { } texture { }), with POV-Ray's rules:
// patterned textures cannot be layers.
TextureRef layer_textures(Parser& parser, const Token& at, const TextureRef& below,
                          const TextureRef& above);
TextureRef parse_texture(Parser& parser, const Token& keyword);
PigmentRef parse_pigment(Parser& parser, const Token& keyword);
NormalRef parse_normal(Parser& parser, const Token& keyword);
FinishRef parse_finish(Parser& parser, const Token& keyword);
InteriorRef parse_interior(Parser& parser, const Token& keyword);
MediaRef parse_media(Parser& parser, const Token& keyword);
DensityRef parse_density(Parser& parser, const Token& keyword);
MaterialRef parse_material(Parser& parser, const Token& keyword);
// After color_map / colour_map, pigment_map, normal_map, slope_map, texture_map, density_map.
ColourMapRef parse_colour_map(Parser& parser, const Token& keyword);
PigmentMapRef parse_pigment_map(Parser& parser, const Token& keyword);
NormalMapRef parse_normal_map(Parser& parser, const Token& keyword);
SlopeMapRef parse_slope_map(Parser& parser, const Token& keyword);
TextureMapRef parse_texture_map(Parser& parser, const Token& keyword);
DensityMapRef parse_density_map(Parser& parser, const Token& keyword);
void parse_default(Parser& parser, const Token& directive);  // after #default
// An image file of POV-Ray type `type` (png, jpeg, ...), also tried with that type's extension.
std::string resolve_image_file(Parser& parser, const std::string& name, const Token& at,
                               const std::string& type, const std::string& what);
// That file's pixels (image_file.h); a file that cannot be read fails at `at`. Null for the
// types not read (iff, pot, sys), which the renderer refuses.
std::shared_ptr<const ImagePixels> read_scene_image(Parser& parser, const std::string& path,
                                                    const std::string& type, const Token& at);
// `function { pattern { PATTERN } }`: after `pattern`.
std::shared_ptr<const Pattern> parse_function_pattern(Parser& parser, const Token& keyword);
// A pattern's value or a pigment's colour at a point, for pattern and pigment functions and
// the renderer; false when it cannot be evaluated (the caller reports that as not supported):
// pattern_evaluation.cpp lists the patterns it evaluates.
bool evaluate_pattern(const Pattern& pattern, Vec3 point, double& value);
bool evaluate_pigment(const Pigment& pigment, Vec3 point, Colour& colour);
// Whether evaluate_pattern / evaluate_pigment know the value. What they cannot evaluate
// (function images, surface coordinates, unsupported patterns) they cannot anywhere, so one
// point tells.
bool pattern_is_evaluable(const Pattern& pattern);
bool pigment_is_evaluable(const Pigment& pigment);
// The point in a pattern's own space (its warps undone, its turbulence applied), and the
// linear part of the transform from that space to the world's (its transform warps composed);
// false for warps and mappings it cannot undo.
bool pattern_space_point(const Pattern& pattern, Vec3& point);
Matrix4 pattern_to_world(const Pattern& pattern);
// POV-Ray's lookup of a map at a pattern value: at or past the last entry that entry, at or
// before the first the first, else the two entries around the value blended linearly (weight:
// the share of `high`). False for an empty map.
struct MapBlend {
    size_t low = 0, high = 0;
    double weight = 0;
};
bool look_up_map(const BlendMap& map, double value, MapBlend& blend);

// ---- scene items
CameraRef parse_camera(Parser& parser, const Token& keyword);
FogRef parse_fog(Parser& parser, const Token& keyword);
RainbowRef parse_rainbow(Parser& parser, const Token& keyword);
SkySphereRef parse_sky_sphere(Parser& parser, const Token& keyword);
// Into the scene: global_settings { } and a top-level media { }.
void parse_global_settings(Parser& parser, const Token& keyword);
void parse_atmospheric_media(Parser& parser, const Token& keyword);
// A top-level statement other than an object (camera, global_settings, background, fog,
// rainbow, sky_sphere, media, default, ray_source, illuminance_receiver) whose keyword was just
// taken, added to the scene; false (nothing read) when `keyword` starts none of them.
bool parse_scene_statement(Parser& parser, const Token& keyword);

}  // namespace rayset::tracer
