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
    Material scratch;
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
    auto error = [](const std::string& text) {
        try {
            RenderScene scene(parse_scene_text(text, "test.pov"));
            RenderSettings settings;
            settings.width = 4, settings.height = 3, settings.passes = 1, settings.threads = 1;
            render(scene, settings);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("fog { distance 2 colour rgb 1 turbulence 0.3 }"),
              "not supported: fog turbulence at test.pov:1:1");
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
