// Acceptance tests of the renderer against closed-form answers: the furnace (a closed white
// diffuse sphere: the radiance inside is a geometric series), a point light over a plane
// (illuminance I cos(theta) / d^2) and a Lambertian rectangular area light (Lambert's contour
// integral, rayset::analytic::polygon_irradiance). Seeds are fixed; every statistical bound is
// z standard errors of the estimate, z and the confidence it gives stated beside it.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "converters/analytic/analytic_geometry.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

using test::render_text;

// Mean of the red channel over every pixel and its standard error: inside a uniform sphere
// every pixel's samples have the same distribution, so the pixel means are independent and
// identically distributed.
void image_mean(const Film& film, double& mean, double& standard_error) {
    const int n = film.nx() * film.ny();
    double sum = 0, squares = 0;
    for (int y = 0; y < film.ny(); ++y)
        for (int x = 0; x < film.nx(); ++x) {
            const double v = film.mean(x, y).red;
            sum += v, squares += v * v;
        }
    mean = sum / n;
    standard_error = std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1));
    std::printf("image mean %.6g W/(m^2 sr), standard error %.3g\n", mean, standard_error);
}

// z = 4.5: a two-sided normal tail of 6.8e-6 per comparison.
constexpr double kZ = 4.5;

// Every wall point of a closed enclosure seen from inside emits Le and reflects a fraction a of
// the uniform radiance L around it: L = Le + a L, so L = Le / (1 - a) = 0.5 / 0.2 = 2.5
// W/(m^2 sr) (red channel; `enclosure` has diffuse 0.8 and emission 0.5 in red).
void expect_furnace_balance(const std::string& enclosure, uint64_t seed) {
    const double albedo = 0.8, emitted = 0.5;
    RenderSettings settings;
    settings.width = 32, settings.height = 24, settings.passes = 64, settings.seed = seed;
    const RenderResult r =
        render_text("camera { location <0,0,0> look_at <0,0,1> }\n" + enclosure, settings);
    double mean = 0, se = 0;
    image_mean(r.film, mean, se);
    const double expected = emitted / (1 - albedo);
    EXPECT_LT(se, 0.01 * expected);  // the test can tell a 5% error
    EXPECT_NEAR(mean, expected, kZ * se) << "standard error " << se;
}

TEST(RenderFurnace, EmittingWhiteSphereConvergesToGeometricSeries) {
    expect_furnace_balance(
        "sphere { <0,0,0>, 100 pigment { rgb 1 } finish { diffuse 0.8 emission 0.5 ambient 0 } }",
        11);
}

TEST(RenderFurnace, CsgEnclosureWithAPatternKeepsTheBalance) {
    // The same furnace made as CSG: a box with a ball cut out (its inner wall is the ball's
    // surface, normals turned in), a checker whose two colours share the red channel: the
    // pattern and the subtracted part's normals must not change the balance.
    expect_furnace_balance(R"(
        difference {
            box { -120, 120 }
            sphere { <0,0,0>, 100 }
            pigment { checker rgb <1, 0.5, 0.2>, rgb <1, 0.2, 0.6> scale 20 }
            finish { diffuse 0.8 emission 0.5 ambient 0 }
        })",
                           12);
}

TEST(RenderFurnace, BumpedWallsKeepTheBalance) {
    // Normal patterns tilt the shading normal, by noise and down a slope steep enough to tip
    // it past the wall's plane in places: the diffuse lobe still reflects the whole albedo.
    expect_furnace_balance(R"(
        sphere { <0,0,0>, 100
            texture { pigment { rgb 1 } normal { bumps 2 scale 5 }
                      finish { diffuse 0.8 emission 0.5 ambient 0 } }
            texture { pigment { rgbt <1, 1, 1, 0.5> } normal { gradient x 20 scale 7 }
                      finish { diffuse 0.8 emission 0.5 ambient 0 } }
        })",
                           13);
}

