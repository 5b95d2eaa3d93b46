// Camera rays in POV-Ray's frame (see camera.h).
#include "tracer/render/camera.h"

#include <cmath>

#include <fmt/format.h>

#include "core/error.h"

namespace rayset::tracer {

namespace {

// Omnimax: the lens's angle from D at the radius R of the image point about the lens centre,
// in radians, and the reach of its circle (both read back from POV-Ray 3.7 with probe renders,
// to 2e-5: a sphere about the camera coloured by the direction's components).
constexpr double kOmnimaxReach = 1.283458;  // R where the image circle ends (about 90 degrees)
double omnimax_angle(double r) {
    const double r2 = r * r;
    return r * (1.099583 + r2 * (-0.0446445 + r2 * 0.0737172));
}

}  // namespace

void check_camera_renderable(const Camera& camera) {
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
    d_ = normalized(camera.direction);
    r_ = normalized(camera.right);
    u_ = normalized(camera.up);
    right_over_up_ = length(camera.right) / length(camera.up);
    angle_ = camera.angle * kRadiansPerDegree;
    vertical_angle_ = camera.vertical_angle * kRadiansPerDegree;
    if (camera.projection == CameraProjection::mesh)
        mesh_ = std::make_shared<const MeshCameraRays>(camera.mesh, camera.location.z,
                                                       camera.direction.z);
}

CameraRay SceneCamera::ray(double px, double py) const {
    const double x = px / width_ - 0.5, y = 0.5 - py / height_;
    const Camera& c = camera_;
    // The unit vector at `around` from D toward R and `up` from that toward U.
    auto turned = [&](double around, double up) {
        return std::cos(up) * (std::sin(around) * r_ + std::cos(around) * d_) + std::sin(up) * u_;
    };
    switch (c.projection) {
        case CameraProjection::orthographic: return {c.location + x * c.right + y * c.up, d_};
        case CameraProjection::spherical:
            return {c.location, turned(x * angle_, y * vertical_angle_)};
        case CameraProjection::cylinder: {
            // Types 1 and 3 turn around up, 2 and 4 around right.
            if (c.cylinder_type == 1 || c.cylinder_type == 3) {
                const Vec3 around = turned(x * angle_, 0);
                return c.cylinder_type == 1 ? CameraRay{c.location, normalized(around + y * c.up)}
                                            : CameraRay{c.location + y * c.up, around};
            }
            const Vec3 around = turned(0, y * angle_);
            return c.cylinder_type == 2 ? CameraRay{c.location, normalized(around + x * c.right)}
                                        : CameraRay{c.location + x * c.right, around};
        }
        case CameraProjection::ultra_wide_angle: {
            const double ax = x * angle_, ay = y * angle_ / right_over_up_;
            return {c.location, normalized(std::sin(ax) * r_ + std::sin(ay) * u_ +
                                           std::cos(ax) * std::cos(ay) * d_)};
        }
        case CameraProjection::panoramic: {
            // Right, up and direction as given (not unit): their lengths shape the view.
            const double longitude = kPi * x, latitude = kPi * y;
            return {c.location, normalized(std::cos(latitude) * std::sin(longitude) * c.right +
                                           std::sin(latitude) * c.up +
                                           std::cos(latitude) * std::cos(longitude) * c.direction)};
        }
        case CameraProjection::omnimax: {
            const double x0 = 2 * x, y0 = 2 * y;  // -1 .. 1 across the image
            // A wide view puts the lens centre below the image centre; a tall one scales.
            const bool wide = right_over_up_ > 1;
            const double lx = wide ? right_over_up_ * x0 : kOmnimaxReach * x0;
            const double ly = wide ? y0 + kOmnimaxReach - 1 : kOmnimaxReach * y0 / right_over_up_;
            const double r = std::hypot(lx, ly);
            if (r > kOmnimaxReach) return CameraRay::none();
            const double theta = omnimax_angle(r), phi = std::atan2(ly, lx);
            const double along_up = std::sin(theta) * std::sin(phi), along_d = std::cos(theta);
            // The dome: only the half of the view within 90 degrees of D + U.
            if (along_up + along_d < 0) return CameraRay::none();
            return {c.location,
                    std::sin(theta) * std::cos(phi) * r_ + along_up * u_ + along_d * d_};
        }
        case CameraProjection::mesh: return mesh_->ray(px, py, width_, height_);
        case CameraProjection::fisheye: {
            const double fx = x * right_over_up_, r = std::hypot(fx, y);
            if (r > 0.5) return CameraRay::none();
            const double theta = r * angle_, phi = std::atan2(y, fx);
            return {c.location, std::sin(theta) * (std::cos(phi) * r_ + std::sin(phi) * u_) +
                                    std::cos(theta) * d_};
        }
        default: return {c.location, normalized(c.direction + x * c.right + y * c.up)};
    }
}

}  // namespace rayset::tracer
