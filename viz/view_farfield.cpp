// Photometric-solid view: the far-field surface coloured by intensity, axes in intensity units.
#include "viz/view_style.h"
#include "viz/views.h"
#include "viz/vtk_arrays.h"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

namespace rayset::viz {

ViewHandles add_farfield_view(vtkRenderer* renderer, vtkPolyData* solid, const std::string& title) {
    double range[2];
    solid->GetPointData()->GetScalars()->GetRange(range);
    auto lut = colour_map(range[0], range[1]);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(solid);
    mapper->SetLookupTable(lut);
    mapper->UseLookupTableScalarRangeOn();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    renderer->AddActor(actor);

    const std::string unit = field_string(solid, "unit");
    double bounds[6];
    solid->GetBounds(bounds);
    add_scalar_bar(renderer, lut, "intensity (" + unit + ")");
    add_axes(renderer, bounds, unit, "I_");
    add_title(renderer, title);
    ViewHandles h;
    h.azimuth = -60, h.elevation = 15;
    return h;
}

}  // namespace rayset::viz
