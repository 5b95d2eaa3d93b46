// What fills objects (interior_media.h): POV-Ray's fade as Beer-Lambert absorption in both
// integrators, and homogeneous media in the path integrator (transmittance, emission, single
// scattering, energy) against closed forms; the phase functions against their definitions.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/random.h"
#include "tracer/render/phase_function.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

constexpr double kZ = 4.5;

using test::render_text;

// Mean of the image's pixels in one channel (0 red, 1 green, 2 blue) and its standard error
// from the pixels' spread.
void image_mean(const Film& film, int channel, double& mean, double& standard_error) {
    const int n = film.nx() * film.ny();
    double sum = 0, squares = 0;
    for (int y = 0; y < film.ny(); ++y)
        for (int x = 0; x < film.nx(); ++x) {
            const Rgb c = film.mean(x, y);
            const double v = channel == 0 ? c.red : channel == 1 ? c.green : c.blue;
            sum += v, squares += v * v;
        }
    mean = sum / n;
    standard_error = std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1));
}

// An orthographic camera looking along +z at an emitting wall (radiance `wall` in POV-Ray's
// colour scale) at z = 10 through `object` (which lies between).
std::string wall_behind(const std::string& object, const std::string& wall = "rgb 1") {
    return "global_settings { length_unit \"m\" }\n"
           "camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right x up y }\n"
           "plane { z, 10 pigment { " +
           wall + " } finish { ambient 0 diffuse 0 emission 1 } }\n" + object + "\n";
}

// Fade in a glass slab 2 units thick (ior 1.5) seen at normal incidence against a wall of
// radiance 1: Fresnel reflectance R = 0.04 at each face, transmittance T through the slab
// once, so L = (1 - R)^2 T / (1 - R^2 T^2) (the light reflected back and forth inside and out
// again toward the camera; what the faces reflect toward the camera comes from the black
// space behind it). Each camera path brings T^(2k + 1) or nothing: about 4000 paths a channel
// leave a standard error near 0.4%; the bound is kZ of it.
void expect_slab_transmits(const std::string& integrator, const std::string& fade,
                           Rgb transmittance) {
    RenderSettings settings;
    settings.width = 16, settings.height = 16, settings.passes = 16, settings.seed = 5;
    const RenderResult r =
        render_text("global_settings { integrator \"" + integrator + "\" }\n" +
                        wall_behind("box { <-1, -1, 0>, <1, 1, 2> pigment { rgbt 1 } "
                                    "finish { ambient 0 diffuse 0 } "
                                    "interior { ior 1.5 " +
                                    fade + " } }"),
                    settings);
    const double R = 0.04;
    const double t[3] = {transmittance.red, transmittance.green, transmittance.blue};
    for (int c = 0; c < 3; ++c) {
        const double expected = (1 - R) * (1 - R) * t[c] / (1 - R * R * t[c] * t[c]);
        double mean = 0, se = 0;
        image_mean(r.film, c, mean, se);
        std::printf("%s, %s, channel %d: %.5f +- %.5f, closed form %.5f\n", integrator.c_str(),
                    fade.c_str(), c, mean, se, expected);
        EXPECT_NEAR(mean, expected, kZ * se + 1e-9);
        EXPECT_LT(se, 0.01 * expected);
    }
}

TEST(RenderInteriorFade, ExponentialFadeIsPovRaysBeerLambert) {
    // fade_power 1000 and above: POV-Ray's exp(-(1 - fade_color) d / fade_distance), d = 2.
    const Rgb t{std::exp(-0.5 * 2 / 4), std::exp(-0.8 * 2 / 4), std::exp(-1.0 * 2 / 4)};
    expect_slab_transmits("path", "fade_distance 4 fade_power 1001 fade_color <0.5, 0.2, 0>", t);
}

TEST(RenderInteriorFade, PowerFadeHasPovRaysValueAtFadeDistance) {
    // fade_power 2: Beer-Lambert matching POV-Ray's (1 + fade_color) / 2 at d = fade_distance,
    // here d = 2 = fade_distance.
    expect_slab_transmits("path", "fade_distance 2 fade_power 2 fade_color <0.5, 0.2, 0>",
                          {0.75, 0.6, 0.5});
}

