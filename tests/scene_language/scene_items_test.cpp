// Tests of the scene items that are not objects: camera (every projection, its vectors as
// POV-Ray resolves them, focal blur, mesh_camera, declared cameras), global_settings (every key,
// the radiosity, photons and subsurface blocks), background, fog, rainbow and sky_sphere. Values
// are worked out by hand from the text; where POV-Ray's behaviour is not in its manual, the
// comment says how POV-Ray 3.7.0 was seen to behave (renders or parses of small scenes).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry.h"
#include "scene_language/scene_test_support.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

using namespace scene_test;

Camera camera_of(const std::string& body) { return parse("camera { " + body + " }").camera; }

// ---------------------------------------------------------------- camera

TEST(SceneItemsCamera, DefaultsAsPovRay) {
    const SceneDescription none = parse("");
    EXPECT_FALSE(none.has_camera);
    const Camera c = camera_of("");
    EXPECT_EQ(c.projection, CameraProjection::perspective);
    expect_vec(c.location, {0, 0, 0});
    expect_vec(c.direction, {0, 0, 1});
    expect_vec(c.up, {0, 1, 0});
    expect_vec(c.right, {1.33, 0, 0});
    expect_vec(c.sky, {0, 1, 0});
    EXPECT_EQ(c.angle, 0);
    EXPECT_EQ(c.focal_blur.aperture, 0);
    EXPECT_DOUBLE_EQ(c.focal_blur.confidence, 0.9);
    EXPECT_DOUBLE_EQ(c.focal_blur.variance, 1.0 / 128);
    EXPECT_FALSE(c.normal);
    EXPECT_EQ(c.statement.str(), "test.pov:1:1");
    EXPECT_EQ(c.projection_location.line, 0);
}

TEST(SceneItemsCamera, EveryProjectionKeyword) {
    const std::pair<const char*, CameraProjection> cases[] = {
        {"perspective", CameraProjection::perspective},
        {"orthographic", CameraProjection::orthographic},
        {"fisheye", CameraProjection::fisheye},
        {"ultra_wide_angle", CameraProjection::ultra_wide_angle},
        {"omnimax", CameraProjection::omnimax},
        {"panoramic", CameraProjection::panoramic},
        {"cylinder 3", CameraProjection::cylinder},
        {"spherical", CameraProjection::spherical}};
    for (const auto& [text, projection] : cases) {
        const Camera c = camera_of(text);
        EXPECT_EQ(c.projection, projection) << text;
        EXPECT_EQ(c.projection_location.str(), "test.pov:1:10") << text;
    }
    EXPECT_EQ(camera_of("cylinder 3").cylinder_type, 3);
    EXPECT_EQ(camera_of("cylinder 1.7").cylinder_type, 1);  // truncated, as POV-Ray accepts it
    // A second type keyword before any other item replaces the first (POV-Ray accepts it).
    EXPECT_EQ(camera_of("orthographic fisheye").projection, CameraProjection::fisheye);
    EXPECT_EQ(error_of("camera { cylinder 5 }"),
              "cylinder camera type 5 (expected 1, 2, 3 or 4) "
              "at test.pov:1:19");
    EXPECT_EQ(error_of("camera { cylinder 0 }"),
              "cylinder camera type 0 (expected 1, 2, 3 or 4) "
              "at test.pov:1:19");
    // POV-Ray: "Expected 'perspective camera modifier', orthographic found instead".
    EXPECT_EQ(error_of("camera { location -z orthographic }"),
              "the camera type 'orthographic' must come first in the camera at test.pov:1:22");
}

TEST(SceneItemsCamera, PerspectiveAngle) {
    // |direction| = 0.5 |right| / tan(angle / 2): 0.5 * 1.33 / tan(45 deg).
    Camera c = camera_of("angle 90");
    expect_vec(c.direction, {0, 0, 0.665});
    EXPECT_EQ(c.angle, 90);
    // angle 0 leaves the direction alone (POV-Ray renders it as if no angle were given).
    c = camera_of("direction 2*z angle 0");
    expect_vec(c.direction, {0, 0, 2});
    EXPECT_EQ(c.angle, 0);
    EXPECT_EQ(error_of("camera { angle 180 }"),
              "a perspective camera's angle must be smaller than 180 degrees, found 180 at "
              "test.pov:1:16");
    EXPECT_EQ(error_of("camera { angle -10 }"),
              "the camera's angle must not be negative, found "
              "-10 at test.pov:1:16");
    EXPECT_EQ(error_of("camera { direction 0 angle 60 }"),
              "the camera direction is zero: 'angle' cannot set its length at test.pov:1:28");
    EXPECT_EQ(error_of("camera { location 1 look_at 1 }"),
              "camera location and look_at must "
              "differ at test.pov:1:21");
}

