// mesh, mesh2 (reference manual 3.4.5.2.3 - 3.4.5.2.4) and our mesh_file. Every count and
// index is checked before it is used; a list claiming more entries than the limits allow
// fails before anything is stored for it.
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "tracer/scene_language/object_grammar.h"

namespace rayset::tracer {
namespace {

using Triple = std::array<int, 3>;
constexpr Triple kNone{-1, -1, -1};

// The index of `texture` in the mesh's texture list, added on first use.
int texture_index(TriangleMesh& mesh, std::map<const Texture*, int>& known,
                  const TextureRef& texture) {
    auto [it, added] = known.emplace(texture.get(), static_cast<int>(mesh.textures.size()));
    if (added) mesh.textures.push_back(texture);
    return it->second;
}

// texture { TEXTURE_ID }: a mesh triangle takes a declared texture only (POV-Ray's rule).
TextureRef parse_texture_identifier(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    const TextureRef* declared = p.peek_declared<TextureRef>();
    if (!declared)
        p.fail_identifier(p.peek(),
                          "a texture identifier (a mesh triangle takes no texture definition)");
    TextureRef texture = *declared;
    p.next();
    p.expect_close(keyword, open);
    return texture;
}

// A mesh's triangle or smooth_triangle: corners (and normals), then [uv_vectors A, B, C],
// then [texture { ID } | texture_list { ID ID ID }]. Degenerate triangles are dropped, as
// POV-Ray drops them.
class MeshBuilder {
public:
    explicit MeshBuilder(Parser& p) : p_(p), mesh_(std::make_shared<TriangleMesh>()) {}

    void triangle(const Token& keyword) {
        const Token open = p_.expect_open(keyword);
        const bool smooth = keyword.is(Keyword::smooth_triangle);
        std::array<Vec3, 3> corners, normals;
        for (size_t i = 0; i < 3; ++i) {
            if (i > 0) p_.accept_comma();
            corners[i] = p_.parse_vector();
            if (smooth) p_.accept_comma(), normals[i] = p_.parse_vector();
        }
        std::array<Vec2, 3> uv;
        const bool has_uv = p_.accept(Keyword::uv_vectors);
        for (size_t i = 0; has_uv && i < 3; ++i) {
            if (i > 0) p_.accept_comma();
            uv[i] = parse_vec2(p_, "as a uv vector of the triangle");
        }
        const Triple textures = parse_textures();
        p_.expect_close(keyword, open);
        if (length(cross(corners[1] - corners[0], corners[2] - corners[0])) == 0) return;
        add(corners, smooth ? &normals : nullptr, has_uv ? &uv : nullptr, textures);
    }

    std::shared_ptr<TriangleMesh> finish(const Token& at) {
        if (mesh_->faces.empty())
            p_.fail(at, "no triangles in the mesh (POV-Ray drops degenerate ones)");
        if (!smooth_) mesh_->normal_faces.clear();
        if (!any_uv_) mesh_->uv_faces.clear();
        if (!any_texture_) mesh_->face_textures.clear();
        return mesh_;
    }

private:
    Triple parse_textures() {
        const Token token = p_.peek();
        if (token.is(Keyword::texture)) {
            p_.next();
            const int index = texture_index(*mesh_, known_, parse_texture_identifier(p_, token));
            return {index, index, index};
        }
        if (!token.is(Keyword::texture_list)) return kNone;
        p_.next();
        const Token open = p_.expect_open(token);
        Triple indices{};
        for (size_t i = 0; i < 3; ++i) {
            p_.accept_comma();
            const TextureRef* declared = p_.peek_declared<TextureRef>();
            if (!declared) p_.fail_identifier(p_.peek(), "a texture identifier in 'texture_list'");
            indices[i] = texture_index(*mesh_, known_, *declared);
            p_.next();
        }
        p_.expect_close(token, open);
        return indices;
    }