TEST(RenderFurnace, PointLightInWhiteSphereMatchesClosedForm) {
    // A point light of intensity I at the centre of a sphere of radius R gives every wall point
    // E0 = I / R^2; each wall point also sees the whole sphere of radiance L, so
    // L = a/pi (E0 + pi L) and L = a I / (pi R^2 (1 - a)). R = 200 mm = 0.2 m, I = 3 W/sr, a = 0.6.
    const double albedo = 0.6, intensity = 3, radius_m = 0.2;
    RenderSettings settings;
    settings.width = 32, settings.height = 24, settings.passes = 64, settings.seed = 5;
    const RenderResult r = render_text(R"(
        camera { location <0,0,0> look_at <0,0,1> }
        light_source { <0,0,0> color rgb 3 }
        sphere { <0,0,0>, 200 pigment { rgb 1 } finish { diffuse 0.6 ambient 0 } }
    )",
                                       settings);
    double mean = 0, se = 0;
    image_mean(r.film, mean, se);
    const double expected = albedo * intensity / (kPi * radius_m * radius_m * (1 - albedo));
    EXPECT_LT(se, 0.01 * expected);
    EXPECT_NEAR(mean, expected, kZ * se) << "standard error " << se;
}

TEST(RenderFurnace, EllipsoidFurnaceHoldsToo) {
    // The closed-surface argument L = Le / (1 - a) needs no sphere: a non-uniformly scaled
    // sphere (an ellipsoid, user geometry under its full matrix) must give the same radiance.
    RenderSettings settings;
    settings.width = 32, settings.height = 24, settings.passes = 64, settings.seed = 3;
    const RenderResult r = render_text(R"(
        camera { location <10,0,0> look_at <0,0,1> }
        sphere { <0,0,0>, 100 scale <3, 1, 0.5> rotate <10, 20, 30>
                 pigment { rgb 1 } finish { diffuse 0.5 emission 1 ambient 0 } }
    )",
                                       settings);
    double mean = 0, se = 0;
    image_mean(r.film, mean, se);
    EXPECT_LT(se, 0.01 * 2.0);
    EXPECT_NEAR(mean, 2.0, kZ * se) << "standard error " << se;
}

TEST(RenderFurnace, MirrorLobeAndGlassKeepTheBalance) {
    // The walls reflect 0.5 diffusely and 0.3 as a mirror: still L = Le / (1 - 0.8). A lossless
    // glass ball (ior 1.5) inside a uniform radiance field changes nothing seen from outside:
    // the eta^2 radiance scaling on entering and leaving cancels.
    RenderSettings settings;
    settings.width = 32, settings.height = 24, settings.passes = 64, settings.seed = 8;
    const RenderResult r = render_text(R"(
        camera { location <0,0,-50> look_at <0,0,0> angle 40 }
        sphere { <0,0,0>, 100 pigment { rgb 1 }
            finish { diffuse 0.5 reflection 0.3 emission 1 ambient 0 } }
        sphere { <0,0,0>, 20 pigment { rgbf <1,1,1,1> } interior { ior 1.5 } }
    )",
                                       settings);
    double mean = 0, se = 0;
    image_mean(r.film, mean, se);
    EXPECT_LT(se, 0.01 * 5.0);
    EXPECT_NEAR(mean, 5.0, kZ * se) << "standard error " << se;
}

TEST(RenderSky, GradientSkyGivesTwoThirdsPiOfItsZenithRadiance) {
    // A sky_sphere of radiance L = y W/(m^2 sr) in every channel (gradient y from black at the
    // horizon to white at the zenith) over an upward receiver: E = integral of cos^2 over the
    // hemisphere = 2 pi / 3 W/m^2 per channel, 683 x 2 pi / 3 lx. The receiver samples cosine-
    // weighted directions, each an estimate pi L of relative spread 0.35: 800 passes leave a
    // standard error of 1.2%, the bound is kZ of it (seed fixed).
    RenderSettings settings;
    settings.render_image = false, settings.passes = 800, settings.seed = 3;
    const RenderResult r = render_text(R"(
        sky_sphere { pigment { gradient y colour_map { [0 rgb 0] [1 rgb 1] } } }
        illuminance_receiver { <0, 0, 0>, <0, 0, 10>, <10, 0, 0> resolution <1, 1> name "ground" }
    )",
                                       settings);
    const double expected = 683 * 2 * kPi / 3;
    const SampleGrid& e = r.receivers.at(0).irradiance;
    EXPECT_NEAR(e.photometric_mean(0, 0), expected, kZ * e.photometric_standard_error(0, 0));
    EXPECT_LT(e.photometric_standard_error(0, 0), 0.02 * expected);
    std::printf("ground %.6g lx +- %.3g, closed form %.6g\n", e.photometric_mean(0, 0),
                e.photometric_standard_error(0, 0), expected);
}

