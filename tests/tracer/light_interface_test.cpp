// One light interface for both integrators (tracer/render/light.h): the path tracer renders
// ray-file sources (light sampling of the model and MIS with its body), and the bidirectional
// integrator samples and emits photons from POV-Ray's point, spot and area lights. Truths: the
// closed form of a Lambertian disk's illuminance and the energy balance of a closed box.
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string_view>

#include <gtest/gtest.h>

#include "converters/analytic/analytic_sources.h"
#include "core/error.h"
#include "core/random.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"
#include "support/test_support.h"
#include "tracer/render/direct_light.h"
#include "tracer/render/light.h"
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
    ASSERT_EQ(r.layers.size(), 3u);
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
    // A black floor reflects nothing: the light is all primary, as the bidirectional splits it.
    for (int j = 0; j < floor.irradiance.ny(); ++j)
        for (int i = 0; i < floor.irradiance.nx(); ++i) {
            EXPECT_EQ(r.layers[0].receivers.at(0).irradiance.mean(i, j).green, 0);
            EXPECT_EQ(r.layers[2].receivers.at(0).irradiance.mean(i, j).green, 0);
            EXPECT_DOUBLE_EQ(r.layers[1].receivers.at(0).irradiance.mean(i, j).green,
                             floor.irradiance.mean(i, j).green);
        }
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

// The wall averages of a closed box lit by lights of power P (W, grey) split into the layers:
// every watt lands once straight from its light, primary light P / A on the walls, and
// a / (1 - a) times more after reflections, secondary light P a / ((1 - a) A); a receiver
// sees no light's body, so its direct visibility is nothing.
void expect_layer_balance(const RenderResult& r, double power, double albedo,
                          const std::string& what) {
    const double area = test::kClosedBoxArea;
    ASSERT_EQ(r.layers.size(), 3u);
    EXPECT_EQ(test::wall_average(r.layers[0].receivers).mean, 0) << what;
    const test::WallAverage primary = test::wall_average(r.layers[1].receivers);
    const test::WallAverage secondary = test::wall_average(r.layers[2].receivers);
    const double primary_truth = power / area,
                 secondary_truth = power * albedo / ((1 - albedo) * area);
    std::printf(
        "%s: primary %.5g W/m^2 (truth %.5g, se %.2g), secondary %.5g (truth %.5g, se %.2g)\n",
        what.c_str(), primary.mean, primary_truth, primary.standard_error, secondary.mean,
        secondary_truth, secondary.standard_error);
    // Noise small enough for the comparison to mean something.
    EXPECT_LT(primary.standard_error, 0.0025 * primary_truth) << what;
    EXPECT_LT(secondary.standard_error, 0.005 * secondary_truth) << what;
    // Each mean within 4 of its standard errors (a normal mean misses by more 6e-5 of the time)
    // plus 0.2% for the walls' midpoint rule: the receivers read the exact light of a point
    // light 0.06% high, of a cosine spotlight 0.13%.
    auto bound = [](const test::WallAverage& a, double truth) {
        return 4 * a.standard_error + 0.002 * truth;
    };
    EXPECT_NEAR(primary.mean, primary_truth, bound(primary, primary_truth)) << what;
    EXPECT_NEAR(secondary.mean, secondary_truth, bound(secondary, secondary_truth)) << what;
}

TEST(LightInterface, PathTracerSplitsARayFileSourcesLightAsTheBidirectionalDoes) {
    const double albedo = 0.5;
    test::ClosedBox box;
    box.diffuse = albedo, box.integrator = "path";
    box.sources = {test::disk_files().model};
    RenderSettings settings;
    settings.render_image = false, settings.passes = 64, settings.seed = 8;
    expect_layer_balance(render_text(test::closed_box_scene(box), settings), 1, albedo,
                         "path tracer, closed box, ray-file source");
}

// A closed box lit by one POV-Ray light of power P (W, grey) at its centre, through the
// bidirectional integrator (primary light by light sampling, secondary from the light's photons
// after a bounce) and through the path tracer: the same layers.
void expect_bidirectional_balance(const std::string& light, double power, const char* what) {
    const double albedo = 0.5;
    test::ClosedBox box;  // 20 x 20 cells a wall: a gather radius under half a cell
    box.diffuse = albedo, box.more = light;
    RenderSettings settings;
    settings.render_image = false, settings.passes = 8, settings.seed = 6;
    settings.photons_per_pass = 200000, settings.photon_radius = 2;
    expect_layer_balance(render_text(test::closed_box_scene(box), settings), power, albedo, what);
}

