// OBJ meshes through tinyobjloader (Debian's libtinyobjloader-dev).
#include "tracer/render/mesh_loader.h"

#include <tiny_obj_loader.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace rayset::tracer {

namespace {

// tinyobjloader only warns about a face that names a vertex or normal the file does not have (an
// index past the last, or a relative index before the first); Embree and the shading would read
// past the mesh's arrays. It gives no line, so the face is named by its place among the
// triangles.
void check_indices(const std::vector<std::array<int, 3>>& faces, size_t count, const char* what,
                   const char* statement, const std::string& path, const std::string& where) {
    for (size_t f = 0; f < faces.size(); ++f)
        for (int index : faces[f]) {
            if (index < 0)
                throw Error(fmt::format(
                    "{}: triangle {} (in file order, polygons split into triangles) names a {} "
                    "before the first: a relative (negative) index reaches back past the first "
                    "'{}' line (mesh_file at {})",
                    path, f + 1, what, statement, where));
            if (static_cast<size_t>(index) >= count)
                throw Error(fmt::format(
                    "{}: triangle {} (in file order, polygons split into triangles) names {} {} "
                    "but the file has {} ('{}' lines) (mesh_file at {})",
                    path, f + 1, what, index + 1, count, statement, where));
        }
}

// The file's text with its subdivision-surface tags ('t' statements) made comments: a tag states
// counts that tinyobjloader allocates before it reads the values (1777777777 strings from one
// line of a corrupt file), and a mesh rendered as triangles has no use for them.
std::string text_without_tags(const std::string& path, const std::string& where) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(fmt::format("{}: cannot open OBJ mesh: {} (mesh_file at {})", path,
                                std::strerror(errno), where));
    std::ostringstream text;
    text << in.rdbuf();  // an empty file inserts nothing: the parser then finds no faces
    std::string s = std::move(text).str();
    auto blank = [](char c) { return c == ' ' || c == '\t'; };
    for (size_t line = 0; line < s.size();) {
        size_t i = line;
        while (i < s.size() && blank(s[i])) ++i;
        if (i + 1 < s.size() && s[i] == 't' && blank(s[i + 1])) s[i] = '#';
        const size_t end = s.find('\n', i);
        line = end == std::string::npos ? s.size() : end + 1;
    }
    return s;
}

}  // namespace

std::shared_ptr<const TriangleMesh> load_mesh_file(const MeshFileShape& shape,
                                                   const std::string& where) {
    if (shape.format != "obj")
        throw Error(fmt::format("not supported: mesh_file of format '{}' (only .obj is read) at {}",
                                shape.format, where));
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // Materials come from the scene: no .mtl file is read (the second text, empty).
    if (!reader.ParseFromString(text_without_tags(shape.path, where), "", config))
        throw Error(fmt::format("{}: cannot read OBJ mesh: {} (mesh_file at {})", shape.path,
                                reader.Error(), where));
    auto mesh = std::make_shared<TriangleMesh>();
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
        mesh->vertices.push_back(
            {attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
    for (size_t i = 0; i + 2 < attrib.normals.size(); i += 3)
        mesh->normals.push_back({attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]});
    bool every_corner_has_normal = !mesh->normals.empty();
    for (const tinyobj::shape_t& part : reader.GetShapes()) {
        const auto& indices = part.mesh.indices;
        for (size_t f = 0; f + 2 < indices.size(); f += 3) {
            mesh->faces.push_back({indices[f].vertex_index, indices[f + 1].vertex_index,
                                   indices[f + 2].vertex_index});
            mesh->normal_faces.push_back({indices[f].normal_index, indices[f + 1].normal_index,
                                          indices[f + 2].normal_index});
            for (int k = 0; k < 3; ++k) every_corner_has_normal &= indices[f + k].normal_index >= 0;
        }
    }
    if (!every_corner_has_normal) mesh->normals.clear(), mesh->normal_faces.clear();
    if (mesh->faces.empty())
        throw Error(
            fmt::format("{}: the OBJ file has no faces (mesh_file at {})", shape.path, where));
    check_indices(mesh->faces, mesh->vertices.size(), "vertex", "v", shape.path, where);
    check_indices(mesh->normal_faces, mesh->normals.size(), "normal", "vn", shape.path, where);
    return mesh;
}

}  // namespace rayset::tracer
