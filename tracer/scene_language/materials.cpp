// texture { pigment { ... } finish { ... } }, and interior { ior }. Pigments are uniform
// colours only; patterns, normals and layered textures are reported as not supported.
#include <fmt/format.h>

#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace {

template <typename T>
const T* declared_as(const Value* value) {
    return value ? std::get_if<T>(value) : nullptr;
}

}  // namespace

Texture Parser::parse_texture(const Token& keyword) {
    const Token open = expect_open(keyword);
    Texture texture;
    const Token& first = peek();
    if (first.kind == TokenKind::identifier) {
        if (const Texture* declared = declared_as<Texture>(lookup(first.text))) {
            texture = *declared;
            next();
        }
    }
    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::symbol && token.text == "}") break;
        if (token.kind == TokenKind::identifier && token.text == "pigment") {
            next();
            const Token pigment_open = expect_open(token);
            parse_pigment_body(texture.pigment, token, pigment_open);
        } else if (token.kind == TokenKind::identifier && token.text == "finish") {
            next();
            const Token finish_open = expect_open(token);
            parse_finish_body(texture.finish, token, finish_open);
        } else if (token.kind == TokenKind::identifier && token.text == "normal") {
            fail_not_supported(token, "normal (bump) patterns");
        } else {
            Matrix4 ignored;  // transforms do not change a uniform colour
            if (!parse_transform_item(ignored))
                fail_identifier(token, fmt::format("pigment, finish or '}}' to close 'texture' opened at {}",
                                                   location_of(open).str()));
        }
    }
    expect_close(keyword, open);
    return texture;
}

Pigment Parser::parse_pigment(const Token& keyword) {
    const Token open = expect_open(keyword);
    Pigment pigment;
    parse_pigment_body(pigment, keyword, open);
    return pigment;
}

void Parser::parse_pigment_body(Pigment& pigment, const Token& keyword, const Token& open) {
    const Token& first = peek();
    if (first.kind == TokenKind::identifier) {
        if (const Pigment* declared = declared_as<Pigment>(lookup(first.text))) {
            pigment = *declared;
            next();
        }
    }
    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::symbol && token.text == "}") break;
        if (starts_expression(token)) {
            pigment.colour = parse_colour(true);
            continue;
        }
        Matrix4 ignored;  // transforms do not change a uniform colour
        if (!parse_transform_item(ignored))
            fail_identifier(token, fmt::format("a colour or '}}' to close '{}' opened at {}", keyword.text,
                                               location_of(open).str()));
    }
    expect_close(keyword, open);
}

Finish Parser::parse_finish(const Token& keyword) {
    const Token open = expect_open(keyword);
    Finish finish;
    parse_finish_body(finish, keyword, open);
    return finish;
}

Rgb Parser::parse_rgb() {
    // A float or a colour, as POV-Ray's ambient, emission and reflection take.
    const Colour c = parse_colour(false);
    return c.rgb();
}

void Parser::parse_finish_body(Finish& finish, const Token& keyword, const Token& open) {
    const Token& first = peek();
    if (first.kind == TokenKind::identifier) {
        if (const Finish* declared = declared_as<Finish>(lookup(first.text))) {
            finish = *declared;
            next();
        }
    }
    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::symbol && token.text == "}") break;
        const std::string w = token.kind == TokenKind::identifier ? token.text : "";
        if (w == "ambient") {
            next();
            finish.ambient = parse_rgb();
        } else if (w == "emission") {
            next();
            finish.emission = parse_rgb();
        } else if (w == "diffuse") {
            next();
            if (peek_word("albedo")) fail_not_supported(peek(), "'albedo'");
            finish.diffuse = parse_float("after 'diffuse'");
            if (accept_symbol(",")) fail_not_supported(token, "diffuse with a back-side value");
        } else if (w == "brilliance") {
            next();
            finish.brilliance = parse_float("after 'brilliance'");
        } else if (w == "specular") {
            next();
            finish.specular = parse_float("after 'specular'");
        } else if (w == "roughness") {
            next();
            const Token at = peek();
            finish.roughness = parse_float("after 'roughness'");
            if (!(finish.roughness > 0)) fail(at, "roughness must be positive");
        } else if (w == "phong") {
            next();
            finish.phong = parse_float("after 'phong'");
        } else if (w == "phong_size") {
            next();
            finish.phong_size = parse_float("after 'phong_size'");
        } else if (w == "metallic") {
            next();
            finish.metallic = starts_expression(peek()) ? parse_float() : 1.0;
        } else if (w == "conserve_energy") {
            next();
            finish.conserve_energy = parse_optional_bool();
        } else if (w == "reflection") {
            next();
            if (peek_symbol("{")) {
                // reflection { [min,] max [fresnel on] [falloff F] [metallic M] }
                const Token reflection_open = next();
                const Rgb first_value = parse_rgb();
                accept_comma();
                finish.reflection_min = finish.reflection_max = first_value;
                if (starts_expression(peek()) || peek_word("color") || peek_word("colour"))
                    finish.reflection_max = parse_rgb();
                for (;;) {
                    if (peek_symbol("}")) break;
                    const Token item = next();
                    if (item.kind == TokenKind::identifier && item.text == "fresnel") finish.reflection_fresnel = parse_optional_bool();
                    else if (item.kind == TokenKind::identifier && item.text == "falloff") finish.reflection_falloff = parse_float("after 'falloff'");
                    else if (item.kind == TokenKind::identifier && item.text == "metallic") finish.metallic = starts_expression(peek()) ? parse_float() : 1.0;
                    else fail_identifier(item, fmt::format("fresnel, falloff, metallic or '}}' to close 'reflection' opened at {}",
                                                           location_of(reflection_open).str()));
                }
                expect_close(token, reflection_open);
            } else {
                finish.reflection_min = finish.reflection_max = parse_rgb();
            }
        } else {
            fail_identifier(token, fmt::format("a finish keyword or '}}' to close '{}' opened at {}", keyword.text,
                                               location_of(open).str()));
        }
    }
    expect_close(keyword, open);
}

Interior Parser::parse_interior(const Token& keyword) {
    const Token open = expect_open(keyword);
    Interior interior;
    const Token& first = peek();
    if (first.kind == TokenKind::identifier) {
        if (const Interior* declared = declared_as<Interior>(lookup(first.text))) {
            interior = *declared;
            next();
        }
    }
    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::symbol && token.text == "}") break;
        if (token.kind == TokenKind::identifier && token.text == "ior") {
            next();
            const Token at = peek();
            interior.ior = parse_float("after 'ior'");
            if (!(interior.ior > 0)) fail(at, "ior must be positive");
        } else {
            fail_identifier(token, fmt::format("ior or '}}' to close 'interior' opened at {}", location_of(open).str()));
        }
    }
    expect_close(keyword, open);
    return interior;
}

}  // namespace rayset::tracer
