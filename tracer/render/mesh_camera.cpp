// POV-Ray's mesh_camera (see mesh_camera.h).
#include "tracer/render/mesh_camera.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "tracer/render/camera.h"
#include "tracer/scene_language/object_tree.h"

namespace rayset::tracer {

namespace {

const TriangleMesh& mesh_of(const ObjectNode& node) {
    const auto* shape = std::get_if<MeshShape>(&node.shape);
    if (node.kind != ObjectNode::Kind::shape || !shape || !shape->mesh)
        throw Error("a mesh_camera takes mesh or mesh2 objects only");
    return *shape->mesh;
}

// Barycentric coordinates of p in the uv triangle t; any negative: outside.
std::array<double, 3> barycentric(Vec2 p, const std::array<Vec2, 3>& t) {
    const double d = (t[1].y - t[2].y) * (t[0].x - t[2].x) + (t[2].x - t[1].x) * (t[0].y - t[2].y);
    if (d == 0) return {-1, -1, -1};
    const double a = ((t[1].y - t[2].y) * (p.x - t[2].x) + (t[2].x - t[1].x) * (p.y - t[2].y)) / d;
    const double b = ((t[2].y - t[0].y) * (p.x - t[2].x) + (t[0].x - t[2].x) * (p.y - t[2].y)) / d;
    return {a, b, 1 - a - b};
}

}  // namespace

MeshCameraRays::MeshCameraRays(const MeshCamera& camera, double location_z, double direction_z)
    : camera_(camera) {
    const double sign = direction_z < 0 ? -1 : 1;
    for (const ObjectRef& node : camera.meshes) {
        const TriangleMesh& mesh = mesh_of(*node);
        const Matrix4& to_world = node->transform;
        std::vector<Face>& faces = meshes_.emplace_back();
        faces.reserve(mesh.faces.size());
        for (size_t f = 0; f < mesh.faces.size(); ++f) {
            Face face;
            std::array<Vec3, 3> local;
            for (int k = 0; k < 3; ++k) local[k] = mesh.vertices[mesh.faces[f][k]];
            const Vec3 local_normal = cross(local[2] - local[0], local[1] - local[0]);
            if (is_zero(local_normal)) {  // a degenerate face keeps its pixel black
                face.direction = {};
                faces.push_back(face);
                continue;
            }
            const Vec3 unit_normal = normalized(local_normal);
            const Vec3 centroid = (1.0 / 3) * (local[0] + local[1] + local[2]);
            face.origin_move = to_world.vector(location_z * unit_normal);
            face.origin = to_world.point(centroid) + face.origin_move;
            face.direction = sign * normalized(to_world.normal(unit_normal));
            for (int k = 0; k < 3; ++k) face.corners[k] = to_world.point(local[k]);
            face.normals = {face.direction, face.direction, face.direction};
            const bool has_normals = !mesh.normals.empty() &&
                                     (mesh.normal_faces.empty() || mesh.normal_faces[f][0] >= 0);
            if (camera.smooth && has_normals) {
                const auto& index =
                    mesh.normal_faces.empty() ? mesh.faces[f] : mesh.normal_faces[f];
                for (int k = 0; k < 3; ++k)
                    face.normals[k] = sign * normalized(to_world.normal(mesh.normals[index[k]]));
            }
            if (!mesh.uvs.empty()) {
                const auto& index = mesh.uv_faces.empty() ? mesh.faces[f] : mesh.uv_faces[f];
                for (int k = 0; k < 3; ++k) face.uvs[k] = mesh.uvs[index[k]];
            }
            faces.push_back(face);
        }
    }
    if (camera.distribution == 3) build_uv_grid();
}

// Distribution 3 looks a point up among the faces' uv triangles: a grid over their box, each
// cell listing the triangles whose box meets it, about two faces a cell.
void MeshCameraRays::build_uv_grid() {
    std::vector<const Face*> faces;
    Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
    for (const auto& mesh : meshes_)
        for (const Face& face : mesh) {
            if (is_zero(face.direction)) continue;
            faces.push_back(&face);
            for (const Vec2& uv : face.uvs) {
                lo = {std::min(lo.x, uv.x), std::min(lo.y, uv.y)};
                hi = {std::max(hi.x, uv.x), std::max(hi.y, uv.y)};
            }
        }
    if (faces.empty()) return;
    uv_cells_ = std::clamp(static_cast<int>(std::sqrt(faces.size() / 2.0)), 1, 2048);
    uv_min_ = lo;
    uv_cell_size_ = {std::max(hi.x - lo.x, 1e-12) / uv_cells_,
                     std::max(hi.y - lo.y, 1e-12) / uv_cells_};
    auto cell_range = [&](const Face& face, int axis_lo[2], int axis_hi[2]) {
        for (int axis = 0; axis < 2; ++axis) {
            double a = 1e300, b = -1e300;
            for (const Vec2& uv : face.uvs) {
                const double v = axis == 0 ? (uv.x - uv_min_.x) / uv_cell_size_.x
                                           : (uv.y - uv_min_.y) / uv_cell_size_.y;
                a = std::min(a, v);
                b = std::max(b, v);
            }
            axis_lo[axis] = std::clamp(static_cast<int>(std::floor(a)), 0, uv_cells_ - 1);
            axis_hi[axis] = std::clamp(static_cast<int>(std::floor(b)), 0, uv_cells_ - 1);
        }
    };
    std::vector<int> counts(uv_cells_ * uv_cells_ + 1, 0);
    for (const Face* face : faces) {
        int a[2], b[2];
        cell_range(*face, a, b);
        for (int j = a[1]; j <= b[1]; ++j)
            for (int i = a[0]; i <= b[0]; ++i) ++counts[j * uv_cells_ + i + 1];
    }
    for (size_t c = 1; c < counts.size(); ++c) counts[c] += counts[c - 1];
    uv_cell_start_ = counts;
    uv_faces_.resize(counts.back());
    for (const Face* face : faces) {
        int a[2], b[2];
        cell_range(*face, a, b);
        for (int j = a[1]; j <= b[1]; ++j)
            for (int i = a[0]; i <= b[0]; ++i) uv_faces_[counts[j * uv_cells_ + i]++] = face;
    }
}

CameraRay MeshCameraRays::face_ray(const std::vector<Face>& faces, long face) const {
    if (face < 0 || face >= static_cast<long>(faces.size()) || is_zero(faces[face].direction))
        return CameraRay::none();
    return {faces[face].origin, faces[face].direction};
}

CameraRay MeshCameraRays::uv_ray(Vec2 uv) const {
    if (uv_cell_start_.empty()) return CameraRay::none();
    const int i = static_cast<int>(std::floor((uv.x - uv_min_.x) / uv_cell_size_.x));
    const int j = static_cast<int>(std::floor((uv.y - uv_min_.y) / uv_cell_size_.y));
    if (i < 0 || j < 0 || i >= uv_cells_ || j >= uv_cells_) return CameraRay::none();
    const int cell = j * uv_cells_ + i;
    for (int k = uv_cell_start_[cell]; k < uv_cell_start_[cell + 1]; ++k) {
        const Face& face = *uv_faces_[k];
        const std::array<double, 3> w = barycentric(uv, face.uvs);
        if (w[0] < -1e-12 || w[1] < -1e-12 || w[2] < -1e-12) continue;
        const Vec3 point = w[0] * face.corners[0] + w[1] * face.corners[1] + w[2] * face.corners[2];
        const Vec3 normal =
            w[0] * face.normals[0] + w[1] * face.normals[1] + w[2] * face.normals[2];
        return {point + face.origin_move, normalized(normal)};
    }
    return CameraRay::none();
}

CameraRay MeshCameraRays::ray(double x, double y, int width, int height) const {
    if (camera_.distribution == 3) return uv_ray({x / width, 1 - y / height});
    const int column = std::clamp(static_cast<int>(x), 0, width - 1);
    const int row = std::clamp(static_cast<int>(y), 0, height - 1);
    const int rays = std::max(camera_.rays_per_pixel, 1);
    const int ray = std::min(static_cast<int>((x - column) * rays), rays - 1);
    const long pixels = static_cast<long>(width) * height;
    const long pixel = static_cast<long>(row) * width + column;
    switch (camera_.distribution) {
        case 0:
            if (ray >= static_cast<int>(meshes_.size())) return CameraRay::none();
            return face_ray(meshes_[ray], pixel);
        case 1: {
            long face = pixels * ray + pixel;
            for (const auto& faces : meshes_) {
                if (face < static_cast<long>(faces.size())) return face_ray(faces, face);
                face -= static_cast<long>(faces.size());
            }
            return CameraRay::none();
        }
        default: {
            const int blocks = static_cast<int>(meshes_.size());
            const int block_width = std::max(width / blocks, 1);
            const int block = std::min(column / block_width, blocks - 1);
            const long local = static_cast<long>(row) * block_width + column - block * block_width;
            if (column - block * block_width >= block_width) return CameraRay::none();
            return face_ray(meshes_[block], local);
        }
    }
}

}  // namespace rayset::tracer
