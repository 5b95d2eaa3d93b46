// What the appearance grammar files share (internal to the scene language):
//   grammar_appearance.cpp  texture, layered textures, object modifiers, material, #default
//   grammar_patterns.cpp    pattern types, pattern modifiers, warps, pattern functions
//   grammar_images.cpp      image_map, bump_map, material_map and image_pattern images
//   grammar_blend_maps.cpp  color_map, pigment_map, normal_map, slope_map, texture_map,
//                           density_map and the lists after block patterns
//   grammar_pigments.cpp    pigment, normal and density bodies
//   grammar_finish.cpp      finish
//   grammar_media.cpp       interior and media
#pragma once

#include <functional>
#include <limits>

#include <fmt/format.h>
#include <string>
#include <vector>

#include "tracer/scene_language/grammar.h"

namespace rayset::tracer {

// What a pattern is read for: the items a map or list may hold, and the patterns allowed.
enum class PatternRole { pigment, normal, texture, density, function };
const char* role_name(PatternRole role);  // "pigment", "normal", ...

// ---- grammar_patterns.cpp
// True when `token` names a pattern type allowed for `role` (image_map and its kin included).
bool is_pattern_type(Parser& p, const Token& token, PatternRole role);
// After a pattern type keyword (taken): its parameters, in `pattern`, which keeps its other
// settings (as POV-Ray keeps them when an identifier's pattern type is replaced); for normals
// (`amount` given) the bump size that may follow; and for block patterns the list after them,
// returned (null: no list written).
BlendMapPointer parse_pattern_type(Parser& p, const Token& keyword, Pattern& pattern,
                                   PatternRole role, double* amount);
// One pattern modifier other than a transform (turbulence, warp, frequency, waveforms,
// noise_generator, the modifiers of the pattern's kind, uv_mapping); false when the next
// token starts none.
bool parse_pattern_modifier(Parser& p, Pattern& pattern, PatternRole role);

// ---- grammar_images.cpp
// After image_map, bump_map, material_map or image_pattern (taken): the image and its
// modifiers up to the closing brace, except material_map's textures, which `on_item` reads
// (it returns false when the next token is none of its items).
std::shared_ptr<const ImageMap> parse_image(Parser& p, const Token& keyword,
                                            const std::function<bool()>& on_item = {});

// ---- grammar_blend_maps.cpp
// The list after a block pattern (colours, pigments, normals, textures or densities as the
// role allows), read while items follow; null when none follows (pattern functions: never).
// Missing items take the pattern's built-in ones.
BlendMapPointer parse_block_list(Parser& p, PatternKind kind, PatternRole role);
// The map after `keyword` (color_map ... density_map, taken), checked against the pattern.
BlendMapPointer parse_map_modifier(Parser& p, const Token& keyword, BlendMapKind kind,
                                   const Pattern& pattern);

// ---- grammar_pigments.cpp
// A pigment, normal or density body up to `close` (a '}' or, in a map entry, a ']'), into
// `item`, which holds the starting value (a copy of the default texture's, or a map entry's).
void parse_pigment_body(Parser& p, Pigment& pigment, PatternRole role, const Token& keyword,
                        const Token& open, Symbol close);
void parse_normal_body(Parser& p, Normal& normal, const Token& keyword, const Token& open,
                       Symbol close);
// What a pigment or normal starts as: the #default texture's.
Pigment default_pigment(Parser& p);
Normal default_normal(Parser& p);
Finish default_finish(Parser& p);
const Texture& default_texture(Parser& p);

// ---- grammar_appearance.cpp
// A texture body up to `close` (texture { } or a texture_map entry).
TextureRef parse_texture_body(Parser& p, const Token& keyword, const Token& open, Symbol close);

// ---- grammar_media.cpp
// The items of an interior block after its identifier, up to its closing brace.
void parse_interior_items(Parser& p, Interior& interior, const Token& keyword, const Token& open);

// ---- grammar_finish.cpp
void parse_finish_body(Parser& p, Finish& finish, const Token& keyword, const Token& open);

// ---- helpers
// A float read where POV-Ray takes a whole number: truncated, as POV-Ray does, and kept within
// int's range (a huge or undefined value cannot overflow the conversion).
inline int truncated(double value) {
    if (!(value > -2147483648.0)) return std::numeric_limits<int>::min();
    if (!(value < 2147483647.0)) return std::numeric_limits<int>::max();
    return static_cast<int>(value);
}

// `KEYWORD VALUE` items written once, as tables: the field each keyword sets. A float item
// may stand for a whole number (POV-Ray truncates: `octaves 2.7` is 2).
template <class Item>
struct KeywordField {
    Keyword keyword;
    double Item::*number = nullptr;
    int Item::*whole = nullptr;
    Rgb Item::*colour = nullptr;
    Vec3 Item::*vector = nullptr;
    bool Item::*flag = nullptr;  // a keyword alone sets it
    int minimum = 0;             // whole numbers: the smallest allowed
};
template <class Item>
KeywordField<Item> number_field(Keyword keyword, double Item::*field) {
    KeywordField<Item> f{keyword};
    f.number = field;
    return f;
}
template <class Item>
KeywordField<Item> whole_field(Keyword keyword, int Item::*field, int minimum) {
    KeywordField<Item> f{keyword};
    f.whole = field;
    f.minimum = minimum;
    return f;
}
template <class Item>
KeywordField<Item> colour_field(Keyword keyword, Rgb Item::*field) {
    KeywordField<Item> f{keyword};
    f.colour = field;
    return f;
}
template <class Item>
KeywordField<Item> vector_field(Keyword keyword, Vec3 Item::*field) {
    KeywordField<Item> f{keyword};
    f.vector = field;
    return f;
}
template <class Item>
KeywordField<Item> flag_field(Keyword keyword, bool Item::*field) {
    KeywordField<Item> f{keyword};
    f.flag = field;
    return f;
}

// The item of `table` the next token names, read into `item`; false when it names none.
template <class Item>
bool parse_keyword_field(Parser& p, Item& item, const std::vector<KeywordField<Item>>& table) {
    const Token token = p.peek();
    for (const KeywordField<Item>& entry : table) {
        if (!token.is(entry.keyword)) continue;
        p.next();
        const std::string after = fmt::format("after '{}'", p.word(token));
        if (entry.number) item.*entry.number = p.parse_float(after);
        if (entry.colour) item.*entry.colour = p.parse_colour().rgb();
        if (entry.vector) item.*entry.vector = p.parse_vector();
        if (entry.flag) item.*entry.flag = true;
        if (entry.whole) {
            const Token at = p.peek();
            const double value = p.parse_float(after);
            if (!(value >= entry.minimum))
                p.fail(at, fmt::format("'{}' must be at least {}, found {}", p.word(token),
                                       entry.minimum, value));
            item.*entry.whole = truncated(value);
        }
        return true;
    }
    return false;
}

// "to close 'pigment' opened at FILE:LINE:COLUMN" for messages.
std::string closing_purpose(Parser& p, const Token& keyword, const Token& open,
                            Symbol close = Symbol::rbrace);
// A word POV-Ray reserves that our keyword table lacks (exr, hdr, bmp, number_of_sides ...).
bool is_word(Parser& p, const Token& token, const char* word);

}  // namespace rayset::tracer
