// Density-lattice view: the occupied voxels at or above a threshold (rays per voxel) as cubes
// of the voxel size, or the contour surface at that threshold; the threshold is what the
// interactive slider moves.
#include "viz/view_style.h"
#include "viz/views.h"

#include <vtkActor.h>
#include <vtkContourFilter.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkThresholdPoints.h>

namespace rayset::viz {

ViewHandles add_density_view(vtkRenderer* renderer, vtkImageData* density, const std::string& title,
                             double threshold, bool contour) {
    double range[2];
    density->GetPointData()->GetScalars()->GetRange(range);
    auto lut = colour_map(std::max(threshold, 0.0), range[1]);
    const double cell = density->GetSpacing()[0];
    ViewHandles h;
    h.threshold_min = 1;
    h.threshold_max = std::max(1.0, range[1]);
    h.azimuth = -90, h.elevation = 55;

    if (contour) {
        auto surface = vtkSmartPointer<vtkContourFilter>::New();
        surface->SetInputData(density);
        surface->SetValue(0, threshold);
        auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
        mapper->SetInputConnection(surface->GetOutputPort());
        mapper->SetLookupTable(lut);
        mapper->UseLookupTableScalarRangeOn();
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        actor->GetProperty()->SetLineWidth(2);  // a one-layer lattice contours into lines
        renderer->AddActor(actor);
        h.set_threshold = [surface](double t) { surface->SetValue(0, t); };
    } else {
        auto kept = vtkSmartPointer<vtkThresholdPoints>::New();
        kept->SetInputData(density);
        kept->ThresholdByUpper(threshold);
        add_cell_cubes(renderer, kept->GetOutputPort(), cell, lut);
        h.set_threshold = [kept](double t) { kept->ThresholdByUpper(t); };
    }
    double bounds[6];
    density->GetBounds(bounds);
    for (int a = 0; a < 6; ++a)
        bounds[a] += (a % 2 ? 0.5 : -0.5) * cell;  // cell faces, not centres
    add_scalar_bar(renderer, lut, "rays per voxel");
    add_axes(renderer, bounds, "mm");
    add_title(renderer, title);
    return h;
}

}  // namespace rayset::viz