TEST(SceneItemsCamera, OtherProjectionsKeepTheirAngle) {
    // Seen in POV-Ray 3.7 renders: without angle, fisheye, cylinder and ultra_wide_angle cover 90
    // degrees across, spherical 360 by 180.
    EXPECT_EQ(camera_of("fisheye").angle, 90);
    EXPECT_EQ(camera_of("cylinder 1").angle, 90);
    // No limit but for perspective and orthographic.
    EXPECT_EQ(camera_of("fisheye angle 400").angle, 400);
    Camera c = camera_of("spherical");
    EXPECT_EQ(c.angle, 360);
    EXPECT_EQ(c.vertical_angle, 180);
    c = camera_of("spherical angle 90");
    EXPECT_EQ(c.angle, 90);
    EXPECT_EQ(c.vertical_angle, 45);
    EXPECT_EQ(camera_of("spherical angle 100, 30").vertical_angle, 30);
    EXPECT_EQ(camera_of("spherical angle 100 30").vertical_angle, 30);
    // The angle does not change the direction of these projections.
    expect_vec(camera_of("ultra_wide_angle direction 2*z angle 120").direction, {0, 0, 2});
    EXPECT_EQ(error_of("camera { spherical angle 10, -20 }"),
              "the camera's vertical angle must not be negative, found -20 at test.pov:1:30");
    EXPECT_EQ(error_of("camera { fisheye angle -1 }"),
              "the camera's angle must not be negative, "
              "found -1 at test.pov:1:24");
}

TEST(SceneItemsCamera, OrthographicSizeAsPovRayRendersIt) {
    // Without up and right, the area a perspective camera sees at the look_at point: at distance
    // 10 with |direction| 1, right 1.33 * 10 and up 10.
    Camera c = camera_of("orthographic location -10*z look_at 0");
    expect_vec(c.right, {13.3, 0, 0}, 1e-12);
    expect_vec(c.up, {0, 10, 0}, 1e-12);
    // POV-Ray's default look_at is the point <0,0,1>: from -10*z the view is 11 high, from
    // <5,0,-10> sqrt(146) (measured in POV-Ray 3.7 renders: 11.00 and 12.08).
    expect_vec(camera_of("orthographic location -10*z").up, {0, 11, 0}, 1e-12);
    expect_vec(camera_of("orthographic location <5,0,-10>").up, {0, std::sqrt(146.0), 0}, 1e-12);
    // The distance is divided by |direction| (POV-Ray: 5.5 high with direction 2*z).
    expect_vec(camera_of("orthographic location -10*z direction 2*z").up, {0, 5.5, 0}, 1e-12);
    // up or right given: their lengths are the view (the other one from the default camera).
    c = camera_of("orthographic location -10*z look_at 0 right 4*x up 3*y");
    expect_vec(c.right, {4, 0, 0});
    expect_vec(c.up, {0, 3, 0});
    c = camera_of("orthographic location -10*z look_at 0 up 3*y");
    expect_vec(c.right, {1.33, 0, 0});
    // angle brings back the perspective-sized view: |direction| = 0.5 * 4 / tan(45 deg) = 2,
    // scale 10 / 2 (POV-Ray: 20 x 15 units).
    c = camera_of("orthographic location -10*z look_at 0 right 4*x up 3*y angle 90");
    expect_vec(c.right, {20, 0, 0}, 1e-12);
    expect_vec(c.up, {0, 15, 0}, 1e-12);
    // angle without a value: the same mode with the direction as it is (POV-Ray: 40 x 30).
    c = camera_of("orthographic location -10*z look_at 0 right 4*x up 3*y angle");
    expect_vec(c.right, {40, 0, 0}, 1e-12);
    expect_vec(c.up, {0, 30, 0}, 1e-12);
    EXPECT_EQ(error_of("camera { orthographic angle 180 }"),
              "an orthographic camera's angle must be smaller than 180 degrees, found 180 at "
              "test.pov:1:29");
}

TEST(SceneItemsCamera, FocalBlur) {
    Camera c = camera_of(
        "aperture 0.5 blur_samples 3, 10 focal_point <0,0,5> confidence 0.95 "
        "variance 1/1000");
    EXPECT_EQ(c.focal_blur.aperture, 0.5);
    EXPECT_EQ(c.focal_blur.min_samples, 3);
    EXPECT_EQ(c.focal_blur.max_samples, 10);
    expect_vec(c.focal_blur.focal_point, {0, 0, 5});
    EXPECT_EQ(c.focal_blur.confidence, 0.95);
    EXPECT_EQ(c.focal_blur.variance, 0.001);
    EXPECT_EQ(c.focal_blur_location.str(), "test.pov:1:10");
    // POV-Ray's minimum: 4 below 7 samples, else 7; the comma is optional.
    EXPECT_EQ(camera_of("blur_samples 5").focal_blur.min_samples, 4);
    EXPECT_EQ(camera_of("blur_samples 20").focal_blur.min_samples, 7);
    EXPECT_EQ(camera_of("blur_samples 3").focal_blur.min_samples, 3);
    EXPECT_EQ(camera_of("blur_samples 2 9").focal_blur.min_samples, 2);
    // The focal point moves with the camera (a POV-Ray render is sharp at the moved point).
    expect_vec(camera_of("focal_point <0,0,5> translate -5*z").focal_blur.focal_point, {0, 0, 0});
    // variance 1 means the default, with a warning (POV-Ray's manual).
    EXPECT_DOUBLE_EQ(camera_of("variance 1").focal_blur.variance, 1.0 / 128);
    EXPECT_EQ(warnings_of("camera { variance 1 }"),
              std::vector<std::string>{"test.pov:1:10: warning: focal blur variance 1 replaced by "
                                       "the default 1/128\n"});
    c = camera_of("aperture 1 blur_samples 5 bokeh { pigment { rgb <1, 0.5, 0> } }");
    ASSERT_TRUE(c.focal_blur.bokeh);
    EXPECT_FALSE(camera_of("bokeh { }").focal_blur.bokeh);
    EXPECT_EQ(error_of("camera { blur_samples 0 }"),
              "expected an integer >= 1 after "
              "'blur_samples', found 0 at test.pov:1:23");
    EXPECT_EQ(error_of("camera { blur_samples 10, 5 }"),
              "blur_samples: the minimum 10 is larger than the maximum 5 at test.pov:1:23");
    EXPECT_EQ(error_of("camera { bokeh { rgb 1 } }"),
              "expected pigment or '}' to close 'bokeh' opened at test.pov:1:16, found 'rgb' at "
              "test.pov:1:18");
}

