// The top level of a scene file, the flattening of object trees into world-space instances,
// and the public entry points.
#include "tracer/scene_language/scene_language.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace fs = std::filesystem;

SceneDescription Parser::parse(const std::string& text, const std::string& path) {
    std::error_code error;
    const fs::path directory = fs::absolute(fs::path(path), error).parent_path();
    allowed_roots_.push_back(fs::weakly_canonical(directory, error).string());
    for (const std::string& folder : options_.include_paths) allowed_roots_.push_back(fs::weakly_canonical(folder, error).string());
    for (const std::string& folder : options_.allowed_roots) allowed_roots_.push_back(fs::weakly_canonical(folder, error).string());
    scopes_.emplace_back();  // global: the main file's declarations live here
    push_file(text, path, directory.string(), nullptr);

    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::end) {
            // A directive's expression may have read the end of file before its block opened.
            if (!conditionals_.empty()) {
                const Token& opened = conditionals_.back().opened;
                fail(token, fmt::format("unclosed #{} opened at {}: expected #end before end of file", opened.text,
                                        location_of(opened).str()));
            }
            break;
        }
        const std::string w = token.kind == TokenKind::identifier ? token.text : "";
        if (starts_object(token)) {
            flatten(*parse_object(), Inherited{});
        } else if (w == "camera") {
            next();
            scene_.camera = parse_camera(token);
            scene_.has_camera = true;
        } else if (w == "global_settings") {
            next();
            parse_global_settings(token);
        } else if (w == "background") {
            next();
            parse_background(token);
        } else if (w == "ray_source") {
            next();
            parse_ray_source(token);
        } else if (w == "illuminance_receiver") {
            next();
            parse_receiver(token);
        } else {
            fail_identifier(token, "an object, light_source, camera, global_settings, background, ray_source or "
                                   "illuminance_receiver");
        }
    }
    return std::move(scene_);
}

void Parser::flatten(const ObjectNode& node, const Inherited& parent) {
    Inherited here = parent;
    here.to_world = parent.to_world * node.transform;
    if (node.texture) here.texture = &*node.texture;
    if (node.interior) here.interior = &*node.interior;
    here.no_shadow = parent.no_shadow || node.no_shadow;
    here.no_image = parent.no_image || node.no_image;
    here.no_reflection = parent.no_reflection || node.no_reflection;
    here.hollow = parent.hollow || node.hollow;

    switch (node.kind) {
        case ObjectNode::Kind::union_of:
            for (const ObjectRef& child : node.children) flatten(*child, here);
            return;
        case ObjectNode::Kind::light: {
            LightSource light = node.light;
            light.position = here.to_world.point(light.position);
            light.point_at = here.to_world.point(light.point_at);
            light.axis1 = here.to_world.vector(light.axis1);
            light.axis2 = here.to_world.vector(light.axis2);
            scene_.lights.push_back(light);
            return;
        }
        case ObjectNode::Kind::shape: {
            ObjectInstance instance;
            instance.shape = node.shape;
            instance.object_to_world = here.to_world;
            instance.textured = here.texture != nullptr;
            if (here.texture) instance.texture = *here.texture;
            instance.has_interior = here.interior != nullptr;
            if (here.interior) instance.interior = *here.interior;
            instance.no_shadow = here.no_shadow;
            instance.no_image = here.no_image;
            instance.no_reflection = here.no_reflection;
            instance.hollow = here.hollow;
            instance.location = node.location;
            scene_.objects.push_back(std::move(instance));
            return;
        }
    }
}

SceneDescription parse_scene_text(const std::string& text, const std::string& virtual_path, const ParseOptions& options) {
    return Parser(options).parse(text, virtual_path);
}

SceneDescription parse_scene_file(const std::string& path, const ParseOptions& options) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(fmt::format("{}: cannot open scene file", path));
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scene_text(text.str(), path, options);
}

}  // namespace rayset::tracer
