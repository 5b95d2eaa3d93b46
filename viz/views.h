// One small VTK pipeline per view, each adding its props (data, scalar bar or legend, axes
// with units, title) to a renderer. add_view() picks the pipeline for an input and a view.
#pragma once

#include "viz/input.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <functional>
#include <string>
#include <vector>

namespace rayset::viz {

// What interactive mode can adjust after a view is built, and the camera it starts from.
struct ViewHandles {
    std::function<void(double)> set_threshold;  // density: rays per voxel
    double threshold_min = 0, threshold_max = 0;
    double azimuth = -60, elevation = 30;  // default camera direction (scene.h, degrees)
    bool flat = false;                     // a 2-D chart: parallel projection, no turning
};

ViewHandles add_view(vtkRenderer* renderer, Input& input, View view, const ViewOptions& options);

ViewHandles add_rays_view(vtkRenderer* renderer, vtkPolyData* cloud, const std::string& title,
                          bool colour_by_flux);
ViewHandles add_farfield_view(vtkRenderer* renderer, vtkPolyData* solid, const std::string& title);
// Several far fields overlaid in one polar chart, one colour and legend entry per plane and file.
ViewHandles add_polar_view(vtkRenderer* renderer, const std::vector<const IntensityTable*>& tables);
ViewHandles add_density_view(vtkRenderer* renderer, vtkImageData* density, const std::string& title,
                             double threshold, bool contour);
ViewHandles add_spheres_view(vtkRenderer* renderer, vtkPolyData* spheres, const std::string& title);
ViewHandles add_flux_view(vtkRenderer* renderer, vtkImageData* flux, const std::string& title);
ViewHandles add_diagram_view(vtkRenderer* renderer, vtkPolyData* diagram, const std::string& title);
ViewHandles add_image_view(vtkRenderer* renderer, const ExrLayer& layer, const std::string& title);

}  // namespace rayset::viz