TEST(RenderPointLight, ReceiverOnPlaneRecordsInverseSquareCosine) {
    // Light 1 m above a diffuse floor; a 2 m x 2 m receiver lying on it, facing up
    // (cross(edge1, edge2) = cross(z, x) = +y). Nothing is above the floor, so the illuminance
    // is the direct term alone: E = 683 lm/W * I cos(theta) / d^2 with I = 2 W/sr in every
    // channel (luminance weights sum to 1). Next-event estimation of a point light is exact, so
    // the map's statistical error is zero and the bound is its standard error (0) plus rounding.
    RenderSettings settings;
    settings.render_image = false, settings.passes = 8, settings.seed = 1;
    const RenderResult r = render_text(R"(
        light_source { <100, 1000, -50> color rgb 2 }
        plane { y, 0 pigment { rgb 0.7 } finish { diffuse 1 } }
        illuminance_receiver { <-1000, 0, -1000>, <0, 0, 2000>, <2000, 0, 0>
            resolution <9, 7> name "floor" }
    )",
                                       settings);
    ASSERT_EQ(r.receivers.size(), 1u);
    const ReceiverMap& map = r.receivers[0];
    for (int j = 0; j < 7; ++j)
        for (int i = 0; i < 9; ++i) {
            const Vec3 p = map.cell_centre(i, j);
            const Vec3 to_light = Vec3{100, 1000, -50} - p;
            const double d_m = length(to_light) / 1000, cos_theta = to_light.y / length(to_light);
            const double expected = 683 * 2 * cos_theta / (d_m * d_m);
            EXPECT_NEAR(map.irradiance.photometric_mean(i, j), expected,
                        kZ * map.irradiance.photometric_standard_error(i, j) + 1e-9 * expected)
                << "cell " << i << "," << j;
        }
}

TEST(RenderPointLight, ShadowlessLightPassesThroughObjects) {
    // The receiver of the test above under a black box that covers it: an ordinary light leaves
    // it dark; a shadowless one (POV-Ray's) lights it as if the box were not there, exactly
    // I cos(theta) / d^2 (the box is black, so nothing else reaches the floor).
    auto floor_map = [](const std::string& light) {
        RenderSettings settings;
        settings.render_image = false, settings.passes = 2, settings.seed = 1;
        return render_text(light + R"(
            box { <-1500, 100, -1500>, <1500, 200, 1500> pigment { rgb 0 } }
            plane { y, 0 pigment { rgb 0.7 } finish { diffuse 1 } }
            illuminance_receiver { <-1000, 0, -1000>, <0, 0, 2000>, <2000, 0, 0>
                resolution <5, 4> name "floor" })",
                           settings)
            .receivers.at(0);
    };
    const ReceiverMap dark = floor_map("light_source { <100, 1000, -50> color rgb 2 }");
    const ReceiverMap lit = floor_map("light_source { <100, 1000, -50> color rgb 2 shadowless }");
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 5; ++i) {
            const Vec3 to_light = Vec3{100, 1000, -50} - lit.cell_centre(i, j);
            const double d_m = length(to_light) / 1000, cos_theta = to_light.y / length(to_light);
            EXPECT_EQ(dark.irradiance.photometric_mean(i, j), 0);
            EXPECT_NEAR(lit.irradiance.photometric_mean(i, j), 683 * 2 * cos_theta / (d_m * d_m),
                        1e-9 * 683 * 2);
        }
}

TEST(RenderPointLight, CameraSeesAPlaneWithLambertsLuminance) {
    // A white diffuse plane (albedo 0.7) 1 m from a point light of I = 2 W/sr, seen straight on
    // through a 1 degree camera between them: L = albedo / pi x I / d^2 in every channel
    // (nothing else in the scene, so no interreflection). The same for a plane in POV-Ray's two
    // orientations and for a finite slab in its place: the infinite plane must not differ.
    // Bound: the 1 degree field reaches 4.4 mm off the axis, where cos / d^2 is lower by at
    // most 6e-5 (the image mean by less); a shadow ray lost to self-intersection costs the
    // whole pixel sample (before the fix here, 17% of them on the plane).
    RenderSettings settings;
    settings.width = settings.height = 8, settings.passes = 16, settings.seed = 2;
    const double expected = 0.7 / kPi * 2 / (1.0 * 1.0);
    for (const char* surface :
         {"plane { z, 0 pigment { rgb 0.7 } finish { diffuse 1 } }",
          "plane { -z, 0 pigment { rgb 0.7 } finish { diffuse 1 } }",
          "box { <-100, -100, 0>, <100, 100, 10> pigment { rgb 0.7 } finish { diffuse 1 } }"}) {
        const RenderResult r = render_text(std::string(R"(
            camera { location <0, 0, -500> look_at <0, 0, 0> angle 1 }
            light_source { <0, 0, -1000> color rgb 2 }
        )") + surface,
                                           settings);
        double mean = 0, standard_error = 0;
        image_mean(r.film, mean, standard_error);
        EXPECT_NEAR(mean, expected, kZ * standard_error + 6e-5 * expected) << surface;
    }
}

