// Camera rays in POV-Ray's frame (see camera.h).
#include "tracer/render/camera.h"

#include "converters/error.h"

namespace rayset::tracer {

PerspectiveCamera::PerspectiveCamera(const Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height) {
    if (width < 1 || height < 1) throw Error("image size must be at least 1 x 1 pixels");
}

CameraRay PerspectiveCamera::ray(double x, double y) const {
    const double s = x / width_, t = y / height_;
    const Vec3 d = camera_.direction + (s - 0.5) * camera_.right + (0.5 - t) * camera_.up;
    return {camera_.location, analytic::normalized(d)};
}

}  // namespace rayset::tracer