TEST(RenderInteriorFade, BidirectionalCameraPathsFade) {
    // The bidirectional camera pass through the glass slab above onto a white diffuse wall lit
    // by a point light (1 W/sr) between slab and wall, 2 units from it: the wall's radiance
    // I cos / (pi r^2) at each point, seen through (1 - R)^2 T / (1 - R^2 T^2). Light the slab
    // reflects back onto the wall (under 0.1%) is left out. Averaged over 16 points of
    // each pixel; the Fresnel choice leaves a standard error near 0.4%.
    RenderSettings settings;
    settings.width = 16, settings.height = 16, settings.passes = 16, settings.seed = 5;
    settings.photons_per_pass = 20000;
    const RenderResult r = render_text(R"(
        global_settings { length_unit "m" integrator "bidirectional" }
        camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right x up y }
        light_source { <0, 0, 8> color rgb 1 }
        plane { z, 10 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
        box { <-1, -1, 0>, <1, 1, 2> pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
              interior { ior 1.5 fade_distance 4 fade_power 1001 fade_color <0.5, 0.2, 0> } }
    )",
                                       settings);
    double wall = 0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            const double x = -0.5 + (i + 0.5) / 64, y = -0.5 + (j + 0.5) / 64;
            const double r2 = x * x + y * y + 4;
            wall += 2 / std::sqrt(r2) / (kPi * r2) / (64 * 64);
        }
    const double R = 0.04;
    const double t[3] = {std::exp(-0.25), std::exp(-0.4), std::exp(-0.5)};
    for (int c = 0; c < 3; ++c) {
        const double expected = wall * (1 - R) * (1 - R) * t[c] / (1 - R * R * t[c] * t[c]);
        double mean = 0, se = 0;
        image_mean(r.film, c, mean, se);
        std::printf("channel %d: %.6f +- %.6f, closed form %.6f\n", c, mean, se, expected);
        EXPECT_NEAR(mean, expected, kZ * se + 0.001 * expected);
    }
}

TEST(RenderInteriorFade, BidirectionalPhotonsFade) {
    // A spotlight of 1 W/sr (5 degree cone) 10 units above a receiver under a slab 2 units
    // thick of index 1 (light goes straight through; only photons carry it, shadow rays stop
    // at the slab): E = I cos^3 / h^2 T^(1 / cos) with T = exp(-(1 - c) 2 / 4), averaged over
    // the photons' disk (radius 0.5, shrinking over the passes: the average over the first disk
    // is 0.2% under the centre's value, the tolerance 1%). About 10^5 photons land in it: a
    // standard error near 0.3%.
    RenderSettings settings;
    settings.render_image = false, settings.passes = 4, settings.seed = 2;
    settings.photons_per_pass = 100000, settings.photon_radius = 0.5;
    const RenderResult r = render_text(R"(
        global_settings { length_unit "m" integrator "bidirectional" }
        light_source { <0, 10, 0> color rgb 1
                       spotlight point_at <0, 0, 0> radius 5 falloff 5 tightness 0 }
        box { <-5, 3, -5>, <5, 5, 5> pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
              interior { fade_distance 4 fade_power 1001 fade_color <0.5, 0.2, 0> } }
        plane { y, 0 pigment { rgb 0.5 } }
        illuminance_receiver { <-0.1, 0, -0.1>, <0, 0, 0.2>, <0.2, 0, 0> resolution <1, 1> }
    )",
                                       settings);
    const Rgb e = r.receivers.at(0).irradiance.mean(0, 0);
    const double got[3] = {e.red, e.green, e.blue};
    const double sigma[3] = {0.5 / 4, 0.8 / 4, 1.0 / 4};
    for (int c = 0; c < 3; ++c) {
        const double expected = std::exp(-sigma[c] * 2) / 100;
        std::printf("channel %d: %.6f W/m^2, closed form %.6f\n", c, got[c], expected);
        EXPECT_NEAR(got[c], expected, 0.01 * expected);
    }
}

