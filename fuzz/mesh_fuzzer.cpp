// Fuzzes the OBJ mesh reader behind `mesh_file { "part.obj" }`: each input is an OBJ file that
// load_mesh_file() reads through tinyobjloader (whose parser is compiled into this harness,
// tinyobjloader.cpp, so that the fuzzer sees its branches too). The renderer hands the mesh's
// index buffers to Embree and looks up the corners of the faces it hits, both without checks:
// every index the loader hands out must name a vertex (or normal) the mesh has, and the harness
// stops with a report when one does not.
#include "core/error.h"
#include "fuzz/fuzz_support.h"
#include "tracer/render/mesh_loader.h"

#include <cstdio>
#include <cstdlib>

namespace {

void check_indices(const std::vector<std::array<int, 3>>& faces, size_t count, const char* what) {
    for (size_t f = 0; f < faces.size(); ++f)
        for (int index : faces[f])
            if (index < 0 || static_cast<size_t>(index) >= count) {
                std::fprintf(stderr, "face %zu: %s index %d out of range: the mesh has %zu\n", f,
                             what, index, count);
                std::abort();
            }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    rayset::tracer::MeshFileShape shape;
    shape.path = rayset::fuzz::write_input(data, size, "input.obj");
    shape.format = "obj";
    try {
        const auto mesh = rayset::tracer::load_mesh_file(shape, "the fuzz harness");
        check_indices(mesh->faces, mesh->vertices.size(), "vertex");
        check_indices(mesh->normal_faces, mesh->normals.size(), "normal");
    } catch (const rayset::Error& error) {
        // The loader found the file bad and said so: what it should do.
        rayset::fuzz::expect_file_named(error, shape.path);
    }
    return 0;
}
