// Several ray sources and ordinary lights in one bidirectional render (issue 6): a white LED
// given as two ray files, blue (460 nm) and yellow (580 nm), at one position, plus a point
// light. Receiver illuminance in lux against the closed forms: each disk's irradiance times
// its luminous efficacy (CIE V(lambda) x 683), the point light's I cos / d^2; and that both
// colours arrive.
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "converters/analytic/analytic_sources.h"
#include "converters/analytic/synth.h"
#include "converters/colour/spectrum.h"
#include "converters/rays/ray_stream.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"
#include "lightmodel/model_support.h"
#include "support/test_support.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

struct Led {
    double wavelength_nm, flux;  // W
    uint64_t seed;
    std::string model;  // .vdb
    std::shared_ptr<lightmodel::LightModel> light_model;
    analytic::LambertianDisk disk() const {
        analytic::Spectrum s;
        s.wavelength_nm = wavelength_nm;
        return analytic::LambertianDisk::with_flux(1, flux, s);
    }
    double efficacy() const {
        return kMaxLuminousEfficacy * photopic_efficiency(wavelength_nm);
    }  // lm/W
};

TEST(BidirectionalMixed, WhiteLedFromTwoRayFilesPlusAPointLight) {
    test::ScratchDir scratch;
    Led leds[2] = {{460, 0.3, 11, "", nullptr}, {580, 0.7, 12, "", nullptr}};
    for (Led& led : leds) {
        const std::string key = "led" + std::to_string(int(led.wavelength_nm));
        led.model =
            test::synthesised_model(scratch.path().string(), key, led.disk(), 1000000, led.seed)
                .model;
        led.light_model =
            std::make_shared<lightmodel::LightModel>(lightmodel::read_model(led.model));
    }
    // Both disks 20 mm above a black floor facing down (rotate 90 x: +z -> -y), the point
    // light 30 mm up and 25 mm aside, radiant intensity 1e-4 W/sr per channel (68.3 mcd).
    const double H = 20, intensity = 1e-4;
    const Vec3 lamp{25, 30, 0};
    const std::string scene = R"(
        global_settings { integrator "bidirectional" }
        plane { y, 0 pigment { rgb 0 } }
        ray_source { ")" + leds[0].model +
                              R"(" rotate <90, 0, 0> translate <0, 20, 0> }
        ray_source { ")" + leds[1].model +
                              R"(" rotate <90, 0, 0> translate <0, 20, 0> }
        light_source { <25, 30, 0> color rgb 1e-4 }
        illuminance_receiver { <-40, 0, -40>, <0, 0, 80>, <80, 0, 0>
            resolution <4, 4> name "floor" }
    )";
    RenderSettings settings;
    settings.render_image = false, settings.passes = 4096, settings.seed = 5,
    settings.photons_per_pass = 64;
    const RenderResult r =
        render(RenderScene(parse_scene_text(scene, scratch.file("mixed.pov"))), settings);
    const ReceiverMap& map = r.receivers.at(0);  // every layer and the point light
    double worst = 0;
    for (int j = 0; j < map.irradiance.ny(); ++j)
        for (int i = 0; i < map.irradiance.nx(); ++i) {
            const Vec3 p = map.cell_centre(i, j), q{p.x, p.z, H};  // disk frame: floor at z = H
            const Vec3 w = normalized(q);
            // Lux from each disk: closed form (W/mm^2 -> W/m^2) x efficacy, times the model's
            // far field over the disk's (docs: removes the 1e6-ray model's own ~1.2% noise).
            double lux = 0;
            for (const Led& led : leds) {
                const lightmodel::ComplexSource model(led.light_model);
                const analytic::LambertianDisk disk = led.disk();
                lux += 1e6 * disk.irradiance(q, {0, 0, -1}) * led.efficacy() * model.intensity(w) /
                       disk.intensity(w);
            }
            const Vec3 to_lamp = lamp - p;
            const double d2 = dot(to_lamp, to_lamp) * 1e-6;  // m^2
            lux += kLumensPerWatt * intensity * (to_lamp.y / std::sqrt(dot(to_lamp, to_lamp))) / d2;
            const double measured = map.irradiance.photometric_mean(i, j);
            const double se = map.irradiance.photometric_standard_error(i, j);
            worst = std::max(worst, std::fabs(measured / lux - 1));
            EXPECT_LT(se, 0.0025 * lux) << i << "," << j;  // the 1% below is then 4 se or more
            EXPECT_NEAR(measured, lux, 0.01 * lux) << "cell " << i << "," << j << " se " << se;
        }
    std::printf("blue + yellow ray files + point light: worst cell %.4f off the closed forms\n",
                worst);
    // Colour: the blue file's light reaches the blue channel, and the yellow file's (580 nm,
    // ten times the blue's luminous flux) makes the sum redder than it is blue.
    const Rgb centre = map.irradiance.mean(1, 1) + map.irradiance.mean(2, 2);
    EXPECT_GT(centre.blue, 0);
    EXPECT_GT(centre.red, centre.blue);
}

TEST(BidirectionalMixed, LuminousOnlyFileGivesTheSameLux) {
    // The same 555 nm disk twice: its ray file as synthesised (W and lm per ray), and a copy
    // that keeps only the luminous column, as photometric ray files do (its wavelengths stay).
    // One model is in W (683.002 lm/W at 555 nm), the other in lm: their lux and colour must
    // agree to rounding, the same rays drawing the same samples.
    test::ScratchDir scratch;
    analytic::Spectrum spectrum;
    spectrum.wavelength_nm = 555;
    const auto disk = analytic::LambertianDisk::with_flux(1, 1, spectrum);
    const std::string both = scratch.file("both.tm25ray"),
                      luminous = scratch.file("luminous.tm25ray");
    {
        auto out = create_rays(both, RayFormat::tm25, synth_header(disk, 200000, 3));
        synthesize(disk, 200000, 3, *out);
    }
    {
        auto in = open_rays(both);
        RayHeader header = in->header();
        header.has_radiant = false;
        header.stated_radiant = std::nan("");
        auto out = create_rays(luminous, RayFormat::tm25, header);
        RayChunk chunk;
        while (in->read(chunk)) out->write(chunk);
        out->finish();
    }
    ASSERT_FALSE(open_rays(luminous)->header().has_radiant);
    auto lux = [&](const std::string& file) {
        const std::string scene = R"(
            global_settings { integrator "bidirectional" }
            plane { y, 0 pigment { rgb 0 } }
            ray_source { ")" + file +
                                  R"(" rotate <90, 0, 0> translate <0, 20, 0> }
            illuminance_receiver { <-40, 0, -40>, <0, 0, 80>, <80, 0, 0>
                resolution <3, 3> name "floor" }
        )";
        RenderSettings settings;
        settings.render_image = false, settings.passes = 64, settings.seed = 8,
        settings.photons_per_pass = 64;
        return render(RenderScene(parse_scene_text(scene, scratch.file("s.pov"))), settings)
            .receivers.at(0);
    };
    const ReceiverMap a = lux(both), b = lux(luminous);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            const double ea = a.irradiance.photometric_mean(i, j),
                         eb = b.irradiance.photometric_mean(i, j);
            EXPECT_GT(ea, 0);
            EXPECT_NEAR(eb, ea, 1e-6 * ea) << i << "," << j;
            const Rgb ca = a.irradiance.mean(i, j), cb = b.irradiance.mean(i, j);
            EXPECT_NEAR(cb.red, ca.red, 1e-6 * ca.red);
            EXPECT_NEAR(cb.blue, ca.blue, 1e-6 * ca.red);
        }
}

}  // namespace
}  // namespace rayset::tracer