TEST(SceneItemsCamera, MeshCamera) {
    // Each mesh is read as an ordinary mesh object, here written inline (POV-Ray accepts both that
    // and `mesh { DECLARED_MESH transforms }`).
    const std::string m = "mesh { triangle { 0, x, y } }";
    Camera c = parse("camera { mesh_camera { 2 1 100 mesh { triangle { 0, x, y } translate x } " +
                     m + " } location -0.01*z }")
                   .camera;
    EXPECT_EQ(c.projection, CameraProjection::mesh);
    EXPECT_EQ(c.mesh.rays_per_pixel, 2);
    EXPECT_EQ(c.mesh.distribution, 1);
    EXPECT_EQ(c.mesh.max_distance, 100);
    EXPECT_EQ(c.mesh.meshes.size(), 2u);
    EXPECT_FALSE(c.mesh.smooth);
    expect_vec(c.location, {0, 0, -0.01});
    c = parse("camera { mesh_camera { 1 3 " + m + " smooth } }").camera;
    EXPECT_TRUE(c.mesh.smooth);
    EXPECT_EQ(c.mesh.max_distance, 0);
    // POV-Ray's checks (its messages: "Rays per pixel may not be 0", "Unrecognized distribution
    // method", "Rays per pixel must be <= number of meshes for distribution method #0", ...).
    EXPECT_EQ(error_of("camera { mesh_camera { 0 0 " + m + " } }"),
              "expected an integer >= 1 as the mesh_camera's rays per pixel, found 0 at "
              "test.pov:1:24");
    EXPECT_EQ(error_of("camera { mesh_camera { 1 4 " + m + " } }"),
              "unknown mesh_camera distribution 4 (expected 0, 1, 2 or 3) at test.pov:1:26");
    EXPECT_EQ(error_of("camera { mesh_camera { 1 0 } }"),
              "expected a mesh or mesh2 in the mesh_camera, found '}' at test.pov:1:28");
    EXPECT_EQ(error_of("camera { mesh_camera { 1 0 sphere { 0, 1 } } }"),
              "expected mesh, mesh2, smooth or '}' to close 'mesh_camera' opened at test.pov:1:22, "
              "found 'sphere' at test.pov:1:28");
    EXPECT_EQ(error_of("camera { mesh_camera { 2 0 " + m + " } }"),
              "mesh_camera distribution 0 takes at most one ray per pixel per mesh: 2 rays per "
              "pixel, 1 meshes at test.pov:1:24");
    EXPECT_EQ(error_of("camera { mesh_camera { 2 2 " + m + " " + m + " } }"),
              "mesh_camera distribution 2 takes 1 ray per pixel, found 2 at test.pov:1:24");
    // column 58: after "camera { mesh_camera { 1 0 " (27 characters) and the 30 of the mesh.
    EXPECT_EQ(error_of("camera { mesh_camera { 1 0 " + m + " smooth } }"),
              "'smooth' needs mesh_camera distribution 3, found 0 at test.pov:1:58");
    EXPECT_EQ(error_of("camera { mesh_camera { 1 0 " + m + " } angle 30 }"),
              "'angle' does not apply to a mesh_camera (its rays come from the mesh faces) at "
              "test.pov:1:60");
}

TEST(SceneItemsCamera, DeclaredCameraTakesTransformsOnly) {
    const SceneDescription s = parse(R"(
#declare Cam = camera { orthographic location -10*z look_at 0 aperture 0.2 focal_point <0,0,1> }
camera { Cam translate <1, 2, 3> })");
    EXPECT_EQ(s.camera.projection, CameraProjection::orthographic);
    expect_vec(s.camera.location, {1, 2, -7});
    expect_vec(s.camera.right, {13.3, 0, 0}, 1e-12);
    expect_vec(s.camera.focal_blur.focal_point, {1, 2, 4});
    expect_vec(s.camera.transform.point({0, 0, 0}), {1, 2, 3});
    EXPECT_EQ(s.camera.statement.str(), "test.pov:3:1");
    EXPECT_EQ(s.camera.projection_location.str(), "test.pov:2:25");
    // POV-Ray: "No matching } in 'camera', location found instead".
    EXPECT_EQ(error_of("#declare Cam = camera { }\ncamera { Cam location 0 }"),
              "expected a transform or '}' to close 'camera' opened at test.pov:2:8 (a declared "
              "camera takes transforms only), found 'location' at test.pov:2:14");
    // The last camera statement is the scene's.
    const SceneDescription two = parse("camera { location -z } camera { location -2*z }");
    expect_vec(two.camera.location, {0, 0, -2});
}

