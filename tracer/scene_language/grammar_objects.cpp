// Objects: shapes, unions, object{} copies, meshes, light sources, the modifiers and transforms
// they take, and the flattening of object trees into world-space instances and lights.
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/object_tree.h"

namespace rayset::tracer {
namespace {

ObjectRef parse_shape(Parser& p, const Token& keyword);
ObjectRef parse_union(Parser& p, const Token& keyword);
ObjectRef parse_object_statement(Parser& p, const Token& keyword);
ObjectRef parse_mesh(Parser& p, const Token& keyword);
ObjectRef parse_mesh2(Parser& p, const Token& keyword);
ObjectRef parse_mesh_file(Parser& p, const Token& keyword);
ObjectRef parse_light_source(Parser& p, const Token& keyword);
bool parse_light_modifier(Parser& p, LightSource& light);
bool parse_object_modifier(Parser& p, ObjectNode& node);
void parse_object_modifiers(Parser& p, ObjectNode& node, const Token& keyword, const Token& open);

ObjectRef parse_shape(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = std::make_shared<ObjectNode>();
    node->location = p.location_of(keyword);
    if (keyword.is(Keyword::sphere)) {
        SphereShape s;
        s.centre = p.parse_vector();
        p.accept_comma();
        const Token at = p.peek();
        s.radius = p.parse_float("as the sphere radius");
        if (!(s.radius > 0)) p.fail(at, fmt::format("the sphere radius must be positive, found {}", s.radius));
        node->shape = s;
    } else if (keyword.is(Keyword::box)) {
        const Vec3 a = p.parse_vector();
        p.accept_comma();
        const Vec3 b = p.parse_vector();
        node->shape = BoxShape{{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                               {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
    } else if (keyword.is(Keyword::plane)) {
        const Token at = p.peek();
        const Vec3 n = p.parse_vector();
        p.accept_comma();
        if (length(n) < 1e-10) p.fail(at, "degenerate plane normal (zero length)");
        node->shape = PlaneShape{normalized(n), p.parse_float("as the plane distance")};
    } else {  // triangle
        TriangleShape t;
        t.a = p.parse_vector();
        p.accept_comma();
        t.b = p.parse_vector();
        p.accept_comma();
        t.c = p.parse_vector();
        node->shape = t;
    }
    parse_object_modifiers(p, *node, keyword, open);
    return node;
}

ObjectRef parse_union(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = std::make_shared<ObjectNode>();
    node->kind = ObjectNode::Kind::union_of;
    node->location = p.location_of(keyword);
    for (;;) {
        const Token& token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (starts_object(p, token)) {
            node->children.push_back(parse_object(p));
        } else if (!parse_object_modifier(p, *node)) {
            p.fail_identifier(token, fmt::format("an object, an object modifier or '}}' to close 'union' opened at {}",
                                                 p.location_of(open).str()));
        }
    }
    p.expect_close(keyword, open);
    return node;
}

ObjectRef parse_object_statement(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    ObjectRef base;
    if (const ObjectRef* declared = p.peek_declared<ObjectRef>()) {
        base = *declared;
        p.next();
    } else if (starts_object(p, p.peek())) {
        base = parse_object(p);
    } else {
        p.fail_identifier(p.peek(), "an object identifier or an object after 'object {'");
    }
    auto node = std::make_shared<ObjectNode>(*base);
    if (node->kind == ObjectNode::Kind::light) {
        for (;;) {
            if (p.peek_is(Symbol::rbrace)) break;
            if (!parse_light_modifier(p, node->light) && !p.parse_transform_item(node->transform))
                p.fail_identifier(p.peek(), fmt::format("a light_source modifier or '}}' to close 'object' opened at {}",
                                                        p.location_of(open).str()));
        }
        p.expect_close(keyword, open);
    } else {
        parse_object_modifiers(p, *node, keyword, open);
    }
    return node;
}

ObjectRef parse_mesh(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto mesh = std::make_shared<TriangleMesh>();
    auto node = std::make_shared<ObjectNode>();
    node->location = p.location_of(keyword);
    while (p.peek_is(Keyword::triangle)) {
        const Token triangle = p.next();
        const Token triangle_open = p.expect_open(triangle);
        for (int i = 0; i < 3; ++i) {
            if (i > 0) p.accept_comma();
            mesh->vertices.push_back(p.parse_vector());
        }
        const int base = static_cast<int>(mesh->vertices.size()) - 3;
        mesh->faces.push_back({base, base + 1, base + 2});
        if (!p.peek_is(Symbol::rbrace))
            p.fail_not_supported(p.peek(), "modifiers on a triangle inside a mesh (put them on the mesh)");
        p.expect_close(triangle, triangle_open);
    }
    if (mesh->faces.empty()) p.fail_expected("at least one 'triangle { ... }' in the mesh", p.peek());
    if (p.accept(Keyword::inside_vector)) p.parse_vector();  // only matters for CSG
    node->shape = MeshShape{mesh};
    parse_object_modifiers(p, *node, keyword, open);
    return node;
}

ObjectRef parse_mesh2(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto mesh = std::make_shared<TriangleMesh>();
    auto node = std::make_shared<ObjectNode>();
    node->location = p.location_of(keyword);

    // "NAME { count, entry, entry, ... }" with exactly `count` entries.
    auto read_list = [&](const Token& name, auto&& read_entry) {
        const Token list_open = p.expect_open(name);
        const int count = p.parse_int(fmt::format("as the number of entries of '{}'", p.word(name)), 0);
        for (int i = 0; i < count; ++i) {
            p.accept_comma();
            if (p.peek_is(Symbol::rbrace))
                p.fail(p.peek(), fmt::format("'{}' declares {} entries, found '}}' after {}", p.word(name), count, i));
            read_entry();
        }
        p.accept_comma();
        if (!p.peek_is(Symbol::rbrace))
            p.fail_expected(fmt::format("'}}' after the {} entries declared by '{}'", count, p.word(name)), p.peek());
        p.expect_close(name, list_open);
    };
    auto read_index_triple = [&](std::vector<std::array<int, 3>>& out) {
        const Vec3 v = p.parse_vector();
        out.push_back({static_cast<int>(v.x), static_cast<int>(v.y), static_cast<int>(v.z)});
    };
    std::vector<Token> face_tokens, normal_face_tokens;
    Token faces_keyword, normal_indices_keyword;
    bool have_vertices = false, have_faces = false, have_normal_indices = false;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Keyword::vertex_vectors)) {
            p.next();
            read_list(token, [&] { mesh->vertices.push_back(p.parse_vector()); });
            have_vertices = true;
        } else if (token.is(Keyword::normal_vectors)) {
            p.next();
            read_list(token, [&] { mesh->normals.push_back(p.parse_vector()); });
        } else if (token.is(Keyword::face_indices)) {
            faces_keyword = p.next();
            read_list(faces_keyword, [&] {
                face_tokens.push_back(p.peek());
                read_index_triple(mesh->faces);
            });
            have_faces = true;
        } else if (token.is(Keyword::normal_indices)) {
            normal_indices_keyword = p.next();
            read_list(normal_indices_keyword, [&] {
                normal_face_tokens.push_back(p.peek());
                read_index_triple(mesh->normal_faces);
            });
            have_normal_indices = true;
        } else if (token.is(Keyword::uv_vectors) || token.is(Keyword::uv_indices) || token.is(Keyword::texture_list)) {
            p.fail_not_supported(token, fmt::format("'{}' in mesh2", p.word(token)));
        } else {
            break;
        }
    }
    if (!have_vertices) p.fail_expected("'vertex_vectors' in mesh2", p.peek());
    if (!have_faces) p.fail_expected("'face_indices' in mesh2", p.peek());
    auto check = [&](const std::vector<std::array<int, 3>>& faces, const std::vector<Token>& at, size_t limit,
                     const char* what, const char* list) {
        for (size_t f = 0; f < faces.size(); ++f)
            for (int index : faces[f])
                if (index < 0 || static_cast<size_t>(index) >= limit)
                    p.fail(at[f], fmt::format("{} index {} out of range: there are {} {}", what, index, limit, list));
    };
    check(mesh->faces, face_tokens, mesh->vertices.size(), "vertex", "vertex_vectors");
    if (have_normal_indices) {
        if (mesh->normal_faces.size() != mesh->faces.size())
            p.fail(normal_indices_keyword, fmt::format("normal_indices has {} entries, face_indices {}",
                                                       mesh->normal_faces.size(), mesh->faces.size()));
        check(mesh->normal_faces, normal_face_tokens, mesh->normals.size(), "normal", "normal_vectors");
    } else if (!mesh->normals.empty() && mesh->normals.size() != mesh->vertices.size()) {
        p.fail(faces_keyword, fmt::format("without normal_indices, normal_vectors ({}) must match vertex_vectors ({})",
                                          mesh->normals.size(), mesh->vertices.size()));
    }
    if (p.accept(Keyword::inside_vector)) p.parse_vector();
    node->shape = MeshShape{mesh};
    parse_object_modifiers(p, *node, keyword, open);
    return node;
}

ObjectRef parse_mesh_file(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    const Token name_token = p.peek();
    const std::string name = p.parse_string();
    std::string extension = std::filesystem::path(name).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".obj" && extension != ".ply")
        p.fail(name_token, fmt::format("mesh_file \"{}\": unknown format '{}' (expected .obj or .ply)", name, extension));
    auto node = std::make_shared<ObjectNode>();
    node->location = p.location_of(keyword);
    node->shape = MeshFileShape{p.resolve_file(name, name_token, "mesh file"), extension.substr(1)};
    parse_object_modifiers(p, *node, keyword, open);
    return node;
}

ObjectRef parse_light_source(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = std::make_shared<ObjectNode>();
    const ObjectRef* declared = p.peek_declared<ObjectRef>();
    if (declared) {
        if ((*declared)->kind != ObjectNode::Kind::light) p.fail_identifier(p.peek(), "a light_source identifier");
        *node = **declared;
        p.next();
    } else {
        node->kind = ObjectNode::Kind::light;
        node->location = p.location_of(keyword);
        node->light.location = node->location;
        node->light.position = p.parse_vector();
        p.accept_comma();
        node->light.colour = p.parse_colour().rgb();
    }
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        if (!parse_light_modifier(p, node->light) && !p.parse_transform_item(node->transform))
            p.fail_identifier(p.peek(), fmt::format("a light_source modifier or '}}' to close 'light_source' opened at {}",
                                                    p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    return node;
}

bool parse_light_modifier(Parser& p, LightSource& light) {
    const Token token = p.peek();
    if (token.is(Keyword::color) || token.is(Keyword::colour) || token.is(Keyword::rgb)) {
        light.colour = p.parse_colour().rgb();
        return true;
    }
    auto after = [&] { return fmt::format("after '{}'", p.word(token)); };
    if (token.is(Keyword::spotlight)) light.spotlight = true;
    else if (token.is(Keyword::point_at)) p.next(), light.point_at = p.parse_vector();
    else if (token.is(Keyword::radius)) p.next(), light.radius = p.parse_float(after());
    else if (token.is(Keyword::falloff)) p.next(), light.falloff = p.parse_float(after());
    else if (token.is(Keyword::tightness)) p.next(), light.tightness = p.parse_float(after());
    else if (token.is(Keyword::adaptive)) p.next(), light.adaptive = p.parse_int(after(), 0);
    else if (token.is(Keyword::jitter)) p.next(), light.jitter = p.parse_optional_bool();
    else if (token.is(Keyword::circular)) p.next(), light.circular = p.parse_optional_bool();
    else if (token.is(Keyword::orient)) p.next(), light.orient = p.parse_optional_bool();
    else if (token.is(Keyword::fade_distance)) p.next(), light.fade_distance = p.parse_float(after());
    else if (token.is(Keyword::fade_power)) p.next(), light.fade_power = p.parse_float(after());
    else if (token.is(Keyword::shadowless)) light.shadowless = true;
    else if (token.is(Keyword::area_light)) {
        // area_light <axis1>, <axis2>, size1, size2
        p.next();
        light.area_light = true;
        light.axis1 = p.parse_vector();
        p.accept_comma();
        light.axis2 = p.parse_vector();
        p.accept_comma();
        light.size1 = p.parse_int("as the first area_light size", 1);
        p.accept_comma();
        light.size2 = p.parse_int("as the second area_light size", 1);
    } else {
        return false;
    }
    if (token.is(Keyword::spotlight) || token.is(Keyword::shadowless)) p.next();
    return true;
}

bool parse_object_modifier(Parser& p, ObjectNode& node) {
    if (p.parse_transform_item(node.transform)) return true;
    const Token keyword = p.peek();
    if (parse_appearance_modifier(p, node.appearance)) return true;
    if (keyword.is(Keyword::normal)) {
        p.fail_not_supported(keyword, "normal (bump) patterns");
    } else if (keyword.is(Keyword::no_shadow)) {
        p.next();
        node.no_shadow = p.parse_optional_bool();
    } else if (keyword.is(Keyword::no_image)) {
        p.next();
        node.no_image = p.parse_optional_bool();
    } else if (keyword.is(Keyword::no_reflection)) {
        p.next();
        node.no_reflection = p.parse_optional_bool();
    } else if (keyword.is(Keyword::hollow)) {
        p.next();
        node.hollow = p.parse_optional_bool();
    } else {
        return false;
    }
    return true;
}

void parse_object_modifiers(Parser& p, ObjectNode& node, const Token& keyword, const Token& open) {
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        if (!parse_object_modifier(p, node))
            p.fail_identifier(p.peek(), fmt::format("an object modifier or '}}' to close '{}' opened at {}",
                                                    p.word(keyword), p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
}

struct Inherited {
    Matrix4 to_world;
    ObjectAppearance appearance;
    bool no_shadow = false, no_image = false, no_reflection = false, hollow = false;
};

void flatten(SceneDescription& scene, const ObjectNode& node, const Inherited& parent) {
    Inherited here = parent;
    here.to_world = parent.to_world * node.transform;
    here.appearance = node.appearance;
    inherit_appearance(here.appearance, parent.appearance);
    here.no_shadow = parent.no_shadow || node.no_shadow;
    here.no_image = parent.no_image || node.no_image;
    here.no_reflection = parent.no_reflection || node.no_reflection;
    here.hollow = parent.hollow || node.hollow;

    switch (node.kind) {
        case ObjectNode::Kind::union_of:
            for (const ObjectRef& child : node.children) flatten(scene, *child, here);
            return;
        case ObjectNode::Kind::light: {
            LightSource light = node.light;
            light.position = here.to_world.point(light.position);
            light.point_at = here.to_world.point(light.point_at);
            light.axis1 = here.to_world.vector(light.axis1);
            light.axis2 = here.to_world.vector(light.axis2);
            scene.lights.push_back(light);
            return;
        }
        case ObjectNode::Kind::shape: {
            ObjectInstance instance;
            instance.shape = node.shape;
            instance.object_to_world = here.to_world;
            instance.appearance = here.appearance;
            instance.no_shadow = here.no_shadow;
            instance.no_image = here.no_image;
            instance.no_reflection = here.no_reflection;
            instance.hollow = here.hollow;
            instance.location = node.location;
            scene.objects.push_back(std::move(instance));
            return;
        }
    }
}

}  // namespace

bool starts_object(Parser& parser, const Token& token) {
    (void)parser;
    return token.is(Keyword::sphere) || token.is(Keyword::box) || token.is(Keyword::plane) ||
           token.is(Keyword::triangle) || token.is(Keyword::mesh) || token.is(Keyword::mesh2) ||
           token.is(Keyword::union_) || token.is(Keyword::object) || token.is(Keyword::light_source) ||
           token.is(Keyword::mesh_file);
}

ObjectRef parse_object(Parser& p) {
    const Token keyword = p.next();
    if (keyword.is(Keyword::union_)) return parse_union(p, keyword);
    if (keyword.is(Keyword::object)) return parse_object_statement(p, keyword);
    if (keyword.is(Keyword::mesh)) return parse_mesh(p, keyword);
    if (keyword.is(Keyword::mesh2)) return parse_mesh2(p, keyword);
    if (keyword.is(Keyword::mesh_file)) return parse_mesh_file(p, keyword);
    if (keyword.is(Keyword::light_source)) return parse_light_source(p, keyword);
    return parse_shape(p, keyword);
}

void add_to_scene(Parser& parser, const ObjectRef& object) { flatten(parser.scene(), *object, Inherited{}); }

bool object_bounding_box(const ObjectNode& object, Vec3& minimum, Vec3& maximum) {
    (void)object, (void)minimum, (void)maximum;
    return false;
}

bool object_inside(const ObjectNode& object, Vec3 point, bool& inside) {
    (void)object, (void)point, (void)inside;
    return false;
}

bool object_trace(const ObjectNode& object, Vec3 origin, Vec3 direction, Vec3& hit, Vec3& normal, bool& found) {
    (void)object, (void)origin, (void)direction, (void)hit, (void)normal, (void)found;
    return false;
}

}  // namespace rayset::tracer
