// POV-Ray's mesh_camera: each ray leaves a face of a mesh along the face's normal. Measured
// against POV-Ray 3.7 (one triangle a, b, c per probe):
// - the ray of a face starts at its centroid, moved by location.z along the face's unit normal
//   in the mesh's own coordinates, and runs along that normal, n = normalize((c - a) x (b - a)),
//   taken to the world as a normal (inverse transpose); a direction whose z is negative reverses
//   the ray, not the move of its origin. Only the z of location and direction are used.
// - distribution 0: pixel p (row by row from the top) is face p; ray k of a pixel comes from
//   mesh k. 1: the meshes' faces one list, ray k of pixel p is face W H k + p. 2: the meshes side
//   by side, each a sub-camera floor(W / M) pixels wide (pixel p of a block its face p; the
//   columns left over cast no ray). 3: the pixel's
//   point (u, v) = (x / W, 1 - y / H) in the faces' uv coordinates; the ray leaves the point of
//   the face that holds it, along the face's normal, or with `smooth` along the normal the
//   vertex normals interpolate there.
// A pixel whose face does not exist casts no ray. Several rays of a pixel are averaged: the
// ray a sample takes is chosen by its horizontal position inside the pixel.
//
// Where POV-Ray 3.7 departs from the above (its own first-pass sampling): distributions 0 to 2
// render their first image row twice (row y shows the faces of row y - 1), distribution 2 takes
// face y W/M + x in block k, not y W/M + x - k W/M, and distribution 3 samples pixel corners.
#pragma once

#include <array>
#include <vector>

#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

struct CameraRay;

class MeshCameraRays {
public:
    MeshCameraRays(const MeshCamera& camera, double location_z, double direction_z);
    // (x, y) in pixels, continuous, of a W x H image; see the file's comment.
    CameraRay ray(double x, double y, int width, int height) const;

private:
    struct Face {
        Vec3 origin, direction;       // the face's ray: from the centroid along the normal
        std::array<Vec3, 3> corners;  // world
        std::array<Vec3, 3> normals;  // world, unit, the vertices' (smooth); else `direction`
        std::array<Vec2, 3> uvs;
        Vec3 origin_move;  // world: location.z along the normal in the mesh's coordinates
    };

    void build_uv_grid();
    CameraRay face_ray(const std::vector<Face>& faces, long face) const;
    CameraRay uv_ray(Vec2 uv) const;

    MeshCamera camera_;
    std::vector<std::vector<Face>> meshes_;
    // Distribution 3: the faces whose uv triangle meets each cell of a grid over the uv box.
    std::vector<const Face*> uv_faces_;
    std::vector<int> uv_cell_start_;  // cell c holds uv_faces_[start[c] .. start[c + 1])
    Vec2 uv_min_, uv_cell_size_;
    int uv_cells_ = 1;  // per side
};

}  // namespace rayset::tracer
