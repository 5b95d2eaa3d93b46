// Images laid on space as POV-Ray 3.7 lays image_map, bump_map and image_pattern (reference
// 3.4.7.6.2): the unit square of the x-y plane projected along z (map_type 0), wrapped round
// a sphere (1), a cylinder (2) or a torus of major radius 1 (5), repeated unless `once`.
//
// Read back from POV-Ray's renders of small images: the image's top row at y = 1, pixel
// (column, row from the bottom) covering [c/w, (c+1)/w) x [r/h, (r+1)/h); interpolate 2 is
// bilinear between pixel centres and interpolate 4 weighs the four nearest centres by
// 1 / distance^2 (in pixels), both wrapping round the repeated image.
#pragma once

#include "tracer/scene_language/appearance.h"

namespace rayset::tracer {

// Where pattern-space point `p` falls on the image, u and v in [0, 1) measured from its
// bottom-left corner; false where it shows nothing (outside the unit square with `once`).
bool image_coordinates(const ImageMap& image, Vec3 p, double& u, double& v);

// The image_map colour at pattern-space point `p` (ImageMap::colours looked up and
// interpolated); false when the image has no colours (a function image).
bool image_map_colour(const ImageMap& image, Vec3 p, Colour& colour);

// bump_map's height at `p`: the pixels' grey values (0.297 red + 0.589 green + 0.114 blue of the
// file's numbers, no gamma), interpolated as the colours are; false without pixels.
bool image_height(const ImageMap& image, Vec3 p, double& height);

}  // namespace rayset::tracer
