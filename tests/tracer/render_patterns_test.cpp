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

// The scene `scene_name` with its camera statement (a line) replaced by `camera` if given,
// written to `dir` as `file_name`.
std::string scene_with_camera(const test::ScratchDir& dir, const std::string& scene_name,
                              double assumed_gamma, const std::string& camera,
                              const std::string& file_name) {
    std::string text = test::read_file(test::tracer_scene(scene_name));
    const std::string linear = "assumed_gamma 1.0";
    text.replace(text.find(linear), linear.size(),
                 "assumed_gamma " + std::to_string(assumed_gamma));
    if (!camera.empty()) {
        const size_t start = text.find("camera {");
        text.replace(start, text.find('\n', start) - start, camera);
    }
    const std::string scene_file = dir.file(file_name);
    test::write_file(scene_file, text);
    return scene_file;
}

// The pattern scene under `assumed_gamma` (its colours encoded with it) and seen through
// `camera` (its camera statement when empty), against POV-Ray's render written with that file
// gamma: POV-Ray shows a flat colour unchanged, and here it is decoded to c^gamma of radiance,
// so c^(1/gamma) must give it back. With `our_camera`, the scene is seen here through that
// camera instead (one that should see what POV-Ray's does). With `reach` 1, a pixel agrees when
// POV-Ray's colour there is the colour met here at it or at one of its eight neighbours: a
// silhouette within one pixel.
void expect_flat_colours_agree(const std::string& scene_name, double assumed_gamma,
                               const std::string& camera = "", const std::string& our_camera = "",
                               int reach = 0) {
    const int width = 240, height = 180;
    test::ScratchDir dir;
    const std::string scene_file =
        scene_with_camera(dir, scene_name, assumed_gamma, camera, scene_name);
    std::vector<uint8_t> reference;
    std::string message;
    if (!test::povray_render(scene_file, width, height, reference, message, assumed_gamma))
        GTEST_SKIP() << message;

    const RenderScene scene(parse_scene_file(
        our_camera.empty()
            ? scene_file
            : scene_with_camera(dir, scene_name, assumed_gamma, our_camera, "ours.pov")));
    const std::vector<SurfaceHit> hits = centre_hits(scene, width, height);
    const double to_pigment = scene.units().per_square_metre();  // emission -> pigment
    auto encoded = [&](double v) { return std::pow(to_pigment * v, 1 / assumed_gamma); };
    std::vector<Rgb> ours(hits.size());
    int patterned = 0;
    std::optional<Material> scratch;
    for (size_t i = 0; i < hits.size(); ++i) {
        if (hits[i].object < 0) continue;
        const Rgb e = scene.material(hits[i], scratch).emission;
        ours[i] = {encoded(e.red), encoded(e.green), encoded(e.blue)};
        ++patterned;
    }
    int agree = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const uint8_t* pov = &reference[3 * (size_t(y) * width + x)];
            bool agrees = false;
            for (int dy = -reach; dy <= reach && !agrees; ++dy)
                for (int dx = -reach; dx <= reach && !agrees; ++dx) {
                    const int u = std::clamp(x + dx, 0, width - 1);
                    const int v = std::clamp(y + dy, 0, height - 1);
                    agrees = agrees_with_povray(ours[size_t(v) * width + u], pov);
                }
            agree += agrees;
        }
    const double fraction = double(agree) / double(hits.size());
    std::printf("%s, assumed_gamma %g, %s%s%s: colours agree on %d of %zu pixels (%.4f)\n",
                scene_name.c_str(), assumed_gamma, camera.empty() ? "its camera" : camera.c_str(),
                our_camera.empty() ? "" : " (here a mesh camera)",
                reach ? ", within one pixel" : "", agree, hits.size(), fraction);
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

// Surfaces of revolution (closed, open, turned, scaled unevenly, cut from a box) and polygons
// (with a hole, a self-crossing star, tilted).
TEST(RenderShapes, SorsAndPolygonsAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("sors.pov", 1.0);
}

// Sphere sweeps of the three spline kinds (linear, b_spline, cubic_spline), turned and scaled
// unevenly, a loop crossing itself, one cut open by a box and two cut from a box. Measured:
// 99.86% of the pixels agree; the rest is a thin gap POV-Ray leaves inside a b_spline sweep,
// seen through the box's cut (tracer/render/README.md).
TEST(RenderShapes, SphereSweepsAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("sweeps.pov", 1.0);
}

