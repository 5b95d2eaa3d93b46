// Ray view: sampled origins as points and their directions as arrows, coloured by wavelength
// (when the file knows it) or by flux.
#include "viz/view_style.h"
#include "viz/views.h"
#include "viz/vtk_arrays.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkDataArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <algorithm>
#include <cmath>

namespace rayset::viz {

ViewHandles add_rays_view(vtkRenderer* renderer, vtkPolyData* cloud, const std::string& title,
                          bool colour_by_flux) {
    // Wavelengths that are unknown (NaN) do not count; without any, colour by flux.
    double range[2] = {1e300, -1e300};
    vtkDataArray* wavelength = cloud->GetPointData()->GetArray("wavelength");
    for (vtkIdType i = 0; i < wavelength->GetNumberOfTuples(); ++i) {
        const double nm = wavelength->GetComponent(i, 0);
        if (std::isfinite(nm)) range[0] = std::min(range[0], nm), range[1] = std::max(range[1], nm);
    }
    const bool by_wavelength = !colour_by_flux && range[0] <= range[1];
    const char* array = by_wavelength ? "wavelength" : "flux";
    if (!by_wavelength) cloud->GetPointData()->GetArray(array)->GetRange(range);
    auto lut = colour_map(range[0], range[1]);

    auto points = vtkSmartPointer<vtkPolyDataMapper>::New();
    points->SetInputData(cloud);
    points->SetScalarModeToUsePointFieldData();
    points->SelectColorArray(array);
    points->SetLookupTable(lut);
    points->UseLookupTableScalarRangeOn();
    auto point_actor = vtkSmartPointer<vtkActor>::New();
    point_actor->SetMapper(points);
    point_actor->GetProperty()->SetPointSize(3);
    renderer->AddActor(point_actor);

    double bounds[6];
    cloud->GetBounds(bounds);
    const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
                                      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
                                      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
    auto arrow = vtkSmartPointer<vtkArrowSource>::New();
    arrow->SetTipResolution(8);
    arrow->SetShaftResolution(8);
    auto arrows = vtkSmartPointer<vtkGlyph3DMapper>::New();
    arrows->SetInputData(cloud);
    arrows->SetSourceConnection(arrow->GetOutputPort());
    arrows->SetOrientationArray("direction");
    arrows->OrientOn();
    // Arrows 6% of the cloud's size: long enough to read, short enough not to hide it.
    arrows->ScalingOn();
    arrows->SetScaleModeToNoDataScaling();
    arrows->SetScaleFactor(0.06 * (diagonal > 0 ? diagonal : 1));
    arrows->SetScalarModeToUsePointFieldData();
    arrows->SelectColorArray(array);
    arrows->SetLookupTable(lut);
    arrows->UseLookupTableScalarRangeOn();
    auto arrow_actor = vtkSmartPointer<vtkActor>::New();
    arrow_actor->SetMapper(arrows);
    renderer->AddActor(arrow_actor);

    const std::string unit = field_string(cloud, "unit");
    add_scalar_bar(renderer, lut,
                   by_wavelength ? "wavelength (nm)"
                                 : "flux per ray (" + field_string(cloud, "flux_unit") + ")");
    add_axes(renderer, bounds, unit);
    add_title(renderer, title);
    ViewHandles h;
    h.azimuth = -60, h.elevation = 30;
    return h;
}

}  // namespace rayset::viz