// A white diffuse wall (a box's face at z = 10) lit by a point light of 1 W/sr at (0, 0, 8),
// both inside a clear box of absorption 0.1 (z from 0 to 20), seen through it: the wall's
// radiance I cos / (pi r^2) dimmed by exp(-0.1 r) on the light's way and exp(-1) on the
// camera's. Light the wall reflects leaves through the clear box. Averaged over a 64 x 64 grid
// of each image; pixel jitter alone is random: 0.1%.
void expect_lit_inside_absorbing_box(const std::string& integrator) {
    RenderSettings settings;
    settings.width = 16, settings.height = 16, settings.passes = 4, settings.seed = 4;
    settings.photons_per_pass = 10000;
    const RenderResult r = render_text(
        "global_settings { length_unit \"m\" integrator \"" + integrator +
            "\" }\n"
            "camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right x up y }\n"
            "light_source { <0, 0, 8> color rgb 1 }\n"
            "box { <-20, -20, 0>, <20, 20, 20> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } "
            "hollow interior { media { absorption 0.1 } } }\n"
            "box { <-5, -5, 10>, <5, 5, 11> pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n",
        settings);
    double expected = 0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            const double x = -0.5 + (i + 0.5) / 64, y = -0.5 + (j + 0.5) / 64;
            const double d = std::sqrt(x * x + y * y + 4);
            expected += 2 / d / (kPi * d * d) * std::exp(-0.1 * d - 1) / (64 * 64);
        }
    double mean = 0, se = 0;
    image_mean(r.film, 0, mean, se);
    std::printf("%s: %.6f, closed form %.6f\n", integrator.c_str(), mean, expected);
    EXPECT_NEAR(mean, expected, 0.002 * expected);
}

TEST(RenderMedia, LightInsideAnAbsorbingMediumIsDimmedOnItsWay) {
    expect_lit_inside_absorbing_box("path");
    expect_lit_inside_absorbing_box("bidirectional");
}

// A hollow clear box (index 1) 2 units deep, 10 wide, holding `media`, between the camera and
// the wall.
std::string media_box(const std::string& media) {
    return "box { <-5, -5, 0>, <5, 5, 2> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } "
           "hollow interior { " +
           media + " } }";
}

Rgb pixel_of(const std::string& scene_text, int passes = 1) {
    RenderSettings settings;
    settings.width = 4, settings.height = 4, settings.passes = passes, settings.seed = 1;
    return render_text(scene_text, settings).film.mean(1, 2);
}

// Paths through the box are 2 units long up to the offsets that move rays off surfaces (1e-5
// of the scene's extent at each face, which the plane makes large; 1e-4 units measured): a
// relative bound of 3e-4 on the closed forms below (optical depths up to 2).
constexpr double kOffsets = 3e-4;

TEST(RenderMedia, AbsorptionTransmitsExponentially) {
    // exp(-sigma_a d) of the wall behind, d = 2 (nothing in the path is random).
    const Rgb l = pixel_of(wall_behind(media_box("media { absorption <0.1, 0.5, 1> }")));
    EXPECT_NEAR(l.red, std::exp(-0.2), kOffsets * std::exp(-0.2));
    EXPECT_NEAR(l.green, std::exp(-1.0), kOffsets * std::exp(-1.0));
    EXPECT_NEAR(l.blue, std::exp(-2.0), kOffsets * std::exp(-2.0));
    // Two media in one interior add up.
    const Rgb two = pixel_of(wall_behind(
        media_box("media { absorption <0.1, 0.5, 1> } media { absorption <0.3, 0, 0> }")));
    EXPECT_NEAR(two.red, std::exp(-0.8), kOffsets * std::exp(-0.8));
    EXPECT_NEAR(two.green, std::exp(-1.0), kOffsets * std::exp(-1.0));
}

TEST(RenderMedia, AtmosphericMediaFillWhatLiesOutsideObjectsAndInsideHollowOnes) {
    // An atmosphere of absorption 0.1 between the camera and the wall 15 units away (the wall
    // a plane whose inside lies beyond it: inside a non-hollow object there is no atmosphere,
    // as in POV-Ray): exp(-1.5); a hollow clear box 2 units deep on the way changes nothing, a
    // non-hollow one takes its 2 units out: exp(-1.3).
    const std::string scene =
        "global_settings { length_unit \"m\" }\n"
        "camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right x up y }\n"
        "plane { -z, -10 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 1 } }\n"
        "media { absorption 0.1 }\n";
    const std::string box =
        "box { <-5, -5, 0>, <5, 5, 2> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } ";
    EXPECT_NEAR(pixel_of(scene).red, std::exp(-1.5), kOffsets * std::exp(-1.5));
    EXPECT_NEAR(pixel_of(scene + box + "hollow }").red, std::exp(-1.5), kOffsets * std::exp(-1.5));
    EXPECT_NEAR(pixel_of(scene + box + "}").red, std::exp(-1.3), kOffsets * std::exp(-1.3));
}