void expect_path_balance(const std::string& light, double power, const char* what) {
    const double albedo = 0.5;
    test::ClosedBox box;
    box.diffuse = albedo, box.more = light, box.integrator = "path";
    RenderSettings settings;
    settings.render_image = false, settings.passes = 64, settings.seed = 6;
    expect_layer_balance(render_text(test::closed_box_scene(box), settings), power, albedo,
                         std::string("path tracer, ") + what);
}

// POV-Ray lights of 1e-3 W/sr per channel and their power: a point light emits 4 pi I, a
// two-sided area light the same, a cosine spotlight pi I.
struct PovLight {
    const char* text;
    double power;
    const char* what;
};
constexpr double kIntensity = 1e-3;
const PovLight kPovLights[] = {
    {"light_source { <0, 10, 0> color rgb 0.001 }", 4 * kPi* kIntensity, "point light"},
    {"light_source { <0, 10, 0> color rgb 0.001 area_light <10, 0, 0>, <0, 0, 10>, 2, 2 }",
     4 * kPi* kIntensity, "area light"},
    {"light_source { <0, 10, 0> color rgb 0.001 area_light <10, 0, 0>, <0, 0, 10>, 2, 2 "
     "circular }",
     4 * kPi* kIntensity, "circular area light"},
    {"light_source { <0, 10, 0> color rgb 0.001 area_light <10, 0, 0>, <0, 0, 10>, 2, 2 "
     "circular orient }",
     4 * kPi* kIntensity, "oriented area light"},
    {"light_source { <0, 10, 0> color rgb 0.001 spotlight point_at <0, -50, 0> radius -90 "
     "falloff 90 tightness 1 }",
     kPi* kIntensity, "cosine spotlight"},
    {"light_source { <0, 10, 0> color rgb 0.001 spotlight point_at <0, -50, 0> radius -90 "
     "falloff 90 tightness 1 area_light <10, 0, 0>, <0, 0, 10>, 2, 2 circular orient }",
     kPi* kIntensity, "oriented cosine area spotlight"},
};

// The same box through vertex connection and merging: every light's light subpaths, light
// samples, connections and merges weighted together, split into the same layers.
void expect_vcm_balance(const std::string& light, std::vector<std::string> sources, double power,
                        const char* what) {
    const double albedo = 0.5;
    test::ClosedBox box;
    box.diffuse = albedo, box.more = light, box.integrator = "vcm";
    box.sources = std::move(sources);
    RenderSettings settings;
    // Merging's bias, light missing within the radius of the walls' edges, is under the noise
    // at a quarter of a cell (0.5% of the secondary light at 2 mm, here 0.5 mm).
    settings.render_image = false, settings.passes = 4, settings.seed = 6;
    settings.photons_per_pass = 32768, settings.photon_radius = 0.5;
    expect_layer_balance(render_text(test::closed_box_scene(box), settings), power, albedo,
                         std::string("vcm, ") + what);
}

TEST(LightInterface, VcmBalancesARayFileSourceAndPovRayLights) {
    expect_vcm_balance("", {test::disk_files().model}, 1, "ray-file source");
    for (const PovLight& light : kPovLights)
        expect_vcm_balance(light.text, {}, light.power, light.what);
}

TEST(LightInterface, VcmGathersWithinARadiusOfTheViewNotOfWhereLightLands) {
    // A point light 10 mm over an open floor lights it out to the horizon; the camera sees a
    // patch 40 mm wide. The first radius is a hundredth of the diagonal of where merges happen,
    // the view, as the bidirectional integrator's: not of where light subpaths end (a point
    // light's flux on a plane falls off only as 1/d^3: their middle 90% spans about 12 times its
    // height, three times the view).
    const std::string scene_text = R"(
        global_settings { integrator "INTEGRATOR" }
        camera { location <0, 60, 0> look_at <0, 0, 0> angle 37 }
        plane { y, 0 pigment { rgb 0.8 } finish { diffuse 1 ambient 0 } }
        light_source { <0, 10, 0> color rgb 1 }
    )";
    double radius[2];
    int k = 0;
    for (const std::string integrator : {"bidirectional", "vcm"}) {
        std::string text = scene_text;
        text.replace(text.find("INTEGRATOR"), 10, integrator);
        RenderSettings settings;
        settings.width = 32, settings.height = 32, settings.passes = 1, settings.seed = 3;
        settings.photons_per_pass = 4096;
        radius[k++] = render_text(text, settings).photon_radius;
    }
    std::printf("first radius: bidirectional %.4g mm, vcm %.4g mm\n", radius[0], radius[1]);
    // The view at the floor: 2 x 60 tan(18.5 deg) = 40.2 mm wide, 3/4 of that high (POV-Ray's
    // default right and up); the middle 90% of it has a diagonal of 0.9 x 1.25 x 40.2 mm. Pixel
    // centres and jittered visible points differ by a pixel's share of it.
    const double view = 2 * 60 * std::tan(37.0 / 2 * kPi / 180);
    EXPECT_NEAR(radius[1], 0.9 * 1.25 * view / 100, 0.05 * radius[1]);
    EXPECT_NEAR(radius[1], radius[0], 0.05 * radius[0]);
}