// Julia fractals: quaternion squares and cubes, hypercomplex squares and a function, sliced at
// w = 0.2, turned and scaled unevenly, cut by a box. Their silhouettes are long and ragged and
// POV-Ray's marching is its own: pixel for pixel 97.1% of the pixels agree (measured; below the
// bound of the other shapes), within one pixel 98.2%.
TEST(RenderShapes, JuliaFractalsAgreeWithPovRayWithinOnePixel) {
    expect_flat_colours_agree("julias.pov", 1.0, "", "", 1);
}

// Bicubic patches of several subdivisions, type 0 and 1, turned and scaled unevenly.
TEST(RenderShapes, BicubicPatchesAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("patches.pov", 1.0);
}

// Parametric surfaces: a torus turned on its side, a twisted ribbon scaled unevenly, a rippled
// sheet cut round by its sphere container, a saddle cut by its box, turned.
TEST(RenderShapes, ParametricsAgreeWithPovRayPixelForPixel) {
    expect_flat_colours_agree("parametrics.pov", 1.0);
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

// The wide-angle projections: spherical, the four cylinders, ultra_wide_angle, fisheye and
// omnimax (what lies outside their circles black in both), panoramic, turned and with right,
// up and direction of other lengths.
TEST(RenderPatterns, AgreeWithPovRayThroughTheWideAngleCameras) {
    for (const char* camera :
         {"camera { spherical location <0, 5, -7> look_at <0, 0, 0.5> angle 220 110 }",
          "camera { cylinder 1 location <1, 8, -8> look_at <0, 0, 0.5> angle 150 up 1.5*y }",
          "camera { cylinder 2 location <0, 9, -7> look_at <0, 0, 0.5> angle 120 right 2*x }",
          "camera { cylinder 3 location <0, 9, -7> look_at <0, 0, 0.5> angle 140 up 6*y }",
          "camera { cylinder 4 location <0, 9, -7> look_at <0, 0, 0.5> angle 100 right 12*x }",
          "camera { ultra_wide_angle location <0, 9, -5> look_at <0, 0, 0.5> angle 160 }",
          "camera { fisheye location <0, 9, -3> look_at <0, 0, 0.5> angle 170 rotate y*10 }",
          "camera { omnimax location <0, 6, -4> look_at <0, 0, 0.5> }",
          "camera { omnimax location <0, 9, -0.5> look_at <0, 0, 1> right x up 1.1*y }",
          "camera { panoramic location <0, 9, -5> look_at <0, 0, 0.5> }",
          "camera { panoramic location <0, 9, -5> look_at <0, 0, 0.5> right 2*x direction 3*z }"})
        expect_flat_colours_agree("patterns.pov", 1.0, camera);
}

// A mesh_camera whose faces (one per pixel, distribution 0) or smooth uv grid (distribution 3)
// aim along the rays of the scene's perspective camera sees what POV-Ray's perspective camera
// does (POV-Ray's own mesh camera departs from its documented pixel mapping: mesh_camera.h).
TEST(RenderPatterns, MeshCamerasSeeWhatThePerspectiveCameraTheyFollowSees) {
    const std::string include = test::read_file(test::tracer_scene("mesh_cameras.inc")) + "\n";
    const std::string view = "<0, 12, -4>, <0, 0, 0.5>, 60";
    expect_flat_colours_agree(
        "patterns.pov", 1.0, "",
        include + "camera { mesh_camera { 1 0 PixelMesh(" + view + ", 240, 180) } }");
    expect_flat_colours_agree(
        "patterns.pov", 1.0, "",
        include + "camera { mesh_camera { 1 3 UvMesh(" + view + ", 60, 45) smooth } }");
}

// The rules of a face's ray, each read back from POV-Ray 3.7 with probe renders (a 1 x 1 image
// of one triangle; the hit point's direction and position shown as colours): the ray leaves the
// centroid along (c - a) x (b - a), taken to the world as a normal (so a mirroring scale turns
// it); location.z moves the origin along the unit normal in the mesh's coordinates (so a scale
// of 3 along it moves it 3 times as far); a negative direction.z reverses the ray but not the
// move. And the pixel-to-face maps of distributions 0, 1 (meshes summed, ray k at face
// W H k + p) and 2 (meshes side by side).
TEST(RenderPatterns, MeshCameraRaysFollowPovRaysRules) {
    auto ray = [](const std::string& camera, double x, double y, int width = 1, int height = 1) {
        const SceneDescription scene = parse_scene_text(camera, "test.pov");
        return SceneCamera(scene.camera, width, height).ray(x, y);
    };
    auto expect_ray = [](const CameraRay& r, Vec3 origin, Vec3 direction) {
        EXPECT_TRUE(r.exists);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR((&r.origin.x)[k], (&origin.x)[k], 1e-12);
            EXPECT_NEAR((&r.direction.x)[k], (&direction.x)[k], 1e-12);
        }
    };
    const std::string unit = "triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }";
    auto camera = [](const std::string& mesh, const std::string& rest) {
        return "camera { mesh_camera { 1 0 mesh { " + mesh + " } } " + rest + " }";
    };
    const double third = 1.0 / 3, half_root2 = std::sqrt(0.5);
    expect_ray(ray(camera(unit, ""), 0.5, 0.5), {third, third, 0}, {0, 0, -1});
    expect_ray(ray(camera(unit, "location <0, 0, 0.1>"), 0.5, 0.5), {third, third, -0.1},
               {0, 0, -1});
    expect_ray(ray(camera(unit + " scale <1, 1, 3>", "location <0, 0, 0.04>"), 0.5, 0.5),
               {third, third, -0.12}, {0, 0, -1});
    expect_ray(ray(camera(unit + " scale -1", ""), 0.5, 0.5), {-third, -third, 0}, {0, 0, 1});
    expect_ray(ray(camera(unit, "location <0, 0, 0.06> direction -z"), 0.5, 0.5),
               {third, third, -0.06}, {0, 0, 1});
    expect_ray(ray(camera("triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 1> }", ""), 0.5, 0.5),
               {third, third, third}, {0, half_root2, -half_root2});

    // Faces T(i) at x = i (centroid x = i + 0.1); pixel (x, y) of a 3 x 2 image.
    auto row = [](int mesh, int first, int count) {
        std::string text = "mesh { ";
        for (int i = first; i < first + count; ++i)
            text += "triangle { <" + std::to_string(i) + ", " + std::to_string(mesh) + ", 0>, <" +
                    std::to_string(i) + ".3, " + std::to_string(mesh) + ", 0>, <" +
                    std::to_string(i) + ", " + std::to_string(mesh) + ".3, 0> } ";
        return text + "} ";
    };
    auto face_x = [&](const std::string& mesh_camera, double x, double y) {
        const CameraRay r = ray("camera { mesh_camera { " + mesh_camera + " } }", x, y, 3, 2);
        return r.exists ? r.origin.x - 0.1 : -1.0;
    };
    const std::string two_meshes = row(0, 0, 4) + row(1, 0, 4);
    EXPECT_NEAR(face_x("1 0 " + row(0, 0, 6), 1.5, 1.5), 4, 1e-12);   // pixel 4
    EXPECT_NEAR(face_x("1 0 " + row(0, 0, 4), 1.5, 1.5), -1, 1e-12);  // no face 4: no ray
    EXPECT_NEAR(face_x("2 0 " + two_meshes, 1.75, 0.5), 1, 1e-12);    // ray 1: mesh 1, face 1
    EXPECT_NEAR(face_x("2 1 " + row(0, 0, 3) + row(1, 0, 6), 0.75, 0.5), 3, 1e-12);  // face 6
    EXPECT_NEAR(face_x("1 2 " + two_meshes, 1.5, 1.5), 1, 1e-12);   // block 1 (width 1), face 1
    EXPECT_NEAR(face_x("1 2 " + two_meshes, 2.5, 1.5), -1, 1e-12);  // left over: no ray
}

// The colour moves with the object: a checker on a box translated by one square shows the
// other colour at the same world point; and it is the pigment's, not a mean.
TEST(RenderPatterns, MaterialFollowsThePatternAndTheObject) {
    auto diffuse_at = [](const std::string& text, Vec3 point) {
        const RenderScene scene(parse_scene_text(text, "test.pov"));
        std::optional<Material> scratch;
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
