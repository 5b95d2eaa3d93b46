// One .vdb file holds a whole model: the lattices as grids (density, flux, luminous), the
// spheres, diagrams and spectra as tables in index space, and the frames and provenance as
// metadata (docs/light-model.md lists every name). OpenVDB's vdb_print lists it.
#pragma once

#include "lightmodel/model.h"

#include <string>

namespace rayset::lightmodel {

// Writes through a temporary file renamed into place, so a failed write leaves nothing.
void write_model(const LightModel& model, const std::string& path);
// Throws rayset::Error naming the file and what is missing or inconsistent.
LightModel read_model(const std::string& path);

}  // namespace rayset::lightmodel
