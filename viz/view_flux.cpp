// Flux-lattice view: every cell holding light as a cube of the cell size, coloured by its flux.
#include "viz/view_style.h"
#include "viz/views.h"
#include "viz/vtk_arrays.h"

#include <vtkActor.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkThresholdPoints.h>

#include <limits>

namespace rayset::viz {

ViewHandles add_flux_view(vtkRenderer* renderer, vtkImageData* flux, const std::string& title) {
    double range[2];
    flux->GetPointData()->GetScalars()->GetRange(range);
    auto lut = colour_map(0, range[1]);
    const double cell = flux->GetSpacing()[0];
    auto lit = vtkSmartPointer<vtkThresholdPoints>::New();
    lit->SetInputData(flux);
    lit->ThresholdByUpper(std::numeric_limits<double>::min());  // cells holding light
    // Slightly smaller than the cell so neighbouring cells stay apart.
    add_cell_cubes(renderer, lit->GetOutputPort(), 0.92 * cell, lut);

    double bounds[6];
    flux->GetBounds(bounds);
    for (int a = 0; a < 6; ++a) bounds[a] += (a % 2 ? 0.5 : -0.5) * cell;
    add_scalar_bar(renderer, lut, "flux per cell (" + field_string(flux, "unit") + ")");
    add_axes(renderer, bounds, "mm");
    add_title(renderer, title);
    ViewHandles h;
    h.azimuth = -90, h.elevation = 55;
    return h;
}

}  // namespace rayset::viz
