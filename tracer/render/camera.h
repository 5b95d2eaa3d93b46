// The camera of a SceneDescription, kept in POV-Ray's frame. The image point (s, t) in [0, 1]^2
// (t downward) has the offsets x = s - 0.5 and y = 0.5 - t; with D, R, U the unit direction,
// right and up, and A the camera's angle in degrees (read back from POV-Ray 3.7's renders):
// - perspective: a ray from the location along direction + x right + y up;
// - orthographic: from the location + x right + y up along the direction (the parser has sized
//   right and up from the angle, as POV-Ray does);
// - spherical: longitude x A and latitude y V (V the vertical angle) about D;
// - cylinder 1: around U by x A, rising y up; cylinder 2: around R by y A, along x right;
//   cylinders 3 and 4: the same with the viewpoint moved by y up (3) or x right (4) instead;
// - ultra_wide_angle: sin(x A) R + sin(y A |up| / |right|) U + cos(x A) cos(...) D;
// - fisheye: at the angle r A from D, r = |(x |right| / |up|, y)|; none beyond r = 1/2 (POV-Ray
//   leaves those pixels black);
// - panoramic: cos(b) sin(a) right + sin(b) up + cos(b) cos(a) direction, a = 180 x and b =
//   180 y degrees, the three vectors as given (their lengths shape the view; angle is ignored);
// - omnimax: a 180-degree lens about the point (lx, ly) = (x0 |right| / |up|, y0 + k - 1) of
//   the image (x0 = 2 x, y0 = 2 y), or (k x0, k y0 |up| / |right|) when |right| <= |up|; the
//   angle from D a fixed odd polynomial of r = |(lx, ly)| (camera.cpp), k = 1.2835 where it ends
//   at 90 degrees; no ray beyond k or more than 90 degrees from D + U (the dome's half);
// - mesh_camera: from the faces of meshes (mesh_camera.h).
// Like POV-Ray, the image size does not change right/up: a 4:3 image of a square camera
// is stretched exactly as POV-Ray stretches it.
#pragma once

#include <memory>

#include "tracer/render/mesh_camera.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

// Throws rayset::Error ("not supported: FEATURE at FILE:LINE:COLUMN") for what the camera does
// not render: focal blur, a normal perturbation.
void check_camera_renderable(const Camera& camera);

struct CameraRay {
    Vec3 origin, direction;  // direction of unit length
    bool exists = true;      // false where the projection casts no ray (outside a fisheye)
    // What a pixel without a ray gets.
    static CameraRay none() { return {{}, {0, 0, 1}, false}; }
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
    Vec3 d_, r_, u_;                              // unit direction, right and up
    double right_over_up_ = 1;                    // |right| / |up|
    double angle_ = 0, vertical_angle_ = 0;       // radians
    std::shared_ptr<const MeshCameraRays> mesh_;  // the mesh_camera projection
};

}  // namespace rayset::tracer
