// Maps and lists (reference 3.4.6.1.2-4, 3.4.6.2.1-2, 3.4.6.5.1, 3.4.8.4.3): color_map,
// pigment_map, normal_map, slope_map, texture_map and density_map with their identifiers, and
// the list of colours, pigments, normals, textures or densities after a block pattern.
#include <fmt/format.h>

#include "tracer/scene_language/appearance_grammar.h"

namespace rayset::tracer {
namespace {

constexpr size_t kMaxMapEntries = 256;  // POV-Ray's limit ("Blend_Map too long")

const char* map_keyword(BlendMapKind kind) {
    switch (kind) {
        case BlendMapKind::colour: return "color_map";
        case BlendMapKind::pigment: return "pigment_map";
        case BlendMapKind::normal: return "normal_map";
        case BlendMapKind::slope: return "slope_map";
        case BlendMapKind::texture: return "texture_map";
        case BlendMapKind::density: return "density_map";
    }
    return "";
}

BlendMapEntry colour_entry(double value, const Colour& colour) {
    BlendMapEntry entry;
    entry.value = value;
    entry.colour = colour;
    return entry;
}

// A colour entry after its value: `COLOUR`, or the old `Value_2 COLOUR_1 COLOUR_2` form, which
// becomes two entries (value_1, colour_1) and (value_2, colour_2).
void parse_colour_entry(Parser& p, BlendMap& map, double value, const Token& open) {
    const Colour first = p.parse_colour();
    p.accept_comma();
    if (p.peek_is(Symbol::rbracket)) {
        map.entries.push_back(colour_entry(value, first));
        return;
    }
    // Old form: what was read is the second value, a float filling all five terms.
    if (first.green != first.red || first.blue != first.red || first.filter != first.red ||
        first.transmit != first.red)
        p.fail_expected(
            fmt::format("']' to close the color_map entry opened at {}", p.location_of(open).str()),
            p.peek());
    map.entries.push_back(colour_entry(value, p.parse_colour()));
    p.accept_comma();
    map.entries.push_back(colour_entry(first.red, p.parse_colour()));
}

void parse_entry_item(Parser& p, BlendMap& map, BlendMapEntry& entry, const Token& open) {
    switch (map.kind) {
        case BlendMapKind::colour: break;  // read by parse_colour_entry
        case BlendMapKind::pigment:
        case BlendMapKind::density: {
            // A density starts black, a pigment as the #default one (as their blocks do).
            auto pigment = std::make_shared<Pigment>(
                map.kind == BlendMapKind::pigment ? default_pigment(p) : Pigment{});
            pigment->location = p.location_of(open);
            parse_pigment_body(
                p, *pigment,
                map.kind == BlendMapKind::pigment ? PatternRole::pigment : PatternRole::density,
                open, open, Symbol::rbracket);
            entry.pigment = pigment;
            break;
        }
        case BlendMapKind::normal: {
            auto normal = std::make_shared<Normal>(default_normal(p));
            normal->location = p.location_of(open);
            parse_normal_body(p, *normal, open, open, Symbol::rbracket);
            entry.normal = normal;
            break;
        }
        case BlendMapKind::slope: {
            const Numeric point = p.parse_vector_terms(2);
            entry.height = point.v[0];
            entry.slope = point.v[1];
            break;
        }
        case BlendMapKind::texture:
            entry.texture = parse_texture_body(p, open, open, Symbol::rbracket);
            break;
    }
}

// `[ VALUE [,] ITEM ]` entries up to the map's closing brace.
void parse_entries(Parser& p, BlendMap& map, const Token& keyword, bool weights_optional) {
    while (p.peek_is(Symbol::lbracket)) {
        const Token open = p.next();
        if (map.entries.size() >= kMaxMapEntries)
            p.fail(open, fmt::format("'{}' has more than {} entries (POV-Ray's limit)",
                                     p.word(keyword), kMaxMapEntries));
        BlendMapEntry entry;
        if (weights_optional && !p.starts_expression(p.peek()))
            entry.value = 1.0;  // average: weight 1
        else
            entry.value =
                p.parse_float(fmt::format("as the value of a '{}' entry", p.word(keyword)));
        p.accept_comma();
        if (map.kind == BlendMapKind::colour) {
            parse_colour_entry(p, map, entry.value, open);
        } else {
            parse_entry_item(p, map, entry, open);
            map.entries.push_back(entry);
        }
        p.expect(Symbol::rbracket, [&] {
            return fmt::format("to close the '{}' entry opened at {}", p.word(keyword),
                               p.location_of(open).str());
        });
    }
}

// A map identifier (or array element) of the kind.
bool take_declared_map(Parser& p, BlendMapKind kind, BlendMapPointer& result) {
    auto take = [&](auto tagged) {
        if (!p.take_declared(tagged)) return false;
        result = tagged.item;
        return true;
    };
    switch (kind) {
        case BlendMapKind::colour: return take(ColourMapRef{});
        case BlendMapKind::pigment: return take(PigmentMapRef{});
        case BlendMapKind::normal: return take(NormalMapRef{});
        case BlendMapKind::slope: return take(SlopeMapRef{});
        case BlendMapKind::texture: return take(TextureMapRef{});
        case BlendMapKind::density: return take(DensityMapRef{});
    }
    return false;
}

BlendMapPointer parse_map_block(Parser& p, const Token& keyword, BlendMapKind kind,
                                bool weights_optional) {
    const Token open = p.expect_open(keyword);
    BlendMapPointer result;
    if (!take_declared_map(p, kind, result)) {
        if (p.peek().is_identifier() && p.peek_value())
            p.fail_identifier(p.peek(),
                              fmt::format("a {} identifier or '[' entries", map_keyword(kind)));
        auto map = std::make_shared<BlendMap>();
        map->kind = kind;
        parse_entries(p, *map, keyword, weights_optional);
        if (map->entries.empty())
            p.fail_expected(
                fmt::format("at least one '[' entry in '{}' (POV-Ray's rule)", p.word(keyword)),
                p.peek());
        result = map;
    }
    if (!p.peek_is(Symbol::rbrace))
        p.fail_identifier(p.peek(), fmt::format("'[' or {}", closing_purpose(p, keyword, open)));
    p.expect_close(keyword, open);
    return result;
}

// One item of a block pattern's list, or false when the next token starts none.
bool parse_list_item(Parser& p, PatternRole role, BlendMapKind& kind, BlendMapEntry& entry,
                     bool first) {
    const Token token = p.peek();
    const bool colour =
        (role == PatternRole::pigment || role == PatternRole::density) && p.starts_colour(token);
    const Keyword item_keyword = role == PatternRole::pigment   ? Keyword::pigment
                                 : role == PatternRole::normal  ? Keyword::normal
                                 : role == PatternRole::texture ? Keyword::texture
                                                                : Keyword::density;
    const bool block = token.is(item_keyword);
    if (!colour && !block) return false;
    if (first) {
        kind = colour                         ? BlendMapKind::colour
               : role == PatternRole::pigment ? BlendMapKind::pigment
               : role == PatternRole::normal  ? BlendMapKind::normal
               : role == PatternRole::texture ? BlendMapKind::texture
                                              : BlendMapKind::density;
    } else if (colour != (kind == BlendMapKind::colour)) {
        return false;  // POV-Ray's lists are all colours or all blocks
    }
    if (colour) {
        entry.colour = p.parse_colour();
        return true;
    }
    p.next();
    switch (role) {
        case PatternRole::pigment: entry.pigment = parse_pigment(p, token); break;
        case PatternRole::density: entry.pigment = parse_density(p, token).item; break;
        case PatternRole::normal: entry.normal = parse_normal(p, token); break;
        case PatternRole::texture: {
            const Token open = p.expect_open(token);
            entry.texture = parse_texture_body(p, token, open, Symbol::rbrace);
            p.expect_close(token, open);
            break;
        }
        case PatternRole::function: break;
    }
    return true;
}

// A list item not written: the pattern's built-in colour, a flat normal, the default texture.
void fill_missing_item(Parser& p, PatternKind pattern, BlendMapKind kind, size_t index,
                       BlendMapEntry& entry) {
    const BlendMap& builtin = builtin_colour_map(pattern);
    const Colour colour = index < builtin.entries.size() ? builtin.entries[index].colour : Colour{};
    switch (kind) {
        case BlendMapKind::colour: entry.colour = colour; break;
        case BlendMapKind::pigment:
        case BlendMapKind::density: {
            auto pigment = std::make_shared<Pigment>();
            pigment->colour = colour;
            entry.pigment = pigment;
            break;
        }
        case BlendMapKind::normal: entry.normal = std::make_shared<Normal>(); break;
        case BlendMapKind::texture:
            entry.texture = std::make_shared<Texture>(default_texture(p));
            break;
        case BlendMapKind::slope: break;
    }
}

}  // namespace

BlendMapPointer parse_block_list(Parser& p, PatternKind kind, PatternRole role) {
    const int size = list_size(kind);
    if (size == 0 || role == PatternRole::function) return nullptr;
    auto map = std::make_shared<BlendMap>();
    for (int i = 0; i < size; ++i) {
        if (i > 0) p.accept_comma();
        BlendMapEntry entry;
        entry.value = i;
        if (!parse_list_item(p, role, map->kind, entry, i == 0)) break;
        map->entries.push_back(entry);
    }
    if (map->entries.empty()) return nullptr;
    p.accept_comma();
    for (size_t i = map->entries.size(); i < static_cast<size_t>(size); ++i) {
        BlendMapEntry entry;
        entry.value = static_cast<double>(i);
        fill_missing_item(p, kind, map->kind, i, entry);
        map->entries.push_back(entry);
    }
    return map;
}

BlendMapPointer parse_map_modifier(Parser& p, const Token& keyword, BlendMapKind kind,
                                   const Pattern& pattern) {
    const PatternKind k = pattern.kind;
    if (list_size(k) > 0 || k == PatternKind::image_map || k == PatternKind::bump_map ||
        k == PatternKind::material_map)
        p.fail(keyword,
               fmt::format(
                   "'{}' cannot be used with the {} pattern (POV-Ray's rule: it takes a list or "
                   "its image)",
                   p.word(keyword), pattern_name(k)));
    return parse_map_block(p, keyword, kind, k == PatternKind::average);
}

ColourMapRef parse_colour_map(Parser& p, const Token& keyword) {
    return {parse_map_block(p, keyword, BlendMapKind::colour, false)};
}
PigmentMapRef parse_pigment_map(Parser& p, const Token& keyword) {
    return {parse_map_block(p, keyword, BlendMapKind::pigment, false)};
}
NormalMapRef parse_normal_map(Parser& p, const Token& keyword) {
    return {parse_map_block(p, keyword, BlendMapKind::normal, false)};
}
SlopeMapRef parse_slope_map(Parser& p, const Token& keyword) {
    return {parse_map_block(p, keyword, BlendMapKind::slope, false)};
}
TextureMapRef parse_texture_map(Parser& p, const Token& keyword) {
    return {parse_map_block(p, keyword, BlendMapKind::texture, false)};
}
DensityMapRef parse_density_map(Parser& p, const Token& keyword) {
    return {parse_map_block(p, keyword, BlendMapKind::density, false)};
}

}  // namespace rayset::tracer
