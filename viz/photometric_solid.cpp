#include "viz/photometric_solid.h"
#include "core/geometry.h"

#include "viz/vtk_arrays.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataNormals.h>

#include <cmath>

namespace rayset::viz {

vtkSmartPointer<vtkPolyData> photometric_solid(const IntensityTable& table, double c_step_deg,
                                               double gamma_step_deg) {
    const int nc = std::max(3, int(std::lround(360 / c_step_deg)));
    const int ng = std::max(2, int(std::lround(180 / gamma_step_deg)));
    const double deg = kRadiansPerDegree;
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();  // exported values keep the table's precision
    auto intensity = named_doubles("intensity");
    auto error = named_doubles("standard_error");
    // Row j = gamma j * step (0 and 180 included: the poles repeat once per C, which keeps the
    // grid regular; the repeated points coincide).
    for (int i = 0; i < nc; ++i) {
        const double c = i * 360.0 / nc;
        for (int j = 0; j <= ng; ++j) {
            const double g = j * 180.0 / ng;
            const double value = table.photometry.intensity(c, g);
            const double s = std::sin(g * deg);
            points->InsertNextPoint(value * s * std::cos(c * deg), value * s * std::sin(c * deg),
                                    table.axis * value * std::cos(g * deg));
            intensity->InsertNextValue(value);
            if (table.standard_error) error->InsertNextValue(table.standard_error->intensity(c, g));
        }
    }
    auto quads = vtkSmartPointer<vtkCellArray>::New();
    for (int i = 0; i < nc; ++i) {
        const int next = (i + 1) % nc;
        for (int j = 0; j < ng; ++j) {
            const vtkIdType q[4] = {i * (ng + 1) + j, next * (ng + 1) + j, next * (ng + 1) + j + 1,
                                    i * (ng + 1) + j + 1};
            quads->InsertNextCell(4, q);
        }
    }
    auto solid = vtkSmartPointer<vtkPolyData>::New();
    solid->SetPoints(points);
    solid->SetPolys(quads);
    solid->GetPointData()->SetScalars(intensity);
    if (table.standard_error) solid->GetPointData()->AddArray(error);
    set_field_string(solid, "unit", table.unit);
    set_field_string(solid, "source", table.label);

    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SetInputData(solid);
    normals->SplittingOff();
    normals->ConsistencyOn();
    normals->AutoOrientNormalsOff();
    normals->Update();
    vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
    return out;
}

}  // namespace rayset::viz
