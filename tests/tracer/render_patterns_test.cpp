// Patterned pigments in the renderer: the colour a surface point gets, and the sky a ray that
// leaves the scene sees, are POV-Ray's. The scenes are rendered by POV-Ray itself without
// anti-aliasing in linear 8-bit output, and compared pixel by pixel with what each pixel's
// centre ray meets here: scenes/patterns.pov (twelve patterns with colour maps, lists,
// frequencies and transforms of pigments and objects, on flat-lit boxes and a checkered floor;
// the material's emission is the pigment, finish { emission 1 diffuse 0 }) and scenes/sky.pov
// (a sky_sphere of three layers with filter and transmit over a background, turned and scaled
// by `emission`).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/error.h"
#include "tracer/render/camera.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

using test::agrees_with_povray;

TEST(RenderPatterns, SkyAgreesWithPovRayPixelForPixel) {
    const int width = 240, height = 180;
    const std::string scene_file = test::tracer_scene("sky.pov");
    std::vector<uint8_t> reference;
    std::string message;
    if (!test::povray_render(scene_file, width, height, reference, message))
        GTEST_SKIP() << message;

    const RenderScene scene(parse_scene_file(scene_file));
    const SceneCamera camera(scene.description().camera, width, height);
    const double to_colour = scene.units().per_square_metre();  // radiance -> POV-Ray colour
    int agree = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const CameraRay ray = camera.ray(x + 0.5, y + 0.5);
            const size_t i = size_t(y) * width + x;
            agree += agrees_with_povray(to_colour * scene.sky().radiance(ray.direction),
                                        &reference[3 * i]);
        }
    const double fraction = double(agree) / (width * height);
    std::printf("sky colours agree on %d of %d pixels (%.4f)\n", agree, width * height, fraction);
    EXPECT_GE(fraction, 0.98);
}

// The pattern scene under `assumed_gamma` (its colours encoded with it) and seen through
// `camera` (its camera statement when empty), against POV-Ray's render written with that file
// gamma: POV-Ray shows a flat colour unchanged, and here it is decoded to c^gamma of radiance,
// so c^(1/gamma) must give it back.
void expect_flat_colours_agree(const std::string& scene_name, double assumed_gamma,
                               const std::string& camera = "") {
    const int width = 240, height = 180;
    test::ScratchDir dir;
    std::string text = test::read_file(test::tracer_scene(scene_name));
    const std::string linear = "assumed_gamma 1.0";
    text.replace(text.find(linear), linear.size(),
                 "assumed_gamma " + std::to_string(assumed_gamma));
    if (!camera.empty()) {
        const size_t start = text.find("camera {");
        text.replace(start, text.find('\n', start) - start, camera);
    }
    const std::string scene_file = dir.file(scene_name);
    test::write_file(scene_file, text);
    std::vector<uint8_t> reference;
    std::string message;
    if (!test::povray_render(scene_file, width, height, reference, message, assumed_gamma))
        GTEST_SKIP() << message;

    const RenderScene scene(parse_scene_file(scene_file));
    const std::vector<SurfaceHit> hits = centre_hits(scene, width, height);
    const double to_pigment = scene.units().per_square_metre();  // emission -> pigment
    auto encoded = [&](double v) { return std::pow(to_pigment * v, 1 / assumed_gamma); };
    int agree = 0, patterned = 0;
    Material scratch;
    for (size_t i = 0; i < hits.size(); ++i) {
        Rgb ours{};
        if (hits[i].object >= 0) {
            const Rgb e = scene.material(hits[i], scratch).emission;
            ours = {encoded(e.red), encoded(e.green), encoded(e.blue)};
        }
        agree += agrees_with_povray(ours, &reference[3 * i]);
        patterned += hits[i].object >= 0;
    }
    const double fraction = double(agree) / double(hits.size());
    std::printf("%s, assumed_gamma %g, %s: colours agree on %d of %zu pixels (%.4f)\n",
                scene_name.c_str(), assumed_gamma, camera.empty() ? "its camera" : camera.c_str(),
                agree, hits.size(), fraction);
    // Most pixels show an object (the wide-angle cameras see sky too): nothing, black in both,
    // cannot carry the agreement.
    EXPECT_GT(patterned, width * height / 2);
    EXPECT_GE(fraction, 0.98);
}

TEST(RenderPatterns, AgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("patterns.pov", 1.0);
}

// Layered textures (filter and transmit, a patterned layer, three layers), texture maps and
// texture lists, one a map of a layered texture.
TEST(RenderPatterns, LayersAndTexturePatternsAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("layers.pov", 1.0);
}

TEST(RenderPatterns, AgreeWithPovRayUnderAnotherAssumedGamma) {
    expect_flat_colours_agree("patterns.pov", 2.2);
}

// Cylinders and cones (closed, open, tilted, to a point), a disc with a hole and tori (one
// scaled unevenly and turned), patterned: silhouettes and hit points both.
TEST(RenderShapes, AgreeWithPovRayPixelForPixel) { expect_flat_colours_agree("shapes.pov", 1.0); }

