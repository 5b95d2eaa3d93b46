// texture { pigment { ... } finish { ... } }, interior { ior }, material, and #default. Pigments
// are uniform colours; patterns and normals are reported as not supported.
#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"

namespace rayset::tracer {
namespace {

void parse_pigment_body(Parser& p, Pigment& pigment, const Token& keyword, const Token& open) {
    if (const PigmentRef* declared = p.peek_declared<PigmentRef>()) {
        pigment = **declared;
        p.next();
    }
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (p.starts_colour(token)) {
            pigment.colour = p.parse_colour();
            continue;
        }
        Matrix4 ignored;  // transforms do not change a uniform colour
        if (!p.parse_transform_item(ignored))
            p.fail_identifier(token, fmt::format("a colour or '}}' to close '{}' opened at {}", p.word(keyword),
                                                 p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
}

Rgb parse_rgb(Parser& p) { return p.parse_colour().rgb(); }  // a float or a colour

void parse_finish_body(Parser& p, Finish& finish, const Token& keyword, const Token& open) {
    if (const FinishRef* declared = p.peek_declared<FinishRef>()) {
        finish = **declared;
        p.next();
    }
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        auto after = [&] { return fmt::format("after '{}'", p.word(token)); };
        if (token.is(Keyword::ambient)) {
            p.next();
            finish.ambient = parse_rgb(p);
        } else if (token.is(Keyword::emission)) {
            p.next();
            finish.emission = parse_rgb(p);
        } else if (token.is(Keyword::diffuse)) {
            p.next();
            if (p.peek_is(Keyword::albedo)) p.fail_not_supported(p.peek(), "'albedo'");
            finish.diffuse = p.parse_float(after());
            if (p.accept(Symbol::comma)) p.fail_not_supported(token, "diffuse with a back-side value");
        } else if (token.is(Keyword::brilliance)) {
            p.next();
            finish.brilliance = p.parse_float(after());
        } else if (token.is(Keyword::specular)) {
            p.next();
            finish.specular = p.parse_float(after());
        } else if (token.is(Keyword::roughness)) {
            p.next();
            const Token at = p.peek();
            finish.roughness = p.parse_float(after());
            if (!(finish.roughness > 0)) p.fail(at, "roughness must be positive");
        } else if (token.is(Keyword::phong)) {
            p.next();
            finish.phong = p.parse_float(after());
        } else if (token.is(Keyword::phong_size)) {
            p.next();
            finish.phong_size = p.parse_float(after());
        } else if (token.is(Keyword::metallic)) {
            p.next();
            finish.metallic = p.starts_expression(p.peek()) ? p.parse_float() : 1.0;
        } else if (token.is(Keyword::conserve_energy)) {
            p.next();
            finish.conserve_energy = p.parse_optional_bool();
        } else if (token.is(Keyword::reflection)) {
            p.next();
            if (p.peek_is(Symbol::lbrace)) {
                // reflection { [min,] max [fresnel on] [falloff F] [metallic M] }
                const Token reflection_open = p.expect_open(token);
                const Rgb first_value = parse_rgb(p);
                p.accept_comma();
                finish.reflection_min = finish.reflection_max = first_value;
                if (p.starts_colour(p.peek())) finish.reflection_max = parse_rgb(p);
                for (;;) {
                    if (p.peek_is(Symbol::rbrace)) break;
                    const Token item = p.next();
                    if (item.is(Keyword::fresnel)) finish.reflection_fresnel = p.parse_optional_bool();
                    else if (item.is(Keyword::falloff)) finish.reflection_falloff = p.parse_float("after 'falloff'");
                    else if (item.is(Keyword::metallic))
                        finish.metallic = p.starts_expression(p.peek()) ? p.parse_float() : 1.0;
                    else p.fail_identifier(item, fmt::format("fresnel, falloff, metallic or '}}' to close 'reflection' "
                                                             "opened at {}", p.location_of(reflection_open).str()));
                }
                p.expect_close(token, reflection_open);
            } else {
                finish.reflection_min = finish.reflection_max = parse_rgb(p);
            }
        } else {
            p.fail_identifier(token, fmt::format("a finish keyword or '}}' to close '{}' opened at {}", p.word(keyword),
                                                 p.location_of(open).str()));
        }
    }
    p.expect_close(keyword, open);
}

}  // namespace

bool parse_appearance_modifier(Parser& p, ObjectAppearance& appearance) {
    const Token keyword = p.peek();
    auto texture_to_modify = [&]() -> Texture& {
        auto texture = std::make_shared<Texture>(appearance.texture ? *appearance.texture
                                                 : p.default_texture  ? *p.default_texture
                                                                      : Texture{});
        appearance.texture = texture;
        return *texture;
    };
    if (keyword.is(Keyword::texture)) {
        if (appearance.texture) p.fail_not_supported(keyword, "layered textures (a second texture on one object)");
        p.next();
        appearance.texture = parse_texture(p, keyword);
    } else if (keyword.is(Keyword::pigment)) {
        p.next();
        const PigmentRef pigment = parse_pigment(p, keyword);
        texture_to_modify().pigment = *pigment;
    } else if (keyword.is(Keyword::finish)) {
        p.next();
        const FinishRef finish = parse_finish(p, keyword);
        texture_to_modify().finish = *finish;
    } else if (keyword.is(Keyword::interior)) {
        p.next();
        appearance.interior = parse_interior(p, keyword);
    } else {
        return false;
    }
    return true;
}

void inherit_appearance(ObjectAppearance& inner, const ObjectAppearance& outer) {
    if (!inner.texture) inner.texture = outer.texture;
    if (!inner.interior) inner.interior = outer.interior;
}

TextureRef parse_texture(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto texture = std::make_shared<Texture>(p.default_texture ? *p.default_texture : Texture{});
    if (const TextureRef* declared = p.peek_declared<TextureRef>()) {
        *texture = **declared;
        p.next();
    }
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (token.is(Keyword::pigment)) {
            p.next();
            const Token pigment_open = p.expect_open(token);
            parse_pigment_body(p, texture->pigment, token, pigment_open);
        } else if (token.is(Keyword::finish)) {
            p.next();
            const Token finish_open = p.expect_open(token);
            parse_finish_body(p, texture->finish, token, finish_open);
        } else if (token.is(Keyword::normal)) {
            p.fail_not_supported(token, "normal (bump) patterns");
        } else {
            Matrix4 ignored;  // transforms do not change a uniform colour
            if (!p.parse_transform_item(ignored))
                p.fail_identifier(token, fmt::format("pigment, finish or '}}' to close 'texture' opened at {}",
                                                     p.location_of(open).str()));
        }
    }
    p.expect_close(keyword, open);
    return texture;
}

PigmentRef parse_pigment(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto pigment = std::make_shared<Pigment>();
    parse_pigment_body(p, *pigment, keyword, open);
    return pigment;
}

FinishRef parse_finish(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto finish = std::make_shared<Finish>();
    parse_finish_body(p, *finish, keyword, open);
    return finish;
}

InteriorRef parse_interior(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto interior = std::make_shared<Interior>();
    if (const InteriorRef* declared = p.peek_declared<InteriorRef>()) {
        *interior = **declared;
        p.next();
    }
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (token.is(Keyword::ior)) {
            p.next();
            const Token at = p.peek();
            interior->ior = p.parse_float("after 'ior'");
            if (!(interior->ior > 0)) p.fail(at, "ior must be positive");
        } else {
            p.fail_identifier(token, fmt::format("ior or '}}' to close 'interior' opened at {}", p.location_of(open).str()));
        }
    }
    p.expect_close(keyword, open);
    return interior;
}