TEST(RenderMedia, EmissionAddsRadianceAlongThePath) {
    // Emission e without absorption in front of a black wall: e d; with absorption sigma,
    // e (1 - exp(-sigma d)) / sigma (the far part seen through the near part).
    const Rgb l = pixel_of(wall_behind(media_box("media { emission <0.5, 0.25, 0> }"), "rgb 0"));
    EXPECT_NEAR(l.red, 1.0, kOffsets * 1.0);
    EXPECT_NEAR(l.green, 0.5, kOffsets * 0.5);
    EXPECT_NEAR(l.blue, 0.0, 1e-9);
    const Rgb a =
        pixel_of(wall_behind(media_box("media { emission 0.5 absorption 0.7 }"), "rgb 0"));
    const double expected = 0.5 * (1 - std::exp(-1.4)) / 0.7;
    EXPECT_NEAR(a.red, expected, kOffsets * expected);
}

// Single scattering from a point light: the camera looks along +z through a slab z in [0, 1]
// of scattering sigma_s (type `type`) and absorption sigma_a, the light (intensity 1 W/sr) at
// (0, 0, -2) on the camera's side. Along the ray at (x, y): L = integral over s in [0, 1] of
// exp(-sigma_t s) sigma_s p(cos) exp(-sigma_t l) / r^2, with r the distance from the light to
// (x, y, s), l = r s / (s + 2) its part inside the slab and cos the cosine between the light's
// direction there and -z. Quadrature (Simpson, 400 steps) at 16 points of each pixel.
double single_scattering(double x, double y, double sigma_s, double sigma_a,
                         const PhaseFunction& phase) {
    const int steps = 400;
    const double sigma_t = sigma_s + sigma_a;
    double sum = 0;
    for (int i = 0; i <= steps; ++i) {
        const double s = double(i) / steps;
        const double r2 = x * x + y * y + (s + 2) * (s + 2), r = std::sqrt(r2);
        const double cos_theta = -(s + 2) / r;
        const double f =
            std::exp(-sigma_t * (s + r * s / (s + 2))) * sigma_s * phase.eval(cos_theta) / r2;
        sum += f * (i == 0 || i == steps ? 1 : i % 2 ? 4 : 2);
    }
    return sum / (3.0 * steps);
}

// The render's pixels against that, as the mean of their differences and its standard error
// from their spread (the noise alone): the path of a scattered photon also goes on and may
// scatter again, which albedo 0.002 keeps under 0.2% of the single scattering.
void expect_single_scattering(int type, double eccentricity) {
    const double sigma_s = 0.002, sigma_a = 1;
    const PhaseFunction phase(type, eccentricity);
    const int size = 8;
    RenderSettings settings;
    settings.width = size, settings.height = size, settings.passes = 512, settings.seed = 7;
    const std::string media =
        "media { scattering { " + std::to_string(type) + ", " + std::to_string(sigma_s) +
        (type == 5 ? " eccentricity " + std::to_string(eccentricity) : std::string()) +
        " } absorption " + std::to_string(sigma_a) + " }";
    const RenderResult r = render_text(
        "global_settings { length_unit \"m\" }\n"
        "camera { orthographic location <0, 0, -1> look_at <0, 0, 0> right 2*x up 2*y }\n"
        "light_source { <0, 0, -2> color rgb 1 }\n"
        "box { <-5, -5, 0>, <5, 5, 1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } "
        "hollow interior { " +
            media + " } }\n",
        settings);
    double sum = 0, squares = 0, total = 0;
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
            double expected = 0;  // the pixel's footprint is symmetric: its row's sign is moot
            for (int k = 0; k < 16; ++k) {
                const double x = -1 + 2 * (px + (k % 4 + 0.5) / 4) / size;
                const double y = -1 + 2 * (py + (k / 4 + 0.5) / 4) / size;
                expected += single_scattering(x, y, sigma_s, sigma_a, phase) / 16;
            }
            const double difference = r.film.mean(px, py).red - expected;
            sum += difference, squares += difference * difference, total += expected;
        }
    const int n = size * size;
    const double bias = sum / n, expected = total / n;
    const double se = std::sqrt(std::max(0.0, squares / n - bias * bias) / (n - 1));
    std::printf("type %d (g %.1f): mean %.6g, single scattering %.6g, difference %.3g +- %.3g\n",
                type, eccentricity, expected + bias, expected, bias, se);
    EXPECT_NEAR(bias, 0, kZ * se + 0.002 * expected);
    EXPECT_LT(se, 0.01 * expected);
}