// The mean over an image of each layer's luminance weight (W/m^2 sr for grey light) and its
// standard error, from the pixels' own.
struct ImageLayer {
    double mean = 0, standard_error = 0;
};
ImageLayer image_layer(const RenderResult& r, size_t layer) {
    const SampleGrid& film = r.layers.at(layer).film;
    double sum = 0, squares = 0;
    for (int y = 0; y < film.ny(); ++y)
        for (int x = 0; x < film.nx(); ++x) {
            sum += luminance_weight(film.mean(x, y));
            squares += std::pow(film.photometric_standard_error(x, y) / kLumensPerWatt, 2);
        }
    const double n = double(film.nx()) * film.ny();
    return {sum / n, std::sqrt(squares) / n};
}

// An integrator and the passes it renders.
struct Rendering {
    std::string integrator;
    int passes;
};

// Renders an image of the closed box lit by the ray-file source, with `more` in the scene,
// twice, and expects the two images' `layers` (primary and secondary) to agree within 4
// combined standard errors, each known to 0.5% (so 4 se is 2% at most). Direct visibility is
// left out: the few pixels that see the source's body, 1e4 times as bright as the walls, make
// its image mean a matter of sub-pixel coverage (a standard error as large as the mean at this
// size); every integrator sees the body through the same camera rays.
void expect_layers_agree(const std::string& more, uint64_t seed, const Rendering& a,
                         const Rendering& b, double photon_radius = 0.5,
                         const std::vector<size_t>& layers = {kPrimary, kSecondary}) {
    ImageLayer images[2][3];
    for (int k = 0; k < 2; ++k) {
        const Rendering& rendering = k == 0 ? a : b;
        test::ClosedBox box;
        box.cells = 2, box.integrator = rendering.integrator, box.more = more;
        box.sources = {test::disk_files().model};
        RenderSettings settings;
        settings.width = 48, settings.height = 36, settings.seed = seed;
        settings.passes = rendering.passes;
        settings.photon_radius = photon_radius;
        const RenderResult r = render_text(test::closed_box_scene(box), settings);
        for (size_t l = 0; l < 3; ++l) images[k][l] = image_layer(r, l);
    }
    for (size_t l : layers) {
        const ImageLayer &x = images[0][l], &y = images[1][l];
        const double se = std::hypot(x.standard_error, y.standard_error);
        std::printf("%s: %s %.6g (se %.2g), %s %.6g (se %.2g) W/(m^2 sr)\n",
                    light_layers()[l].c_str(), a.integrator.c_str(), x.mean, x.standard_error,
                    b.integrator.c_str(), y.mean, y.standard_error);
        EXPECT_NEAR(y.mean, x.mean, 4 * se) << light_layers()[l];
        EXPECT_LT(se, 0.005 * x.mean) << light_layers()[l];
    }
}

TEST(LightInterface, VcmAgreesWithThePathTracerLayerByLayerOnAnImage) {
    // Inside the closed box, lit by the ray-file source and a point light, a camera sees the
    // walls: light that reaches the image through connections and merges of light subpaths,
    // against the path tracer, layer by layer.
    const std::string view = "camera { location <0, 0, -45> look_at <0, -10, 50> angle 90 }\n" +
                             std::string(kPovLights[0].text) + "\n";
    expect_layers_agree(view, 2, {"path", 128}, {"vcm", 8});
}