// Needs the appearance grammar's normal patterns.
TEST(SceneItemsCamera, NormalPerturbation) {
    const Camera c = camera_of("location -5*z normal { bumps 0.5 scale 0.1 }");
    EXPECT_TRUE(c.normal);
    EXPECT_EQ(c.normal_location.str(), "test.pov:1:24");
}

// ---------------------------------------------------------------- global_settings

TEST(SceneItemsGlobalSettings, DefaultsAsPovRayManual) {
    const GlobalSettings g = parse("").global;
    EXPECT_DOUBLE_EQ(g.adc_bailout, 1.0 / 255);
    EXPECT_EQ(g.ambient_light.red, 1);
    EXPECT_EQ(g.assumed_gamma, 1.0);
    EXPECT_FALSE(g.assumed_gamma_set);
    EXPECT_EQ(g.charset, Charset::ascii);
    EXPECT_EQ(g.irid_wavelength.red, 0.25);
    EXPECT_EQ(g.irid_wavelength.green, 0.18);
    EXPECT_EQ(g.irid_wavelength.blue, 0.14);
    EXPECT_EQ(g.max_intersections, 64);
    EXPECT_EQ(g.max_trace_level, 5);
    EXPECT_EQ(g.mm_per_unit, 10);
    EXPECT_EQ(g.number_of_waves, 10);
    EXPECT_EQ(g.noise_generator, 2);
    EXPECT_FALSE(g.radiosity);
    EXPECT_FALSE(g.photons);
    EXPECT_FALSE(g.subsurface);
}

TEST(SceneItemsGlobalSettings, EveryKey) {
    const GlobalSettings g = parse(R"(
global_settings { adc_bailout 0.01 ambient_light rgb <0.5, 0.25, 1> assumed_gamma 2.2 charset utf8
  irid_wavelength rgb <0.7, 0.52, 0.48> max_intersections 128 max_trace_level 12.9 mm_per_unit 25.4
  number_of_waves 4 noise_generator 3 }
global_settings { max_intersections 200 })")
                                 .global;
    EXPECT_EQ(g.adc_bailout, 0.01);
    EXPECT_EQ(g.ambient_light.green, 0.25);
    EXPECT_EQ(g.assumed_gamma, 2.2);
    EXPECT_TRUE(g.assumed_gamma_set);
    EXPECT_EQ(g.charset, Charset::utf8);
    EXPECT_FLOAT_EQ(g.irid_wavelength.blue, 0.48);
    EXPECT_EQ(g.max_intersections, 200);  // a later statement replaces the key, keeps the others
    EXPECT_EQ(g.max_trace_level, 12);     // truncated, as POV-Ray does
    EXPECT_EQ(g.mm_per_unit, 25.4);
    EXPECT_EQ(g.number_of_waves, 4);
    EXPECT_EQ(g.noise_generator, 3);
    const GlobalSettings srgb = parse("global_settings { assumed_gamma srgb charset sys }").global;
    EXPECT_TRUE(srgb.assumed_gamma_srgb);
    EXPECT_TRUE(srgb.assumed_gamma_set);
    EXPECT_EQ(srgb.charset, Charset::sys);
    // POV-Ray accepts 0 (and values over its 256 limit).
    EXPECT_EQ(parse("global_settings { max_trace_level 0 }").global.max_trace_level, 0);
    EXPECT_EQ(warnings_of("global_settings { hf_gray_16 on }"),
              std::vector<std::string>{
                  "test.pov:1:19: warning: hf_gray_16 is deprecated in POV-Ray 3.7 and has no "
                  "effect\n"});
}

TEST(SceneItemsGlobalSettings, Errors) {
    EXPECT_EQ(error_of("global_settings { noise_generator 4 }"),
              "global_settings noise_generator must be in [1, 3], found 4 at test.pov:1:35");
    EXPECT_EQ(error_of("global_settings { assumed_gamma 0 }"),
              "assumed_gamma must be positive, "
              "found 0 at test.pov:1:33");
    EXPECT_EQ(error_of("global_settings { charset latin1 }"),
              "expected ascii, utf8 or sys after 'charset', found 'latin1' at test.pov:1:27");
    EXPECT_EQ(error_of("global_settings { max_trace_level 1e12 }"),
              "global_settings max_trace_level must be a whole number of at most 10 digits, found "
              "1000000000000 at test.pov:1:35");
    EXPECT_EQ(error_of("global_settings { photon { } }"),
              "unknown identifier 'photon' (expected a global setting or '}' to close "
              "'global_settings' opened at test.pov:1:17) at test.pov:1:19");
}

