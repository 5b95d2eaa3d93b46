// Patterns (reference 3.4.7): the pattern types with their parameters, the pattern modifiers
// (turbulence, warps, frequency, phase, waveforms, noise_generator and each kind's own), and
// pattern functions (`function { pattern { ... } }`). One reading serves pigments, normals,
// textures, densities and functions; the role decides which patterns and lists are allowed.
#include <cmath>

#include <fmt/format.h>

#include "tracer/scene_language/appearance_grammar.h"

namespace rayset::tracer {
namespace {

// The pattern a keyword names: its keyword is its name (pattern_name), and magnet starts a
// magnet mandel or julia.
bool pattern_keyword(Parser& p, const Token& token, PatternKind& kind) {
    if (token.kind != TokenKind::word || !is_keyword(token.name)) return false;
    if (token.is(Keyword::magnet)) {
        kind = PatternKind::mandel;  // or julia: the keyword after the magnet type says
        return true;
    }
    const std::string& word = p.word(token);
    for (int k = static_cast<int>(PatternKind::agate);
         k <= static_cast<int>(PatternKind::material_map); ++k)
        if (word == pattern_name(static_cast<PatternKind>(k))) {
            kind = static_cast<PatternKind>(k);
            return true;
        }
    return false;
}

// Which patterns a role may use: POV-Ray 3.7 keeps facets to normals, each bitmap to its own
// item, and leaves some patterns out of pattern functions (checked against POV-Ray 3.7.0).
bool allowed_in(PatternKind kind, PatternRole role) {
    switch (kind) {
        case PatternKind::facets:
        case PatternKind::bump_map: return role == PatternRole::normal;
        case PatternKind::image_map: return role == PatternRole::pigment;
        case PatternKind::material_map: return role == PatternRole::texture;
        case PatternKind::aoi:
        case PatternKind::average:
        case PatternKind::pavement:
        case PatternKind::square:
        case PatternKind::tiling:
        case PatternKind::triangular:
        case PatternKind::slope: return role != PatternRole::function;
        default: return true;
    }
}

const char* roles_allowed(PatternKind kind) {
    switch (kind) {
        case PatternKind::facets:
        case PatternKind::bump_map: return "a normal";
        case PatternKind::image_map: return "a pigment";
        case PatternKind::material_map: return "a texture";
        default:
            return "a pigment, normal, texture or density (not a pattern function, in POV-Ray 3.7)";
    }
}

// ---------------------------------------------------------------- parameters of the types

void parse_fractal(Parser& p, const Token& keyword, Pattern& pattern) {
    FractalParameters& fractal = pattern.fractal;
    Token type_keyword = keyword;
    fractal.magnet = 0;
    if (keyword.is(Keyword::magnet)) {
        const Token at = p.peek();
        fractal.magnet = p.parse_int("as the magnet type", 0);
        if (fractal.magnet != 1 && fractal.magnet != 2)
            p.fail(at, fmt::format("the magnet type must be 1 or 2, found {}", fractal.magnet));
        type_keyword = p.next();
        if (!type_keyword.is(Keyword::mandel) && !type_keyword.is(Keyword::julia))
            p.fail_expected("'mandel' or 'julia' after the magnet type", type_keyword);
    }
    pattern.kind = type_keyword.is(Keyword::julia) ? PatternKind::julia : PatternKind::mandel;
    if (pattern.kind == PatternKind::julia) {
        const Numeric c = p.parse_vector_terms(2);
        fractal.julia_real = c.v[0];
        fractal.julia_imaginary = c.v[1];
        p.accept_comma();
    }
    fractal.iterations = p.parse_int("as the number of iterations", 0);
}

void parse_slope(Parser& p, const Token& keyword, SlopeParameters& slope) {
    slope = SlopeParameters{};
    if (!p.peek_is(Symbol::lbrace)) {
        // The older form `slope <Direction>`, which POV-Ray 3.7 still reads (balcony.pov).
        slope.direction = p.parse_vector();
        return;
    }
    const Token open = p.expect_open(keyword);
    slope.point_at = p.accept(Keyword::point_at);
    slope.direction = p.parse_vector();
    if (p.accept(Symbol::comma)) {
        slope.low_slope = p.parse_float("as the low slope");
        p.accept_comma();
        slope.high_slope = p.parse_float("as the high slope");
    }
    if (!slope.point_at && p.peek_is(Keyword::altitude)) {
        p.next();
        slope.altitude_given = true;
        slope.altitude = p.parse_vector();
        if (p.accept(Symbol::comma)) {
            slope.low_altitude = p.parse_float("as the low altitude");
            p.accept_comma();
            slope.high_altitude = p.parse_float("as the high altitude");
        }
    }
    p.expect_close(keyword, open);
}

void parse_object_pattern_object(Parser& p, Pattern& pattern) {
    if (p.take_declared(pattern.object)) {
        return;
    } else if (starts_object(p, p.peek())) {
        pattern.object = parse_object(p);
    } else {
        p.fail_identifier(p.peek(), "an object identifier or an object in the 'object' pattern");
    }
}

void parse_density_file(Parser& p, Pattern& pattern) {
    p.expect(Keyword::df3, "after 'density_file' (the only format)");
    const Token name_token = p.peek();
    const std::string name = p.parse_string();
    pattern.density_file = p.resolve_file(name, name_token, "density file");
}

// The parameters that follow some pattern keywords (gradient <v>, spiral1 N, julia <c>, N ...).
void parse_type_parameters(Parser& p, const Token& keyword, Pattern& pattern) {
    switch (pattern.kind) {
        case PatternKind::gradient: pattern.gradient = p.parse_vector(); break;
        case PatternKind::spiral1:
        case PatternKind::spiral2:
            pattern.spiral_arms = truncated(p.parse_float("as the number of spiral arms"));
            break;
        case PatternKind::tiling: {
            const Token at = p.peek();
            pattern.tiling = truncated(p.parse_float("as the tiling number"));
            if (pattern.tiling < 1 || pattern.tiling > 27)
                p.fail(at, fmt::format("the tiling number must be between 1 and 27, found {}",
                                       pattern.tiling));
            break;
        }
        case PatternKind::mandel:
        case PatternKind::julia: parse_fractal(p, keyword, pattern); break;
        case PatternKind::slope: parse_slope(p, keyword, pattern.slope); break;
        case PatternKind::density_file: parse_density_file(p, pattern); break;
        case PatternKind::function: pattern.function = p.parse_function(keyword); break;
        case PatternKind::pigment_pattern: pattern.pigment = parse_pigment(p, keyword); break;
        case PatternKind::image_pattern:
        case PatternKind::image_map: pattern.image = parse_image(p, keyword); break;
        default: break;
    }
}

// ---------------------------------------------------------------- warps

const std::vector<KeywordField<Turbulence>>& turbulence_fields() {
    static const std::vector<KeywordField<Turbulence>> fields = {
        whole_field(Keyword::octaves, &Turbulence::octaves, 0),
        number_field(Keyword::omega, &Turbulence::omega),
        number_field(Keyword::lambda, &Turbulence::lambda),
    };
    return fields;
}

void parse_repeat_warp(Parser& p, const Token& at, Warp& warp) {
    warp.kind = Warp::Kind::repeat;
    warp.repeat = p.parse_vector();
    const int axes = (warp.repeat.x != 0) + (warp.repeat.y != 0) + (warp.repeat.z != 0);
    if (axes == 0) p.fail(at, "a repeat warp needs a direction along one axis, found <0, 0, 0>");
    if (axes > 1)
        p.fail(at, "a repeat warp repeats along one axis only (two components must be 0)");
    static const std::vector<KeywordField<Warp>> fields = {
        vector_field(Keyword::offset, &Warp::offset),
        vector_field(Keyword::flip, &Warp::flip),
    };
    while (parse_keyword_field(p, warp, fields)) {
    }
}

void parse_black_hole_warp(Parser& p, Warp& warp) {
    warp.kind = Warp::Kind::black_hole;
    warp.centre = p.parse_vector();
    p.accept_comma();
    warp.radius = p.parse_float("as the black hole radius");
    static const std::vector<KeywordField<Warp>> fields = {
        number_field(Keyword::strength, &Warp::strength),
        number_field(Keyword::falloff, &Warp::falloff),
        flag_field(Keyword::inverse, &Warp::inverse),
        whole_field(Keyword::type, &Warp::black_hole_type, 0),
        vector_field(Keyword::repeat, &Warp::black_hole_repeat),
        vector_field(Keyword::turbulence, &Warp::black_hole_turbulence),
    };
    while (parse_keyword_field(p, warp, fields)) {
    }
}

// cylindrical, spherical, toroidal: orientation, dist_exp; toroidal also major_radius.
void parse_mapping_warp(Parser& p, Warp& warp) {
    static const std::vector<KeywordField<Warp>> fields = {
        vector_field(Keyword::orientation, &Warp::orientation),
        number_field(Keyword::dist_exp, &Warp::distance_exponent),
    };
    static const std::vector<KeywordField<Warp>> toroidal_fields = {
        vector_field(Keyword::orientation, &Warp::orientation),
        number_field(Keyword::dist_exp, &Warp::distance_exponent),
        number_field(Keyword::major_radius, &Warp::major_radius),
    };
    while (parse_keyword_field(p, warp,
                               warp.kind == Warp::Kind::toroidal ? toroidal_fields : fields)) {
    }
}

Warp parse_warp(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    Warp warp;
    warp.location = p.location_of(keyword);
    const Token item = p.next();
    if (item.is(Keyword::repeat)) {
        parse_repeat_warp(p, item, warp);
    } else if (item.is(Keyword::black_hole)) {
        parse_black_hole_warp(p, warp);
    } else if (item.is(Keyword::turbulence)) {
        warp.kind = Warp::Kind::turbulence;
        warp.turbulence.amount = p.parse_vector();
        while (parse_keyword_field(p, warp.turbulence, turbulence_fields())) {
        }
    } else if (item.is(Keyword::cylindrical) || item.is(Keyword::spherical) ||
               item.is(Keyword::toroidal)) {
        warp.kind = item.is(Keyword::cylindrical) ? Warp::Kind::cylindrical
                    : item.is(Keyword::spherical) ? Warp::Kind::spherical
                                                  : Warp::Kind::toroidal;
        parse_mapping_warp(p, warp);
    } else if (item.is(Keyword::planar)) {
        warp.kind = Warp::Kind::planar;
        if (!p.peek_is(Symbol::rbrace)) {
            warp.plane_normal = p.parse_vector();
            p.accept_comma();
            warp.plane_distance = p.parse_float("as the planar warp's distance");
        }
    } else if (item.is(Keyword::cubic)) {
        warp.kind = Warp::Kind::cubic;
    } else {
        p.fail_expected(
            "repeat, black_hole, turbulence, cylindrical, spherical, toroidal, planar or cubic in "
            "'warp'",
            item);
    }
    p.expect_close(keyword, open);
    return warp;
}

// ---------------------------------------------------------------- kind-specific modifiers

// A modifier only some pattern kinds take, with POV-Ray's rule and its message.
struct KindModifier {
    Keyword keyword;
    std::initializer_list<PatternKind> kinds;
    const char* kinds_text;
};

const KindModifier kKindModifiers[] = {
    {Keyword::agate_turb, {PatternKind::agate}, "agate"},
    {Keyword::brick_size, {PatternKind::brick}, "brick"},
    {Keyword::mortar, {PatternKind::brick}, "brick"},
    {Keyword::control0, {PatternKind::quilted}, "quilted"},
    {Keyword::control1, {PatternKind::quilted}, "quilted"},
    {Keyword::metric, {PatternKind::crackle, PatternKind::facets}, "crackle or facets"},
    {Keyword::offset, {PatternKind::crackle}, "crackle"},
    {Keyword::solid, {PatternKind::crackle}, "crackle"},
    {Keyword::form, {PatternKind::crackle, PatternKind::pavement}, "crackle or pavement"},
    {Keyword::coords, {PatternKind::facets}, "facets"},
    {Keyword::size, {PatternKind::facets}, "facets"},
    {Keyword::interpolate, {PatternKind::density_file}, "density_file"},
    {Keyword::exponent, {PatternKind::mandel, PatternKind::julia}, "mandel or julia (not magnet)"},
    {Keyword::interior,
     {PatternKind::mandel, PatternKind::julia, PatternKind::pavement},
     "fractal or pavement"},
    {Keyword::exterior,
     {PatternKind::mandel, PatternKind::julia, PatternKind::pavement},
     "fractal or pavement"},
    {Keyword::pattern, {PatternKind::pavement}, "pavement"},
};

bool is_kind_modifier(const Token& token, const KindModifier*& modifier) {
    for (const KindModifier& entry : kKindModifiers)
        if (token.is(entry.keyword)) {
            modifier = &entry;
            return true;
        }
    return false;
}

void parse_fractal_colouring(Parser& p, const Token& keyword, Pattern& pattern) {
    const bool exterior = keyword.is(Keyword::exterior);
    const Token at = p.peek();
    const int type = truncated(p.parse_float(fmt::format("as the {} type", p.word(keyword))));
    const int highest = exterior ? 8 : 6;
    if (type < 0 || type > highest)
        p.fail(at, fmt::format("the fractal {} type must be 0 to {}, found {}", p.word(keyword),
                               highest, type));
    p.accept_comma();
    const double factor = p.parse_float(fmt::format("as the {} factor", p.word(keyword)));
    if (exterior)
        pattern.fractal.exterior_type = type, pattern.fractal.exterior_factor = factor;
    else
        pattern.fractal.interior_type = type, pattern.fractal.interior_factor = factor;
}

// After a kind modifier's keyword (taken), allowed for this pattern.
void parse_kind_modifier(Parser& p, const Token& keyword, Pattern& pattern) {
    auto after = [&] { return fmt::format("after '{}'", p.word(keyword)); };
    auto whole = [&] { return truncated(p.parse_float(after())); };
    const bool pavement = pattern.kind == PatternKind::pavement;
    switch (static_cast<Keyword>(keyword.name)) {
        case Keyword::agate_turb: pattern.agate_turbulence = p.parse_float(after()); break;
        case Keyword::brick_size: pattern.brick_size = p.parse_vector(); break;
        case Keyword::mortar: pattern.mortar = p.parse_float(after()); break;
        case Keyword::control0: pattern.quilted_control0 = p.parse_float(after()); break;
        case Keyword::control1: pattern.quilted_control1 = p.parse_float(after()); break;
        case Keyword::metric: pattern.crackle.metric = p.parse_float(after()); break;
        case Keyword::offset: pattern.crackle.offset = p.parse_float(after()); break;
        case Keyword::solid: pattern.crackle.solid = p.parse_optional_bool(); break;
        case Keyword::form:
            if (pavement)
                pattern.pavement.form = whole();
            else
                pattern.crackle.form = p.parse_vector();
            break;
        case Keyword::coords: pattern.facets_coords = p.parse_float(after()); break;
        case Keyword::size: pattern.facets_size = p.parse_float(after()); break;
        case Keyword::interpolate: pattern.interpolate = whole(); break;
        case Keyword::exponent: pattern.fractal.exponent = whole(); break;
        case Keyword::pattern: pattern.pavement.pattern = whole(); break;
        case Keyword::interior:
        case Keyword::exterior:
            if (!pavement)
                parse_fractal_colouring(p, keyword, pattern);
            else if (keyword.is(Keyword::interior))
                pattern.pavement.interior = whole();
            else
                pattern.pavement.exterior = whole();
            break;
        default: break;
    }
}

Waveform waveform_of(const Token& token, bool& found) {
    found = true;
    if (token.is(Keyword::ramp_wave)) return Waveform::ramp;
    if (token.is(Keyword::triangle_wave)) return Waveform::triangle;
    if (token.is(Keyword::sine_wave)) return Waveform::sine;
    if (token.is(Keyword::scallop_wave)) return Waveform::scallop;
    if (token.is(Keyword::cubic_wave)) return Waveform::cubic;
    if (token.is(Keyword::poly_wave)) return Waveform::poly;
    found = false;
    return Waveform::ramp;
}

const std::vector<KeywordField<Pattern>>& pattern_fields() {
    static const std::vector<KeywordField<Pattern>> fields = {
        number_field(Keyword::phase, &Pattern::phase),
        flag_field(Keyword::uv_mapping, &Pattern::uv_mapping),
    };
    return fields;
}

// Modifiers every pattern takes; false when the next token is none of them.
bool parse_general_modifier(Parser& p, const Token& token, Pattern& pattern) {
    bool is_wave = false;
    const Waveform wave = waveform_of(token, is_wave);
    if (is_wave) {
        p.next();
        pattern.waveform = wave;
        if (wave == Waveform::poly)
            pattern.poly_exponent = p.starts_expression(p.peek()) ? p.parse_float() : 1.0;
        return true;
    }
    if (parse_keyword_field(p, pattern, pattern_fields()) ||
        parse_keyword_field(p, pattern.turbulence, turbulence_fields()))
        return true;
    if (p.accept(Keyword::turbulence)) {
        pattern.turbulence.amount = p.parse_vector();
    } else if (p.accept(Keyword::frequency)) {
        pattern.frequency = p.parse_float("after 'frequency'");
        pattern.frequency_written = true;
    } else if (p.accept(Keyword::warp)) {
        pattern.warps.push_back(parse_warp(p, token));
    } else if (p.accept(Keyword::noise_generator)) {
        const Token at = p.peek();
        pattern.noise_generator = truncated(p.parse_float("after 'noise_generator'"));
        if (pattern.noise_generator < 0 || pattern.noise_generator > 3)
            p.fail(at, fmt::format("noise_generator must be 0, 1, 2 or 3, found {}",
                                   pattern.noise_generator));
        if (pattern.noise_generator == 0)
            pattern.noise_generator = p.scene().global.noise_generator;
    } else {
        return false;
    }
    return true;
}

}  // namespace

const char* role_name(PatternRole role) {
    switch (role) {
        case PatternRole::pigment: return "pigment";
        case PatternRole::normal: return "normal";
        case PatternRole::texture: return "texture";
        case PatternRole::density: return "density";
        case PatternRole::function: return "pattern";
    }
    return "";
}

bool is_pattern_type(Parser& p, const Token& token, PatternRole role) {
    (void)role;  // a pattern not allowed in the role is reported by parse_pattern_type
    PatternKind kind;
    return pattern_keyword(p, token, kind);
}

BlendMapPointer parse_pattern_type(Parser& p, const Token& keyword, Pattern& pattern,
                                   PatternRole role, double* amount) {
    PatternKind kind = PatternKind::plain;
    pattern_keyword(p, keyword, kind);
    if (!allowed_in(kind, role))
        p.fail(keyword, fmt::format("'{}' can only be used in {}, found in a {}", p.word(keyword),
                                    roles_allowed(kind), role_name(role)));
    pattern.kind = kind;
    pattern.location = p.location_of(keyword);
    if (pattern.noise_generator == 0) pattern.noise_generator = p.scene().global.noise_generator;
    // POV-Ray's patterns that default to a triangle wave set it with their keyword; the others
    // keep the waveform a pattern identifier brought (checked with POV-Ray 3.7).
    if (kind == PatternKind::marble || kind == PatternKind::wood || kind == PatternKind::spiral1 ||
        kind == PatternKind::spiral2)
        pattern.waveform = Waveform::triangle;
    BlendMapPointer list;
    if (kind == PatternKind::bump_map) {
        // bump_map { ... bump_size AMOUNT }: the normal's amount
        pattern.image = parse_image(p, keyword, [&] {
            if (!amount || !p.peek_is(Keyword::bump_size)) return false;
            p.next();
            *amount = p.parse_float("after 'bump_size'");
            return true;
        });
    } else if (kind == PatternKind::material_map) {
        // material_map { IMAGE MODIFIERS TEXTURE... }: the image's index picks a texture
        auto textures = std::make_shared<BlendMap>();
        textures->kind = BlendMapKind::texture;
        pattern.image = parse_image(p, keyword, [&] {
            const Token item = p.peek();
            if (!item.is(Keyword::texture)) return false;
            p.next();
            const Token open = p.expect_open(item);
            BlendMapEntry entry;
            entry.value = static_cast<double>(textures->entries.size());
            entry.texture = parse_texture_body(p, item, open, Symbol::rbrace);
            p.expect_close(item, open);
            textures->entries.push_back(entry);
            return true;
        });
        if (textures->entries.empty())
            p.fail(keyword, "a material_map needs at least one texture (POV-Ray's rule)");
        list = textures;
    } else if (kind == PatternKind::object) {
        // object { OBJECT LIST_ITEM_A, LIST_ITEM_B }: the list inside the braces
        const Token open = p.expect_open(keyword);
        parse_object_pattern_object(p, pattern);
        list = parse_block_list(p, kind, role);
        p.expect_close(keyword, open);
    } else {
        parse_type_parameters(p, keyword, pattern);
    }
    if (amount) {  // normals: PATTERN [,] [Bump_Size]
        const bool comma = p.accept(Symbol::comma);
        if (comma || p.starts_expression(p.peek())) *amount = p.parse_float("as the bump size");
    }
    if (list_size(kind) > 0 && kind != PatternKind::object && kind != PatternKind::material_map)
        list = parse_block_list(p, kind, role);
    return list;
}

bool parse_pattern_modifier(Parser& p, Pattern& pattern, PatternRole role) {
    (void)role;
    const Token token = p.peek();
    if (parse_general_modifier(p, token, pattern)) return true;
    const KindModifier* modifier = nullptr;
    if (is_kind_modifier(token, modifier) || token.is(Keyword::number_of_sides) ||
        token.is(Keyword::number_of_tiles)) {
        if (!modifier) {  // number_of_sides, number_of_tiles: pavement
            if (pattern.kind != PatternKind::pavement)
                p.fail(token, fmt::format("'{}' can only be used with pavement, found with {}",
                                          p.word(token), pattern_name(pattern.kind)));
            p.next();
            const int value = truncated(p.parse_float(fmt::format("after '{}'", p.word(token))));
            (token.is(Keyword::number_of_sides) ? pattern.pavement.sides : pattern.pavement.tiles) =
                value;
            return true;
        }
        bool allowed = false;
        for (PatternKind kind : modifier->kinds) allowed = allowed || kind == pattern.kind;
        if (!allowed)
            p.fail(token, fmt::format("'{}' can only be used with {}, found with {}", p.word(token),
                                      modifier->kinds_text, pattern_name(pattern.kind)));
        p.next();
        parse_kind_modifier(p, token, pattern);
        return true;
    }
    return false;
}

std::shared_ptr<const Pattern> parse_function_pattern(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto pattern = std::make_shared<Pattern>();
    const Token type = p.next();
    if (!is_pattern_type(p, type, PatternRole::function))
        p.fail_identifier(type, fmt::format("a pattern type after 'pattern {{' opened at {}",
                                            p.location_of(open).str()));
    parse_pattern_type(p, type, *pattern, PatternRole::function, nullptr);
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        Matrix4 transform;
        if (p.parse_transform_item(transform)) {
            transform_pattern(*pattern, transform);
            continue;
        }
        if (!parse_pattern_modifier(p, *pattern, PatternRole::function))
            p.fail_identifier(p.peek(), fmt::format("a pattern modifier or {}",
                                                    closing_purpose(p, keyword, open)));
    }
    p.expect_close(keyword, open);
    return pattern;
}

std::string closing_purpose(Parser& p, const Token& keyword, const Token& open, Symbol close) {
    return fmt::format("'{}' to close '{}' opened at {}", symbol_text(close), p.word(keyword),
                       p.location_of(open).str());
}

bool is_word(Parser& p, const Token& token, const char* word) {
    return token.kind == TokenKind::word && p.word(token) == word;
}

}  // namespace rayset::tracer