TEST(LightInterface, VcmPrimaryLightHasNoMergingBiasAtEdges) {
    // The same view with a radius of 5 in the 100-wide box: a merge within 5 of an edge loses
    // the part of its disc beyond the edge (a few percent of the secondary layer here). Light
    // straight from a light is never merged, so vcm's primary layer still agrees with the path
    // tracer's; the secondary layer, which keeps merging's bias, is not compared.
    const std::string view = "camera { location <0, 0, -45> look_at <0, -10, 50> angle 90 }\n" +
                             std::string(kPovLights[0].text) + "\n";
    expect_layers_agree(view, 2, {"path", 128}, {"vcm", 8}, 5, {kPrimary});
}

TEST(LightInterface, VcmAgreesWithTheBidirectionalThroughAMirrorAndGlass) {
    // The closed box with a mirror ball and a glass ball on its floor under the ray-file
    // source: caustics on the floor (light -> mirror or glass -> floor <- camera), which vcm
    // merges at the camera path's first smooth surface and connects elsewhere, and light the
    // camera sees through both balls. Against the bidirectional integrator (photons gathered
    // at the first smooth surface, path tracing elsewhere): a vcm weight that does not add up
    // to one shows as a difference. (The path tracer, which finds the small source through a
    // mirror only by chance, would need 1000 times the passes for the same standard error.)
    const std::string scene_more =
        "camera { location <0, 10, -45> look_at <0, -40, 10> angle 80 }\n"
        "sphere { <18, -38, 5>, 12 pigment { rgb 0 } finish { diffuse 0 reflection 1 ambient 0 } "
        "}\n"
        "sphere { <-18, -38, 5>, 12 pigment { rgbt 1 } finish { diffuse 0 ambient 0 } interior { "
        "ior 1.5 } }\n";
    expect_layers_agree(scene_more, 4, {"bidirectional", 16}, {"vcm", 16});
}

TEST(LightInterface, EveryIntegratorTheSceneLanguageNamesRenders) {
    // The renderer makes an integrator of every name a scene may give, with the light layers,
    // and each lights the closed box's walls.
    for (const std::string_view name : kIntegratorNames) {
        const std::string integrator(name);
        SCOPED_TRACE(integrator);
        EXPECT_EQ(integrator_layers(integrator), light_layers());
        test::ClosedBox box;
        box.cells = 2, box.integrator = integrator;
        box.more = "camera { location <0, 0, -45> look_at <0, -10, 50> angle 90 }\n" +
                   std::string(kPovLights[0].text);
        RenderSettings settings;
        settings.width = 8, settings.height = 6, settings.passes = 1, settings.seed = 3;
        settings.photons_per_pass = 4096;
        const RenderResult r = render_text(test::closed_box_scene(box), settings);
        ASSERT_EQ(r.layers.size(), 3u);
        EXPECT_GT(image_layer(r, kPrimary).mean, 0);
    }
}

TEST(LightInterface, BidirectionalSamplesAndEmitsPovRayLights) {
    for (const PovLight& light : kPovLights)
        expect_bidirectional_balance(light.text, light.power, light.what);
}

TEST(LightInterface, PathTracerSplitsPovRayLightsAsTheBidirectionalDoes) {
    for (const PovLight& light : kPovLights)
        expect_path_balance(light.text, light.power, light.what);
}

