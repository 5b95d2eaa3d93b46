// Far-field views: the real OSRAM blue LED's photometric solid and polar curves render, and the
// polar curves reach the maximum `rayconv info` reports for the same far field; IES / LDT
// files and the comparison overlay render too.
#include <gtest/gtest.h>

#include "support/test_support.h"
#include "viz/export.h"
#include "viz/polar_curves.h"
#include "viz/scene.h"
#include "viz/viz_support.h"
#include "viz/vtk_arrays.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkXMLPolyDataReader.h>
#include <nlohmann/json.hpp>

#include <fmt/format.h>
#include <cmath>

namespace {

using namespace rayset;

const char* kBlue = "rayfiles/rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY";

double max_of(vtkPolyData* data, const char* name) {
    double range[2];
    data->GetPointData()->GetArray(name)->GetRange(range);
    return range[1];
}

void expect_rendered(viz::Input& first, viz::Input* second, viz::View view,
                     const std::string& png) {
    viz::SceneOptions options;
    options.width = 640, options.height = 480, options.offscreen = true;
    viz::Scene scene = viz::build_scene(first, second, view, {}, options);
    viz::write_png(scene, png);
    const double everywhere[4] = {0, 1, 0, 1};
    const test::PngStatistics s = test::png_statistics(png, everywhere);
    EXPECT_EQ(s.width, 640);
    // Curves, grid, labels or a solid: well over a percent of the window, and in colour.
    EXPECT_GT(s.foreground, 0.01 * s.width * s.height) << png;
    EXPECT_GT(s.region_colours, 20) << png;
}

}  // namespace

TEST(PhotometryViews, OsramBluePolarMaximumIsRayconvInfoMaximum) {
    RAYSET_REQUIRE_SHARED_DATA();
    const std::string blue = test::shared_data(kBlue);
    test::ScratchDir dir;
    // The independent route: rayconv farfield -> IES -> rayconv info --json.
    const auto farfield = test::run_command(
        fmt::format("'{}' farfield '{}' -o '{}'", RAYCONV_EXE, blue, dir.file("blue.ies")));
    ASSERT_EQ(farfield.status, 0) << farfield.output;
    const auto info =
        test::run_command(fmt::format("'{}' info '{}' --json", RAYCONV_EXE, dir.file("blue.ies")));
    ASSERT_EQ(info.status, 0) << info.output;
    const double reported = nlohmann::json::parse(info.output)["max_intensity_cd"].get<double>();

    viz::Input input(blue);
    const auto written = viz::export_input(input, {}, dir.file("export"));
    EXPECT_EQ(written.size(), 4u);  // rays, farfield, polar, .vtm
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(dir.file("export/polar.vtp").c_str());
    reader->Update();
    vtkPolyData* polar = reader->GetOutput();
    EXPECT_EQ(viz::field_string(polar, "unit"), "cd");
    // The IES file holds the digits the values' standard errors support (to the error's second
    // digit: 0.01 cd at the 18 cd maximum of this file, so within 3e-4 of it); the curves hold
    // doubles.
    RecordProperty("polar_max_cd", fmt::format("{:.10g}", max_of(polar, "intensity")));
    RecordProperty("rayconv_info_max_cd", fmt::format("{:.10g}", reported));
    EXPECT_NEAR(max_of(polar, "intensity"), reported, 3e-4 * reported);
    EXPECT_GE(polar->GetNumberOfCells(), 2);

    reader->SetFileName(dir.file("export/farfield.vtp").c_str());
    reader->Update();
    EXPECT_NEAR(max_of(reader->GetOutput(), "intensity"), reported, 3e-4 * reported);

    expect_rendered(input, nullptr, viz::View::farfield, dir.file("solid.png"));
    expect_rendered(input, nullptr, viz::View::polar, dir.file("polar.png"));
    expect_rendered(input, nullptr, viz::View::rays, dir.file("rays.png"));
}