TEST(SceneItemsGlobalSettings, RadiosityEveryKey) {
    const GlobalSettings empty = parse("global_settings { radiosity { } }").global;
    ASSERT_TRUE(empty.radiosity);
    const RadiositySettings defaults;
    EXPECT_EQ(empty.radiosity->count, 35);
    EXPECT_EQ(defaults.error_bound, 1.8);
    EXPECT_EQ(defaults.nearest_count, 5);
    EXPECT_EQ(defaults.pretrace_start, 0.08);
    EXPECT_EQ(defaults.pretrace_end, 0.04);
    EXPECT_EQ(defaults.recursion_limit, 2);
    const GlobalSettings g = parse(R"(global_settings { radiosity {
  adc_bailout 0.005 always_sample on brightness 1.5 count 100, 1000 error_bound 0.5
  gray_threshold 0.3
  low_error_factor 0.4 max_sample 2 maximum_reuse 0.3 minimum_reuse 0.01 nearest_count 8 4 normal on
  media on subsurface off pretrace_start 0.1 pretrace_end 0.02 recursion_limit 3
  save_file "a.rad" load_file "b.rad" } })")
                                 .global;
    const RadiositySettings& r = *g.radiosity;
    EXPECT_EQ(r.adc_bailout, 0.005);
    EXPECT_TRUE(r.always_sample);
    EXPECT_EQ(r.brightness, 1.5);
    EXPECT_EQ(r.count, 100);
    EXPECT_EQ(r.direction_pool, 1000);
    EXPECT_EQ(r.error_bound, 0.5);
    EXPECT_EQ(r.gray_threshold, 0.3);
    EXPECT_EQ(r.low_error_factor, 0.4);
    EXPECT_EQ(r.max_sample, 2);
    EXPECT_EQ(r.maximum_reuse, 0.3);
    EXPECT_EQ(r.minimum_reuse, 0.01);
    EXPECT_EQ(r.nearest_count, 8);
    EXPECT_EQ(r.adaptive_nearest_count, 4);
    EXPECT_TRUE(r.normal);
    EXPECT_TRUE(r.media);
    EXPECT_FALSE(r.subsurface);
    EXPECT_EQ(r.pretrace_start, 0.1);
    EXPECT_EQ(r.pretrace_end, 0.02);
    EXPECT_EQ(r.recursion_limit, 3);
    EXPECT_EQ(r.save_file, "a.rad");
    EXPECT_EQ(r.load_file, "b.rad");
    // A second block goes on from the first.
    const GlobalSettings twice =
        parse(
            "global_settings { radiosity { count 50 } } global_settings { radiosity { brightness "
            "2 } }")
            .global;
    EXPECT_EQ(twice.radiosity->count, 50);
    EXPECT_EQ(twice.radiosity->brightness, 2);
    EXPECT_EQ(warnings_of("global_settings { radiosity { minimum_reuse 0.15 } }"),
              std::vector<std::string>{
                  "test.pov:1:19: warning: radiosity maximum_reuse should be at least twice "
                  "minimum_reuse\n"});
}

TEST(SceneItemsGlobalSettings, RadiosityErrorsAsPovRay) {
    auto radiosity_error = [](const std::string& items) {
        return error_of("global_settings { radiosity { " + items + " } }");
    };
    EXPECT_EQ(radiosity_error("count 0"),
              "expected an integer >= 1 after 'count', found 0 at "
              "test.pov:1:37");
    EXPECT_EQ(radiosity_error("count 10, 5"),
              "radiosity count 10 is larger than its direction "
              "pool 5 at test.pov:1:41");
    EXPECT_EQ(radiosity_error("nearest_count 25"),
              "radiosity nearest_count must be in [1, 20], found 25 at test.pov:1:45");
    EXPECT_EQ(radiosity_error("nearest_count 5, 10"),
              "radiosity nearest_count's adaptive pretrace value must be in [0, 5), found 10 at "
              "test.pov:1:48");
    EXPECT_EQ(radiosity_error("recursion_limit 30"),
              "radiosity recursion_limit must be in [1, 20], found 30 at test.pov:1:47");
    EXPECT_EQ(radiosity_error("pretrace_start 2"),
              "radiosity pretrace_start must be in (0, 1], found 2 at test.pov:1:46");
    EXPECT_EQ(radiosity_error("pretrace_end 0"),
              "radiosity pretrace_end must be in (0, 1], found "
              "0 at test.pov:1:44");
    EXPECT_EQ(radiosity_error("error_bound 0"),
              "radiosity error_bound must be > 0, found 0 at "
              "test.pov:1:43");
    EXPECT_EQ(radiosity_error("brightness -1"),
              "radiosity brightness must be > 0, found -1 at "
              "test.pov:1:42");
    EXPECT_EQ(radiosity_error("gray_threshold 2"),
              "radiosity gray_threshold must be in [0, 1], found 2 at test.pov:1:46");
    // A boolean here needs its value (POV-Ray: "Expected 'numeric expression', } found instead").
    EXPECT_EQ(radiosity_error("always_sample"),
              "expected a numeric expression, found '}' at test.pov:1:45");
    // POV-Ray checks the pair when the block is read ("maximum_reuse must be larger than
    // minimum_reuse").
    EXPECT_EQ(radiosity_error("minimum_reuse 0.3 maximum_reuse 0.2"),
              "radiosity maximum_reuse 0.2 must be larger than minimum_reuse 0.3 at test.pov:1:19");
    // importance belongs to objects and #default, not to global_settings.
    EXPECT_EQ(radiosity_error("importance 0.5"),
              "expected a radiosity setting or '}' to close 'radiosity' opened at test.pov:1:29, "
              "found 'importance' at test.pov:1:31");
}