TEST(RenderMedia, SingleScatteringOfAPointLight) {
    expect_single_scattering(1, 0);
    expect_single_scattering(2, 0);
    expect_single_scattering(3, 0);
    expect_single_scattering(4, 0);
    expect_single_scattering(5, 0.6);
    expect_single_scattering(5, -0.4);
}

TEST(RenderMedia, LightsWithoutMediaInteractionAreNotScattered) {
    // POV-Ray's media_interaction off: the single-scattering scene above lit by such a light
    // alone is black, and the scene says so in a note.
    const RenderScene scene(parse_scene_text(
        "camera { orthographic location <0, 0, -1> look_at <0, 0, 0> right 2*x up 2*y }\n"
        "light_source { <0, 0, -2> color rgb 1 media_interaction off }\n"
        "box { <-5, -5, 0>, <5, 5, 1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } "
        "hollow interior { media { scattering { 1, 0.5 } } } }\n",
        "test.pov"));
    ASSERT_EQ(scene.notes().size(), 2u);
    EXPECT_NE(scene.notes()[1].find("media_interaction off"), std::string::npos);
    RenderSettings settings;
    settings.width = 4, settings.height = 4, settings.passes = 4, settings.seed = 1;
    double mean = 0, se = 0;
    image_mean(render(scene, settings).film, 0, mean, se);
    EXPECT_EQ(mean, 0);
}

// A sphere of the interior `interior` under a sky of radiance 1 from everywhere: when its media
// only scatter, every path leaves sooner or later with its weight kept, so every pixel is 1 in
// every channel (the image mean within kZ standard errors of its pixels).
void expect_furnace_kept(const std::string& interior) {
    RenderSettings settings;
    settings.width = 16, settings.height = 16, settings.passes = 16, settings.seed = 3;
    const RenderResult r = render_text(
        "camera { location <0, 0, -5> look_at 0 }\n"
        "background { rgb 1 }\n"
        "sphere { 0, 1 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow\n"
        "    interior { " +
            interior + " } }\n",
        settings);
    for (int c = 0; c < 3; ++c) {
        double mean = 0, se = 0;
        image_mean(r.film, c, mean, se);
        std::printf("channel %d: %.5f +- %.5f\n", c, mean, se);
        EXPECT_NEAR(mean, 1.0, kZ * se + 1e-9);
        EXPECT_LT(se, 0.01);
    }
}

TEST(RenderMedia, ScatteringWithoutAbsorptionKeepsEnergyInAFurnace) {
    // Different amounts per channel, two phase functions.
    expect_furnace_kept(
        "media { scattering { 1, <2, 1, 0.5> } } media { scattering { 5, 1 eccentricity 0.7 } }");
}

// gradient z repeats 0..1 in each unit of z: over the box's depth 2 a density of it sums to 1
// unit of path. Ratio tracking and delta tracking under the map's largest entry estimate the
// transmittance and emission without bias: the image mean against the closed form, within kZ
// standard errors of its pixels.
void expect_image(const std::string& scene_text, Rgb expected, int passes) {
    RenderSettings settings;
    settings.width = 16, settings.height = 16, settings.passes = passes, settings.seed = 9;
    const RenderResult r = render_text(scene_text, settings);
    const double e[3] = {expected.red, expected.green, expected.blue};
    for (int c = 0; c < 3; ++c) {
        double mean = 0, se = 0;
        image_mean(r.film, c, mean, se);
        std::printf("channel %d: %.5f +- %.5f, closed form %.5f\n", c, mean, se, e[c]);
        EXPECT_NEAR(mean, e[c], kZ * se + kOffsets * e[c]);
        EXPECT_LT(se, 0.01 * e[c] + 1e-9);
    }
}

TEST(RenderMedia, DensityScalesAbsorptionAndEmission) {
    const std::string gradient = "density { gradient z colour_map { [0 rgb 0] [1 rgb 1] } }";
    // Absorption <1, 0.5, 2> times the gradient times a plain density 0.5 (densities multiply).
    expect_image(wall_behind(media_box("media { absorption <1, 0.5, 2> " + gradient +
                                       " density { rgb 0.5 } }")),
                 {std::exp(-0.5), std::exp(-0.25), std::exp(-1.0)}, 256);
    // Emission 0.8 times the gradient, nothing absorbing: 0.8 x 1.
    expect_image(wall_behind(media_box("media { emission 0.8 " + gradient + " }"), "rgb 0"),
                 {0.8, 0.8, 0.8}, 256);
}

