// Polar chart: C-plane curves of one or more far fields over a ring grid labelled in intensity,
// gamma 0 at the bottom, a legend naming each plane (and file when several are overlaid), and
// each curve's uncertainty band when its far field states standard errors.
#include "viz/polar_curves.h"
#include "viz/view_style.h"
#include "viz/views.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkLegendBoxActor.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

namespace rayset::viz {

namespace {

constexpr double kPlaneColours[6][3] = {{0.85, 0.15, 0.15}, {0.15, 0.35, 0.85}, {0.1, 0.6, 0.2},
                                        {0.9, 0.5, 0.0},    {0.55, 0.2, 0.7},   {0.0, 0.6, 0.6}};

void add_world_label(vtkRenderer* renderer, const std::string& text, double x, double y,
                     int justify) {
    auto label = vtkSmartPointer<vtkTextActor>::New();
    label->SetInput(text.c_str());
    label->GetTextProperty()->SetColor(0.35, 0.35, 0.35);
    label->GetTextProperty()->SetFontSize(12);
    label->GetTextProperty()->SetJustification(justify);
    label->GetTextProperty()->SetVerticalJustificationToCentered();
    label->GetPositionCoordinate()->SetCoordinateSystemToWorld();
    label->GetPositionCoordinate()->SetValue(x, y, 0);
    renderer->AddViewProp(label);
}

vtkSmartPointer<vtkActor> line_actor(vtkPolyData* data, const double colour[3], double width) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(data);
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
    actor->GetProperty()->SetLineWidth(width);
    return actor;
}

// Cell `c` of `data` alone, over the same points: one plane's curve (a line) or band (a strip).
vtkSmartPointer<vtkPolyData> one_cell(vtkPolyData* data, vtkIdType c) {
    auto one = vtkSmartPointer<vtkPolyData>::New();
    one->SetPoints(data->GetPoints());
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->InsertNextCell(data->GetCell(c));
    if (data->GetNumberOfStrips() > 0)
        one->SetStrips(cells);
    else
        one->SetLines(cells);
    return one;
}

// The band of one plane (cell `c` of polar_bands()), translucent in the plane's colour.
vtkSmartPointer<vtkActor> band_actor(vtkPolyData* bands, vtkIdType c, const double colour[3]) {
    auto actor = line_actor(one_cell(bands, c), colour, 1);
    actor->GetProperty()->SetOpacity(0.25);
    return actor;
}

// The rings of intensity, labelled, and the angles around them.
void add_polar_axes(vtkRenderer* renderer, const std::vector<const IntensityTable*>& tables) {
    double maximum = 0;
    for (const auto* t : tables) maximum = std::max(maximum, t->max_intensity);
    const double step = polar_ring_step(maximum);
    const int rings = std::max(1, int(std::ceil(maximum / step - 1e-9)));
    const double grey[3] = {0.75, 0.75, 0.75};
    renderer->AddActor(line_actor(polar_grid(step, rings), grey, 1));
    const std::string unit = tables.front()->unit;
    for (int r = 1; r <= rings; ++r)
        add_world_label(renderer, fmt::format("{:g} {}", r * step, unit), 0.02 * step, r * step, 0);
    const double outer = rings * step * 1.07;
    add_world_label(renderer, "0\xC2\xB0", 0, -outer, 1);
    add_world_label(renderer, "180\xC2\xB0", 0, outer, 1);
    add_world_label(renderer, "90\xC2\xB0", outer, 0, 0);
    add_world_label(renderer, "90\xC2\xB0", -outer, 0, 2);
}

// Each plane's curve (and uncertainty band) in its own colour; returns the legend's entries.
std::vector<std::string> add_polar_curves(vtkRenderer* renderer,
                                          const std::vector<const IntensityTable*>& tables) {
    std::vector<std::string> entries;
    int colour = 0;
    for (const auto* t : tables) {
        auto curves = polar_curves(*t);
        auto bands = polar_bands(*t);
        const auto planes = polar_planes(*t);
        for (vtkIdType c = 0; c < curves->GetNumberOfCells(); ++c, ++colour) {
            if (c < bands->GetNumberOfCells())
                renderer->AddActor(band_actor(bands, c, kPlaneColours[colour % 6]));
            renderer->AddActor(line_actor(one_cell(curves, c), kPlaneColours[colour % 6], 2.5));
            std::string name = fmt::format("C{:g}-C{:g}", planes[c], planes[c] + 180);
            if (c == 2) name += " (max)";
            if (tables.size() > 1) name = t->label + " " + name;
            entries.push_back(name);
        }
    }
    return entries;
}

// The legend: a short horizontal line in each entry's colour, then its name.
void add_polar_legend(vtkRenderer* renderer, const std::vector<std::string>& entries) {
    auto symbol = vtkSmartPointer<vtkPolyData>::New();
    auto symbol_points = vtkSmartPointer<vtkPoints>::New();
    symbol_points->InsertNextPoint(0, 0, 0);
    symbol_points->InsertNextPoint(1, 0, 0);
    auto symbol_line = vtkSmartPointer<vtkCellArray>::New();
    const vtkIdType ends[2] = {0, 1};
    symbol_line->InsertNextCell(2, ends);
    symbol->SetPoints(symbol_points);
    symbol->SetLines(symbol_line);
    auto legend = vtkSmartPointer<vtkLegendBoxActor>::New();
    legend->SetNumberOfEntries(int(entries.size()));
    for (size_t e = 0; e < entries.size(); ++e) {
        double rgb[3] = {kPlaneColours[e % 6][0], kPlaneColours[e % 6][1], kPlaneColours[e % 6][2]};
        legend->SetEntry(int(e), symbol, entries[e].c_str(), rgb);
    }
    legend->GetEntryTextProperty()->SetColor(kText[0], kText[1], kText[2]);
    legend->GetEntryTextProperty()->SetFontSize(12);
    legend->BorderOff();
    legend->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    legend->GetPositionCoordinate()->SetValue(0.70, 0.90 - 0.045 * entries.size());
    legend->GetPosition2Coordinate()->SetCoordinateSystemToNormalizedViewport();
    legend->GetPosition2Coordinate()->SetValue(0.28, 0.045 * entries.size());
    renderer->AddViewProp(legend);
}

// Each table's maximum (with its standard error when known).
std::string polar_title(const std::vector<const IntensityTable*>& tables) {
    std::string title =
        tables.size() == 1 ? tables.front()->label + ": polar curves" : "polar curves";
    bool banded = false;
    for (const auto* t : tables) {
        std::string error;
        if (t->standard_error) {
            error = fmt::format(" \xC2\xB1 {:.2g}",
                                t->standard_error->intensity(t->max_c_deg, t->max_gamma_deg));
            banded = true;
        }
        title += fmt::format("\n{}maximum {:.4g}{} {} at C{:g} gamma {:g}",
                             tables.size() > 1 ? t->label + ": " : "", t->max_intensity, error,
                             t->unit, t->max_c_deg, t->max_gamma_deg);
    }
    if (banded) title += fmt::format("\nbands: \xC2\xB1{:g} standard errors", kBandErrors);
    return title;
}

}  // namespace

ViewHandles add_polar_view(vtkRenderer* renderer,
                           const std::vector<const IntensityTable*>& tables) {
    add_polar_axes(renderer, tables);
    add_polar_legend(renderer, add_polar_curves(renderer, tables));
    add_title(renderer, polar_title(tables));
    ViewHandles h;
    h.flat = true;
    return h;
}

}  // namespace rayset::viz