TEST(LightInterface, LightThroughAMirrorIsSecondaryInBothIntegrators) {
    // The disk 2 mm above a floor faces up, toward a mirror 2 mm above it: the floor sees its
    // back (dark) and its image in the mirror, a disk facing down 6 mm up. Light that reaches a
    // surface through a mirror has scattered on its way: secondary light in both integrators,
    // and the receivers' primary light is nothing. The floor reflects 0.06% (the photons of
    // the bidirectional integrator land only where a smooth lobe is), and so adds no more.
    const double H = 6;
    const std::string scene_text = R"(
        plane { y, 0 pigment { rgb 0.001 } }
        plane { y, 4 pigment { rgb 0 } finish { reflection 1 diffuse 0 ambient 0 } }
        ray_source { ")" + test::disk_files().model +
                                   R"(" rotate <-90, 0, 0> translate <0, 2, 0> }
        illuminance_receiver { <-6, 0, -6>, <0, 0, 12>, <12, 0, 0>
            resolution <4, 4> name "floor" }
    )";
    const analytic::LambertianDisk disk = test::disk_source();
    const lightmodel::ComplexSource model(disk_light_model());
    for (const std::string integrator : {"path", "bidirectional"}) {
        SCOPED_TRACE(integrator);
        RenderSettings settings;
        settings.render_image = false, settings.seed = 4;
        // The path tracer finds the image only by BSDF sampling (1 sample in 30 near the axis):
        // its bound is wider for the same number of standard errors.
        const bool path = integrator == "path";
        settings.passes = path ? 32768 : 64;
        const double bound = path ? 0.05 : 0.02;
        settings.photon_radius = 1;
        const RenderResult r = render_text(
            "global_settings { integrator \"" + integrator + "\" }\n" + scene_text, settings);
        ASSERT_EQ(r.layers.size(), 3u);
        const ReceiverMap& primary = r.layers[1].receivers.at(0);
        const ReceiverMap& secondary = r.layers[2].receivers.at(0);
        double measured = 0, truth = 0, variance = 0;
        for (int j = 0; j < secondary.irradiance.ny(); ++j)
            for (int i = 0; i < secondary.irradiance.nx(); ++i) {
                EXPECT_EQ(primary.irradiance.mean(i, j).green, 0) << i << "," << j;
                // The image's frame: the floor point (x, 0, z) is its point (x, -z, H).
                const Vec3 p = secondary.cell_centre(i, j), q{p.x, -p.z, H};
                const Vec3 w = normalized(q);
                truth += 1e6 * disk.irradiance(q, {0, 0, -1}) * model.intensity(w) /
                         disk.intensity(w);  // W/m^2
                measured += luminance_weight(secondary.irradiance.mean(i, j));
                variance += std::pow(
                    secondary.irradiance.photometric_standard_error(i, j) / kLumensPerWatt, 2);
            }
        std::printf(
            "%s, floor lit through a mirror: secondary %.6g W/m^2 summed over the cells "
            "(truth %.6g, standard error %.2g)\n",
            integrator.c_str(), measured, truth, std::sqrt(variance));
        EXPECT_LT(std::sqrt(variance), bound / 4 * truth);  // the bound is 4 se or more
        EXPECT_NEAR(measured, truth, bound * truth);
    }
}

// The lights of a scene, as the integrators see them.
LightSet lights_of(const std::string& text) {
    return LightSet(parse_scene_text(text, test::disk_files().scratch.file("lights.pov")),
                    SceneUnits{}, false);
}

