// A light model's lattices and body as VTK data in the model frame (mm): the density and flux
// lattices as images whose points are the cell centres, the sphere body as points with radii.
#pragma once

#include "lightmodel/model.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace rayset::viz {

// Point data "density" (float, rays per voxel, 0 where empty); field data "unit" ("rays").
vtkSmartPointer<vtkImageData> density_image(const lightmodel::LightModel& model);
// Point data "flux" (model.flux_unit) and "luminous" (lm); field data "unit".
vtkSmartPointer<vtkImageData> flux_image(const lightmodel::LightModel& model);
// One vertex per sphere at its centre, point data "radius" (mm).
vtkSmartPointer<vtkPolyData> sphere_set(const lightmodel::LightModel& model);

}  // namespace rayset::viz