// Difference, intersection (with an inverted part; of six planes), merge, clipped_by (twice, a
// sphere; a union), bounded_by (holding its object; too small on a sphere, which POV-Ray drops;
// on a plane, which it keeps), parts with pigments of their own, patterned and turned.
TEST(RenderShapes, CsgAgreesWithPovRayPixelForPixel) { expect_flat_colours_agree("csg.pov", 1.0); }

// Quadrics (a hyperboloid cut to a box, a cylinder cut by planes), a quartic torus with a
// bound, a cubic monkey saddle cut to a cylinder and a sphere as a poly.
TEST(RenderShapes, PolynomialsAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("polynomials.pov", 1.0);
}

// Superellipsoids from rounded boxes (exponents 0.2) to pinched stars (3), turned and scaled
// unevenly, cut by a sphere and by a plane.
TEST(RenderShapes, SuperellipsoidsAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("superellipsoids.pov", 1.0);
}

// Isosurfaces of expressions and internal functions, in box and sphere containers, capped and
// open, turned and cut by a sphere.
TEST(RenderShapes, IsosurfacesAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("isosurfaces.pov", 1.0);
}

// Blobs of sphere and cylinder components, a negative one, components scaled on their own,
// several thresholds, one cut by a box.
TEST(RenderShapes, BlobsAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("blobs.pov", 1.0);
}

// Linear prisms swept along y and conically, one with a hole, one open, turned and cut.
TEST(RenderShapes, PrismsAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("prisms.pov", 1.0);
}

// Lathes of the four spline kinds, turned, one cut by a sphere.
TEST(RenderShapes, LathesAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("lathes.pov", 1.0);
}

// Text in three of POV-Ray's fonts (curves, holes, an offset, turned, thick) and cut from a box.
TEST(RenderShapes, TextAgreesWithPovRayPixelForPixel) {
    expect_flat_colours_agree("text.pov", 1.0);
}

// The orthographic camera, sized by its angle at the look_at distance and by right and up.
TEST(RenderPatterns, AgreeWithPovRayThroughAnOrthographicCamera) {
    expect_flat_colours_agree(
        "patterns.pov", 1.0,
        "camera { orthographic location <0, 12, -4> look_at <0, 0, 0.5> angle 60 }");
    expect_flat_colours_agree(
        "patterns.pov", 1.0,
        "camera { orthographic location <3, 9, -6> look_at <0, 0, 0> right 16*x up 12*y }");
}

// The wide-angle projections: spherical, the four cylinders, ultra_wide_angle and fisheye (its
// corners outside the circle black in both), turned and with right and up of other lengths.
TEST(RenderPatterns, AgreeWithPovRayThroughTheWideAngleCameras) {
    for (const char* camera :
         {"camera { spherical location <0, 5, -7> look_at <0, 0, 0.5> angle 220 110 }",
          "camera { cylinder 1 location <1, 8, -8> look_at <0, 0, 0.5> angle 150 up 1.5*y }",
          "camera { cylinder 2 location <0, 9, -7> look_at <0, 0, 0.5> angle 120 right 2*x }",
          "camera { cylinder 3 location <0, 9, -7> look_at <0, 0, 0.5> angle 140 up 6*y }",
          "camera { cylinder 4 location <0, 9, -7> look_at <0, 0, 0.5> angle 100 right 12*x }",
          "camera { ultra_wide_angle location <0, 9, -5> look_at <0, 0, 0.5> angle 160 }",
          "camera { fisheye location <0, 9, -3> look_at <0, 0, 0.5> angle 170 rotate y*10 }"})
        expect_flat_colours_agree("patterns.pov", 1.0, camera);
}

// The colour moves with the object: a checker on a box translated by one square shows the
// other colour at the same world point; and it is the pigment's, not a mean.
TEST(RenderPatterns, MaterialFollowsThePatternAndTheObject) {
    auto diffuse_at = [](const std::string& text, Vec3 point) {
        const RenderScene scene(parse_scene_text(text, "test.pov"));
        Material scratch;
        return scene.material(0, -1, point, {0, 0, 1}, scratch).diffuse;
    };
    const std::string checker =
        "box { -1, 1 pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> } finish { diffuse 1 } ";
    const Vec3 p{0.5, 0.5, 0.5};
    EXPECT_EQ(diffuse_at(checker + "}", p).red, 1);
    EXPECT_EQ(diffuse_at(checker + "}", p).blue, 0);
    EXPECT_EQ(diffuse_at(checker + "translate x }", p).red, 0);
    EXPECT_EQ(diffuse_at(checker + "translate x }", p).blue, 1);
    // gradient x from black to white: the colour is x's fraction, times the diffuse amount.
    EXPECT_NEAR(
        diffuse_at("plane { y, 0 pigment { gradient x } finish { diffuse 0.5 } }", {2.25, 0, 7})
            .green,
        0.125, 1e-12);
}

TEST(RenderPatterns, SpectralTransportRefusesThem) {
    const RenderScene scene(parse_scene_text(
        "camera { location -5 look_at 0 } plane { y, 0 pigment { checker } }", "test.pov"));
    RenderSettings settings;
    settings.width = 4, settings.height = 3, settings.passes = 1, settings.spectral = true;
    try {
        render(scene, settings);
        FAIL() << "rendered";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "not supported: patterned pigments, a sky_sphere or fog in spectral"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace rayset::tracer
