// Pigments, normals and densities (reference 3.4.6.1, 3.4.6.2, 3.4.8.4): an optional
// identifier, then the type (a colour, a pattern or an image), then modifiers. Without an
// identifier they start from the #default texture's pigment or normal, as POV-Ray's do.
#include <fmt/format.h>

#include "tracer/scene_language/appearance_grammar.h"

namespace rayset::tracer {
namespace {

bool same_place(const Token& a, const Token& b) {
    return a.file == b.file && a.line == b.line && a.column == b.column;
}

// A token that is no modifier; `type_allowed` while the type may still come (nothing but an
// identifier read).
[[noreturn]] void fail_modifier(Parser& p, PatternRole role, const Token& keyword,
                                const Token& open, Symbol close, bool type_allowed) {
    const Token token = p.peek();
    const bool is_type =
        is_pattern_type(p, token, role) || (role != PatternRole::normal && p.starts_colour(token));
    if (is_type && !type_allowed)
        p.fail(token,
               fmt::format(
                   "the {} type ('{}') must come first in '{}' opened at {}, before its modifiers "
                   "(POV-Ray's rule)",
                   role_name(role), p.word(token), p.word(keyword), p.location_of(open).str()));
    const char* types = !type_allowed                 ? ""
                        : role == PatternRole::normal ? "a pattern or "
                                                      : "a colour, a pattern or ";
    p.fail_identifier(token, fmt::format("{}a {} modifier or {}", types, role_name(role),
                                         closing_purpose(p, keyword, open, close)));
}

// color_map / colour_map after a colour was written: POV-Ray refuses a map on a solid colour.
void check_map_allowed(Parser& p, const Token& keyword, bool colour_written) {
    if (colour_written)
        p.fail(keyword, fmt::format("'{}' cannot be used with a solid colour (POV-Ray's rule)",
                                    p.word(keyword)));
}

// The type at the start of a pigment or density body: a colour or a pattern. True when a
// colour was written.
bool parse_pigment_type(Parser& p, Pigment& pigment, PatternRole role) {
    const Token token = p.peek();
    if (p.starts_colour(token)) {
        pigment.colour = p.parse_colour();
        if (pigment.pattern->kind != PatternKind::plain)
            pigment.pattern.edit().kind = PatternKind::plain;
        pigment.map = nullptr;
        return true;
    }
    if (is_pattern_type(p, token, role)) {
        p.next();
        const BlendMapPointer list =
            parse_pattern_type(p, token, pigment.pattern.edit(), role, nullptr);
        // A block pattern keyword always sets its list: the one written, else its built-in
        // one (checked with POV-Ray 3.7: an identifier's list does not survive a new type).
        if (list_size(pigment.pattern->kind) > 0) pigment.map = list;
    }
    return false;
}

// One pigment or density modifier other than transforms and pattern modifiers.
bool parse_pigment_only_modifier(Parser& p, Pigment& pigment, PatternRole role,
                                 bool colour_written) {
    const Token token = p.peek();
    if (token.is(Keyword::color_map) || token.is(Keyword::colour_map)) {
        p.next();
        check_map_allowed(p, token, colour_written);
        pigment.map = parse_map_modifier(p, token, BlendMapKind::colour, *pigment.pattern);
    } else if (role == PatternRole::pigment && token.is(Keyword::pigment_map)) {
        p.next();
        check_map_allowed(p, token, colour_written);
        pigment.map = parse_map_modifier(p, token, BlendMapKind::pigment, *pigment.pattern);
    } else if (role == PatternRole::density && token.is(Keyword::density_map)) {
        p.next();
        check_map_allowed(p, token, colour_written);
        pigment.map = parse_map_modifier(p, token, BlendMapKind::density, *pigment.pattern);
    } else if (role == PatternRole::pigment &&
               (token.is(Keyword::quick_color) || token.is(Keyword::quick_colour))) {
        p.next();
        pigment.quick_colour_given = true;
        pigment.quick_colour = p.parse_colour();
    } else {
        return false;
    }
    return true;
}

// One normal modifier other than transforms and pattern modifiers.
bool parse_normal_only_modifier(Parser& p, Normal& normal) {
    const Token token = p.peek();
    auto after = [&] { return fmt::format("after '{}'", p.word(token)); };
    if (token.is(Keyword::normal_map) || token.is(Keyword::slope_map)) {
        p.next();
        const bool slope = token.is(Keyword::slope_map);
        if (!slope && normal.pattern->kind == PatternKind::facets)
            p.fail(token, "'normal_map' cannot be used with facets (POV-Ray's rule)");
        normal.map = parse_map_modifier(
            p, token, slope ? BlendMapKind::slope : BlendMapKind::normal, *normal.pattern);
    } else if (token.is(Keyword::bump_size)) {
        p.next();
        normal.amount = p.parse_float(after());
    } else if (token.is(Keyword::accuracy)) {
        p.next();
        normal.accuracy = p.parse_float(after());
    } else if (token.is(Keyword::no_bump_scale)) {
        p.next();
        normal.no_bump_scale = p.parse_optional_bool();
    } else {
        return false;
    }
    return true;
}

}  // namespace

const Texture& default_texture(Parser& p) {
    static const Texture povray_default;
    return p.default_texture ? *p.default_texture : povray_default;
}

Pigment default_pigment(Parser& p) { return default_texture(p).pigment; }

Normal default_normal(Parser& p) {
    const Texture& texture = default_texture(p);
    return texture.normal ? *texture.normal : Normal{};
}

Finish default_finish(Parser& p) { return *default_texture(p).finish; }

void parse_pigment_body(Parser& p, Pigment& pigment, PatternRole role, const Token& keyword,
                        const Token& open, Symbol close) {
    const bool uv_mapping = p.accept(Keyword::uv_mapping);  // pigment { uv_mapping PIGMENT_BODY }
    PigmentRef declared_pigment;
    DensityRef declared_density;
    if (role == PatternRole::pigment && p.take_declared(declared_pigment))
        pigment = *declared_pigment;
    else if (role == PatternRole::density && p.take_declared(declared_density))
        pigment = *declared_density.item;
    pigment.location = p.location_of(keyword);
    const Token type = p.peek();
    const bool colour_written = parse_pigment_type(p, pigment, role);
    const bool type_written = colour_written || !same_place(p.peek(), type);
    if (uv_mapping) pigment.pattern.edit().uv_mapping = true;
    // Transforms move the pattern at once (their order with warps matters) and every map entry
    // at the end, wherever the map is written (checked with POV-Ray 3.7).
    Matrix4 entries_transform;
    for (;;) {
        if (p.peek_is(close)) break;
        Matrix4 transform;
        if (p.parse_transform_item(transform)) {
            transform_pattern(pigment.pattern.edit(), transform);
            entries_transform = transform * entries_transform;
        } else if (!parse_pattern_modifier(p, pigment.pattern.edit(), role) &&
                   !parse_pigment_only_modifier(p, pigment, role, colour_written)) {
            fail_modifier(p, role, keyword, open, close,
                          !type_written && same_place(p.peek(), type));
        }
    }
    pigment.map = transformed_map(pigment.map, entries_transform);
}

void parse_normal_body(Parser& p, Normal& normal, const Token& keyword, const Token& open,
                       Symbol close) {
    const bool uv_mapping = p.accept(Keyword::uv_mapping);  // normal { uv_mapping NORMAL_BODY }
    NormalRef declared;
    if (p.take_declared(declared)) normal = *declared;
    normal.location = p.location_of(keyword);
    const Token type = p.peek();
    const bool type_written = is_pattern_type(p, type, PatternRole::normal);
    if (type_written) {
        p.next();
        const BlendMapPointer list =
            parse_pattern_type(p, type, normal.pattern.edit(), PatternRole::normal, &normal.amount);
        if (list_size(normal.pattern->kind) > 0) normal.map = list;
    }
    if (uv_mapping) normal.pattern.edit().uv_mapping = true;
    Matrix4 entries_transform;
    for (;;) {
        if (p.peek_is(close)) break;
        Matrix4 transform;
        if (p.parse_transform_item(transform)) {
            transform_pattern(normal.pattern.edit(), transform);
            entries_transform = transform * entries_transform;
        } else if (!parse_pattern_modifier(p, normal.pattern.edit(), PatternRole::normal) &&
                   !parse_normal_only_modifier(p, normal)) {
            fail_modifier(p, PatternRole::normal, keyword, open, close,
                          !type_written && same_place(p.peek(), type));
        }
    }
    normal.map = transformed_map(normal.map, entries_transform);
}

PigmentRef parse_pigment(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto pigment = std::make_shared<Pigment>(default_pigment(p));
    parse_pigment_body(p, *pigment, PatternRole::pigment, keyword, open, Symbol::rbrace);
    p.expect_close(keyword, open);
    return pigment;
}

DensityRef parse_density(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    // A density starts as POV-Ray's plain black pigment, not the #default one: `density {}`
    // is no density at all (checked with POV-Ray 3.7).
    auto density = std::make_shared<Pigment>();
    parse_pigment_body(p, *density, PatternRole::density, keyword, open, Symbol::rbrace);
    p.expect_close(keyword, open);
    return {density};
}

NormalRef parse_normal(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto normal = std::make_shared<Normal>(default_normal(p));
    parse_normal_body(p, *normal, keyword, open, Symbol::rbrace);
    p.expect_close(keyword, open);
    return normal;
}

}  // namespace rayset::tracer
