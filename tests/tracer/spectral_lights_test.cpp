// Ordinary POV-Ray lights in spectral transport (global_settings { spectral on }): a light's
// colour is an illuminant spectrum, the upsampled colour x the luminance-normalised D65. A grey
// point light gives exactly the RGB mode's lux in expectation (I cos / d^2); a coloured one over
// a coloured floor gives the closed forms with the upsampled spectra, integrated here at
// 0.01 nm; an emitting grey furnace and a coloured background likewise. Seeds are fixed; every
// statistical bound is kZ standard errors of the estimate.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "converters/analytic/analytic_geometry.h"
#include "converters/colour/spectrum.h"
#include "lightmodel/emission_spectrum.h"
#include "tracer/render/renderer.h"
#include "tracer/render/rgb_upsampling.h"
#include "tracer/render/spectrum.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

// z = 4.5: a two-sided tail of 6.8e-6 per comparison for a standard error known exactly, 3e-5
// for one estimated from 64 passes (Student's t, 63 degrees of freedom); an estimate from 8
// passes would have 3e-3 (t, 7): one cell in five maps of 63 cells would fail by chance.
constexpr double kZ = 4.5;

using test::render_text;

std::string with_mode(const std::string& scene, bool spectral,
                      const std::string& integrator = "bidirectional") {
    return "global_settings { integrator \"" + integrator + "\" spectral " +
           (spectral ? "on" : "off") + " }\n" + scene;
}

// The integral over 360-830 nm of V(lambda) x f(lambda), 0.01 nm midpoints.
template <class F>
double luminance_integral(F f) {
    double sum = 0;
    for (double nm = kLambdaMin + 0.005; nm < kLambdaMax; nm += 0.01)
        sum += photopic_efficiency(nm) * f(nm) * 0.01;
    return sum;
}

// The illuminant spectrum of an RGB colour by its definition (rgb_upsampling.h): the largest
// channel m x the fitted reflectance of colour / m x the luminance-normalised D65.
double illuminant(const Rgb& colour, double nm) {
    static const lightmodel::BinnedSpectrum d65 = lightmodel::d65_spectrum();
    const double m = std::max({colour.red, colour.green, colour.blue});
    return m * upsample_reflectance((1 / m) * colour)(nm) * d65(nm);
}

TEST(SpectralLights, D65IsLuminanceNormalised) {
    // What makes a grey light (c, c, c) have luminance c in spectral transport.
    const lightmodel::BinnedSpectrum d65 = lightmodel::d65_spectrum();
    EXPECT_NEAR(luminance_integral([&](double nm) { return d65(nm); }), 1, 1e-6);
    const IlluminantSpectrum grey({0.3, 0.3, 0.3});
    EXPECT_EQ(grey(555.5), 0.3 * d65(555.5));
}

const char* kFloorScene = R"(
    light_source { <100, 1000, -50> color rgb %s }
    plane { y, 0 pigment { rgb %s } finish { diffuse 1 } }
    illuminance_receiver { <-1000, 0, -1000>, <0, 0, 2000>, <2000, 0, 0>
        resolution <9, 7> name "floor" }
)";

std::string floor_scene(const std::string& light, const std::string& floor) {
    char text[1024];
    std::snprintf(text, sizeof text, kFloorScene, light.c_str(), floor.c_str());
    return text;
}

// I cos / d^2 per unit intensity at a cell centre (m^-2).
double inverse_square_cosine(const ReceiverMap& map, int i, int j) {
    const Vec3 to_light = Vec3{100, 1000, -50} - map.cell_centre(i, j);
    const double d_m = length(to_light) / 1000, cos_theta = to_light.y / length(to_light);
    return cos_theta / (d_m * d_m);
}