    void add(const std::array<Vec3, 3>& corners, const std::array<Vec3, 3>* normals,
             const std::array<Vec2, 3>* uv, const Triple& textures) {
        const int base = static_cast<int>(mesh_->vertices.size());
        for (const Vec3& corner : corners) mesh_->vertices.push_back(corner);
        mesh_->faces.push_back({base, base + 1, base + 2});
        Triple normal_face = kNone;
        if (normals) {
            const int first = static_cast<int>(mesh_->normals.size());
            for (const Vec3& n : *normals) mesh_->normals.push_back(n);
            normal_face = {first, first + 1, first + 2};
            smooth_ = true;
        }
        mesh_->normal_faces.push_back(normal_face);
        Triple uv_face = kNone;
        if (uv) {
            const int first = static_cast<int>(mesh_->uvs.size());
            for (const Vec2& v : *uv) mesh_->uvs.push_back(v);
            uv_face = {first, first + 1, first + 2};
            any_uv_ = true;
        }
        mesh_->uv_faces.push_back(uv_face);
        mesh_->face_textures.push_back(textures);
        any_texture_ = any_texture_ || textures != kNone;
    }

    Parser& p_;
    std::shared_ptr<TriangleMesh> mesh_;
    std::map<const Texture*, int> known_;
    bool smooth_ = false, any_uv_ = false, any_texture_ = false;
};

void parse_inside_vector(Parser& p, TriangleMesh& mesh) {
    if (!p.accept(Keyword::inside_vector)) return;
    mesh.has_inside_vector = true;
    mesh.inside_vector = p.parse_vector();
}

// mesh2's sections. NAME { COUNT, ENTRY, ENTRY ... } with exactly COUNT entries.
class Mesh2Reader {
public:
    explicit Mesh2Reader(Parser& p) : p_(p), mesh_(std::make_shared<TriangleMesh>()) {}

    // The sections in POV-Ray's order: vectors, texture_list, indices.
    void read_sections() {
        for (;;) {
            const Token token = p_.peek();
            int rank = 0;
            if (token.is(Keyword::vertex_vectors) || token.is(Keyword::normal_vectors) ||
                token.is(Keyword::uv_vectors))
                rank = 0;
            else if (token.is(Keyword::texture_list))
                rank = 1;
            else if (token.is(Keyword::face_indices) || token.is(Keyword::normal_indices) ||
                     token.is(Keyword::uv_indices))
                rank = 2;
            else
                break;
            if (rank < rank_)
                p_.fail(token,
                        fmt::format(
                            "'{}' after the {} in mesh2: its sections come in the order vectors, "
                            "texture_list, indices",
                            p_.word(token), rank_ == 2 ? "indices" : "texture_list"));
            rank_ = rank;
            p_.next();
            read_section(token);
        }
    }

    std::shared_ptr<TriangleMesh> finish(const Token& keyword) {
        if (mesh_->vertices.empty() && !have_vertices_)
            p_.fail_expected("'vertex_vectors' in mesh2", p_.peek());
        if (!have_faces_) p_.fail_expected("'face_indices' in mesh2", p_.peek());
        check_indices(mesh_->faces, face_at_, mesh_->vertices.size(), "vertex", "vertex_vectors");
        check_normals(keyword);
        check_uvs(keyword);
        check_textures();
        return mesh_;
    }

private:
    void read_section(const Token& name) {
        if (name.is(Keyword::vertex_vectors)) {
            have_vertices_ = true;
            read_list(name, [&] { mesh_->vertices.push_back(p_.parse_vector()); });
        } else if (name.is(Keyword::normal_vectors)) {
            read_list(name, [&] { mesh_->normals.push_back(p_.parse_vector()); });
        } else if (name.is(Keyword::uv_vectors)) {
            read_list(name, [&] { mesh_->uvs.push_back(parse_vec2(p_, "in 'uv_vectors'")); });
        } else if (name.is(Keyword::texture_list)) {
            read_list(name, [&] {
                const Token texture = p_.expect(Keyword::texture, "in 'texture_list'");
                mesh_->textures.push_back(parse_texture(p_, texture));
            });
        } else if (name.is(Keyword::face_indices)) {
            have_faces_ = true;
            faces_keyword_ = name;
            read_list(name, [&] { read_face(); });
        } else {
            const bool normals = name.is(Keyword::normal_indices);
            (normals ? normal_indices_ : uv_indices_) = name;
            read_list(name, [&] {
                (normals ? normal_at_ : uv_at_).push_back(p_.peek());
                (normals ? mesh_->normal_faces : mesh_->uv_faces).push_back(read_triple());
            });
        }
    }

