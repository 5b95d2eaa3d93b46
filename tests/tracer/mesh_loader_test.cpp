// The OBJ reader of mesh_file: a face naming a vertex or normal the file does not have is refused
// with the file and the face, before Embree or the shading could read past the mesh's arrays.
#include "tracer/render/mesh_loader.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/test_support.h"

namespace rayset::tracer {
namespace {

struct Loaded {
    std::shared_ptr<const TriangleMesh> mesh;
    std::string error;
};

Loaded load(const test::ScratchDir& dir, const std::string& obj) {
    MeshFileShape shape;
    shape.path = dir.file("part.obj");
    shape.format = "obj";
    test::write_file(shape.path, obj);
    try {
        return {load_mesh_file(shape, "scene.pov:1:1"), ""};
    } catch (const Error& e) {
        return {nullptr, e.what()};
    }
}

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(MeshFileLoader, RelativeIndicesNameTheVerticesBeforeTheFace) {
    test::ScratchDir dir;
    const Loaded loaded = load(dir, std::string(kTriangle) + "vn 0 0 1\nf -3//-1 -2//-1 -1//-1\n");
    ASSERT_TRUE(loaded.mesh) << loaded.error;
    ASSERT_EQ(loaded.mesh->faces.size(), 1u);
    EXPECT_EQ(loaded.mesh->faces[0], (std::array<int, 3>{0, 1, 2}));
    EXPECT_EQ(loaded.mesh->normal_faces[0], (std::array<int, 3>{0, 0, 0}));
}

TEST(MeshFileLoader, FaceNamingAVertexPastTheLastIsRefused) {
    test::ScratchDir dir;
    const Loaded loaded = load(dir, std::string(kTriangle) + "f 1 2 3\nf 1 2 4\n");
    EXPECT_FALSE(loaded.mesh);
    EXPECT_EQ(loaded.error, dir.file("part.obj") +
                                ": triangle 2 (in file order, polygons split into triangles) "
                                "names vertex 4 but the file has 3 ('v' lines) (mesh_file at "
                                "scene.pov:1:1)");
}

TEST(MeshFileLoader, RelativeIndexReachingBeforeTheFirstVertexIsRefused) {
    test::ScratchDir dir;
    const Loaded loaded = load(dir, std::string(kTriangle) + "f -1 -2 -4\n");
    EXPECT_FALSE(loaded.mesh);
    EXPECT_NE(loaded.error.find(dir.file("part.obj") + ": triangle 1 "), std::string::npos)
        << loaded.error;
    EXPECT_NE(loaded.error.find("names a vertex before the first: a relative (negative) index"),
              std::string::npos)
        << loaded.error;
}

TEST(MeshFileLoader, FaceNamingANormalPastTheLastIsRefused) {
    test::ScratchDir dir;
    const Loaded loaded = load(dir, std::string(kTriangle) + "vn 0 0 1\nf 1//1 2//1 3//2\n");
    EXPECT_FALSE(loaded.mesh);
    EXPECT_NE(loaded.error.find("triangle 1 (in file order, polygons split into triangles) names "
                                "normal 2 but the file has 1 ('vn' lines)"),
              std::string::npos)
        << loaded.error;
}

// A subdivision tag states how many values follow; tinyobjloader would allocate that many
// (here 1777777777 strings, 57 GB) before reading them. Tags are not used for triangles: the
// faces load as if the tags were not there.
TEST(MeshFileLoader, TagsAreIgnored) {
    test::ScratchDir dir;
    const Loaded loaded = load(dir, std::string(kTriangle) +
                                        "  t crease 2/2/1777777777 1 2 0.5 0.5\n"
                                        "\tt interpolateboundary 1/0/0 1\nf 1 2 3\n");
    ASSERT_TRUE(loaded.mesh) << loaded.error;
    ASSERT_EQ(loaded.mesh->faces.size(), 1u);
    EXPECT_EQ(loaded.mesh->faces[0], (std::array<int, 3>{0, 1, 2}));
}

TEST(MeshFileLoader, MissingFileIsNamed) {
    test::ScratchDir dir;
    MeshFileShape shape;
    shape.path = dir.file("absent.obj");
    shape.format = "obj";
    try {
        load_mesh_file(shape, "scene.pov:3:1");
        FAIL() << "a missing mesh file loaded";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), shape.path +
                                             ": cannot open OBJ mesh: No such file or directory "
                                             "(mesh_file at scene.pov:3:1)");
    }
}

}  // namespace
}  // namespace rayset::tracer
