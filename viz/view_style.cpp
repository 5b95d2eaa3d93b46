#include "viz/view_style.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCubeAxesActor.h>
#include <vtkCubeSource.h>
#include <vtkGlyph3DMapper.h>
#include <vtkProperty.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>

namespace rayset::viz {

namespace {

// Viridis (matplotlib) at 0, 1/8, ..., 1.
constexpr double kViridis[9][3] = {
    {0.267, 0.005, 0.329}, {0.283, 0.141, 0.458}, {0.254, 0.265, 0.530},
    {0.207, 0.372, 0.553}, {0.164, 0.471, 0.558}, {0.128, 0.567, 0.551},
    {0.135, 0.659, 0.518}, {0.267, 0.749, 0.441}, {0.993, 0.906, 0.144}};

void dark_text(vtkTextProperty* p, int size) {
    p->SetColor(kText[0], kText[1], kText[2]);
    p->SetFontSize(size);
    p->ShadowOff();
    p->BoldOff();
    p->ItalicOff();
}

}  // namespace

vtkSmartPointer<vtkLookupTable> colour_map(double lo, double hi) {
    if (!(hi > lo)) hi = lo + std::max(1e-12, std::abs(lo) * 1e-6);
    auto lut = vtkSmartPointer<vtkLookupTable>::New();
    const int n = 256;
    lut->SetNumberOfTableValues(n);
    lut->SetTableRange(lo, hi);
    for (int i = 0; i < n; ++i) {
        const double t = double(i) / (n - 1) * 8;
        const int k = std::min(7, int(t));
        const double f = t - k;
        double rgb[3];
        for (int c = 0; c < 3; ++c) rgb[c] = (1 - f) * kViridis[k][c] + f * kViridis[k + 1][c];
        lut->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1);
    }
    lut->SetNanColor(0.6, 0.6, 0.6, 1);
    return lut;
}

void add_scalar_bar(vtkRenderer* renderer, vtkScalarsToColors* map, const std::string& title) {
    auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
    bar->SetLookupTable(map);
    bar->SetTitle(title.c_str());
    bar->SetNumberOfLabels(5);
    bar->UnconstrainedFontSizeOn();
    bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    bar->GetPositionCoordinate()->SetValue(0.86, 0.1);
    bar->SetWidth(0.12);
    bar->SetHeight(0.8);
    bar->SetBarRatio(0.3);
    dark_text(bar->GetTitleTextProperty(), 14);
    dark_text(bar->GetLabelTextProperty(), 12);
    renderer->AddViewProp(bar);
}

void add_axes(vtkRenderer* renderer, const double bounds[6], const std::string& unit,
              const std::string& prefix) {
    auto axes = vtkSmartPointer<vtkCubeAxesActor>::New();
    axes->SetBounds(bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]);
    axes->SetCamera(renderer->GetActiveCamera());
    axes->SetXTitle((prefix + "x").c_str());
    axes->SetYTitle((prefix + "y").c_str());
    axes->SetZTitle((prefix + "z").c_str());
    axes->SetXUnits(unit.c_str());
    axes->SetYUnits(unit.c_str());
    axes->SetZUnits(unit.c_str());
    axes->SetFlyModeToOuterEdges();
    axes->SetGridLineLocation(vtkCubeAxesActor::VTK_GRID_LINES_FURTHEST);
    for (int a = 0; a < 3; ++a) {
        axes->GetTitleTextProperty(a)->SetColor(kText[0], kText[1], kText[2]);
        axes->GetLabelTextProperty(a)->SetColor(kText[0], kText[1], kText[2]);
    }
    for (auto* p : {axes->GetXAxesLinesProperty(), axes->GetYAxesLinesProperty(),
                    axes->GetZAxesLinesProperty()})
        p->SetColor(0.3, 0.3, 0.3);
    // A flat source has a (nearly) zero-thickness axis, whose labels would pile up.
    const double largest =
        std::max({bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]});
    if (bounds[1] - bounds[0] <= 1e-3 * largest) axes->XAxisVisibilityOff();
    if (bounds[3] - bounds[2] <= 1e-3 * largest) axes->YAxisVisibilityOff();
    if (bounds[5] - bounds[4] <= 1e-3 * largest) axes->ZAxisVisibilityOff();
    renderer->AddViewProp(axes);
}

void add_title(vtkRenderer* renderer, const std::string& text) {
    auto title = vtkSmartPointer<vtkTextActor>::New();
    title->SetInput(text.c_str());
    dark_text(title->GetTextProperty(), 16);
    title->GetTextProperty()->SetVerticalJustificationToTop();
    title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    title->GetPositionCoordinate()->SetValue(0.02, 0.97);
    renderer->AddViewProp(title);
}

void add_cell_cubes(vtkRenderer* renderer, vtkAlgorithmOutput* cells, double edge,
                    vtkLookupTable* lut) {
    auto cube = vtkSmartPointer<vtkCubeSource>::New();
    cube->SetXLength(edge);
    cube->SetYLength(edge);
    cube->SetZLength(edge);
    auto mapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
    mapper->SetInputConnection(cells);
    mapper->SetSourceConnection(cube->GetOutputPort());
    mapper->ScalingOff();
    mapper->OrientOff();
    mapper->SetLookupTable(lut);
    mapper->UseLookupTableScalarRangeOn();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
}

}  // namespace rayset::viz
