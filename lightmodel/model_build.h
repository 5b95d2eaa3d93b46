// Builds the complex light-source model from a ray file in three streaming passes, so memory
// is bounded by the lattices, not by the number of rays:
//   1. bounds of the origins, ray count;
//   2. density lattice, flux lattice with per-cell spectra, goniometric diagrams;
//   3. a reservoir sample of the origins in every boundary cell, then the sphere fits and the
//      body's coverage of each flux cell (coverage.h).
#pragma once

#include "lightmodel/model.h"

#include <functional>
#include <string>

namespace rayset::lightmodel {

// Called with the pass (1..4, 4 = sphere fit) and the fraction done, for progress bars.
using BuildProgress = std::function<void(int pass, double fraction)>;

LightModel build_model(const std::string& ray_file, const ModelOptions& options,
                       const BuildProgress& progress = {});

}  // namespace rayset::lightmodel
