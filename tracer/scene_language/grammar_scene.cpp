// Statements that are not objects: camera, global_settings (with our own keys), background,
// and our extensions ray_source and illuminance_receiver.
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"

namespace rayset::tracer {
namespace {

void parse_radiosity(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    GlobalSettings& g = p.scene().global;
    g.radiosity = true;
    // Keyword and how many floats it takes (0: an optional boolean).
    static const std::pair<Keyword, int> keys[] = {
        {Keyword::pretrace_start, 1}, {Keyword::pretrace_end, 1},     {Keyword::count, 2},
        {Keyword::nearest_count, 2},  {Keyword::recursion_limit, 1},  {Keyword::error_bound, 1},
        {Keyword::low_error_factor, 1}, {Keyword::minimum_reuse, 1},  {Keyword::maximum_reuse, 1},
        {Keyword::gray_threshold, 1}, {Keyword::brightness, 1},       {Keyword::adc_bailout, 1},
        {Keyword::max_sample, 1},     {Keyword::always_sample, 0},    {Keyword::normal, 0},
        {Keyword::media, 0},          {Keyword::subsurface, 0}};
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        int arity = -1;
        for (const auto& [name, count] : keys)
            if (token.is(name)) arity = count;
        if (arity < 0)
            p.fail_identifier(token, fmt::format("a radiosity setting or '}}' to close 'radiosity' opened at {}",
                                                 p.location_of(open).str()));
        p.next();
        std::vector<double> values;
        if (arity == 0) {
            values.push_back(p.parse_optional_bool() ? 1.0 : 0.0);
        } else {
            values.push_back(p.parse_float(fmt::format("after '{}'", p.word(token))));
            if (arity == 2 && (p.accept(Symbol::comma) || p.starts_expression(p.peek())))
                values.push_back(p.parse_float(fmt::format("as the second value of '{}'", p.word(token))));
        }
        g.radiosity_settings[p.word(token)] = values;
    }
    p.expect_close(keyword, open);
}

}  // namespace

// POV-Ray 3.5+ semantics: parameters are collected in any order, then applied as angle,
// look_at, then transforms (POV-Ray's Parse_Camera for language versions >= 3.5).
CameraRef parse_camera(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto result = std::make_shared<Camera>();
    Camera& camera = *result;
    if (const CameraRef* declared = p.peek_declared<CameraRef>()) {
        camera = **declared;
        p.next();
        Matrix4 transform;
        while (!p.peek_is(Symbol::rbrace))
            if (!p.parse_transform_item(transform))
                p.fail_identifier(p.peek(), fmt::format("a transform or '}}' to close 'camera' opened at {}",
                                                        p.location_of(open).str()));
        p.expect_close(keyword, open);
        camera.location = transform.point(camera.location);
        camera.direction = transform.vector(camera.direction);
        camera.up = transform.vector(camera.up);
        camera.right = transform.vector(camera.right);
        camera.sky = transform.vector(camera.sky);
        return result;
    }
    p.accept(Keyword::perspective);
    std::optional<Vec3> look_at;
    std::optional<double> angle;
    Token angle_token, look_at_token;
    Matrix4 transform;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (p.parse_transform_item(transform)) continue;
        if (token.is(Keyword::location)) p.next(), camera.location = p.parse_vector();
        else if (token.is(Keyword::direction)) p.next(), camera.direction = p.parse_vector();
        else if (token.is(Keyword::up)) p.next(), camera.up = p.parse_vector();
        else if (token.is(Keyword::right)) p.next(), camera.right = p.parse_vector();
        else if (token.is(Keyword::sky)) p.next(), camera.sky = p.parse_vector();
        else if (token.is(Keyword::look_at)) p.next(), look_at_token = token, look_at = p.parse_vector();
        else if (token.is(Keyword::angle)) {
            p.next();
            angle_token = p.peek();
            angle = p.parse_float("after 'angle'");
        } else if (token.is(Keyword::orthographic) || token.is(Keyword::fisheye) || token.is(Keyword::ultra_wide_angle) ||
                   token.is(Keyword::omnimax) || token.is(Keyword::panoramic) || token.is(Keyword::spherical) ||
                   token.is(Keyword::cylinder) || token.is(Keyword::mesh_camera)) {
            p.fail_not_supported(token, fmt::format("'{}' camera (only perspective)", p.word(token)));
        } else if (token.is(Keyword::perspective)) {
            p.fail(token, "'perspective' must come first in the camera");
        } else {
            p.fail_identifier(token, fmt::format("a camera keyword or '}}' to close 'camera' opened at {}",
                                                 p.location_of(open).str()));
        }
    }
    p.expect_close(keyword, open);

    if (angle) {
        if (*angle <= 0 || *angle >= 180)
            p.fail(angle_token, fmt::format("the camera angle must lie in (0, 180) degrees, found {}", *angle));
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
        if (dot(direction, direction) < 1e-10) p.fail(look_at_token, "camera location and look_at must differ");
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
    return result;
}