    template <typename ReadEntry>
    void read_list(const Token& name, ReadEntry&& read_entry) {
        const Token open = p_.expect_open(name);
        const int count = parse_count(p_, fmt::format("entries of '{}'", p_.word(name)));
        for (int i = 0; i < count; ++i) {
            p_.accept_comma();
            if (p_.peek_is(Symbol::rbrace))
                p_.fail(p_.peek(), fmt::format("'{}' declares {} entries, found '}}' after {}",
                                               p_.word(name), count, i));
            read_entry();
        }
        p_.accept_comma();
        if (!p_.peek_is(Symbol::rbrace))
            p_.fail_expected(
                fmt::format("'}}' after the {} entries declared by '{}'", count, p_.word(name)),
                p_.peek());
        p_.expect_close(name, open);
    }

    Triple read_triple() {
        const Vec3 v = p_.parse_vector();
        return {static_cast<int>(v.x), static_cast<int>(v.y), static_cast<int>(v.z)};
    }

    // <a, b, c> [, t [, t2, t3]]: one texture index for the face, or three for its corners.
    void read_face() {
        face_at_.push_back(p_.peek());
        mesh_->faces.push_back(read_triple());
        Triple textures = kNone;
        auto texture_follows = [&] {
            if (!p_.peek_is(Symbol::comma)) return false;
            p_.next();
            const Token& next = p_.peek();
            return !next.is(Symbol::less) && !next.is(Symbol::rbrace) && p_.starts_expression(next);
        };
        if (texture_follows()) {
            texture_at_.push_back(p_.peek());
            textures[0] = textures[1] = textures[2] = p_.parse_int("as a texture index", 0);
            if (texture_follows()) {
                textures[1] = p_.parse_int("as a texture index", 0);
                p_.expect(Symbol::comma, "between the three texture indices of a face");
                textures[2] = p_.parse_int("as a texture index", 0);
            }
        }
        mesh_->face_textures.push_back(textures);
    }

    void check_indices(const std::vector<Triple>& faces, const std::vector<Token>& at, size_t limit,
                       const char* what, const char* list) {
        for (size_t f = 0; f < faces.size(); ++f)
            for (int index : faces[f])
                if (index < 0 || static_cast<size_t>(index) >= limit)
                    p_.fail(at[f], fmt::format("{} index {} out of range: there are {} {}", what,
                                               index, limit, list));
    }

    // Without normal_indices the normals follow the vertices; with fewer normal_indices than
    // faces the rest are flat (POV-Ray's way to mix smooth and flat triangles).
    void check_normals(const Token& keyword) {
        TriangleMesh& m = *mesh_;
        if (normal_indices_.kind != TokenKind::end) {
            if (m.normal_faces.size() > m.faces.size())
                p_.fail(normal_indices_,
                        fmt::format("normal_indices has {} entries, more than the {} faces",
                                    m.normal_faces.size(), m.faces.size()));
            check_indices(m.normal_faces, normal_at_, m.normals.size(), "normal", "normal_vectors");
            m.normal_faces.resize(m.faces.size(), kNone);
        } else if (!m.normals.empty() && m.normals.size() != m.vertices.size()) {
            p_.fail(
                keyword,
                fmt::format(
                    "without normal_indices, normal_vectors ({}) must match vertex_vectors ({})",
                    m.normals.size(), m.vertices.size()));
        }
    }

