// Camera rays in POV-Ray's frame (see camera.h).
#include "tracer/render/camera.h"

#include <fmt/format.h>

#include "core/error.h"

namespace rayset::tracer {

namespace {

const char* projection_name(CameraProjection projection) {
    switch (projection) {
        case CameraProjection::perspective: return "perspective";
        case CameraProjection::orthographic: return "orthographic";
        case CameraProjection::mesh: return "mesh_camera";
        case CameraProjection::fisheye: return "fisheye";
        case CameraProjection::ultra_wide_angle: return "ultra_wide_angle";
        case CameraProjection::omnimax: return "omnimax";
        case CameraProjection::panoramic: return "panoramic";
        case CameraProjection::cylinder: return "cylinder";
        case CameraProjection::spherical: return "spherical";
    }
    return "unknown";
}

}  // namespace

void check_camera_renderable(const Camera& camera) {
    if (camera.projection != CameraProjection::perspective &&
        camera.projection != CameraProjection::orthographic)
        throw Error(
            fmt::format("not supported: {} camera (only perspective and orthographic) at {}",
                        projection_name(camera.projection), camera.projection_location.str()));
    if (camera.focal_blur.aperture != 0)
        throw Error(fmt::format("not supported: focal blur (camera aperture {}) at {}",
                                camera.focal_blur.aperture, camera.focal_blur_location.str()));
    if (camera.normal)
        throw Error(fmt::format("not supported: camera normal perturbation at {}",
                                camera.normal_location.str()));
}

SceneCamera::SceneCamera(const Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height) {
    check_camera_renderable(camera);
    if (width < 1 || height < 1) throw Error("image size must be at least 1 x 1 pixels");
}

CameraRay SceneCamera::ray(double x, double y) const {
    const double s = x / width_, t = y / height_;
    const Vec3 on_plane = (s - 0.5) * camera_.right + (0.5 - t) * camera_.up;
    if (camera_.projection == CameraProjection::orthographic)
        return {camera_.location + on_plane, normalized(camera_.direction)};
    return {camera_.location, normalized(camera_.direction + on_plane)};
}

}  // namespace rayset::tracer