FogRef parse_fog(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'fog'"); }
RainbowRef parse_rainbow(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'rainbow'"); }
SkySphereRef parse_sky_sphere(Parser& p, const Token& keyword) { p.fail_not_supported(keyword, "'sky_sphere'"); }

namespace {
void parse_global_settings(Parser& p, const Token& keyword);
void parse_background(Parser& p, const Token& keyword);
void parse_ray_source(Parser& p, const Token& keyword);
void parse_receiver(Parser& p, const Token& keyword);
}  // namespace

bool parse_scene_statement(Parser& p, const Token& keyword) {
    if (keyword.is(Keyword::camera)) {
        p.scene().camera = *parse_camera(p, keyword);
        p.scene().has_camera = true;
    } else if (keyword.is(Keyword::global_settings)) {
        parse_global_settings(p, keyword);
    } else if (keyword.is(Keyword::background)) {
        parse_background(p, keyword);
    } else if (keyword.is(Keyword::ray_source)) {
        parse_ray_source(p, keyword);
    } else if (keyword.is(Keyword::illuminance_receiver)) {
        parse_receiver(p, keyword);
    } else if (keyword.is(Keyword::fog) || keyword.is(Keyword::rainbow) || keyword.is(Keyword::sky_sphere) ||
               keyword.is(Keyword::media)) {
        p.fail_not_supported(keyword, fmt::format("'{}'", p.word(keyword)));
    } else {
        return false;
    }
    return true;
}

namespace {

void parse_global_settings(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    GlobalSettings& g = p.scene().global;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        auto after = [&] { return fmt::format("after '{}'", p.word(token)); };
        if (token.is(Keyword::assumed_gamma)) {
            p.next();
            g.assumed_gamma = p.parse_float(after());
            g.assumed_gamma_set = true;
        } else if (token.is(Keyword::ambient_light)) {
            p.next();
            g.ambient_light = p.parse_colour().rgb();
        } else if (token.is(Keyword::max_trace_level)) {
            p.next();
            g.max_trace_level = p.parse_int(after(), 1);
        } else if (token.is(Keyword::radiosity)) {
            p.next();
            parse_radiosity(p, token);
        } else if (token.is(ContextWord::length_unit)) {
            p.next();
            const Token at = p.peek();
            const std::string unit = p.parse_string();
            static const std::pair<const char*, double> units[] = {
                {"um", 1e-3}, {"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}, {"in", 25.4}, {"ft", 304.8}};
            bool known = false;
            for (const auto& [name, mm] : units)
                if (unit == name) known = true, g.length_unit = unit, g.millimetres_per_unit = mm;
            if (!known) p.fail(at, fmt::format("unknown length_unit \"{}\" (expected um, mm, cm, m, in or ft)", unit));
        } else if (token.is(ContextWord::integrator)) {
            p.next();
            const Token at = p.peek();
            const std::string name = p.parse_string();
            if (name != "path" && name != "bidirectional")
                p.fail(at, fmt::format("unknown integrator \"{}\" (expected \"path\" or \"bidirectional\")", name));
            g.integrator = name;
        } else if (token.is(ContextWord::spectral)) {
            p.next();
            g.spectral = p.parse_float("after 'spectral' (on or off)") != 0;
        } else if (token.is(ContextWord::passes)) {
            p.next();
            g.passes = p.parse_int(after(), 1);
        } else if (token.is(ContextWord::time_limit)) {
            p.next();
            const Token at = p.peek();
            g.time_limit = p.parse_float("after 'time_limit' (seconds)");
            if (!(g.time_limit > 0)) p.fail(at, "time_limit must be positive (seconds)");
        } else {
            p.fail_identifier(token, fmt::format("a global setting or '}}' to close 'global_settings' opened at {}",
                                                 p.location_of(open).str()));
        }
    }
    p.expect_close(keyword, open);
}

void parse_background(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    p.scene().background = p.parse_colour();
    p.expect_close(keyword, open);
}

void parse_ray_source(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    RaySource source;
    source.location = p.location_of(keyword);
    const Token name_token = p.peek();
    source.path = p.resolve_file(p.parse_string(), name_token, "ray file");
    while (!p.peek_is(Symbol::rbrace))
        if (!p.parse_transform_item(source.source_to_world))
            p.fail_identifier(p.peek(), fmt::format("a transform or '}}' to close 'ray_source' opened at {}",
                                                    p.location_of(open).str()));
    p.expect_close(keyword, open);
    p.scene().ray_sources.push_back(source);
}

void parse_receiver(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    SceneDescription& scene = p.scene();
    IlluminanceReceiver receiver;
    receiver.location = p.location_of(keyword);
    receiver.name = fmt::format("receiver{}", scene.receivers.size() + 1);
    receiver.corner = p.parse_vector();
    p.accept_comma();
    receiver.edge1 = p.parse_vector();
    p.accept_comma();
    receiver.edge2 = p.parse_vector();
    if (length(cross(receiver.edge1, receiver.edge2)) < 1e-12)
        p.fail(keyword, "illuminance_receiver edges are parallel or zero: the rectangle has no area");
    bool have_resolution = false;
    Matrix4 transform;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (token.is(ContextWord::resolution)) {
            p.next();
            const Token at = p.peek();
            const Numeric n = p.parse_numeric();
            if (n.terms != 2 || n.v[0] < 1 || n.v[1] < 1 || n.v[0] != std::floor(n.v[0]) || n.v[1] != std::floor(n.v[1]))
                p.fail(at, "expected 'resolution <nx, ny>' with two positive integers");
            receiver.nx = static_cast<int>(n.v[0]);
            receiver.ny = static_cast<int>(n.v[1]);
            have_resolution = true;
        } else if (token.is(ContextWord::name)) {
            p.next();
            receiver.name = p.parse_string();
        } else if (!p.parse_transform_item(transform)) {
            p.fail_identifier(token, fmt::format("resolution, name, a transform or '}}' to close 'illuminance_receiver' "
                                                 "opened at {}", p.location_of(open).str()));
        }
    }
    if (!have_resolution) p.fail_expected("'resolution <nx, ny>' in illuminance_receiver", p.peek());
    p.expect_close(keyword, open);
    for (const IlluminanceReceiver& other : scene.receivers)
        if (other.name == receiver.name)
            p.fail(keyword, fmt::format("duplicate illuminance_receiver name \"{}\" (first at {})", receiver.name,
                                        other.location.str()));
    receiver.corner = transform.point(receiver.corner);
    receiver.edge1 = transform.vector(receiver.edge1);
    receiver.edge2 = transform.vector(receiver.edge2);
    scene.receivers.push_back(receiver);
}

}  // namespace
}  // namespace rayset::tracer
