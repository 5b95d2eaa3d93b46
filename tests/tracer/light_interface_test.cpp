// One light interface for both integrators (tracer/render/light.h): the path tracer renders
// ray-file sources (light sampling of the model and MIS with its body), and the bidirectional
// integrator samples and emits photons from POV-Ray's point, spot and area lights. Truths: the
// closed form of a Lambertian disk's illuminance and the energy balance of a closed box.
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "converters/analytic/analytic_sources.h"
#include "core/error.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"
#include "support/test_support.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

std::shared_ptr<const lightmodel::LightModel> disk_light_model() {
    static const auto model = std::make_shared<const lightmodel::LightModel>(
        lightmodel::read_model(test::disk_files().model));
    return model;
}

RenderResult render_text(const std::string& text, const RenderSettings& settings) {
    return render(RenderScene(parse_scene_text(text, test::disk_files().scratch.file("test.pov"))),
                  settings);
}

TEST(LightInterface, PathTracerLightsAFloorWithARayFileSourceInLux) {
    // The disk H = 20 mm above a black floor (tracer_support). The truth: the disk's closed form
    // times the model's far field over the disk's (removing the 10^6-ray model's own noise, as
    // bidirectional_sources_test does); the path tracer alone must agree within 1% in every cell.
    const double H = 20;
    RenderSettings settings;
    settings.render_image = false, settings.passes = 16384, settings.seed = 3;
    const RenderResult r =
        render_text(test::disk_over_black_floor(test::disk_files().model, "path"), settings);
    ASSERT_TRUE(r.layers.empty());
    const lightmodel::ComplexSource model(disk_light_model());
    const analytic::LambertianDisk disk = test::disk_source();
    const ReceiverMap& floor = r.receivers.at(0);
    double worst = 0;
    for (int j = 0; j < floor.irradiance.ny(); ++j)
        for (int i = 0; i < floor.irradiance.nx(); ++i) {
            const Vec3 p = floor.cell_centre(i, j), q{p.x, p.z, H};
            const Vec3 w = normalized(q);
            const double truth = 1e6 * disk.irradiance(q, {0, 0, -1}) * model.intensity(w) /
                                 disk.intensity(w);  // W/m^2
            const double measured = luminance_weight(floor.irradiance.mean(i, j));
            const double se = floor.irradiance.photometric_standard_error(i, j) / kLumensPerWatt;
            worst = std::max(worst, std::fabs(measured / truth - 1));
            EXPECT_LT(se, 0.0025 * truth) << "cell " << i << "," << j;  // 1% is then 4 se or more
            EXPECT_NEAR(measured, truth, 0.01 * truth) << "cell " << i << "," << j << " se " << se;
        }
    std::printf("path tracer, disk over a floor: worst cell %.4f off the closed form\n", worst);
}

TEST(LightInterface, PathTracerConservesEnergyInAClosedBoxLitByARayFile) {
    // Every watt lands on a wall once directly and a / (1 - a) times more after reflections.
    // The wall average is taken at the 20 x 20 cell centres of each wall (a midpoint rule,
    // 0.06% above the integral here, measured at 16 times these samples).
    const double albedo = 0.5, flux = 1, area = test::kClosedBoxArea;
    test::ClosedBox box;
    box.diffuse = albedo, box.integrator = "path";
    box.sources = {test::disk_files().model};
    RenderSettings settings;
    settings.render_image = false, settings.passes = 64, settings.seed = 8;
    const RenderResult r = render_text(test::closed_box_scene(box), settings);
    const test::WallAverage walls = test::wall_average(r.receivers);
    const double truth = flux / ((1 - albedo) * area);
    std::printf("path tracer, closed box: %.5g W/m^2 (truth %.5g, standard error %.2g)\n",
                walls.mean, truth, walls.standard_error);
    EXPECT_LT(walls.standard_error, 0.0025 * truth);  // 1% is then 4 se or more
    EXPECT_NEAR(walls.mean, truth, 0.01 * truth);
}