TEST(SceneItemsGlobalSettings, PhotonsEveryKey) {
    const GlobalSettings empty = parse("global_settings { photons { } }").global;
    ASSERT_TRUE(empty.photons);
    EXPECT_EQ(empty.photons->gather_min, 20);
    EXPECT_EQ(empty.photons->gather_max, 100);
    EXPECT_EQ(empty.photons->jitter, 0.4);
    EXPECT_EQ(empty.photons->expand_increase, 0.2);
    EXPECT_EQ(empty.photons->expand_min, 40);
    EXPECT_FALSE(empty.photons->max_trace_level);
    EXPECT_FALSE(empty.photons->autostop);
    const PhotonSettings p = *parse(R"(global_settings { photons {
  spacing 0.02 count 20000 gather 10, 50 media 100, 2 jitter 0.3 max_trace_level 4 adc_bailout 0.1
  save_file "p.ph" autostop 0.5 expand_thresholds 0.3, 30 radius 1, 2, 3, 4 } })")
                                  .global.photons;
    EXPECT_EQ(p.spacing, 0.02);
    EXPECT_EQ(p.count, 20000);
    EXPECT_EQ(p.gather_min, 10);
    EXPECT_EQ(p.gather_max, 50);
    EXPECT_EQ(p.media_max_steps, 100);
    EXPECT_EQ(p.media_factor, 2);
    EXPECT_EQ(p.jitter, 0.3);
    EXPECT_EQ(p.max_trace_level, 4);
    EXPECT_EQ(p.adc_bailout, 0.1);
    EXPECT_EQ(p.save_file, "p.ph");
    EXPECT_EQ(p.autostop, 0.5);
    EXPECT_EQ(p.expand_increase, 0.3);
    EXPECT_EQ(p.expand_min, 30);
    EXPECT_EQ(p.radius, 1);
    EXPECT_EQ(p.radius_multiplier, 2);
    EXPECT_EQ(p.media_radius, 3);
    EXPECT_EQ(p.media_radius_multiplier, 4);
    // radius: a comma keeps an empty place (POV-Ray's `radius ,0.5`).
    const PhotonSettings r =
        *parse("global_settings { photons { radius ,0.5,,3 count 10 } }").global.photons;
    EXPECT_EQ(r.radius, 0);
    EXPECT_EQ(r.radius_multiplier, 0.5);
    EXPECT_EQ(r.media_radius, 0);
    EXPECT_EQ(r.media_radius_multiplier, 3);
    EXPECT_EQ(r.count, 10);
    // Both files: POV-Ray loads, with a warning.
    const std::string both = "global_settings { photons { save_file \"a\" load_file \"b\" } }";
    EXPECT_EQ(parse(both).global.photons->save_file, "");
    EXPECT_EQ(warnings_of(both),
              std::vector<std::string>{"test.pov:1:19: warning: photons: both save_file and "
                                       "load_file given; the map is loaded (as POV-Ray does)\n"});
    EXPECT_EQ(error_of("global_settings { photons { gather 100, 20 } }"),
              "photons gather: the minimum 100 must be less than the maximum 20 at test.pov:1:36");
    EXPECT_EQ(error_of("global_settings { photons { gather 20 } }"),
              "expected a numeric expression, found '}' at test.pov:1:39");
}

TEST(SceneItemsGlobalSettings, Subsurface) {
    const GlobalSettings empty = parse("global_settings { subsurface { } }").global;
    ASSERT_TRUE(empty.subsurface);
    EXPECT_EQ(empty.subsurface->diffuse_samples, 50);
    EXPECT_EQ(empty.subsurface->single_samples, 50);
    EXPECT_FALSE(empty.subsurface->radiosity);
    const SubsurfaceSettings s = *parse(
                                      "global_settings { subsurface { samples 10, 20 radiosity "
                                      "on } }")
                                      .global.subsurface;
    EXPECT_EQ(s.diffuse_samples, 10);
    EXPECT_EQ(s.single_samples, 20);
    EXPECT_TRUE(s.radiosity);
    EXPECT_EQ(error_of("global_settings { subsurface { samples 10 } }"),
              "expected a numeric expression, found '}' at test.pov:1:43");
}

// ---------------------------------------------------------------- background and atmosphere

TEST(SceneItemsAtmosphere, Background) {
    // Each background replaces the last; an empty one is black (POV-Ray renders it so).
    EXPECT_EQ(parse("background { rgb <0.5, 0.25, 1> } background { }").background.blue, 0);
    const Colour c = parse("background { rgb <0.5, 0.25, 1> } background { red 0.1 }").background;
    EXPECT_FLOAT_EQ(c.red, 0.1);
    EXPECT_EQ(c.green, 0);
}

