// Loads the meshes `mesh_file { "part.obj" }` names (Wavefront OBJ through tinyobjloader),
// polygons triangulated, in the file's own coordinates and unit.
#pragma once

#include <memory>
#include <string>

#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

// Throws rayset::Error naming the file and, for the scene, `where` (the mesh_file statement).
std::shared_ptr<const TriangleMesh> load_mesh_file(const MeshFileShape& shape,
                                                   const std::string& where);

}  // namespace rayset::tracer
