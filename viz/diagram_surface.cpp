#include "viz/diagram_surface.h"
#include "core/geometry.h"

#include "core/error.h"
#include "viz/vtk_arrays.h"

#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <fmt/format.h>
#include <cmath>

namespace rayset::viz {

int diagram_index(const lightmodel::LightModel& model, const lightmodel::Coord& cell) {
    for (size_t k = 0; k < model.diagram_cells.size(); ++k)
        if (model.diagram_cells[k] == cell && !model.diagrams[k].empty()) return int(k);
    return -1;
}

double diagram_flux(const lightmodel::LightModel& model, int index) {
    double flux = 0;
    for (const auto& c : model.flux_cells)
        if (c.intensity_cell == index) flux += c.flux;
    return flux;
}

lightmodel::Coord brightest_intensity_cell(const lightmodel::LightModel& model) {
    int best = -1;
    double best_flux = -1;
    for (size_t k = 0; k < model.diagrams.size(); ++k) {
        const double f = diagram_flux(model, int(k));
        if (!model.diagrams[k].empty() && f > best_flux) best = int(k), best_flux = f;
    }
    if (best < 0) throw Error("the model has no intensity cell that emits light");
    return model.diagram_cells[best];
}

vtkSmartPointer<vtkPolyData> diagram_surface(const lightmodel::LightModel& model,
                                             const lightmodel::Coord& cell, int rings,
                                             int sectors) {
    const int k = diagram_index(model, cell);
    if (k < 0) {
        std::string cells;
        for (size_t i = 0; i < model.diagram_cells.size() && i < 32; ++i)
            cells += fmt::format(" {},{},{}", model.diagram_cells[i][0], model.diagram_cells[i][1],
                                 model.diagram_cells[i][2]);
        throw Error(fmt::format("intensity cell {},{},{} emits nothing; cells with a diagram:{}",
                                cell[0], cell[1], cell[2], cells));
    }
    const auto& diagram = model.diagrams[k];
    const double flux = diagram_flux(model, k);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();  // exported values keep the table's precision
    auto intensity = named_doubles("intensity");
    auto add = [&](Vec3 w) {
        const double value = flux * diagram.pdf(w);
        intensity->InsertNextValue(value);
        return points->InsertNextPoint(value * w.x, value * w.y, value * w.z);
    };
    add({0, 0, 1});
    for (int j = 1; j < rings; ++j) {
        const double theta = kPi * j / rings;
        for (int i = 0; i < sectors; ++i) {
            const double phi = 2 * kPi * i / sectors;
            add({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                 std::cos(theta)});
        }
    }
    const vtkIdType south = add({0, 0, -1});

    auto ring_point = [&](int j, int i) {
        return vtkIdType(1 + (j - 1) * sectors + (i % sectors));
    };
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    for (int i = 0; i < sectors; ++i) {
        const vtkIdType top[3] = {0, ring_point(1, i), ring_point(1, i + 1)};
        polys->InsertNextCell(3, top);
        const vtkIdType bottom[3] = {south, ring_point(rings - 1, i + 1), ring_point(rings - 1, i)};
        polys->InsertNextCell(3, bottom);
        for (int j = 1; j + 1 < rings; ++j) {
            const vtkIdType q[4] = {ring_point(j, i), ring_point(j + 1, i),
                                    ring_point(j + 1, i + 1), ring_point(j, i + 1)};
            polys->InsertNextCell(4, q);
        }
    }
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    surface->SetPoints(points);
    surface->SetPolys(polys);
    surface->GetPointData()->SetScalars(intensity);
    const Vec3 centre = model.intensity_frame.cell_centre(cell);
    set_field_values(surface, "cell", {double(cell[0]), double(cell[1]), double(cell[2])});
    set_field_values(surface, "cell_centre_mm", {centre.x, centre.y, centre.z});
    set_field_values(surface, "cell_flux", {flux});
    set_field_string(surface, "unit", model.flux_unit + "/sr");
    return surface;
}

}  // namespace rayset::viz
