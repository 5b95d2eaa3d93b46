// Statements that are not objects: camera, global_settings (with our own keys), background,
// and our extensions ray_source and illuminance_receiver.
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "tracer/scene_language/parser.h"

namespace rayset::tracer {

// POV-Ray 3.5+ semantics: parameters are collected in any order, then applied as angle,
// look_at, then transforms (POV-Ray's Parse_Camera for language versions >= 3.5).
Camera Parser::parse_camera(const Token& keyword) {
    const Token open = expect_open(keyword);
    Camera camera;
    const Token& first = peek();
    const Value* declared = first.kind == TokenKind::identifier ? lookup(first.text) : nullptr;
    if (declared && std::holds_alternative<Camera>(*declared)) {
        camera = std::get<Camera>(*declared);
        next();
        Matrix4 transform;
        while (!peek_symbol("}"))
            if (!parse_transform_item(transform))
                fail_identifier(peek(), fmt::format("a transform or '}}' to close 'camera' opened at {}", location_of(open).str()));
        expect_close(keyword, open);
        camera.location = transform.point(camera.location);
        camera.direction = transform.vector(camera.direction);
        camera.up = transform.vector(camera.up);
        camera.right = transform.vector(camera.right);
        camera.sky = transform.vector(camera.sky);
        return camera;
    }
    accept_word("perspective");
    std::optional<Vec3> look_at;
    std::optional<double> angle;
    Token angle_token;
    Token look_at_token;
    Matrix4 transform;
    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::symbol && token.text == "}") break;
        const std::string w = token.kind == TokenKind::identifier ? token.text : "";
        if (parse_transform_item(transform)) continue;
        if (w == "location") next(), camera.location = parse_vector();
        else if (w == "direction") next(), camera.direction = parse_vector();
        else if (w == "up") next(), camera.up = parse_vector();
        else if (w == "right") next(), camera.right = parse_vector();
        else if (w == "sky") next(), camera.sky = parse_vector();
        else if (w == "look_at") next(), look_at_token = token, look_at = parse_vector();
        else if (w == "angle") {
            next();
            angle_token = peek();
            angle = parse_float("after 'angle'");
        } else if (w == "orthographic" || w == "fisheye" || w == "ultra_wide_angle" || w == "omnimax" ||
                   w == "panoramic" || w == "spherical" || w == "cylinder" || w == "mesh_camera") {
            fail_not_supported(token, fmt::format("'{}' camera (only perspective)", w));
        } else if (w == "perspective") {
            fail(token, "'perspective' must come first in the camera");
        } else {
            fail_identifier(token, fmt::format("a camera keyword or '}}' to close 'camera' opened at {}", location_of(open).str()));
        }
    }
    expect_close(keyword, open);

    if (angle) {
        if (*angle <= 0 || *angle >= 180)
            fail(angle_token, fmt::format("the camera angle must lie in (0, 180) degrees, found {}", *angle));
        camera.angle = *angle;
        const double direction_length = length(camera.right) / std::tan(*angle * analytic::kPi / 360.0) / 2.0;
        camera.direction = direction_length * normalized(camera.direction);
    }
    if (look_at) {
        const double direction_length = length(camera.direction);
        const double up_length = length(camera.up);
        const double right_length = length(camera.right);
        const double handedness = dot(cross(camera.up, camera.direction), camera.right);
        Vec3 direction = *look_at - camera.location;
        if (dot(direction, direction) < 1e-10) fail(look_at_token, "camera location and look_at must differ");
        direction = normalized(direction);
        Vec3 right = cross(camera.sky, direction);
        if (length(right) < 1e-10) right = camera.right;  // sky parallel to the view: keep the old right
        right = normalized(right);
        camera.up = up_length * cross(direction, right);
        camera.direction = direction_length * direction;
        camera.right = (handedness > 0 ? right_length : -right_length) * right;
    }
    camera.location = transform.point(camera.location);
    camera.direction = transform.vector(camera.direction);
    camera.up = transform.vector(camera.up);
    camera.right = transform.vector(camera.right);
    camera.sky = transform.vector(camera.sky);
    return camera;
}

void Parser::parse_global_settings(const Token& keyword) {
    const Token open = expect_open(keyword);
    GlobalSettings& g = scene_.global;
    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::symbol && token.text == "}") break;
        const std::string w = token.kind == TokenKind::identifier ? token.text : "";
        if (w == "assumed_gamma") {
            next();
            g.assumed_gamma = parse_float("after 'assumed_gamma'");
        } else if (w == "ambient_light") {
            next();
            g.ambient_light = parse_rgb();
        } else if (w == "max_trace_level") {
            next();
            g.max_trace_level = parse_int("after 'max_trace_level'", 1);
        } else if (w == "radiosity") {
            next();
            parse_radiosity(token);
        } else if (w == "length_unit") {
            next();
            const Token at = peek();
            const std::string unit = parse_string();
            static const std::pair<const char*, double> units[] = {
                {"um", 1e-3}, {"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}, {"in", 25.4}, {"ft", 304.8}};
            bool known = false;
            for (const auto& [name, mm] : units)
                if (unit == name) known = true, g.length_unit = unit, g.millimetres_per_unit = mm;
            if (!known) fail(at, fmt::format("unknown length_unit \"{}\" (expected um, mm, cm, m, in or ft)", unit));
        } else if (w == "integrator") {
            next();
            const Token at = peek();
            const std::string name = parse_string();
            if (name != "path" && name != "bidirectional")
                fail(at, fmt::format("unknown integrator \"{}\" (expected \"path\" or \"bidirectional\")", name));
            g.integrator = name;
        } else if (w == "spectral") {
            next();
            g.spectral = parse_float("after 'spectral' (on or off)") != 0;
        } else if (w == "passes") {
            next();
            g.passes = parse_int("after 'passes'", 1);
        } else if (w == "time_limit") {
            next();
            const Token at = peek();
            g.time_limit = parse_float("after 'time_limit' (seconds)");
            if (!(g.time_limit > 0)) fail(at, "time_limit must be positive (seconds)");
        } else {
            fail_identifier(token, fmt::format("a global setting or '}}' to close 'global_settings' opened at {}",
                                               location_of(open).str()));
        }
    }
    expect_close(keyword, open);
}

