// Coverage of the emitting volume by the body: for each flux cell, the fraction g_c of its
// emission whose line meets the sphere body, measured by casting lines through points of the
// cell's voxels in directions drawn from its diagram. The body is fitted to where the origins
// are, so it leaves out the parts of voxels that no ray left from (the rim of a disk, pores
// between samples); dividing the cell's radiance by g_c puts that light where the body is,
// which is where the rays came from, and keeps what a camera sees of the cell equal to its
// flux (docs/light-model.md, "Coverage").
#pragma once

#include "lightmodel/model.h"

namespace rayset::lightmodel {

// Sets FluxCell::visible_fraction of every cell; `lines` per cell (binomial error
// sqrt(g (1 - g) / lines)), deterministic for a seed.
void measure_visible_fractions(LightModel& model, int lines, uint64_t seed);

}  // namespace rayset::lightmodel
