// Fog in the renderer: what an eye path sees through it is POV-Ray's. scenes/fog.pov (ground
// fog with filter and transmit over flat-lit tiles, a floor and the background, seen downward
// and upward through its layer) is rendered by POV-Ray itself without anti-aliasing in linear
// 8-bit output and compared pixel by pixel with the surface or sky each pixel's centre ray meets
// here, seen through FogMedium; the path integrator's use of it against the closed form.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>

#include "core/error.h"
#include "tracer/render/camera.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

using test::agrees_with_povray;

// fog.pov with its fog statement's `fog_type 2` replaced by `fog_type`.
void expect_fog_agrees(const std::string& fog_type) {
    const int width = 240, height = 180;
    test::ScratchDir dir;
    std::string text = test::read_file(test::tracer_scene("fog.pov"));
    text.replace(text.find("fog_type 2"), 10, fog_type);
    const std::string scene_file = dir.file("fog.pov");
    test::write_file(scene_file, text);
    std::vector<uint8_t> reference;
    std::string message;
    if (!test::povray_render(scene_file, width, height, reference, message))
        GTEST_SKIP() << message;

    const RenderScene scene(parse_scene_file(scene_file));
    ASSERT_TRUE(scene.fog().present());
    const SceneCamera camera(scene.description().camera, width, height);
    const std::vector<SurfaceHit> hits = centre_hits(scene, width, height);
    const double to_colour = scene.units().per_square_metre();  // radiance -> POV-Ray colour
    int agree = 0;
    std::optional<Material> scratch;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * width + x;
            const CameraRay ray = camera.ray(x + 0.5, y + 0.5);
            const bool found = hits[i].object >= 0;
            const Rgb beyond = found ? scene.material(hits[i], scratch).emission
                                     : scene.sky().radiance(ray.direction);
            Rgb through, added;
            scene.fog().along(ray.origin, ray.direction,
                              found ? hits[i].t : std::numeric_limits<double>::infinity(), through,
                              added);
            agree += agrees_with_povray(to_colour * (added + through * beyond), &reference[3 * i]);
        }
    const double fraction = double(agree) / (width * height);
    std::printf("%s: colours agree on %d of %d pixels (%.4f)\n", fog_type.c_str(), agree,
                width * height, fraction);
    EXPECT_GE(fraction, 0.98);
}

TEST(RenderFog, GroundFogAgreesWithPovRayPixelForPixel) { expect_fog_agrees("fog_type 2"); }

TEST(RenderFog, ConstantFogAgreesWithPovRayPixelForPixel) { expect_fog_agrees("fog_type 1"); }

// Fog turbulence thins the fog in patches (fog.h): POV-Ray's and ours cannot agree point for
// point (noise.h), so the optical depth each pixel's ray sees through white fog to a black wall
// (POV-Ray's: -ln(1 - pixel)) is compared in mean and spread over the image, for constant and
// ground fog. The view spans 40 x 40 units of turbulence, 1600 noise cells and more: the
// sampling error of either figure is under 1%; the bounds, 3% on the mean and 25% on the
// spread, are the model's (the turbulence's distribution read back from POV-Ray's renders).
void expect_turbulent_fog_agrees(const std::string& fog) {
    const int width = 200, height = 200;
    test::ScratchDir dir;
    const std::string scene_file = dir.file("turbulent_fog.pov");
    test::write_file(scene_file,
                     "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
                     "camera { orthographic location <0, 2, -10> look_at <0, 2, 0> "
                     "right 40*x up 40*y }\n"
                     "plane { -z, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 } }\n" +
                         fog + "\n");
    std::vector<uint8_t> reference;
    std::string message;
    if (!test::povray_render(scene_file, width, height, reference, message))
        GTEST_SKIP() << message;
    const RenderScene scene(parse_scene_file(scene_file));
    const SceneCamera camera(scene.description().camera, width, height);
    const std::vector<SurfaceHit> hits = centre_hits(scene, width, height);
    double sum[2] = {0, 0}, squares[2] = {0, 0};
    int n = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * width + x;
            const double fogged = reference[3 * i] / 255.0;
            if (hits[i].object < 0 || fogged >= 0.99) continue;  // too thick to read back
            const CameraRay ray = camera.ray(x + 0.5, y + 0.5);
            const double depth[2] = {
                scene.fog().optical_depth(ray.origin, ray.direction, hits[i].t),
                -std::log(1 - fogged)};
            for (int k = 0; k < 2; ++k) sum[k] += depth[k], squares[k] += depth[k] * depth[k];
            ++n;
        }
    ASSERT_GT(n, width * height / 2);
    double mean[2], sd[2];
    for (int k = 0; k < 2; ++k) {
        mean[k] = sum[k] / n;
        sd[k] = std::sqrt(std::max(0.0, squares[k] / n - mean[k] * mean[k]));
    }
    std::printf("%s: optical depth mean %.4f (POV-Ray %.4f), sd %.4f (POV-Ray %.4f)\n", fog.c_str(),
                mean[0], mean[1], sd[0], sd[1]);
    EXPECT_NEAR(mean[0], mean[1], 0.03 * mean[1]);
    EXPECT_NEAR(sd[0], sd[1], 0.25 * sd[1]);
}