    void check_uvs(const Token& keyword) {
        TriangleMesh& m = *mesh_;
        if (uv_indices_.kind != TokenKind::end) {
            if (m.uv_faces.size() != m.faces.size())
                p_.fail(uv_indices_, fmt::format("uv_indices has {} entries, face_indices {}",
                                                 m.uv_faces.size(), m.faces.size()));
            check_indices(m.uv_faces, uv_at_, m.uvs.size(), "uv", "uv_vectors");
        } else if (!m.uvs.empty() && m.uvs.size() != m.vertices.size()) {
            p_.fail(
                keyword,
                fmt::format("without uv_indices, uv_vectors ({}) must match vertex_vectors ({})",
                            m.uvs.size(), m.vertices.size()));
        }
    }

    void check_textures() {
        TriangleMesh& m = *mesh_;
        size_t with_texture = 0;
        for (size_t f = 0; f < m.faces.size(); ++f) {
            if (m.face_textures[f] == kNone) continue;
            for (int index : m.face_textures[f])
                if (static_cast<size_t>(index) >= m.textures.size())
                    p_.fail(texture_at_[with_texture],
                            fmt::format("texture index {} out of range: texture_list has {}", index,
                                        m.textures.size()));
            ++with_texture;
        }
        if (with_texture == 0) m.face_textures.clear();
    }

    Parser& p_;
    std::shared_ptr<TriangleMesh> mesh_;
    int rank_ = 0;
    bool have_vertices_ = false, have_faces_ = false;
    Token faces_keyword_, normal_indices_, uv_indices_;  // kind `end` until read
    std::vector<Token> face_at_, normal_at_, uv_at_, texture_at_;
};

}  // namespace

// mesh { TRIANGLES... [inside_vector V] MODIFIERS }
ObjectRef parse_mesh(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    // mesh { MESH_ID modifiers }: a declared mesh, as `object { MESH_ID }` takes it (POV-Ray
    // accepts this form, and mesh_camera's examples use it).
    const Token first = p.peek();
    if (ObjectRef declared; p.take_declared(declared)) {
        if (!std::holds_alternative<MeshShape>(declared->shape))
            p.fail(first, "wrong type: '" + p.word(first) +
                              "' is not a mesh, expected a mesh identifier or triangles");
        auto copy = std::make_shared<ObjectNode>(*declared);
        finish_shape(p, *copy, keyword, open);
        return copy;
    }
    auto node = new_node(p, keyword);
    MeshBuilder builder(p);
    while (p.peek_is(Keyword::triangle) || p.peek_is(Keyword::smooth_triangle))
        builder.triangle(p.next());
    std::shared_ptr<TriangleMesh> mesh = builder.finish(p.peek());
    parse_inside_vector(p, *mesh);
    node->shape = MeshShape{mesh};
    finish_shape(p, *node, keyword, open);
    return node;
}

// mesh2 { VECTORS LISTS INDICES [inside_vector V] MODIFIERS }
ObjectRef parse_mesh2(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    Mesh2Reader reader(p);
    reader.read_sections();
    std::shared_ptr<TriangleMesh> mesh = reader.finish(keyword);
    parse_inside_vector(p, *mesh);
    node->shape = MeshShape{mesh};
    finish_shape(p, *node, keyword, open);
    return node;
}

ObjectRef parse_mesh_file(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    const Token name_token = p.peek();
    const std::string name = p.parse_string();
    std::string extension = std::filesystem::path(name).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".obj" && extension != ".ply")
        p.fail(name_token,
               fmt::format("mesh_file \"{}\": unknown format '{}' (expected .obj or .ply)", name,
                           extension));
    auto node = new_node(p, keyword);
    node->shape = MeshFileShape{p.resolve_file(name, name_token, "mesh file"), extension.substr(1)};
    finish_shape(p, *node, keyword, open);
    return node;
}

}  // namespace rayset::tracer
