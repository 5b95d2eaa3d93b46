// The goniometric diagram of one intensity cell as a 3-D polar surface: the point toward each
// direction w lies at distance I_k(w) = Phi_k D_k(w) from the centre, the far-field intensity
// (flux_unit/sr) of the light leaving the cell (Phi_k: flux of the flux cells using diagram k).
#pragma once

#include "lightmodel/model.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace rayset::viz {

// Index into model.diagrams of intensity cell `cell`, -1 when the cell emits nothing.
int diagram_index(const lightmodel::LightModel& model, const lightmodel::Coord& cell);
// The intensity cell whose diagram carries the most flux (the default to show).
lightmodel::Coord brightest_intensity_cell(const lightmodel::LightModel& model);
// Flux of the flux cells that use diagram `index`.
double diagram_flux(const lightmodel::LightModel& model, int index);

// Surface centred at the origin, in units of intensity. Point 0 is the +z pole, the last point
// the -z pole, and between them `rings` - 1 rings of `sectors` points at theta = j pi / rings,
// phi = i 2 pi / sectors. Point data "intensity"; field data "cell" (i, j, k), "cell_centre_mm",
// "cell_flux", "unit". Throws rayset::Error when the cell emits nothing.
vtkSmartPointer<vtkPolyData> diagram_surface(const lightmodel::LightModel& model,
                                             const lightmodel::Coord& cell, int rings = 90,
                                             int sectors = 72);

}  // namespace rayset::viz