void Parser::parse_radiosity(const Token& keyword) {
    const Token open = expect_open(keyword);
    GlobalSettings& g = scene_.global;
    g.radiosity = true;
    // Keyword and how many floats it takes (0: an optional boolean).
    static const std::pair<const char*, int> keys[] = {
        {"pretrace_start", 1}, {"pretrace_end", 1},   {"count", 2},          {"nearest_count", 2},
        {"recursion_limit", 1}, {"error_bound", 1},   {"low_error_factor", 1}, {"minimum_reuse", 1},
        {"maximum_reuse", 1},  {"gray_threshold", 1}, {"brightness", 1},     {"adc_bailout", 1},
        {"max_sample", 1},     {"always_sample", 0},  {"normal", 0},         {"media", 0},
        {"subsurface", 0}};
    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::symbol && token.text == "}") break;
        int arity = -1;
        for (const auto& [name, count] : keys)
            if (token.kind == TokenKind::identifier && token.text == name) arity = count;
        if (arity < 0)
            fail_identifier(token, fmt::format("a radiosity setting or '}}' to close 'radiosity' opened at {}",
                                               location_of(open).str()));
        next();
        std::vector<double> values;
        if (arity == 0) {
            values.push_back(parse_optional_bool() ? 1.0 : 0.0);
        } else {
            values.push_back(parse_float(fmt::format("after '{}'", token.text)));
            if (arity == 2 && (accept_symbol(",") || starts_expression(peek())))
                values.push_back(parse_float(fmt::format("as the second value of '{}'", token.text)));
        }
        g.radiosity_settings[token.text] = values;
    }
    expect_close(keyword, open);
}

void Parser::parse_background(const Token& keyword) {
    const Token open = expect_open(keyword);
    scene_.background = parse_colour(true);
    expect_close(keyword, open);
}

void Parser::parse_ray_source(const Token& keyword) {
    const Token open = expect_open(keyword);
    RaySource source;
    source.location = location_of(keyword);
    const Token name_token = peek();
    source.path = resolve_file(parse_string(), name_token, "ray file");
    while (!peek_symbol("}"))
        if (!parse_transform_item(source.source_to_world))
            fail_identifier(peek(), fmt::format("a transform or '}}' to close 'ray_source' opened at {}", location_of(open).str()));
    expect_close(keyword, open);
    scene_.ray_sources.push_back(source);
}

void Parser::parse_receiver(const Token& keyword) {
    const Token open = expect_open(keyword);
    IlluminanceReceiver receiver;
    receiver.location = location_of(keyword);
    receiver.name = fmt::format("receiver{}", scene_.receivers.size() + 1);
    receiver.corner = parse_vector();
    accept_comma();
    receiver.edge1 = parse_vector();
    accept_comma();
    receiver.edge2 = parse_vector();
    if (length(cross(receiver.edge1, receiver.edge2)) < 1e-12)
        fail(keyword, "illuminance_receiver edges are parallel or zero: the rectangle has no area");
    bool have_resolution = false;
    Matrix4 transform;
    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::symbol && token.text == "}") break;
        if (token.kind == TokenKind::identifier && token.text == "resolution") {
            next();
            const Token at = peek();
            const Numeric n = parse_additive();
            if (n.terms != 2 || n.v[0] < 1 || n.v[1] < 1 || n.v[0] != std::floor(n.v[0]) || n.v[1] != std::floor(n.v[1]))
                fail(at, "expected 'resolution <nx, ny>' with two positive integers");
            receiver.nx = static_cast<int>(n.v[0]);
            receiver.ny = static_cast<int>(n.v[1]);
            have_resolution = true;
        } else if (token.kind == TokenKind::identifier && token.text == "name") {
            next();
            receiver.name = parse_string();
        } else if (!parse_transform_item(transform)) {
            fail_identifier(token, fmt::format("resolution, name, a transform or '}}' to close 'illuminance_receiver' "
                                               "opened at {}", location_of(open).str()));
        }
    }
    if (!have_resolution) fail_expected("'resolution <nx, ny>' in illuminance_receiver", peek());
    expect_close(keyword, open);
    for (const IlluminanceReceiver& other : scene_.receivers)
        if (other.name == receiver.name)
            fail(keyword, fmt::format("duplicate illuminance_receiver name \"{}\" (first at {})", receiver.name, other.location.str()));
    receiver.corner = transform.point(receiver.corner);
    receiver.edge1 = transform.vector(receiver.edge1);
    receiver.edge2 = transform.vector(receiver.edge2);
    scene_.receivers.push_back(receiver);
}

}  // namespace rayset::tracer