TEST(SceneItemsAtmosphere, FogKeysAndDefaults) {
    const Fog defaults = parse("fog { }").atmosphere.fogs.at(0);
    EXPECT_EQ(defaults.fog_type, 1);
    EXPECT_EQ(defaults.octaves, 6);
    EXPECT_EQ(defaults.omega, 0.5);
    EXPECT_EQ(defaults.lambda, 2.0);
    EXPECT_EQ(defaults.turb_depth, 0.5);
    expect_vec(defaults.up, {0, 1, 0});
    EXPECT_EQ(defaults.location.str(), "test.pov:1:1");
    const Fog f = parse(R"(fog { fog_type 2 distance 150 rgbf <0.5, 0.6, 0.7, 0.2> turbulence 0.5
  octaves 3
  omega 0.3 lambda 3 turb_depth 0.2 fog_offset 25 fog_alt 1.5 })")
                      .atmosphere.fogs.at(0);
    EXPECT_EQ(f.fog_type, 2);
    EXPECT_EQ(f.distance, 150);
    EXPECT_FLOAT_EQ(f.colour.green, 0.6);
    EXPECT_FLOAT_EQ(f.colour.filter, 0.2);
    expect_vec(f.turbulence, {0.5, 0.5, 0.5});
    EXPECT_EQ(f.octaves, 3);
    EXPECT_EQ(f.omega, 0.3);
    EXPECT_EQ(f.lambda, 3);
    EXPECT_EQ(f.turb_depth, 0.2);
    EXPECT_EQ(f.fog_offset, 25);
    EXPECT_EQ(f.fog_alt, 1.5);
    // POV-Ray renders fog_type 2.7 as ground fog and 3 or 0 as constant fog.
    EXPECT_EQ(parse("fog { fog_type 2.7 }").atmosphere.fogs.at(0).fog_type, 2);
    EXPECT_EQ(parse("fog { fog_type 3 }").atmosphere.fogs.at(0).fog_type, 1);
    EXPECT_EQ(parse("fog { fog_type 0 }").atmosphere.fogs.at(0).fog_type, 1);
    // Fogs are layered.
    EXPECT_EQ(parse("fog { distance 1 } fog { distance 2 }").atmosphere.fogs.size(), 2u);
}

TEST(SceneItemsAtmosphere, FogUpTurnsWithTheTransformsBeforeIt) {
    // In POV-Ray 3.7 renders of a ground fog, `rotate -90*z up y` thins along y and
    // `up y rotate -90*z` along x; translate leaves up alone; `up 2*y` renders as `up y`.
    auto up_of = [](const std::string& items) {
        return parse("fog { " + items + " }").atmosphere.fogs.at(0).up;
    };
    expect_vec(up_of("rotate -90*z up y"), {0, 1, 0});
    expect_vec(up_of("up y rotate -90*z"), {1, 0, 0}, 1e-15);
    expect_vec(up_of("up y translate 3*y"), {0, 1, 0});
    expect_vec(up_of("up 2*y"), {0, 1, 0});
    const Fog f = parse("fog { translate <1, 2, 3> scale 2 }").atmosphere.fogs.at(0);
    expect_vec(f.transform.point({0, 0, 0}), {2, 4, 6});
}

TEST(SceneItemsAtmosphere, FogIdentifier) {
    const SceneDescription s = parse(
        "#declare F = fog { distance 10 rgb 1 up x }\nfog { F "
        "fog_type 2 rotate 90*z }");
    const Fog& f = s.atmosphere.fogs.at(0);
    EXPECT_EQ(f.distance, 10);
    EXPECT_EQ(f.fog_type, 2);
    expect_vec(f.up, {0, 1, 0}, 1e-15);  // rotate 90*z takes +x to +y
    EXPECT_EQ(f.location.str(), "test.pov:2:1");
    EXPECT_EQ(error_of("fog { fog_offset 1 spacing 2 }"),
              "expected a fog keyword, a colour or '}' to close 'fog' opened at test.pov:1:5, "
              "found 'spacing' at test.pov:1:20");
}

