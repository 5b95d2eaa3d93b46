// Photometric-solid view: the far-field surface coloured by intensity, axes in intensity units,
// and, when the far field states standard errors, a translucent shell at the top of its
// uncertainty band (I + kBandErrors se).
#include "viz/view_style.h"
#include "viz/views.h"
#include "viz/vtk_arrays.h"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

namespace rayset::viz {

namespace {

// The solid pushed out along each direction from I to I + kBandErrors se.
vtkSmartPointer<vtkActor> band_shell(vtkPolyData* solid, vtkDataArray* error) {
    vtkDataArray* intensity = solid->GetPointData()->GetScalars();
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    for (vtkIdType k = 0; k < solid->GetNumberOfPoints(); ++k) {
        double p[3];
        solid->GetPoint(k, p);
        const double value = intensity->GetTuple1(k);
        const double scale = value > 0 ? (value + kBandErrors * error->GetTuple1(k)) / value : 1;
        points->InsertNextPoint(p[0] * scale, p[1] * scale, p[2] * scale);
    }
    auto shell = vtkSmartPointer<vtkPolyData>::New();
    shell->SetPoints(points);
    shell->SetPolys(solid->GetPolys());
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(shell);
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.6, 0.6, 0.6);
    actor->GetProperty()->SetOpacity(0.2);
    return actor;
}

}  // namespace

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
    if (vtkDataArray* error = solid->GetPointData()->GetArray("standard_error"))
        renderer->AddActor(band_shell(solid, error));

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
