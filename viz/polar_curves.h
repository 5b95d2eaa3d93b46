// Polar C-plane curves, the way lighting engineers read a far field: each curve is one plane
// through the polar axis (C and C + 180), drawn in a 2-D chart with gamma = 0 pointing down
// (nadir, as in every photometric report) and the intensity as the distance from the centre.
#pragma once

#include "viz/intensity_table.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace rayset::viz {

// The planes drawn: C0-C180, C90-C270, and the plane through the maximum when it is neither,
// so the curves always reach the table's maximum.
std::vector<double> polar_planes(const IntensityTable& table);

// One polyline per plane in z = 0 of the chart: C side to the right (x = I sin gamma), C + 180
// to the left, y = -I cos gamma. Intensities at the table's own vertical angles (exact values
// for far fields of rays). Point data "intensity" and "gamma_deg" (signed: negative on the
// C + 180 side), and "standard_error" when the table states errors; cell data "plane_c_deg";
// field data "unit", "source".
vtkSmartPointer<vtkPolyData> polar_curves(const IntensityTable& table);

// The uncertainty band of each curve of polar_curves(): one triangle strip per plane between
// I - kBandErrors se and I + kBandErrors se (clamped at 0) along the same angles; cell data
// "plane_c_deg". No cells when the table states no errors.
vtkSmartPointer<vtkPolyData> polar_bands(const IntensityTable& table);

// The chart's grid: circles at `ring_step` intervals up to `outer` and radial lines every 30
// degrees; `ring_step` is a 1-2-5 step giving 4 or 5 rings.
double polar_ring_step(double max_intensity);
vtkSmartPointer<vtkPolyData> polar_grid(double ring_step, int rings);

}  // namespace rayset::viz