TEST(RenderFog, TurbulenceAgreesWithPovRayInMeanAndSpread) {
    expect_turbulent_fog_agrees("fog { distance 10 colour rgb 1 turbulence 1 }");
    expect_turbulent_fog_agrees(
        "fog { distance 10 colour rgb 1 turbulence 0.3 turb_depth 0.8 octaves 3 }");
    expect_turbulent_fog_agrees(
        "fog { fog_type 2 fog_offset 0 fog_alt 3 distance 10 colour rgb 1 "
        "turbulence <0.2, 0.3, 0.2> omega 0.3 }");
}

// An orthographic camera facing a flat-lit wall 3 units away through constant fog of distance 2
// with filter 0.4: every pixel is exp(-1.5) (0.6 + 0.4 F) E + (1 - exp(-1.5)) F exactly, the
// path ending at the wall (it reflects nothing).
TEST(RenderFog, PathIntegratorSeesThroughIt) {
    const RenderScene scene(parse_scene_text(R"(
        camera { orthographic location 0 look_at z right x up y }
        fog { distance 2 colour rgbf <0.5, 0.25, 1, 0.4> }
        plane { z, 3 pigment { rgb <1, 0.6, 0.2> } finish { ambient 0 diffuse 0 emission 1 } })",
                                             "test.pov"));
    RenderSettings settings;
    settings.width = 8, settings.height = 6, settings.passes = 2, settings.threads = 1;
    const RenderResult result = render(scene, settings);
    const double t = std::exp(-1.5);
    const Rgb fog{0.5, 0.25, 1}, wall{1, 0.6, 0.2};
    const Rgb expected = t * (Rgb{0.6, 0.6, 0.6} + 0.4 * fog) * wall + (1 - t) * fog;
    for (int y = 0; y < settings.height; ++y)
        for (int x = 0; x < settings.width; ++x) {
            const Rgb pixel = result.film.mean(x, y);  // W/(m^2 sr): the POV-Ray colour
            EXPECT_NEAR(pixel.red, expected.red, 1e-5);
            EXPECT_NEAR(pixel.green, expected.green, 1e-5);
            EXPECT_NEAR(pixel.blue, expected.blue, 1e-5);
        }
}

TEST(RenderFog, RefusesWhatItDoesNotRender) {
    const auto error = test::render_error;
    EXPECT_EQ(error("fog { distance 2 colour rgb 1 turbulence 0.3 }"), "no error");
    EXPECT_EQ(error("fog { distance 2 colour rgb 1 }\nfog { distance 3 colour rgb 0.5 }"),
              "not supported: more than one fog at test.pov:2:1");
    EXPECT_EQ(error("global_settings { integrator \"bidirectional\" }\n"
                    "fog { distance 2 colour rgb 1 }"),
              "not supported: fog with integrator \"bidirectional\" at test.pov:2:1 (the path "
              "integrator renders it)");
    EXPECT_NE(error("global_settings { spectral on }\nfog { distance 2 colour rgb 1 }")
                  .find("not supported: patterned pigments, a sky_sphere or fog in spectral"),
              std::string::npos);
}

}  // namespace
}  // namespace rayset::tracer