TEST(RenderPointLight, SpotlightFollowsPovRayFalloff) {
    // POV-Ray's spotlight: full intensity inside `radius`, none beyond `falloff`, a smoothstep
    // in cos(angle) between. Receiver cells straight below (inside radius) get I / d^2, cells
    // beyond the falloff cone nothing.
    RenderSettings settings;
    settings.render_image = false, settings.passes = 2, settings.seed = 1;
    const RenderResult r = render_text(R"(
        light_source { <0, 1000, 0> color rgb 1 spotlight radius 10 falloff 20 point_at <0, 0, 0> }
        illuminance_receiver { <-5, 0, -5>, <0, 0, 10>, <10, 0, 0> resolution <1, 1> name "centre" }
        illuminance_receiver { <995, 0, -5>, <0, 0, 10>, <10, 0, 0>
            resolution <1, 1> name "outside" }
    )",
                                       settings);
    EXPECT_NEAR(r.receivers[0].irradiance.photometric_mean(0, 0), 683.0, 1e-9 * 683);
    EXPECT_EQ(r.receivers[1].irradiance.photometric_mean(0, 0), 0.0);
}

TEST(RenderPointLight, SceneUnitAndFadeFollowTheStatedConventions) {
    // Intensity 1 W/sr, 2 scene units above the receiver: with length_unit "m" that is 2 m,
    // E = 1/4 W/m^2; with "cm", 2 cm, E = 1/0.0004 W/m^2. fade_distance 0.5 fade_power 2 scales
    // the intensity to 2 (0.5 unit)^2 in metres: the far field 2 D^2 / d^2 in W/m^2 whatever
    // the unit.
    auto lux_at = [](const std::string& unit, const std::string& fade) {
        RenderSettings settings;
        settings.render_image = false, settings.passes = 1;
        const RenderResult r = render_text(
            "global_settings { length_unit \"" + unit +
                "\" }\n"
                "light_source { <0, 2, 0> color rgb 1 " +
                fade +
                " }\n"
                "illuminance_receiver { <-0.001, 0, -0.001>, <0, 0, 0.002>, <0.002, 0, 0> "
                "resolution <1, 1> }",
            settings);
        return r.receivers[0].irradiance.photometric_mean(0, 0);
    };
    EXPECT_NEAR(lux_at("m", ""), 683 * 0.25, 1e-9 * 683);
    EXPECT_NEAR(lux_at("cm", ""), 683 / 0.0004, 1e-9 * 683 / 0.0004);
    const double fade_far_field = 683 * 2 * 0.5 * 0.5 / (2 * 2);
    EXPECT_NEAR(lux_at("m", "fade_distance 0.5 fade_power 2"), fade_far_field,
                1e-9 * fade_far_field);
    EXPECT_NEAR(lux_at("mm", "fade_distance 0.5 fade_power 2"), fade_far_field,
                1e-9 * fade_far_field);
}

