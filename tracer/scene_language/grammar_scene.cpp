// The one dispatcher of top-level statements that are not objects, background, and our
// extensions ray_source and illuminance_receiver. Camera: grammar_camera.cpp; global_settings:
// grammar_global_settings.cpp; fog, rainbow, sky_sphere and atmospheric media:
// grammar_atmosphere.cpp.
#include <cmath>

#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"

namespace rayset::tracer {
namespace {

// background { COLOUR }: each statement replaces the last; an empty one is black (as POV-Ray 3.7
// renders it).
void parse_background(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    p.scene().background = p.peek_is(Symbol::rbrace) ? Colour{} : p.parse_colour();
    p.expect_close(keyword, open);
}

void parse_ray_source(Parser& p, const Token& keyword);
void parse_receiver(Parser& p, const Token& keyword);

}  // namespace

bool parse_scene_statement(Parser& p, const Token& keyword) {
    SceneDescription& scene = p.scene();
    if (keyword.is(Keyword::camera)) {
        scene.camera = *parse_camera(p, keyword);
        scene.has_camera = true;
    } else if (keyword.is(Keyword::global_settings)) {
        parse_global_settings(p, keyword);
    } else if (keyword.is(Keyword::background)) {
        parse_background(p, keyword);
    } else if (keyword.is(Keyword::fog)) {
        scene.atmosphere.fogs.push_back(*parse_fog(p, keyword));
    } else if (keyword.is(Keyword::rainbow)) {
        scene.atmosphere.rainbows.push_back(*parse_rainbow(p, keyword));
    } else if (keyword.is(Keyword::sky_sphere)) {
        scene.atmosphere.sky_sphere = parse_sky_sphere(p, keyword);
    } else if (keyword.is(Keyword::media)) {
        parse_atmospheric_media(p, keyword);
    } else if (keyword.is(Keyword::default_)) {
        parse_default(p, keyword);  // `default { }` without '#': POV-Ray 3.7 reads it as #default
    } else if (keyword.is(ContextWord::ray_source) && !p.lookup_value(keyword)) {
        parse_ray_source(p, keyword);
    } else if (keyword.is(ContextWord::illuminance_receiver) && !p.lookup_value(keyword)) {
        parse_receiver(p, keyword);
    } else {
        return false;
    }
    return true;
}

namespace {

void parse_ray_source(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    RaySource source;
    source.location = p.location_of(keyword);
    const Token name_token = p.peek();
    source.path = p.resolve_file(p.parse_string(), name_token, "ray file");
    while (!p.peek_is(Symbol::rbrace))
        if (!p.parse_transform_item(source.source_to_world))
            p.fail_identifier(p.peek(),
                              fmt::format("a transform or '}}' to close 'ray_source' opened at {}",
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
        p.fail(keyword,
               "illuminance_receiver edges are parallel or zero: the rectangle has no area");
    bool have_resolution = false;
    Matrix4 transform;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (token.is(ContextWord::resolution)) {
            p.next();
            const Token at = p.peek();
            const Numeric n = p.parse_numeric();
            // Each side at most an image's, the cells at most 2^24 (their sums take 40 bytes a
            // cell for the receiver and as much for each light layer).
            const auto whole = [](double v) {
                return v >= 1 && v <= kMaxImageSide && v == std::floor(v);
            };
            if (n.terms != 2 || !whole(n.v[0]) || !whole(n.v[1]) || n.v[0] * n.v[1] > 16777216)
                p.fail(at,
                       fmt::format("expected 'resolution <nx, ny>' with two whole numbers from 1 "
                                   "to {}, at most 16777216 cells in all, found {}",
                                   kMaxImageSide,
                                   n.terms == 2 ? fmt::format("<{}, {}>", n.v[0], n.v[1])
                                                : fmt::format("{} terms", n.terms)));
            receiver.nx = static_cast<int>(n.v[0]);
            receiver.ny = static_cast<int>(n.v[1]);
            have_resolution = true;
        } else if (token.is(ContextWord::name)) {
            p.next();
            receiver.name = p.parse_string();
        } else if (!p.parse_transform_item(transform)) {
            p.fail_identifier(
                token,
                fmt::format("resolution, name, a transform or '}}' to close 'illuminance_receiver' "
                            "opened at {}",
                            p.location_of(open).str()));
        }
    }
    if (!have_resolution)
        p.fail_expected("'resolution <nx, ny>' in illuminance_receiver", p.peek());
    p.expect_close(keyword, open);
    for (const IlluminanceReceiver& other : scene.receivers)
        if (other.name == receiver.name)
            p.fail(keyword, fmt::format("duplicate illuminance_receiver name \"{}\" (first at {})",
                                        receiver.name, other.location.str()));
    receiver.corner = transform.point(receiver.corner);
    receiver.edge1 = transform.vector(receiver.edge1);
    receiver.edge2 = transform.vector(receiver.edge2);
    scene.receivers.push_back(receiver);
}

}  // namespace
}  // namespace rayset::tracer