TEST(RenderMedia, ScatteringWithDensityKeepsEnergyInAFurnace) {
    // The scattering shaped by a spherical density (0 at the rim, 4 at the centre): delta
    // tracking under the majorant keeps every path's weight.
    expect_furnace_kept(
        "media { scattering { 1, <2, 1, 0.5> } "
        "density { spherical colour_map { [0 rgb 0] [1 rgb 4] } } }");
}

TEST(PhaseFunctions, IntegrateToOneAndSampleTheirDensity) {
    // Each phase function integrates to 1 over the sphere (Simpson over cos in 20000 steps),
    // and 10^6 sampled directions fall into 40 bins of cos with the probability its integral
    // gives: chi-square of 39 degrees of freedom under 80 (p < 1e-4 by chance; seed fixed).
    const PhaseFunction phases[] = {{1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0.8}, {5, -0.3}};
    for (const PhaseFunction& phase : phases) {
        const int steps = 20000;
        double integral = 0;
        for (int i = 0; i <= steps; ++i) {
            const double mu = -1 + 2.0 * i / steps;
            integral += phase.eval(mu) * (i == 0 || i == steps ? 1 : i % 2 ? 4 : 2);
        }
        integral *= 2 * kPi * (2.0 / steps) / 3;
        EXPECT_NEAR(integral, 1.0, 1e-6);

        const int bins = 40, n = 1000000;
        std::vector<double> count(bins, 0.0);
        Pcg32 rng(11, 3);
        const Vec3 forward = normalized(Vec3{0.3, -0.5, 0.8});
        for (int i = 0; i < n; ++i) {
            const Vec3 w = phase.sample(forward, rng.uniform(), rng.uniform(), rng.uniform());
            const double mu = std::clamp(dot(w, forward), -1.0, 1.0);
            count[size_t(std::min(bins - 1, int((mu + 1) / 2 * bins)))] += 1;
        }
        double chi2 = 0;
        for (int b = 0; b < bins; ++b) {
            double p = 0;  // 2 pi times the integral of the phase over the bin
            for (int k = 0; k < 200; ++k) {
                const double mu = -1 + (b + (k + 0.5) / 200) * 2.0 / bins;
                p += 2 * kPi * phase.eval(mu) * (2.0 / bins) / 200;
            }
            const double expected = p * n;
            chi2 += (count[size_t(b)] - expected) * (count[size_t(b)] - expected) / expected;
        }
        std::printf("phase integral %.8f, chi-square %.1f\n", integral, chi2);
        EXPECT_LT(chi2, 80);
    }
}

TEST(RenderMedia, RefusesWhatItDoesNotRender) {
    const auto error = test::render_error;
    const std::string scattering =
        "sphere { 0, 1 hollow pigment { rgbt 1 } interior { media { scattering { 1, 0.1 } } } }\n";
    EXPECT_EQ(error(scattering), "no error");
    EXPECT_EQ(error("global_settings { integrator \"bidirectional\" }\n" + scattering),
              "not supported: media that scatter or emit with integrator \"bidirectional\" (the "
              "path integrator renders them)");
    EXPECT_EQ(error("light_source { 0, 1 area_light x, y, 2, 2 }\n" + scattering),
              "not supported: media that scatter or emit, with area lights or ray-file sources "
              "(point and spot lights only)");
    EXPECT_EQ(error("media { emission 1 }"),
              "not supported: atmospheric media emitting without extinction (infinite radiance "
              "toward the sky) at test.pov:1:1");
    EXPECT_EQ(error("media { absorption 1 }\n"
                    "illuminance_receiver { 0, x, z resolution <1, 1> }"),
              "not supported: illuminance receivers in atmospheric media at test.pov:1:1");
    EXPECT_EQ(error("media { absorption 1 }\n" + scattering),
              "not supported: atmospheric media together with fade or media in objects at "
              "test.pov:2:41");
    EXPECT_EQ(error("global_settings { spectral on }\n" + scattering),
              "not supported: interior fade or media under spectral transport");
    EXPECT_EQ(error("sphere { 0, 1 hollow interior { media { absorption 1 density { "
                    "spiral2 5 } } } }"),
              "not supported: density pattern 'spiral2' at test.pov:1:54");
    EXPECT_EQ(error("triangle { 0, x, y interior { fade_distance 1 } }"),
              "not supported: fade or media in a triangle, which has no inside at "
              "test.pov:1:20");
}

}  // namespace
}  // namespace rayset::tracer
