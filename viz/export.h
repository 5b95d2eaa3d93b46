// --export: every dataset an input offers as VTK XML files ParaView opens (.vti lattices and
// images, .vtp spheres, diagrams, clouds, solids and curves) and one .vtm collecting them.
#pragma once

#include "viz/input.h"

#include <string>
#include <vector>

namespace rayset::viz {

// Writes into `directory` (created if missing):
//   model:      density.vti, flux.vti, spheres.vtp, diagram_I_J_K.vtp for every intensity
//               cell that emits light;
//   rays:       rays.vtp, farfield.vtp (photometric solid), polar.vtp (C-plane curves);
//   photometry: farfield.vtp, polar.vtp;
//   image:      image.vti;
// then <file stem>.vtm naming them all (written last, so it only names files that exist).
// Returns the paths written, the .vtm last. Every file goes through a temporary name.
std::vector<std::string> export_input(Input& input, const ViewOptions& options,
                                      const std::string& directory);

// One dataset to one file; the writer follows the extension (.vti image data, .vtp poly data).
void write_dataset(vtkDataObject* data, const std::string& path);

}  // namespace rayset::viz
