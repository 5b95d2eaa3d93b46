// The body's balls listed by the occupied voxels of the density lattice that their boxes reach
// into, the ball reaching deepest toward the voxel's centre first.
//
// Why: a light sample draws a point in an occupied voxel and asks whether the line from the
// shaded point through it meets the body. That line nearly always meets one of the few balls
// around the point, so testing those (in double precision, as SphereBody confirms its hits)
// answers the question without a traversal of the body's Embree scene. A miss of all of them
// says nothing (the line may meet a ball listed elsewhere): the caller then asks the body.
#pragma once

#include "lightmodel/model.h"
#include "lightmodel/sphere.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace rayset::lightmodel {

class VoxelBalls {
public:
    explicit VoxelBalls(const LightModel& model);

    // Whether the ray origin + t dir (dir unit) enters one of the balls listed for occupied
    // voxel `voxel` (an index into LightModel::voxels) at some t in [0, t_max]. For an origin
    // outside the body, true means the ray meets the body; false means none of these balls.
    bool ray_enters(uint32_t voxel, Vec3 origin, Vec3 dir,
                    double t_max = std::numeric_limits<double>::infinity()) const;

    size_t listed() const { return balls_.size(); }  // balls counted once per voxel listing them

private:
    std::vector<uint32_t> start_;  // per occupied voxel, into balls_; one past the last at the end
    std::vector<Sphere> balls_;    // copies, each voxel's together (one cache line holds four)
};

}  // namespace rayset::lightmodel
