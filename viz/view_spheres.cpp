// Sphere-body view: every boundary sphere drawn with its real radius, coloured by radius.
#include "viz/view_style.h"
#include "viz/views.h"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkPointData.h>
#include <vtkSphereSource.h>

namespace rayset::viz {

ViewHandles add_spheres_view(vtkRenderer* renderer, vtkPolyData* spheres,
                             const std::string& title) {
    double range[2];
    spheres->GetPointData()->GetScalars()->GetRange(range);
    auto lut = colour_map(range[0], range[1]);
    auto unit_sphere = vtkSmartPointer<vtkSphereSource>::New();
    unit_sphere->SetRadius(1);
    unit_sphere->SetThetaResolution(12);
    unit_sphere->SetPhiResolution(8);
    auto mapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
    mapper->SetInputData(spheres);
    mapper->SetSourceConnection(unit_sphere->GetOutputPort());
    mapper->SetScaleArray("radius");
    mapper->SetScaleModeToScaleByMagnitude();
    mapper->SetScaleFactor(1);
    mapper->OrientOff();
    mapper->SetLookupTable(lut);
    mapper->UseLookupTableScalarRangeOn();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    renderer->AddActor(actor);

    double bounds[6];
    spheres->GetBounds(bounds);
    const double r = range[1];
    for (int a = 0; a < 6; ++a) bounds[a] += (a % 2 ? r : -r);
    add_scalar_bar(renderer, lut, "sphere radius (mm)");
    add_axes(renderer, bounds, "mm");
    add_title(renderer, title + " (" + std::to_string(spheres->GetNumberOfPoints()) + ")");
    ViewHandles h;
    h.azimuth = -90, h.elevation = 55;
    return h;
}

}  // namespace rayset::viz