TEST(SpectralLights, GreyPointLightGivesTheRgbLuxAndInverseSquareCosine) {
    // Light 1 m above a grey floor, a receiver lying on it facing up: E = 683 lm/W x I cos / d^2
    // with I = 2 W/sr. RGB transport is exact (next-event estimation of a point light); the
    // spectral estimate's only noise is the hero wavelengths' (the luminance of D65 x V / pdf
    // over the four), bounded by kZ of its standard error per cell. Both integrators: the path
    // tracer is the bidirectional one's estimate of ordinary lights. The path tracer takes one
    // sample per cell and pass, the bidirectional one about a thousand (its photons / cells):
    // passes so that the standard errors rest on many samples in both.
    RenderSettings settings;
    settings.render_image = false, settings.seed = 1;
    const std::string scene = floor_scene("2", "0.7");
    for (const char* integrator : {"path", "bidirectional"}) {
        settings.passes = std::string(integrator) == "path" ? 4096 : 64;
        const RenderResult rgb = render_text(with_mode(scene, false, integrator), settings);
        const RenderResult spectral = render_text(with_mode(scene, true, integrator), settings);
        const ReceiverMap& a = rgb.receivers.at(0);
        const ReceiverMap& b = spectral.receivers.at(0);
        double worst_sigma = 0;
        for (int j = 0; j < 7; ++j)
            for (int i = 0; i < 9; ++i) {
                const double expected = 683 * 2 * inverse_square_cosine(a, i, j);
                const double se = b.irradiance.photometric_standard_error(i, j);
                EXPECT_NEAR(a.irradiance.photometric_mean(i, j), expected, 1e-9 * expected)
                    << integrator << " cell " << i << "," << j;
                EXPECT_GT(se, 0) << integrator;
                EXPECT_NEAR(b.irradiance.photometric_mean(i, j), expected, kZ * se)
                    << integrator << " cell " << i << "," << j;
                worst_sigma = std::max(
                    worst_sigma, std::abs(b.irradiance.photometric_mean(i, j) - expected) / se);
            }
        std::printf(
            "%s, grey point light: centre cell RGB %.6g lx, spectral %.6g lx (se %.2g), truth %.6g "
            "lx; "
            "worst cell %.2f standard errors\n",
            integrator, a.irradiance.photometric_mean(4, 3), b.irradiance.photometric_mean(4, 3),
            b.irradiance.photometric_standard_error(4, 3), 683 * 2 * inverse_square_cosine(a, 4, 3),
            worst_sigma);
    }
}

TEST(SpectralLights, ColouredPointLightOnColouredFloorGivesTheUpsampledClosedForms) {
    // An orange light (rgb <2, 1.2, 0.4>, I = its illuminant spectrum in W/(sr nm)) 1 m above a
    // green floor (diffuse <0.2, 0.6, 0.3>).
    //  - lux on the floor: 683 x integral of V x I(lambda) x cos / d^2;
    //  - luminance of the floor seen straight below the light (a 1 degree camera looking along
    //    the light's axis: cos / d^2 varies by 3e-5 over the view): 683 x integral of
    //    V x rho(lambda) x I(lambda) / (pi h^2), rho the floor's upsampled reflectance.
    const Rgb light_colour{2, 1.2, 0.4}, floor_colour{0.2, 0.6, 0.3};
    const double light_luminance =
        luminance_integral([&](double nm) { return illuminant(light_colour, nm); });
    const ReflectanceSpectrum rho = upsample_reflectance(floor_colour);
    const double reflected_luminance =
        luminance_integral([&](double nm) { return rho(nm) * illuminant(light_colour, nm); });
    const double rgb_light_luminance = luminance_weight(light_colour);
    const double rgb_reflected_luminance = luminance_weight(light_colour * floor_colour);

    RenderSettings settings;
    settings.render_image = false, settings.passes = 64, settings.seed = 2;
    const std::string scene = floor_scene("<2, 1.2, 0.4>", "<0.2, 0.6, 0.3>");
    const RenderResult spectral = render_text(with_mode(scene, true), settings);
    const ReceiverMap& map = spectral.receivers.at(0);
    for (int j = 0; j < 7; ++j)
        for (int i = 0; i < 9; ++i) {
            const double expected = 683 * light_luminance * inverse_square_cosine(map, i, j);
            EXPECT_NEAR(map.irradiance.photometric_mean(i, j), expected,
                        kZ * map.irradiance.photometric_standard_error(i, j))
                << "cell " << i << "," << j;
        }
    const double centre_expected = 683 * light_luminance * inverse_square_cosine(map, 4, 3);
    std::printf(
        "orange point light: centre cell spectral %.6g lx (se %.2g), closed form %.6g lx, RGB mode "
        "%.6g lx "
        "(%+.3f%%)\n",
        map.irradiance.photometric_mean(4, 3), map.irradiance.photometric_standard_error(4, 3),
        centre_expected, 683 * rgb_light_luminance * inverse_square_cosine(map, 4, 3),
        100 * (rgb_light_luminance / light_luminance - 1));

    // The floor's luminance: pixels straight below the light (a slab's face at z = 0 facing the
    // light at z = -1000, camera between them) are independent, identically distributed to 3e-5.
    RenderSettings image = settings;
    image.render_image = true, image.width = image.height = 16, image.passes = 8;
    const std::string view_scene = R"(
        camera { location <0, 0, -500> look_at <0, 0, 0> angle 1 }
        light_source { <0, 0, -1000> color rgb <2, 1.2, 0.4> }
        box { <-100, -100, 0>, <100, 100, 10> pigment { rgb <0.2, 0.6, 0.3> } finish { diffuse 1 } }
    )";
    const RenderResult view = render_text(with_mode(view_scene, true), image);
    const int n = view.film.nx() * view.film.ny();
    double sum = 0, squares = 0;
    for (int y = 0; y < view.film.ny(); ++y)
        for (int x = 0; x < view.film.nx(); ++x) {
            const double v = view.film.photometric_mean(x, y);
            sum += v, squares += v * v;
        }
    const double mean = sum / n, se = std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1));
    const double expected = 683 * reflected_luminance / kPi,
                 rgb_mode = 683 * rgb_reflected_luminance / kPi;
    std::printf(
        "green floor under it: spectral %.6g cd/m^2 (se %.2g), closed form %.6g cd/m^2, RGB mode "
        "%.6g "
        "cd/m^2 (%+.3f%%)\n",
        mean, se, expected, rgb_mode, 100 * (rgb_mode / expected - 1));
    EXPECT_GT(se, 0);
    EXPECT_NEAR(mean, expected, kZ * se + 3e-5 * expected);
}

