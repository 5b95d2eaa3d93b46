// The photometric solid: the closed surface whose distance from the centre toward every
// direction is the intensity toward it (cd or W/sr), the 3-D form of a far field.
#pragma once

#include "viz/intensity_table.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace rayset::viz {

// Points on a regular (C, gamma) grid of `c_step_deg` x `gamma_step_deg` (the table's own steps
// for far fields of rays, so its values are the table's), at I(C, gamma) times the direction,
// with gamma measured from table.axis * z. Point data "intensity" (table.unit), its
// "standard_error" when the table states errors, and normals; field data "unit".
vtkSmartPointer<vtkPolyData> photometric_solid(const IntensityTable& table, double c_step_deg = 5,
                                               double gamma_step_deg = 2.5);

}  // namespace rayset::viz