TEST(RenderAreaLight, LambertianRectangleMatchesContourIntegral) {
    // A 200 mm x 100 mm area light 500 mm above the receiver, a spotlight with POV-Ray's
    // "cosine falloff" (radius -90 falloff 90 tightness 1): its 4 x 4 points of colour 1 emit
    // P = pi W, so the rectangle is a one-sided Lambertian emitter of radiance
    // L = P / (pi A) = 1 / A = 5e-5 W/(mm^2 sr) facing down. The exact irradiance comes from
    // Lambert's contour formula. Light sampling and BSDF sampling are both active (MIS).
    RenderSettings settings;
    settings.render_image = false, settings.passes = 256, settings.seed = 9;
    const RenderResult r = render_text(R"(
        light_source { <0, 500, 0> color rgb 1
            area_light <200, 0, 0>, <0, 0, 100>, 4, 4
            spotlight radius -90 falloff 90 tightness 1 point_at <0, 0, 0> }
        illuminance_receiver { <-600, 0, -600>, <0, 0, 1200>, <1200, 0, 0>
            resolution <6, 6> name "floor" }
    )",
                                       settings);
    const ReceiverMap& map = r.receivers[0];
    const double radiance = 1.0 / (200 * 100);  // W/(mm^2 sr)
    const std::vector<Vec3> light{
        {-100, 500, -50}, {100, 500, -50}, {100, 500, 50}, {-100, 500, 50}};
    // z = 5 with 36 cells: family-wise two-sided normal tail 36 * 5.7e-7 = 2e-5.
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i) {
            const double exact_w_mm2 =
                analytic::polygon_irradiance(radiance, light, map.cell_centre(i, j), {0, 1, 0});
            const double expected = 683 * exact_w_mm2 * 1e6;
            const double se = map.irradiance.photometric_standard_error(i, j);
            EXPECT_LT(se, 0.05 * expected) << "cell " << i << "," << j;
            EXPECT_NEAR(map.irradiance.photometric_mean(i, j), expected, 5 * se)
                << "cell " << i << "," << j;
        }
}

TEST(RenderAreaLight, TwoSidedRectangleEmitsHalfItsPowerEachWay) {
    // A plain (non-spot) area light stands for isotropic points: P = 4 pi c, emitted by both
    // sides of the rectangle (L = P / (2 pi A)). Receivers 400 mm above and below the light at
    // its centre see the same illuminance, and it equals the contour integral.
    RenderSettings settings;
    settings.render_image = false, settings.passes = 256, settings.seed = 2;
    const RenderResult r = render_text(R"(
        light_source { <0, 0, 0> color rgb 1 area_light <100, 0, 0>, <0, 0, 100>, 2, 2 }
        illuminance_receiver { <-1, -400, -1>, <0, 0, 2>, <2, 0, 0> resolution <1, 1> name "below" }
        illuminance_receiver { <-1, 400, -1>, <2, 0, 0>, <0, 0, 2> resolution <1, 1> name "above" }
    )",
                                       settings);
    const double radiance = 4 * kPi / (2 * kPi * 100 * 100);
    const std::vector<Vec3> facing_down{{-50, 0, -50}, {50, 0, -50}, {50, 0, 50}, {-50, 0, 50}};
    const std::vector<Vec3> facing_up{{-50, 0, -50}, {-50, 0, 50}, {50, 0, 50}, {50, 0, -50}};
    const double below =
        683e6 * analytic::polygon_irradiance(radiance, facing_down, {0, -400, 0}, {0, 1, 0});
    const double above =
        683e6 * analytic::polygon_irradiance(radiance, facing_up, {0, 400, 0}, {0, -1, 0});
    EXPECT_NEAR(below, above, 1e-12 * below);
    for (const ReceiverMap& map : r.receivers) {
        const double se = map.irradiance.photometric_standard_error(0, 0);
        EXPECT_NEAR(map.irradiance.photometric_mean(0, 0), below, kZ * se) << map.receiver.name;
    }
}

TEST(RenderAreaLight, CircularLightIsADiscOfItsPower) {
    // A circular area light is the ellipse inscribed in its axes' rectangle: here a disc of
    // radius r = 50 mm, two-sided, of the point lights' power P = 4 pi: L = P / (2 pi^2 r^2).
    // On its axis at height h a facing receiver gets E = pi L r^2 / (r^2 + h^2).
    RenderSettings settings;
    settings.render_image = false, settings.passes = 4096, settings.seed = 4;
    const RenderResult r = render_text(R"(
        light_source { <0, 0, 0> color rgb 1 area_light <100, 0, 0>, <0, 0, 100>, 3, 3 circular }
        illuminance_receiver { <-1, -60, -1>, <0, 0, 2>, <2, 0, 0> resolution <1, 1> name "near" }
        illuminance_receiver { <-1, 400, -1>, <2, 0, 0>, <0, 0, 2> resolution <1, 1> name "far" }
    )",
                                       settings);
    const double radius = 50, radiance = 4 * kPi / (2 * kPi * kPi * radius * radius);
    for (const ReceiverMap& map : r.receivers) {
        const double h = map.receiver.name == "near" ? 60 : 400;
        const double expected =
            683e6 * kPi * radiance * radius * radius / (radius * radius + h * h);
        const double se = map.irradiance.photometric_standard_error(0, 0);
        EXPECT_LT(se, 0.01 * expected) << map.receiver.name;
        EXPECT_NEAR(map.irradiance.photometric_mean(0, 0), expected, kZ * se) << map.receiver.name;
    }
}