TEST(LightInterface, ShadowRaysEndingAtTheBodysBoxMeetWhatTheyMetEndingAtTheBody) {
    // A room around the disk of the tests, 1 mm under the ceiling, a block on the floor casting
    // shadows. Nothing lies near the body, so the lights a render uses (LightSet of the
    // RenderScene) end shadow rays at the body's box. A sphere reaching into the body's box
    // takes that away: then a shadow ray is tested up to the box first and on to the body's
    // entry only where that part is clear (unless_occluded). Either way the same samples must
    // be drawn as by the lights that know nothing of the scene, and every shadow ray must be
    // blocked or not as the ray that ends at the body's entry is.
    const std::string room = R"(
        box { <-50, 0, -50>, <50, 100, 50> }
        box { <-10, 0, -10>, <10, 60, 10> }
        ray_source { ")" + test::disk_files().model +
                             R"(" rotate <90, 0, 0> translate <0, 99, 0> }
    )";
    const double inf = std::numeric_limits<double>::infinity();
    for (const bool near : {false, true}) {
        SCOPED_TRACE(near ? "a sphere near the body" : "nothing near the body");
        const RenderScene scene(
            parse_scene_text(room + (near ? "sphere { <1.5, 99, 0>, 0.6 }" : ""),
                             test::disk_files().scratch.file("room.pov")));
        const LightSet exact(scene.description(), scene.units(), false), fast(scene, false);
        Pcg32 rng(17, 3);
        int drawn = 0, blocked = 0, deferred = 0, grazing = 0;
        uint64_t rays = 0;
        for (int n = 0; n < 20000; ++n) {
            // A point of the floor or of the wall at x = -50, and its normal into the room.
            const bool floor = n % 2 == 0;
            const double a = -49 + 98 * rng.uniform(), b = 99 * rng.uniform();
            const Vec3 point = floor ? Vec3{a, 0, b - 49.5} : Vec3{-50, b, a};
            const Vec3 normal = floor ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
            if (floor && std::fabs(point.x) < 10 && std::fabs(point.z) < 10) continue;
            const LightUniforms u = exact.draw(rng);
            LightLiSampleOf<Rgb> e, f;
            const bool sampled = exact.sample_Li<Rgb>(point, u, {}, e);
            ASSERT_EQ(sampled, fast.sample_Li<Rgb>(point, u, {}, f)) << "sample " << n;
            if (!sampled) continue;
            ++drawn;
            ASSERT_TRUE(e.wi.x == f.wi.x && e.wi.y == f.wi.y && e.wi.z == f.wi.z);
            ASSERT_TRUE(e.Li.red == f.Li.red && e.Li.green == f.Li.green && e.Li.blue == f.Li.blue);
            ASSERT_EQ(e.pdf, f.pdf);
            ASSERT_EQ(f.body_entry_deferred, near) << "sample " << n;
            deferred += f.body_entry_deferred;
            const Vec3 origin = scene.offset(point, normal, e.wi);
            // The body's entry from the ray's origin; a ray that grazes the body, met from the
            // point but not from the origin offset from it, ends at the box.
            double t_body = f.distance;
            if (exact[size_t(e.light)].crossed(origin, e.wi, inf, t_body))
                ASSERT_LE(f.distance, t_body + scene.offset_distance(point));  // box first
            else
                ++grazing;
            const bool by_body = scene.occluded(origin, e.wi, 0, t_body - scene.epsilon());
            ShadowRayOf<Rgb> shadow;
            shadow.cast = true, shadow.origin = origin, shadow.direction = f.wi;
            shadow.t_far = f.distance - scene.epsilon(), shadow.contribution = Rgb{1, 1, 1};
            if (f.body_entry_deferred) shadow.body_beyond = &fast[size_t(f.light)];
            const bool by_render = is_black(unless_occluded(scene, shadow, rays));
            ASSERT_EQ(by_body, by_render) << "sample " << n;
            blocked += by_body;
        }
        std::printf(
            "[ figures  ] %s: %d light samples drawn, %d of them blocked, %d tested up "
            "to the box first, %d grazing the body\n",
            near ? "sphere near" : "clear", drawn, blocked, deferred, grazing);
        EXPECT_LT(grazing, drawn / 100);  // lines along the flat disk's face
        EXPECT_GT(drawn, 10000);
        EXPECT_GT(blocked, 500);  // the block's shadow on the floor and the wall
        EXPECT_LT(blocked, drawn - 500);
    }
}

TEST(LightInterface, APhotonsFluxIsTheRadianceItCarriesOverItsEmissionDensity) {
    // What a bidirectional weight rests on: sample_Le's flux is the light's radiance along the
    // photon's ray (a point light's intensity) over pdf_Le's density for that ray, per channel.
    // Radiance comes from the queries a camera ray uses (crossed, radiance, sample_Li), the
    // density from pdf_Le: two codes, one photon.
    for (const PovLight& pov : kPovLights) {
        SCOPED_TRACE(pov.what);
        const LightSet lights = lights_of(pov.text);
        ASSERT_EQ(lights.size(), 1u);
        const Light& light = lights[0];
        Pcg32 rng(11, 0);
        for (int n = 0; n < 2000; ++n) {
            double u[7];
            for (double& x : u) x = rng.uniform();
            const LightPhotonOf<Rgb> photon = light.sample_Le<Rgb>(u, 0.5);
            const Vec3 origin = photon.origin + 100 * photon.direction, wi = -photon.direction;
            double t = 0, arriving = 0;
            if (light.delta_position()) {
                t = 100;
                LightUniforms none;
                LightLiSampleOf<Rgb> li;
                ASSERT_TRUE(light.sample_Li<Rgb>(origin, none, 1, {}, li));
                arriving = li.Li.green * t * t;  // the intensity toward `origin`
            } else {
                ASSERT_TRUE(light.crossed(origin, wi, 1e300, t)) << "photon " << n;
                EXPECT_NEAR(t, 100, 1e-9) << "photon " << n;
                arriving = light.arriving<Rgb>(origin, wi, t, 1, false, {}).radiance.green;
            }
            const double pdf = light.pdf_Le(origin, wi, t, 1);
            ASSERT_GT(pdf, 0) << "photon " << n;
            EXPECT_NEAR(photon.flux.green, arriving / pdf, 1e-9 * photon.flux.green)
                << "photon " << n;
        }
    }
}