TEST(PhotometryViews, PolarCurvesFollowTheTable) {
    // A table with I = 100 cos(gamma) + 20 sin(gamma) cos(C): the C0 side is brighter than C180.
    viz::IntensityTable t;
    t.unit = "cd";
    Photometry& p = t.photometry;
    for (int v = 0; v <= 180; v += 5) p.vertical_deg.push_back(v);
    for (int h = 0; h <= 360; h += 15) p.horizontal_deg.push_back(h);
    const double deg = kRadiansPerDegree;
    for (double h : p.horizontal_deg)
        for (double v : p.vertical_deg)
            p.candela.push_back(std::max(
                0.0, 100 * std::cos(v * deg) + 20 * std::sin(v * deg) * std::cos(h * deg)));
    t.max_intensity = p.max_candela();
    auto curves = viz::polar_curves(t);
    ASSERT_EQ(curves->GetNumberOfCells(), 2);  // the maximum lies in C0: no third plane
    vtkDataArray* gamma = curves->GetPointData()->GetArray("gamma_deg");
    vtkDataArray* intensity = curves->GetPointData()->GetArray("intensity");
    for (vtkIdType i = 0; i < curves->GetNumberOfPoints(); ++i) {
        const double g = gamma->GetComponent(i, 0), value = intensity->GetComponent(i, 0);
        double x[3];
        curves->GetPoint(i, x);
        // Distance from the centre is the intensity; gamma 0 points down; C side on the right.
        EXPECT_NEAR(std::hypot(x[0], x[1]), value, 1e-9);
        if (value > 1e-9) {
            EXPECT_NEAR(std::atan2(x[0], -x[1]) / deg, g, 1e-9);
        }
    }
    // The first curve is C0-C180: at gamma 45 on the C0 side, 100 cos 45 + 20 sin 45.
    const double expected = 120 / std::sqrt(2);
    bool found = false;
    for (vtkIdType i = 0; i < curves->GetCell(0)->GetNumberOfPoints(); ++i) {
        const vtkIdType id = curves->GetCell(0)->GetPointId(i);
        if (std::abs(gamma->GetComponent(id, 0) - 45) < 1e-9) {
            EXPECT_NEAR(intensity->GetComponent(id, 0), expected, 1e-9);
            found = true;
        }
    }
    EXPECT_TRUE(found);
    EXPECT_EQ(viz::polar_ring_step(120), 50);
    EXPECT_EQ(viz::polar_bands(t)->GetNumberOfCells(), 0);  // no errors stated, no bands

    // With standard errors se = 1 + I / 20: the curves carry them, and each plane's band is a
    // strip whose points alternate between max(0, I - 2 se) and I + 2 se at the curve's angles.
    t.standard_error = p;
    for (double& value : t.standard_error->candela) value = 1 + value / 20;
    curves = viz::polar_curves(t);
    auto bands = viz::polar_bands(t);
    ASSERT_EQ(bands->GetNumberOfCells(), curves->GetNumberOfCells());
    vtkDataArray* error = curves->GetPointData()->GetArray("standard_error");
    ASSERT_NE(error, nullptr);
    intensity = curves->GetPointData()->GetArray("intensity");
    for (vtkIdType c = 0; c < curves->GetNumberOfCells(); ++c) {
        const vtkIdType n = curves->GetCell(c)->GetNumberOfPoints();
        ASSERT_EQ(bands->GetCell(c)->GetNumberOfPoints(), 2 * n);
        for (vtkIdType i = 0; i < n; ++i) {
            const vtkIdType id = curves->GetCell(c)->GetPointId(i);
            const double value = intensity->GetComponent(id, 0), se = error->GetComponent(id, 0);
            EXPECT_NEAR(se, 1 + value / 20, 1e-9);
            double lower[3], upper[3];
            bands->GetPoint(bands->GetCell(c)->GetPointId(2 * i), lower);
            bands->GetPoint(bands->GetCell(c)->GetPointId(2 * i + 1), upper);
            EXPECT_NEAR(std::hypot(lower[0], lower[1]), std::max(0.0, value - 2 * se), 1e-9);
            EXPECT_NEAR(std::hypot(upper[0], upper[1]), value + 2 * se, 1e-9);
        }
    }
}

TEST(PhotometryViews, IesAndLdtRenderAndCompare) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    viz::Input ies(test::shared_data("photometry/ABSOLUTE_LED.ies"));
    viz::Input ldt(test::shared_data("photometry/1-1-0.ldt"));
    EXPECT_EQ(ies.kind(), viz::InputKind::photometry);
    EXPECT_EQ(ldt.kind(), viz::InputKind::photometry);
    // The solid's farthest point is the table's maximum (C and gamma steps that hold the grid).
    vtkSmartPointer<vtkDataObject> data = ies.data(viz::View::farfield, {});
    auto* solid = vtkPolyData::SafeDownCast(data);
    ASSERT_NE(solid, nullptr);
    EXPECT_LE(max_of(solid, "intensity"), ies.intensity().max_intensity * (1 + 1e-12));
    expect_rendered(ies, nullptr, viz::View::farfield, dir.file("ies_solid.png"));
    expect_rendered(ies, &ldt, viz::View::polar, dir.file("compare_polar.png"));
    expect_rendered(ies, &ldt, viz::View::farfield, dir.file("compare_solid.png"));
}
