// A ray file as a point cloud: a uniform random subsample of its rays (reservoir sampling, one
// streaming pass, memory bounded by the sample) with origin, direction, flux and wavelength.
#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <string>

namespace rayset::viz {

struct RayCloudOptions {
    size_t max_rays = 5000;  // every ray when the file has fewer
    uint64_t seed = 1;
};

// One vertex per sampled ray at its origin (file unit). Point data "flux" (radiant W, or lm
// when the file carries only luminous flux), "wavelength" (nm, NaN when unknown), vectors
// "direction"; field data "unit" (length unit), "flux_unit", "rays" (rays in the file).
vtkSmartPointer<vtkPolyData> ray_cloud(const std::string& path,
                                       const RayCloudOptions& options = {});

}  // namespace rayset::viz