// The integral of pdf_Le over every direction leaving the light and the plane across each,
// through the light's centre (a square of side `side` holding the body seen from anywhere):
// directions stratified over the sphere, points jittered on a grid.
double integrated_emission_density(const Light& light, Vec3 centre, double side, int directions,
                                   int grid) {
    Pcg32 rng(5, 1);
    double sum = 0;
    for (int k = 0; k < directions; ++k) {
        const int rows = int(std::sqrt(double(directions)));
        const Vec3 w = uniform_sphere((k % rows + rng.uniform()) / rows,
                                      (k / rows + rng.uniform()) / (directions / rows));
        const Frame frame(w);
        const double h = side / grid;
        for (int j = 0; j < grid; ++j)
            for (int i = 0; i < grid; ++i) {
                const Vec3 q = centre + ((i + rng.uniform()) * h - side / 2) * frame.s +
                               ((j + rng.uniform()) * h - side / 2) * frame.t;
                const Vec3 origin = q + 10 * side * w;
                double t = 0;
                if (light.crossed(origin, -w, 1e300, t))
                    sum += light.pdf_Le(origin, -w, t, 1) * h * h;
            }
    }
    return 4 * kPi * sum / directions;
}

TEST(LightInterface, EmissionDensitiesOfLightsWithABodyIntegrateToOne) {
    // Every photon leaves its light in some direction across some point: pdf_Le integrates to
    // 1. Points jittered in a 40 x 40 grid over 1024 stratified directions: the error is that
    // of the body's outline in the grid and of the stratified cosine, 0.2% here at most.
    for (const PovLight& pov : kPovLights) {
        const LightSet lights = lights_of(pov.text);
        if (lights[0].delta_position()) continue;
        const double integral = integrated_emission_density(lights[0], {0, 10, 0}, 16, 1024, 40);
        std::printf("%s: emission density integrates to %.5f\n", pov.what, integral);
        EXPECT_NEAR(integral, 1, 0.005) << pov.what;
    }
}

TEST(LightInterface, ARaySourcesLineDensityIntegratesToItsFarField) {
    // Across a direction, the photon lines of a ray source's model add up to the share of its
    // flux sent that way, its far-field intensity over its flux: the model's diagrams alone
    // (ComplexSource::intensity), against pdf_Le's lines through the voxels.
    const LightSet lights = lights_of("ray_source { \"" + test::disk_files().model + "\" }");
    const lightmodel::ComplexSource model(disk_light_model());
    const Light& light = lights[0];
    for (const Vec3 w : {Vec3{0, 0, 1}, normalized(Vec3{0.3, 0.2, 1}), normalized(Vec3{1, 0, 1}),
                         normalized(Vec3{-1, 0.5, 0.3})}) {
        const Frame frame(w);
        Pcg32 rng(3, 2);
        const int grid = 400;
        const double side = 4, h = side / grid;  // the disk: radius 1 mm
        double sum = 0;
        for (int j = 0; j < grid; ++j)
            for (int i = 0; i < grid; ++i) {
                const Vec3 q = ((i + rng.uniform()) * h - side / 2) * frame.s +
                               ((j + rng.uniform()) * h - side / 2) * frame.t;
                sum += light.pdf_Le(q + 100 * w, -w, 100, 1) * h * h;
            }
        const double truth = model.intensity(w) / model.phi();
        std::printf(
            "ray source, photon lines toward (%.2f, %.2f, %.2f): %.6g per sr (far "
            "field %.6g)\n",
            w.x, w.y, w.z, sum, truth);
        EXPECT_NEAR(sum, truth, 0.005 * truth);
    }
}

TEST(LightInterface, VcmRefusesWhatItDoesNotRenderNamingThePathIntegrator) {
    const std::string box = "global_settings { integrator \"vcm\" }\nplane { y, 0 }\n";
    RenderSettings settings;
    settings.render_image = false, settings.passes = 1;
    const std::pair<std::string, std::string> refused[] = {
        {"light_source { <0, 10, 0> color rgb 1 shadowless }", "shadowless"},
        {"fog { distance 100 color rgb 0.5 }", "fog"},
        {"sphere { 0, 1 pigment { rgbf 1 } interior { media { scattering { 1, 0.1 } } } "
         "hollow }",
         "media"},
        {"global_settings { spectral on }", "spectral"},
    };
    for (const auto& [text, what] : refused) {
        try {
            render_text(box + text, settings);
            ADD_FAILURE() << "rendered " << what;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("path integrator"), std::string::npos) << e.what();
        }
    }
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
