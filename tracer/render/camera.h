// The camera of a SceneDescription, kept in POV-Ray's frame. The image point (s, t) in [0, 1]^2
// (t downward) is the point (s - 0.5) right + (0.5 - t) up of the image plane; through it
// - perspective: a ray from the location along direction + that point;
// - orthographic: a ray from the location + that point along the direction (the parser has
//   sized right and up from the angle, as POV-Ray does).
// Like POV-Ray, the image size does not change right/up: a 4:3 image of a square camera
// is stretched exactly as POV-Ray stretches it.
#pragma once

#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

// Throws rayset::Error ("not supported: FEATURE at FILE:LINE:COLUMN") for what the camera does
// not render: a projection other than perspective and orthographic, focal blur, a normal
// perturbation.
void check_camera_renderable(const Camera& camera);

struct CameraRay {
    Vec3 origin, direction;  // direction of unit length
};

class SceneCamera {
public:
    SceneCamera(const Camera& camera, int width, int height);
    // (x, y) in pixels, continuous: pixel (i, j) covers [i, i+1) x [j, j+1), j downward.
    CameraRay ray(double x, double y) const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    Camera camera_;
    int width_, height_;
};

}  // namespace rayset::tracer