TEST(RenderAreaLight, OrientedLightIsASphereOfItsPower) {
    // An oriented area light is a Lambertian sphere of its first axis' diameter (R = 50 mm)
    // emitting the point lights' power P = 4 pi: outside it the illuminance of a facing
    // receiver is P / (4 pi d^2) at any distance d from its centre, as a point's; seen from
    // the camera, the sphere's radiance is L = P / (4 pi^2 R^2).
    RenderSettings settings;
    settings.passes = 4096, settings.seed = 6, settings.width = 9, settings.height = 9;
    const RenderResult r = render_text(R"(
        camera { location <0, 0, -1000> look_at <0, 0, 0> angle 1 }
        light_source { <0, 0, 0> color rgb 1 area_light <100, 0, 0>, <0, 0, 100>, 3, 3
                       circular orient }
        illuminance_receiver { <-1, -70, -1>, <0, 0, 2>, <2, 0, 0> resolution <1, 1> name "70" }
        illuminance_receiver { <-1, 400, -1>, <2, 0, 0>, <0, 0, 2> resolution <1, 1> name "400" }
    )",
                                       settings);
    for (const ReceiverMap& map : r.receivers) {
        const double d = std::stod(map.receiver.name);
        const double expected = 683e6 * 4 * kPi / (4 * kPi * d * d);
        const double se = map.irradiance.photometric_standard_error(0, 0);
        EXPECT_LT(se, 0.01 * expected) << map.receiver.name;
        EXPECT_NEAR(map.irradiance.photometric_mean(0, 0), expected, kZ * se) << map.receiver.name;
    }
    // The camera's 1 degree view at 1 m spans 17 mm: the middle pixel sees only the sphere.
    const double radiance = 4 * kPi / (4 * kPi * kPi * 50 * 50) * 1e6;  // W/(m^2 sr)
    EXPECT_NEAR(r.film.mean(4, 4).red, radiance, 1e-9 * radiance);
}

TEST(RenderAreaLight, OrientedSpotlightIsASphereWithTheSpotsFarField) {
    // An oriented area spotlight of intensity I = 1 W/sr on its axis (full inside 30 degrees,
    // none beyond 60): a sphere (R = 50 mm) of radiance I s(w) / (pi R^2) along each direction
    // w leaving it. 400 mm down its axis, every direction from the sphere to the receiver lies
    // within 7.2 degrees of the axis: E = I / d^2 exactly, as a point spotlight's; at 75 degrees
    // off the axis every one lies beyond the falloff: nothing. Seen from its axis, the sphere
    // has the radiance I / (pi R^2).
    RenderSettings settings;
    settings.passes = 4096, settings.seed = 7, settings.width = 9, settings.height = 9;
    const RenderResult r = render_text(R"(
        camera { location <0, -1000, 0> look_at <0, 0, 0> angle 1 }
        light_source { <0, 0, 0> color rgb 1 spotlight point_at <0, -1000, 0> radius 30
                       falloff 60 tightness 0 area_light <100, 0, 0>, <0, 0, 100>, 3, 3
                       circular orient }
        illuminance_receiver { <-1, -400, -1>, <0, 0, 2>, <2, 0, 0> resolution <1, 1>
                               name "axis" }
        illuminance_receiver { <386.4, -103.5, -1>, <-0.5176, -1.9319, 0>, <0, 0, 2>
                               resolution <1, 1> name "75 degrees" }
    )",
                                       settings);
    const double expected = 683e6 / (400.0 * 400.0);
    const double se = r.receivers[0].irradiance.photometric_standard_error(0, 0);
    EXPECT_LT(se, 0.01 * expected);
    EXPECT_NEAR(r.receivers[0].irradiance.photometric_mean(0, 0), expected, kZ * se);
    EXPECT_EQ(r.receivers[1].irradiance.photometric_mean(0, 0), 0.0);
    const double radiance = 1 / (kPi * 50 * 50) * 1e6;  // W/(m^2 sr)
    EXPECT_NEAR(r.film.mean(4, 4).red, radiance, 1e-9 * radiance);
}

}  // namespace
}  // namespace rayset::tracer