// Luminance (cd/m^2) of an image's pixels: mean and standard error, pixels independent and
// identically distributed.
void image_luminance(const Film& film, double& mean, double& standard_error) {
    const int n = film.nx() * film.ny();
    double sum = 0, squares = 0;
    for (int y = 0; y < film.ny(); ++y)
        for (int x = 0; x < film.nx(); ++x) {
            const double v = film.photometric_mean(x, y);
            sum += v, squares += v * v;
        }
    mean = sum / n;
    standard_error = std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1));
}

TEST(SpectralLights, EmittingFurnaceAndBackgroundAreIlluminantSpectra) {
    // Inside a closed grey sphere (diffuse 0.5 + mirror 0.3, emission 1 W/(m^2 sr) per channel)
    // the radiance is the geometric series 1 / (1 - 0.8) = 5 at every wavelength of the D65
    // shape, so the luminance is 683 x 5 cd/m^2 (the RGB furnace's figure, render_physics_test).
    RenderSettings settings;
    settings.width = settings.height = 16, settings.passes = 8, settings.seed = 4;
    const RenderResult furnace = render_text(with_mode(R"(
        camera { location <0,0,-50> look_at <0,0,0> angle 40 }
        sphere { <0,0,0>, 100 pigment { rgb 1 }
            finish { diffuse 0.5 reflection 0.3 emission 1 ambient 0 } }
    )",
                                                       true),
                                             settings);
    double mean = 0, se = 0;
    image_luminance(furnace.film, mean, se);
    std::printf("spectral furnace: %.6g cd/m^2 (se %.2g), closed form %.6g\n", mean, se, 683 * 5.0);
    EXPECT_GT(se, 0);
    EXPECT_NEAR(mean, 683 * 5.0, kZ * se);

    // A coloured background seen directly: 683 x integral of V x its illuminant spectrum.
    const Rgb sky{0.2, 0.4, 0.9};
    const double sky_luminance =
        683 * luminance_integral([&](double nm) { return illuminant(sky, nm); });
    const RenderResult background = render_text(with_mode(R"(
        camera { location <0,0,-50> look_at <0,0,0> angle 40 }
        background { rgb <0.2, 0.4, 0.9> }
    )",
                                                          true),
                                                settings);
    image_luminance(background.film, mean, se);
    std::printf(
        "spectral background: %.6g cd/m^2 (se %.2g), closed form %.6g, RGB mode %.6g (%+.3f%%)\n",
        mean, se, sky_luminance, photometric(sky), 100 * (photometric(sky) / sky_luminance - 1));
    EXPECT_GT(se, 0);
    EXPECT_NEAR(mean, sky_luminance, kZ * se);
}

}  // namespace
}  // namespace rayset::tracer