// A closed box lit by one POV-Ray light of power P (W, grey) at its centre, through the
// bidirectional integrator: primary light P / A on the walls (light sampling), secondary
// P a / ((1 - a) A) (the light's photons after a bounce).
void expect_bidirectional_balance(const std::string& light, double power, const char* what) {
    const double albedo = 0.5, area = test::kClosedBoxArea;
    test::ClosedBox box;  // 20 x 20 cells a wall: a gather radius under half a cell
    box.diffuse = albedo, box.more = light;
    RenderSettings settings;
    settings.render_image = false, settings.passes = 8, settings.seed = 6;
    settings.photons_per_pass = 200000, settings.photon_radius = 2;
    const RenderResult r = render_text(test::closed_box_scene(box), settings);
    ASSERT_EQ(r.layers.size(), 3u);
    const test::WallAverage primary = test::wall_average(r.layers[1].receivers);
    const test::WallAverage secondary_average = test::wall_average(r.layers[2].receivers);
    const double secondary = secondary_average.mean;
    const double primary_truth = power / area,
                 secondary_truth = power * albedo / ((1 - albedo) * area);
    std::printf("%s: primary %.5g W/m^2 (truth %.5g), secondary %.5g (truth %.5g)\n", what,
                primary.mean, primary_truth, secondary, secondary_truth);
    // The bounds below are then 4 standard errors or more.
    EXPECT_LT(primary.standard_error, 0.0025 * primary_truth) << what;
    EXPECT_LT(secondary_average.standard_error, 0.005 * secondary_truth) << what;
    EXPECT_NEAR(primary.mean, primary_truth, 0.01 * primary_truth) << what;
    EXPECT_NEAR(secondary, secondary_truth, 0.02 * secondary_truth) << what;
}

TEST(LightInterface, BidirectionalSamplesAndEmitsPovRayLights) {
    const double intensity = 1e-3;  // W/sr per channel
    // A point light emits 4 pi I; a two-sided area light the same; a cosine spotlight pi I.
    expect_bidirectional_balance("light_source { <0, 10, 0> color rgb 0.001 }", 4 * kPi * intensity,
                                 "point light");
    expect_bidirectional_balance(
        "light_source { <0, 10, 0> color rgb 0.001 area_light <10, 0, 0>, <0, 0, 10>, 2, 2 }",
        4 * kPi * intensity, "area light");
    expect_bidirectional_balance(
        "light_source { <0, 10, 0> color rgb 0.001 area_light <10, 0, 0>, "
        "<0, 0, 10>, 2, 2 circular }",
        4 * kPi * intensity, "circular area light");
    expect_bidirectional_balance(
        "light_source { <0, 10, 0> color rgb 0.001 area_light <10, 0, 0>, "
        "<0, 0, 10>, 2, 2 circular orient }",
        4 * kPi * intensity, "oriented area light");
    expect_bidirectional_balance(
        "light_source { <0, 10, 0> color rgb 0.001 spotlight point_at <0, -50, 0> radius -90 "
        "falloff 90 tightness 1 }",
        kPi * intensity, "cosine spotlight");
    expect_bidirectional_balance(
        "light_source { <0, 10, 0> color rgb 0.001 spotlight point_at <0, -50, 0> radius -90 "
        "falloff 90 tightness 1 area_light <10, 0, 0>, <0, 0, 10>, 2, 2 circular orient }",
        kPi * intensity, "oriented cosine area spotlight");
}

TEST(LightInterface, PathTracerRefusesTheNaiveRaySet) {
    RenderSettings settings;
    settings.render_image = false, settings.passes = 1, settings.naive_sources = true;
    const std::string scene = "plane { y, 0 pigment { rgb 1 } }\nray_source { \"" +
                              test::disk_files().rays + "\" translate <0, 20, 0> }\n";
    try {
        render_text(scene, settings);
        FAIL() << "rendered the naive ray set with the path tracer";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bidirectional"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rayset::tracer
