// The perspective camera of a SceneDescription, kept in POV-Ray's frame: the ray through image
// point (s, t) in [0, 1]^2 (t downward) runs along direction + (s - 0.5) right + (0.5 - t) up.
// Like POV-Ray, the image size does not change right/up: a 4:3 image of a square camera
// is stretched exactly as POV-Ray stretches it.
#pragma once

#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

// Throws rayset::Error ("not supported: FEATURE at FILE:LINE:COLUMN") for what the camera does
// not render: a projection other than perspective, focal blur, a normal perturbation.
void check_camera_renderable(const Camera& camera);

struct CameraRay {
    Vec3 origin, direction;  // direction of unit length
};

class PerspectiveCamera {
public:
    PerspectiveCamera(const Camera& camera, int width, int height);
    // (x, y) in pixels, continuous: pixel (i, j) covers [i, i+1) x [j, j+1), j downward.
    CameraRay ray(double x, double y) const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    Camera camera_;
    int width_, height_;
};

}  // namespace rayset::tracer
