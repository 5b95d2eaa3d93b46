// Objects: the shapes of the subset, unions, object{} copies, meshes, light sources, and the
// modifiers and transforms they take. Each object becomes a node of a tree; the top level
// flattens the tree into instances (scene_language.cpp).
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "tracer/scene_language/parser.h"

namespace rayset::tracer {

bool Parser::starts_object(const Token& token) const {
    if (token.kind != TokenKind::identifier) return false;
    static const char* const keywords[] = {"sphere", "box",   "plane",  "triangle",     "mesh",
                                           "mesh2",  "union", "object", "light_source", "mesh_file"};
    for (const char* keyword : keywords)
        if (token.text == keyword) return true;
    return false;
}

ObjectRef Parser::parse_object() {
    const Token keyword = next();
    const std::string& w = keyword.text;
    if (w == "union") return parse_union(keyword);
    if (w == "object") return parse_object_statement(keyword);
    if (w == "mesh") return parse_mesh(keyword);
    if (w == "mesh2") return parse_mesh2(keyword);
    if (w == "mesh_file") return parse_mesh_file(keyword);
    if (w == "light_source") return parse_light_source(keyword);
    return parse_shape(keyword);
}

ObjectRef Parser::parse_shape(const Token& keyword) {
    const Token open = expect_open(keyword);
    auto node = std::make_shared<ObjectNode>();
    node->location = location_of(keyword);
    const std::string& w = keyword.text;
    if (w == "sphere") {
        SphereShape s;
        s.centre = parse_vector();
        accept_comma();
        const Token at = peek();
        s.radius = parse_float("as the sphere radius");
        if (!(s.radius > 0)) fail(at, fmt::format("the sphere radius must be positive, found {}", s.radius));
        node->shape = s;
    } else if (w == "box") {
        const Vec3 a = parse_vector();
        accept_comma();
        const Vec3 b = parse_vector();
        node->shape = BoxShape{{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                               {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
    } else if (w == "plane") {
        const Token at = peek();
        const Vec3 n = parse_vector();
        accept_comma();
        if (length(n) < 1e-10) fail(at, "degenerate plane normal (zero length)");
        node->shape = PlaneShape{normalized(n), parse_float("as the plane distance")};
    } else {  // triangle
        TriangleShape t;
        t.a = parse_vector();
        accept_comma();
        t.b = parse_vector();
        accept_comma();
        t.c = parse_vector();
        node->shape = t;
    }
    parse_object_modifiers(*node, keyword, open);
    return node;
}

ObjectRef Parser::parse_union(const Token& keyword) {
    const Token open = expect_open(keyword);
    auto node = std::make_shared<ObjectNode>();
    node->kind = ObjectNode::Kind::union_of;
    node->location = location_of(keyword);
    for (;;) {
        const Token& token = peek();
        if (token.kind == TokenKind::symbol && token.text == "}") break;
        if (starts_object(token)) {
            node->children.push_back(parse_object());
        } else if (!parse_object_modifier(*node)) {
            fail_identifier(token, fmt::format("an object, an object modifier or '}}' to close 'union' opened at {}",
                                               location_of(open).str()));
        }
    }
    expect_close(keyword, open);
    return node;
}

ObjectRef Parser::parse_object_statement(const Token& keyword) {
    const Token open = expect_open(keyword);
    const Token& first = peek();
    ObjectRef base;
    if (first.kind == TokenKind::identifier && lookup(first.text) && std::holds_alternative<ObjectRef>(*lookup(first.text))) {
        base = std::get<ObjectRef>(*lookup(first.text));
        next();
    } else if (starts_object(first)) {
        base = parse_object();
    } else {
        fail_identifier(first, "an object identifier or an object after 'object {'");
    }
    auto node = std::make_shared<ObjectNode>(*base);
    if (node->kind == ObjectNode::Kind::light) {
        for (;;) {
            if (peek_symbol("}")) break;
            if (!parse_light_modifier(node->light) && !parse_transform_item(node->transform))
                fail_identifier(peek(), fmt::format("a light_source modifier or '}}' to close 'object' opened at {}",
                                                    location_of(open).str()));
        }
        expect_close(keyword, open);
    } else {
        parse_object_modifiers(*node, keyword, open);
    }
    return node;
}

ObjectRef Parser::parse_mesh(const Token& keyword) {
    const Token open = expect_open(keyword);
    auto mesh = std::make_shared<TriangleMesh>();
    auto node = std::make_shared<ObjectNode>();
    node->location = location_of(keyword);
    while (peek_word("triangle")) {
        const Token triangle = next();
        const Token triangle_open = expect_open(triangle);
        for (int i = 0; i < 3; ++i) {
            if (i > 0) accept_comma();
            mesh->vertices.push_back(parse_vector());
        }
        const int base = static_cast<int>(mesh->vertices.size()) - 3;
        mesh->faces.push_back({base, base + 1, base + 2});
        if (!peek_symbol("}"))
            fail_not_supported(peek(), "modifiers on a triangle inside a mesh (put them on the mesh)");
        expect_close(triangle, triangle_open);
    }
    if (mesh->faces.empty()) fail_expected("at least one 'triangle { ... }' in the mesh", peek());
    if (accept_word("inside_vector")) parse_vector();  // only matters for CSG, which the subset lacks
    node->shape = MeshShape{mesh};
    parse_object_modifiers(*node, keyword, open);
    return node;
}

ObjectRef Parser::parse_mesh2(const Token& keyword) {
    const Token open = expect_open(keyword);
    auto mesh = std::make_shared<TriangleMesh>();
    auto node = std::make_shared<ObjectNode>();
    node->location = location_of(keyword);

    // "NAME { count, entry, entry, ... }" with exactly `count` entries.
    auto read_list = [&](const Token& name, auto&& read_entry) {
        const Token list_open = expect_open(name);
        const int count = parse_int(fmt::format("as the number of entries of '{}'", name.text), 0);
        for (int i = 0; i < count; ++i) {
            accept_comma();
            if (peek_symbol("}"))
                fail(peek(), fmt::format("'{}' declares {} entries, found '}}' after {}", name.text, count, i));
            read_entry();
        }
        accept_comma();
        if (!peek_symbol("}"))
            fail_expected(fmt::format("'}}' after the {} entries declared by '{}'", count, name.text), peek());
        expect_close(name, list_open);
    };
    auto read_index_triple = [&](std::vector<std::array<int, 3>>& out) {
        const Vec3 v = parse_vector();
        out.push_back({static_cast<int>(v.x), static_cast<int>(v.y), static_cast<int>(v.z)});
    };
    std::vector<Token> face_tokens, normal_face_tokens;
    Token faces_keyword, normal_indices_keyword;
    bool have_vertices = false, have_faces = false, have_normal_indices = false;
    for (;;) {
        const Token& token = peek();
        if (token.kind != TokenKind::identifier) break;
        if (token.text == "vertex_vectors") {
            const Token name = next();
            read_list(name, [&] { mesh->vertices.push_back(parse_vector()); });
            have_vertices = true;
        } else if (token.text == "normal_vectors") {
            const Token name = next();
            read_list(name, [&] { mesh->normals.push_back(parse_vector()); });
        } else if (token.text == "face_indices") {
            faces_keyword = next();
            read_list(faces_keyword, [&] {
                face_tokens.push_back(peek());
                read_index_triple(mesh->faces);
            });
            have_faces = true;
        } else if (token.text == "normal_indices") {
            normal_indices_keyword = next();
            read_list(normal_indices_keyword, [&] {
                normal_face_tokens.push_back(peek());
                read_index_triple(mesh->normal_faces);
            });
            have_normal_indices = true;
        } else if (token.text == "uv_vectors" || token.text == "uv_indices" || token.text == "texture_list") {
            fail_not_supported(token, fmt::format("'{}' in mesh2", token.text));
        } else {
            break;
        }
    }
    if (!have_vertices) fail_expected("'vertex_vectors' in mesh2", peek());
    if (!have_faces) fail_expected("'face_indices' in mesh2", peek());
    auto check = [&](const std::vector<std::array<int, 3>>& faces, const std::vector<Token>& at, size_t limit,
                     const char* what) {
        for (size_t f = 0; f < faces.size(); ++f)
            for (int index : faces[f])
                if (index < 0 || static_cast<size_t>(index) >= limit)
                    fail(at[f], fmt::format("{} index {} out of range: there are {} {}", what, index, limit,
                                            std::string(what) == "vertex" ? "vertex_vectors" : "normal_vectors"));
    };
    check(mesh->faces, face_tokens, mesh->vertices.size(), "vertex");
    if (have_normal_indices) {
        if (mesh->normal_faces.size() != mesh->faces.size())
            fail(normal_indices_keyword, fmt::format("normal_indices has {} entries, face_indices {}",
                                                     mesh->normal_faces.size(), mesh->faces.size()));
        check(mesh->normal_faces, normal_face_tokens, mesh->normals.size(), "normal");
    } else if (!mesh->normals.empty()) {
        if (mesh->normals.size() != mesh->vertices.size())
            fail(faces_keyword, fmt::format("without normal_indices, normal_vectors ({}) must match vertex_vectors ({})",
                                            mesh->normals.size(), mesh->vertices.size()));
    }
    if (accept_word("inside_vector")) parse_vector();
    node->shape = MeshShape{mesh};
    parse_object_modifiers(*node, keyword, open);
    return node;
}

ObjectRef Parser::parse_mesh_file(const Token& keyword) {
    const Token open = expect_open(keyword);
    const Token name_token = peek();
    const std::string name = parse_string();
    std::string extension = std::filesystem::path(name).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".obj" && extension != ".ply")
        fail(name_token, fmt::format("mesh_file \"{}\": unknown format '{}' (expected .obj or .ply)", name, extension));
    auto node = std::make_shared<ObjectNode>();
    node->location = location_of(keyword);
    node->shape = MeshFileShape{resolve_file(name, name_token, "mesh file"), extension.substr(1)};
    parse_object_modifiers(*node, keyword, open);
    return node;
}

ObjectRef Parser::parse_light_source(const Token& keyword) {
    const Token open = expect_open(keyword);
    auto node = std::make_shared<ObjectNode>();
    const Token& first = peek();
    const Value* declared = first.kind == TokenKind::identifier ? lookup(first.text) : nullptr;
    if (declared && std::holds_alternative<ObjectRef>(*declared)) {
        const ObjectRef& base = std::get<ObjectRef>(*declared);
        if (base->kind != ObjectNode::Kind::light) fail_identifier(first, "a light_source identifier");
        *node = *base;
        next();
    } else {
        node->kind = ObjectNode::Kind::light;
        node->location = location_of(keyword);
        node->light.location = node->location;
        node->light.position = parse_vector();
        accept_comma();
        node->light.colour = parse_colour(false).rgb();
    }
    for (;;) {
        if (peek_symbol("}")) break;
        if (!parse_light_modifier(node->light) && !parse_transform_item(node->transform))
            fail_identifier(peek(), fmt::format("a light_source modifier or '}}' to close 'light_source' opened at {}",
                                                location_of(open).str()));
    }
    expect_close(keyword, open);
    return node;
}

bool Parser::parse_light_modifier(LightSource& light) {
    const Token& token = peek();
    if (token.kind != TokenKind::identifier) return false;
    const std::string w = token.text;
    if (w == "color" || w == "colour" || w == "rgb") {
        light.colour = parse_colour(false).rgb();
        return true;
    }
    static const char* const keywords[] = {"spotlight", "point_at", "radius",   "falloff",       "tightness",
                                           "area_light", "adaptive", "jitter",  "circular",      "orient",
                                           "fade_distance", "fade_power", "shadowless"};
    bool known = false;
    for (const char* keyword : keywords) known = known || w == keyword;
    if (!known) return false;
    next();
    if (w == "spotlight") light.spotlight = true;
    else if (w == "point_at") light.point_at = parse_vector();
    else if (w == "radius") light.radius = parse_float("after 'radius'");
    else if (w == "falloff") light.falloff = parse_float("after 'falloff'");
    else if (w == "tightness") light.tightness = parse_float("after 'tightness'");
    else if (w == "adaptive") light.adaptive = parse_int("after 'adaptive'", 0);
    else if (w == "jitter") light.jitter = parse_optional_bool();
    else if (w == "circular") light.circular = parse_optional_bool();
    else if (w == "orient") light.orient = parse_optional_bool();
    else if (w == "fade_distance") light.fade_distance = parse_float("after 'fade_distance'");
    else if (w == "fade_power") light.fade_power = parse_float("after 'fade_power'");
    else if (w == "shadowless") light.shadowless = true;
    else {  // area_light <axis1>, <axis2>, size1, size2
        light.area_light = true;
        light.axis1 = parse_vector();
        accept_comma();
        light.axis2 = parse_vector();
        accept_comma();
        light.size1 = parse_int("as the first area_light size", 1);
        accept_comma();
        light.size2 = parse_int("as the second area_light size", 1);
    }
    return true;
}

bool Parser::parse_transform_item(Matrix4& transform) {
    const Token& token = peek();
    if (token.kind != TokenKind::identifier) return false;
    const Token keyword = token;
    if (keyword.text == "translate") {
        next();
        transform = translation(parse_vector()) * transform;
    } else if (keyword.text == "rotate") {
        next();
        transform = pov_rotation(parse_vector()) * transform;
    } else if (keyword.text == "scale") {
        next();
        const Token at = peek();
        const Vec3 s = parse_vector();
        if (s.x == 0 || s.y == 0 || s.z == 0) fail(at, "scale by zero (POV-Ray would change it to 1 with a warning)");
        transform = scaling(s) * transform;
    } else if (keyword.text == "matrix") {
        next();
        const Token open = expect_symbol("<", "after 'matrix'");
        std::array<double, 12> values{};
        for (int i = 0; i < 12; ++i) {
            if (i > 0) accept_comma();
            if (peek_symbol(">")) fail(peek(), fmt::format("'matrix' needs 12 values, found {}", i));
            values[i] = parse_float("in 'matrix'");
        }
        accept_comma();
        expect_symbol(">", fmt::format("to close the 12 values of 'matrix' opened at {}", location_of(open).str()));
        transform = pov_matrix(values) * transform;
    } else if (keyword.text == "transform") {
        next();
        transform = parse_transform_block(keyword) * transform;
    } else {
        return false;
    }
    return true;
}

Matrix4 Parser::parse_transform_block(const Token& keyword) {
    auto declared_transform = [&](const Token& token) -> const TransformValue* {
        if (token.kind != TokenKind::identifier) return nullptr;
        const Value* value = lookup(token.text);
        return value ? std::get_if<TransformValue>(value) : nullptr;
    };
    if (const TransformValue* value = declared_transform(peek())) {
        next();
        return value->matrix;
    }
    const Token open = expect_open(keyword);
    Matrix4 result;
    bool inverse = false;
    for (;;) {
        if (peek_symbol("}")) break;
        if (accept_word("inverse")) {
            inverse = true;
        } else if (const TransformValue* value = declared_transform(peek())) {
            next();
            result = value->matrix * result;
        } else if (!parse_transform_item(result)) {
            fail_identifier(peek(), fmt::format("translate, rotate, scale, matrix, transform, inverse or '}}' to close "
                                                "'transform' opened at {}", location_of(open).str()));
        }
    }
    expect_close(keyword, open);
    return inverse ? result.inverse() : result;
}

bool Parser::parse_object_modifier(ObjectNode& node) {
    if (parse_transform_item(node.transform)) return true;
    const Token& token = peek();
    if (token.kind != TokenKind::identifier) return false;
    const Token keyword = token;
    const std::string& w = keyword.text;
    if (w == "texture") {
        if (node.texture) fail_not_supported(keyword, "layered textures (a second texture on one object)");
        next();
        node.texture = parse_texture(keyword);
    } else if (w == "pigment") {
        next();
        if (!node.texture) node.texture = Texture{};
        const Token open = expect_open(keyword);
        parse_pigment_body(node.texture->pigment, keyword, open);
    } else if (w == "finish") {
        next();
        if (!node.texture) node.texture = Texture{};
        const Token open = expect_open(keyword);
        parse_finish_body(node.texture->finish, keyword, open);
    } else if (w == "interior") {
        next();
        node.interior = parse_interior(keyword);
    } else if (w == "normal") {
        fail_not_supported(keyword, "normal (bump) patterns");
    } else if (w == "no_shadow") {
        next();
        node.no_shadow = parse_optional_bool();
    } else if (w == "no_image") {
        next();
        node.no_image = parse_optional_bool();
    } else if (w == "no_reflection") {
        next();
        node.no_reflection = parse_optional_bool();
    } else if (w == "hollow") {
        next();
        node.hollow = parse_optional_bool();
    } else {
        return false;
    }
    return true;
}

void Parser::parse_object_modifiers(ObjectNode& node, const Token& keyword, const Token& open) {
    for (;;) {
        if (peek_symbol("}")) break;
        if (!parse_object_modifier(node))
            fail_identifier(peek(), fmt::format("an object modifier or '}}' to close '{}' opened at {}", keyword.text,
                                                location_of(open).str()));
    }
    expect_close(keyword, open);
}

}  // namespace rayset::tracer
