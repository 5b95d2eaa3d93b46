// normal { } patterns as POV-Ray 3.7 tilts a surface's shading normal with them.
//
// Most patterns tilt the normal down their slope: n' = n - (2/15) a s grad(v), with a the
// bump size, grad(v) the gradient of the pattern's value in world space (estimated over the
// normal's `accuracy`) and s the pattern's scale across the surface, |M^T n| for M the
// pattern's transform (1 with no_bump_scale): scaling a pattern narrows its bumps without
// steepening them. bumps, dents and wrinkles tilt by a vector noise instead, turned into the
// world as normals are. The factor 2/15 and the noises' factors were read back from POV-Ray
// (the normal's components on a plane lit from grazing directions: a gradient's slope exactly,
// the noises' mean and spread over 40 000 points), including wrinkles' constant lean toward
// (1, 1, 1). What is not reproduced: POV-Ray's noise tilts change by some 15% with the
// pattern's scale, and its dents tilt more along x than along z.
#pragma once

#include "tracer/scene_language/appearance.h"

namespace rayset::tracer {

// The vector added to the unit outward surface normal `n` at `point` (world coordinates);
// the shading normal is n + delta normalised. False where the normal cannot be evaluated.
bool normal_perturbation(const Normal& normal, Vec3 point, Vec3 n, Vec3& delta);
// Whether normal_perturbation can evaluate this normal (anywhere, as for patterns).
bool normal_is_evaluable(const Normal& normal);

}  // namespace rayset::tracer