TEST(SceneItemsAtmosphere, RainbowKeysAndChecks) {
    const Rainbow r = parse(R"(rainbow { direction <0, 0, 1> angle 42.5 width 5 distance 1000
  jitter 0.01
  up <0, 1, 0> arc_angle 120 falloff_angle 30 })")
                          .atmosphere.rainbows.at(0);
    expect_vec(r.direction, {0, 0, 1});
    EXPECT_EQ(r.angle, 42.5);
    EXPECT_EQ(r.width, 5);
    EXPECT_EQ(r.distance, 1000);
    EXPECT_EQ(r.jitter, 0.01);
    EXPECT_EQ(r.arc_angle, 120);
    EXPECT_EQ(r.falloff_angle, 30);
    EXPECT_FALSE(r.colour_map.item);
    const Rainbow defaults = parse("rainbow { direction z }").atmosphere.rainbows.at(0);
    EXPECT_EQ(defaults.arc_angle, 180);
    EXPECT_EQ(defaults.falloff_angle, 180);
    EXPECT_EQ(defaults.jitter, 0);
    expect_vec(defaults.up, {0, 1, 0});
    // Identifiers take further keys; rainbows add up.
    const SceneDescription s = parse(
        "#declare R = rainbow { direction z angle 40 }\nrainbow { R "
        "width 3 } rainbow { R }");
    ASSERT_EQ(s.atmosphere.rainbows.size(), 2u);
    EXPECT_EQ(s.atmosphere.rainbows[0].angle, 40);
    EXPECT_EQ(s.atmosphere.rainbows[0].width, 3);
    EXPECT_EQ(s.atmosphere.rainbows[1].location.str(), "test.pov:2:23");
    // POV-Ray's checks ("Rainbow's direction vector is zero.", "Rainbow's up and direction vector
    // are co-linear.", "Illegal arc angle in rainbow", "Arc angle is smaller than falloff angle").
    EXPECT_EQ(error_of("rainbow { }"),
              "the rainbow's direction is zero (or not given) at "
              "test.pov:1:1");
    EXPECT_EQ(error_of("rainbow { direction z up 0 }"),
              "the rainbow's up vector is zero at "
              "test.pov:1:1");
    EXPECT_EQ(error_of("rainbow { direction z up -2*z }"),
              "the rainbow's up and direction vectors are parallel at test.pov:1:1");
    EXPECT_EQ(error_of("rainbow { direction z arc_angle 400 }"),
              "the rainbow's arc_angle must be in [0, 360] degrees, found 400 at test.pov:1:1");
    EXPECT_EQ(error_of("rainbow { direction z falloff_angle -10 }"),
              "the rainbow's falloff_angle must be in [0, 360] degrees, found -10 at test.pov:1:1");
    EXPECT_EQ(error_of("rainbow { direction z arc_angle 100 falloff_angle 120 }"),
              "the rainbow's falloff_angle 120 is larger than its arc_angle 100 at test.pov:1:1");
    // No transforms and no colour in a rainbow (POV-Ray: "No matching } in 'rainbow', rotate
    // found").
    EXPECT_EQ(error_of("rainbow { direction z rotate x }"),
              "expected a rainbow keyword or '}' to close 'rainbow' opened at test.pov:1:9, found "
              "'rotate' at test.pov:1:23");
}

// Needs the appearance grammar's colour maps and media.
TEST(SceneItemsAtmosphere, RainbowColourMapAndAtmosphericMedia) {
    const SceneDescription s = parse(R"(
rainbow { direction z angle 42 width 5
  color_map { [0 rgbt <1, 0, 0, 0.5>] [1 rgbt <0, 0, 1, 0.5>] } }
media { scattering { 1, 0.1 } }
media { absorption 1 })");
    EXPECT_TRUE(s.atmosphere.rainbows.at(0).colour_map.item);
    ASSERT_EQ(s.atmosphere.media.size(), 2u);
    EXPECT_TRUE(s.atmosphere.media[1].media);
    EXPECT_EQ(s.atmosphere.media[1].location.str(), "test.pov:5:1");
}

TEST(SceneItemsAtmosphere, SkySphere) {
    const SceneDescription s = parse(R"(
sky_sphere { pigment { rgb <1, 0, 0> } }
sky_sphere { rotate 90*y pigment { rgb <0, 0, 1> } pigment { rgbt <0, 1, 0, 0.5> }
  emission rgb <0.8, 0.8, 1> translate y })");
    ASSERT_TRUE(s.atmosphere.sky_sphere);
    // The last sky sphere replaces the first (POV-Ray renders it so).
    const SkySphere& sky = *s.atmosphere.sky_sphere;
    ASSERT_EQ(sky.pigments.size(), 2u);
    EXPECT_EQ(sky.pigments[0]->colour.blue, 1);
    EXPECT_EQ(sky.pigments[1]->colour.transmit, 0.5);
    EXPECT_FLOAT_EQ(sky.emission.red, 0.8);
    // The transforms apply to the whole sky, before or after the pigments (POV-Ray renders
    // `rotate 90*y` the same in both places): +z turns to +x, then moves up 1.
    expect_vec(sky.transform.point({0, 0, 1}), {1, 1, 0}, 1e-15);
    EXPECT_EQ(sky.location.str(), "test.pov:3:1");
    const SceneDescription bright = parse("sky_sphere { pigment { rgb 1 } emission 2 }");
    EXPECT_EQ(bright.atmosphere.sky_sphere->emission.green, 2);
    // A declared sky sphere takes more layers and transforms.
    const SceneDescription layered = parse(
        "#declare S = sky_sphere { pigment { rgb 1 } scale 2 }\nsky_sphere { S pigment { "
        "rgbt 0.5 } }");
    EXPECT_EQ(layered.atmosphere.sky_sphere->pigments.size(), 2u);
    expect_vec(layered.atmosphere.sky_sphere->transform.point({1, 1, 1}), {2, 2, 2});
    // POV-Ray: "Empty sky_sphere statement."
    EXPECT_EQ(error_of("sky_sphere { rotate y }"), "the sky_sphere has no pigment at test.pov:1:1");
}

}  // namespace
}  // namespace rayset::tracer
