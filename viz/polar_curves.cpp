#include "viz/polar_curves.h"
#include "core/geometry.h"

#include "viz/vtk_arrays.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cmath>

namespace rayset::viz {

std::vector<double> polar_planes(const IntensityTable& table) {
    std::vector<double> planes{0, 90};
    const double c = std::fmod(table.max_c_deg, 180);
    if (std::abs(c) > 1e-9 && std::abs(c - 90) > 1e-9) planes.push_back(c);
    return planes;
}

namespace {

// The angles of one plane's curve in drawing order: C + 180 from gamma 180 down to 0 on the
// left (side -1), then C from 0 to 180 on the right (side +1).
struct CurvePoint {
    double plane_c, gamma, side;
};
std::vector<CurvePoint> curve_points(const Photometry& p, double c) {
    std::vector<CurvePoint> out;
    for (size_t v = p.vertical_deg.size(); v-- > 0;)
        out.push_back({c + 180, p.vertical_deg[v], -1});
    for (double g : p.vertical_deg) out.push_back({c, g, 1});
    return out;
}

vtkIdType insert_polar_point(vtkPoints* points, const CurvePoint& at, double value) {
    const double deg = kRadiansPerDegree;
    return points->InsertNextPoint(at.side * value * std::sin(at.gamma * deg),
                                   -value * std::cos(at.gamma * deg), 0);
}

}  // namespace

vtkSmartPointer<vtkPolyData> polar_curves(const IntensityTable& table) {
    const Photometry& p = table.photometry;
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();  // exported values keep the table's precision
    auto intensity = named_doubles("intensity");
    auto error = named_doubles("standard_error");
    auto gamma = named_doubles("gamma_deg");
    auto plane = named_doubles("plane_c_deg");
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (double c : polar_planes(table)) {
        std::vector<vtkIdType> ids;
        for (const CurvePoint& at : curve_points(p, c)) {
            const double value = p.intensity(at.plane_c, at.gamma);
            ids.push_back(insert_polar_point(points, at, value));
            intensity->InsertNextValue(value);
            if (table.standard_error)
                error->InsertNextValue(table.standard_error->intensity(at.plane_c, at.gamma));
            gamma->InsertNextValue(at.side * at.gamma);
        }
        lines->InsertNextCell(vtkIdType(ids.size()), ids.data());
        plane->InsertNextValue(c);
    }
    auto curves = vtkSmartPointer<vtkPolyData>::New();
    curves->SetPoints(points);
    curves->SetLines(lines);
    curves->GetPointData()->SetScalars(intensity);
    if (table.standard_error) curves->GetPointData()->AddArray(error);
    curves->GetPointData()->AddArray(gamma);
    curves->GetCellData()->AddArray(plane);
    set_field_string(curves, "unit", table.unit);
    set_field_string(curves, "source", table.label);
    return curves;
}

vtkSmartPointer<vtkPolyData> polar_bands(const IntensityTable& table) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    auto strips = vtkSmartPointer<vtkCellArray>::New();
    auto plane = named_doubles("plane_c_deg");
    if (table.standard_error)
        for (double c : polar_planes(table)) {
            std::vector<vtkIdType> ids;
            for (const CurvePoint& at : curve_points(table.photometry, c)) {
                const double value = table.photometry.intensity(at.plane_c, at.gamma);
                const double band =
                    kBandErrors * table.standard_error->intensity(at.plane_c, at.gamma);
                ids.push_back(insert_polar_point(points, at, std::max(0.0, value - band)));
                ids.push_back(insert_polar_point(points, at, value + band));
            }
            strips->InsertNextCell(vtkIdType(ids.size()), ids.data());
            plane->InsertNextValue(c);
        }
    auto bands = vtkSmartPointer<vtkPolyData>::New();
    bands->SetPoints(points);
    bands->SetStrips(strips);
    bands->GetCellData()->AddArray(plane);
    return bands;
}

double polar_ring_step(double max_intensity) {
    if (!(max_intensity > 0)) return 1;
    const double raw = max_intensity / 4;
    const double decade = std::pow(10, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * decade >= raw) return m * decade;
    return 10 * decade;
}

vtkSmartPointer<vtkPolyData> polar_grid(double ring_step, int rings) {
    const double deg = kRadiansPerDegree;
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();  // exported values keep the table's precision
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (int r = 1; r <= rings; ++r) {
        std::vector<vtkIdType> ids;
        for (int a = 0; a <= 120; ++a)
            ids.push_back(points->InsertNextPoint(r * ring_step * std::cos(a * 3 * deg),
                                                  r * ring_step * std::sin(a * 3 * deg), 0));
        lines->InsertNextCell(vtkIdType(ids.size()), ids.data());
    }
    const double outer = rings * ring_step;
    for (int a = 0; a < 180; a += 30) {
        const vtkIdType ids[2] = {
            points->InsertNextPoint(outer * std::cos(a * deg), outer * std::sin(a * deg), 0),
            points->InsertNextPoint(-outer * std::cos(a * deg), -outer * std::sin(a * deg), 0)};
        lines->InsertNextCell(2, ids);
    }
    auto grid = vtkSmartPointer<vtkPolyData>::New();
    grid->SetPoints(points);
    grid->SetLines(lines);
    return grid;
}

}  // namespace rayset::viz