NormalRef parse_normal(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "normal (bump) patterns"); }
MediaRef parse_media(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'media'"); }
DensityRef parse_density(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'density'"); }
ColourMapRef parse_colour_map(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'color_map'"); }
PigmentMapRef parse_pigment_map(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'pigment_map'"); }
NormalMapRef parse_normal_map(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'normal_map'"); }
SlopeMapRef parse_slope_map(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'slope_map'"); }
TextureMapRef parse_texture_map(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'texture_map'"); }
DensityMapRef parse_density_map(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'density_map'"); }

MaterialRef parse_material(Parser& p, const Token& keyword) {
    p.fail_not_supported(keyword, "'material'");
}

void parse_default(Parser& p, const Token& directive) {
    p.fail_not_supported(directive, "#default");
}

std::shared_ptr<const Pattern> parse_function_pattern(Parser& p, const Token& keyword) {
    p.fail_not_supported(keyword, "pattern functions");
}

bool evaluate_pattern(const Pattern& pattern, Vec3 point, double& value) {
    (void)pattern, (void)point, (void)value;
    return false;
}

bool evaluate_pigment(const Pigment& pigment, Vec3 point, Colour& colour) {
    (void)point;
    colour = pigment.colour;
    return true;
}

}  // namespace rayset::tracer
