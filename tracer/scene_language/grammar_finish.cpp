// finish { ... } (reference 3.4.6.3): every keyword of POV-Ray 3.7's finish, and the interior
// keywords POV-Ray still takes there with a warning (ior, refraction, caustics).
#include <fmt/format.h>

#include "tracer/scene_language/appearance_grammar.h"

namespace rayset::tracer {
namespace {

Rgb parse_rgb(Parser& p) { return p.parse_colour().rgb(); }  // a float or a colour

double optional_amount(Parser& p, double if_absent) {
    return p.starts_expression(p.peek()) ? p.parse_float() : if_absent;
}

// reflection { [min,] max [fresnel B] [falloff F] [exponent E] [metallic M] }
void parse_reflection_block(Parser& p, Finish& finish, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    const Rgb first = parse_rgb(p);
    p.accept_comma();
    finish.reflection_min = finish.reflection_max = first;
    if (p.starts_colour(p.peek())) finish.reflection_max = parse_rgb(p);
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        const Token item = p.next();
        if (item.is(Keyword::fresnel))
            finish.reflection_fresnel = p.parse_optional_bool();
        else if (item.is(Keyword::falloff))
            finish.reflection_falloff = p.parse_float("after 'falloff'");
        else if (item.is(Keyword::exponent))
            finish.reflection_exponent = p.parse_float("after 'exponent'");
        else if (item.is(Keyword::metallic))
            finish.reflection_metallic = optional_amount(p, 1.0);
        else
            p.fail_identifier(item, fmt::format("fresnel, falloff, exponent, metallic or {}",
                                                closing_purpose(p, keyword, open)));
    }
    p.expect_close(keyword, open);
}

// irid { AMOUNT [thickness T] [turbulence U] }
void parse_irid(Parser& p, Finish& finish, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    finish.irid_amount = p.parse_float("as the iridescence amount");
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        const Token item = p.next();
        if (item.is(Keyword::thickness))
            finish.irid_thickness = p.parse_float("after 'thickness'");
        else if (item.is(Keyword::turbulence))
            finish.irid_turbulence = p.parse_float("after 'turbulence'");
        else
            p.fail_identifier(item, fmt::format("thickness, turbulence or {}",
                                                closing_purpose(p, keyword, open)));
    }
    p.expect_close(keyword, open);
}

// subsurface { translucency COLOUR }
void parse_subsurface(Parser& p, Finish& finish, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    finish.subsurface = true;
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        const Token item = p.next();
        if (item.is(Keyword::translucency))
            finish.translucency = parse_rgb(p);
        else
            p.fail_identifier(item,
                              fmt::format("translucency or {}", closing_purpose(p, keyword, open)));
    }
    p.expect_close(keyword, open);
}

// diffuse, phong, specular: [albedo] AMOUNT (diffuse: [, BACK_AMOUNT]).
void parse_lobe(Parser& p, const Token& keyword, Finish& finish) {
    const bool albedo = p.accept(Keyword::albedo);
    const double amount = p.parse_float(fmt::format("after '{}'", p.word(keyword)));
    if (keyword.is(Keyword::diffuse)) {
        finish.diffuse = amount;
        finish.diffuse_albedo = albedo;
        if (p.accept(Symbol::comma))
            finish.diffuse_back = p.parse_float("as the back-side diffuse amount");
    } else if (keyword.is(Keyword::phong)) {
        finish.phong = amount;
        finish.phong_albedo = albedo;
    } else {
        finish.specular = amount;
        finish.specular_albedo = albedo;
    }
}

// ior, refraction and caustics in a finish: POV-Ray reads them with a warning.
void parse_legacy_interior_item(Parser& p, const Token& keyword, Finish& finish) {
    p.warn(
        keyword,
        fmt::format("'{}' belongs in interior {{ }}; POV-Ray reads it from a finish for old scenes",
                    p.word(keyword)));
    const double value = p.parse_float(fmt::format("after '{}'", p.word(keyword)));
    if (keyword.is(Keyword::ior))
        finish.legacy_ior = value;
    else if (keyword.is(Keyword::refraction))
        finish.legacy_refraction = value;
    else
        finish.legacy_caustics = value;
}

const std::vector<KeywordField<Finish>>& finish_fields() {
    static const std::vector<KeywordField<Finish>> fields = {
        colour_field(Keyword::ambient, &Finish::ambient),
        colour_field(Keyword::emission, &Finish::emission),
        number_field(Keyword::brilliance, &Finish::brilliance),
        number_field(Keyword::crand, &Finish::crand),
        number_field(Keyword::phong_size, &Finish::phong_size),
        number_field(Keyword::reflection_exponent, &Finish::reflection_exponent),
    };
    return fields;
}

// One finish item; false when the next token is none.
bool parse_finish_item(Parser& p, Finish& finish) {
    if (parse_keyword_field(p, finish, finish_fields())) return true;
    const Token token = p.peek();
    if (token.kind != TokenKind::word || !is_keyword(token.name)) return false;
    switch (static_cast<Keyword>(token.name)) {
        case Keyword::diffuse:
        case Keyword::phong:
        case Keyword::specular:
            p.next();
            parse_lobe(p, token, finish);
            return true;
        case Keyword::roughness: {
            p.next();
            const Token at = p.peek();
            finish.roughness = p.parse_float("after 'roughness'");
            if (!(finish.roughness > 0)) p.fail(at, "roughness must be positive");
            return true;
        }
        case Keyword::metallic:
            p.next();
            finish.metallic = optional_amount(p, 1.0);
            return true;
        case Keyword::conserve_energy:
            p.next();
            finish.conserve_energy = p.parse_optional_bool();
            return true;
        case Keyword::reflection:
            p.next();
            if (p.peek_is(Symbol::lbrace))
                parse_reflection_block(p, finish, token);
            else
                finish.reflection_min = finish.reflection_max = parse_rgb(p);
            return true;
        case Keyword::irid:
            p.next();
            parse_irid(p, finish, token);
            return true;
        case Keyword::subsurface:
            p.next();
            parse_subsurface(p, finish, token);
            return true;
        case Keyword::ior:
        case Keyword::refraction:
        case Keyword::caustics:
            p.next();
            parse_legacy_interior_item(p, token, finish);
            return true;
        default: return false;
    }
}

}  // namespace

void parse_finish_body(Parser& p, Finish& finish, const Token& keyword, const Token& open) {
    FinishRef declared;
    if (p.take_declared(declared)) finish = *declared;
    finish.location = p.location_of(keyword);
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        if (!parse_finish_item(p, finish))
            p.fail_identifier(
                p.peek(), fmt::format("a finish keyword or {}", closing_purpose(p, keyword, open)));
    }
}

FinishRef parse_finish(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto finish = std::make_shared<Finish>(default_finish(p));
    parse_finish_body(p, *finish, keyword, open);
    p.expect_close(keyword, open);
    return finish;
}

}  // namespace rayset::tracer
