// Tests of the POV-Ray -> physical material mapping and of the BSDF's sampling against its
// own evaluation, estimated a second way (uniform hemisphere sampling).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/random.h"
#include "tracer/render/camera.h"
#include "tracer/render/material.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

// The material of the scene's first object at `point`.
Material material_of(const std::string& object, Vec3 point = {}) {
    const SceneDescription d = parse_scene_text(object, "test.pov");
    std::optional<Material> scratch;
    return ObjectMaterial(d.objects.at(0), 1.0, ColourDecoding(d.global))
        .at(point, {0, 0, 1}, scratch);
}

TEST(RenderMaterial, PovRayTextureMapping) {
    Material m =
        material_of("sphere { 0, 1 pigment { rgb <0.5, 0.25, 1> } finish { diffuse 0.8 } }");
    EXPECT_DOUBLE_EQ(m.diffuse.red, 0.4);
    EXPECT_DOUBLE_EQ(m.diffuse.green, 0.2);
    EXPECT_DOUBLE_EQ(m.diffuse.blue, 0.8);
    EXPECT_EQ(average(m.glossy), 0);
    // Untextured: POV-Ray renders black.
    m = material_of("sphere { 0, 1 }");
    EXPECT_EQ(max_component(m.diffuse), 0);
    // A mirror keeps its weight; diffuse keeps what is left: 0.9 would make 1.2, so 1 - 0.3.
    m = material_of("sphere { 0, 1 pigment { rgb 1 } finish { diffuse 0.9 reflection 0.3 } }");
    EXPECT_FLOAT_EQ(m.mirror_max.red, 0.3);  // colours are single precision, as in POV-Ray
    EXPECT_FLOAT_EQ(m.diffuse.red, 0.7);
    // Glass: rgbf with an interior -> a dielectric lobe tinted by the pigment.
    m = material_of("sphere { 0, 1 pigment { rgbf <1, 0.5, 0.5, 0.9> } interior { ior 1.5 } }");
    EXPECT_DOUBLE_EQ(m.ior, 1.5);
    EXPECT_FLOAT_EQ(m.transmission.green, 0.45);
    EXPECT_FLOAT_EQ(m.diffuse.red, 0.1 * 0.6);
    // Blinn specular of roughness 0.05 -> Phong exponent 1/0.05/4 = 5; phong_size is taken as is.
    m = material_of("sphere { 0, 1 pigment { rgb 1 } finish { specular 0.2 roughness 0.05 } }");
    EXPECT_DOUBLE_EQ(m.glossy_exponent, 5);
    m = material_of("sphere { 0, 1 pigment { rgb 1 } finish { phong 0.5 phong_size 80 } }");
    EXPECT_DOUBLE_EQ(m.glossy_exponent, 80);
    EXPECT_DOUBLE_EQ(m.glossy.red, 0.5);
    m = material_of("sphere { 0, 1 pigment { rgb 1 } finish { emission 2 } }");
    EXPECT_DOUBLE_EQ(m.emission.blue, 2);
}

// The renderer refuses, at the place the scene writes it, what it does not render.
TEST(RenderMaterial, ColoursDecodedFromTheAssumedGamma) {
    const std::string sphere =
        "sphere { 0, 1 pigment { rgbt <0.5, 0.2, 1.5, 0.25> } finish { diffuse 0.8 } }";
    Material m = material_of("global_settings { assumed_gamma 2.2 } " + sphere);
    EXPECT_DOUBLE_EQ(m.diffuse.red, 0.8 * 0.75 * std::pow(0.5, 2.2));
    // Colours are single precision, as POV-Ray keeps them: 0.2 is 0.2 to 1.5e-8.
    EXPECT_NEAR(m.diffuse.green, 0.8 * 0.75 * std::pow(0.2, 2.2), 1e-7 * m.diffuse.green);
    EXPECT_DOUBLE_EQ(m.diffuse.blue, 0.8 * 0.75);  // the pigment clamped to 1 after decoding
    EXPECT_DOUBLE_EQ(m.transmission.red, 0.25);    // transmit is a fraction: kept
    m = material_of("global_settings { assumed_gamma srgb } " + sphere);
    EXPECT_DOUBLE_EQ(m.diffuse.red, 0.8 * 0.75 * std::pow((0.5 + 0.055) / 1.055, 2.4));
    m = material_of("global_settings { assumed_gamma 1.0 } " + sphere);
    EXPECT_DOUBLE_EQ(m.diffuse.red, 0.8 * 0.75 * 0.5);
}

// Layers: each seen through the filter and transmit of those above; texture patterns: their
// textures blended as their map says. The default finish is diffuse 0.6.
TEST(RenderMaterial, LayersAndTexturePatternsCombineLobeByLobe) {
    Material m = material_of(
        "sphere { 0, 1 texture { pigment { rgb <1, 0, 0> } } "
        "texture { pigment { rgbt <0, 0, 1, 0.25> } } }");
    EXPECT_FLOAT_EQ(m.diffuse.red, 0.6 * 0.25);  // the bottom through 0.25 transmit
    EXPECT_FLOAT_EQ(m.diffuse.green, 0);
    EXPECT_FLOAT_EQ(m.diffuse.blue, 0.6 * 0.75);  // the top's opaque 0.75
    EXPECT_EQ(max_component(m.transmission), 0);  // the bottom is opaque
    // Filter tints what is below: 0.5 x <0, 1, 1> over yellow leaves its green.
    m = material_of(
        "sphere { 0, 1 texture { pigment { rgb <1, 1, 0> } } "
        "texture { pigment { rgbf <0, 1, 1, 0.5> } finish { phong 0.3 } } }");
    EXPECT_FLOAT_EQ(m.diffuse.red, 0);
    EXPECT_FLOAT_EQ(m.diffuse.green, 0.6 * 0.5 + 0.6 * 0.5);
    EXPECT_FLOAT_EQ(m.diffuse.blue, 0.6 * 0.5);
    EXPECT_FLOAT_EQ(m.glossy.red, 0.3);  // the top's highlight, unfiltered
    // A transparent bottom stays transparent through the layers above it.
    m = material_of(
        "sphere { 0, 1 texture { pigment { rgbt 1 } } "
        "texture { pigment { rgbt <1, 1, 1, 0.5> } } }");
    EXPECT_FLOAT_EQ(m.transmission.red, 0.5);
    EXPECT_FLOAT_EQ(m.diffuse.red, 0.6 * 0.5);
    // texture_map: a quarter of the way from white to black along x.
    const std::string mapped =
        "sphere { 0, 1 texture { gradient x texture_map { [0 pigment { rgb 1 }] "
        "[1 pigment { rgb 0 } finish { emission 1 }] } } }";
    m = material_of(mapped, {0.25, 0, 0});
    EXPECT_FLOAT_EQ(m.diffuse.green, 0.6 * 0.75);
    // A texture list picks one texture per checker cell.
    const std::string checker =
        "sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } "
        "texture { pigment { rgb <0, 0, 1> } } } }";
    EXPECT_FLOAT_EQ(material_of(checker, {0.5, 0.5, 0.5}).diffuse.red, 0.6);
    EXPECT_FLOAT_EQ(material_of(checker, {1.5, 0.5, 0.5}).diffuse.red, 0);
    EXPECT_FLOAT_EQ(material_of(checker, {1.5, 0.5, 0.5}).diffuse.blue, 0.6);
}

TEST(RenderMaterial, RefusesWhatItDoesNotRender) {
    auto error = [](const std::string& object) {
        try {
            material_of(object);
        } catch (const rayset::Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    // Transforms of a uniform colour change nothing; ambient is not physical.
    EXPECT_EQ(error("sphere { 0, 1 pigment { rgb 1 scale 2 rotate y } finish { ambient 0.3 } }"),
              "no error");
    // Patterns the language evaluates render (noise ones too); spiral2 and fractals other than
    // the plain Mandelbrot and Julia sets do not yet.
    EXPECT_EQ(error("sphere { 0, 1 pigment { checker } }"), "no error");
    EXPECT_EQ(error("sphere { 0, 1 pigment { spiral1 3 } }"), "no error");
    EXPECT_EQ(error("sphere { 0, 1 pigment { mandel 20 } }"), "no error");
    EXPECT_EQ(error("sphere { 0, 1 pigment { spiral2 3 } }"),
              "not supported: pigment pattern 'spiral2' at test.pov:1:25");
    EXPECT_EQ(error("sphere { 0, 1 pigment { mandel 20 exponent 3 } }"),
              "not supported: pigment pattern 'mandel' at test.pov:1:25");
    // Normals tilt down a pattern's slope, or by noise; block patterns (which take lists of
    // normals), maps of normals and the patterns with a tilt of their own do not render yet.
    EXPECT_EQ(error("sphere { 0, 1\n normal { bumps 0.5 } }"), "no error");
    EXPECT_EQ(error("sphere { 0, 1\n normal { ripples 0.5 } }"),
              "not supported: normal 'ripples' at test.pov:2:11");
    EXPECT_EQ(error("sphere { 0, 1\n normal { checker normal { bumps }, normal { dents } } }"),
              "not supported: normal 'checker' with a list of normals at test.pov:2:11");
    EXPECT_EQ(error("sphere { 0, 1\n normal { gradient x slope_map { [0 <0, 1>] [1 <1, 0>] } } }"),
              "not supported: normal 'gradient' with a normal_map or slope_map at test.pov:2:11");
    // One material holds one highlight: layers whose highlights differ cannot be combined.
    EXPECT_EQ(error("sphere { 0, 1 texture { finish { phong 1 phong_size 10 } } texture { "
                    "pigment { rgbt 1 } finish { phong 1 phong_size 20 } } }"),
              "not supported: textures combining highlights of different sizes at test.pov:1:15");
    EXPECT_EQ(error("sphere { 0, 1 texture { spiral2 3 texture_map { [0 pigment { rgb 1 }] "
                    "[1 pigment { rgb 0 }] } } }"),
              "not supported: patterned textures (spiral2) at test.pov:1:25");
    EXPECT_EQ(error("sphere { 0, 1 finish { irid { 0.3 } } }"),
              "not supported: finish 'irid' at test.pov:1:15");
    EXPECT_EQ(error("sphere { 0, 1 finish { diffuse 0.6, 0.2 } }"),
              "not supported: finish diffuse with a back-side amount at test.pov:1:15");
    EXPECT_EQ(error("sphere { 0, 1 interior_texture { pigment { rgb 1 } } }"),
              "not supported: interior_texture at test.pov:1:15");
}

TEST(RenderMaterial, FresnelAtNormalIncidence) {
    EXPECT_NEAR(fresnel_dielectric(1, 1.5), 0.04, 1e-12);  // ((n - 1) / (n + 1))^2
    EXPECT_EQ(fresnel_dielectric(0.1, 1 / 1.5), 1.0);      // beyond the critical angle
}

// The mean of the sampled weights f cos / pdf is the directional albedo; a second estimate
// integrates eval() with uniform hemisphere directions. Both with 400000 samples; the bound
// is 5 standard errors of their difference (two-sided normal tail 5.7e-7).
TEST(RenderMaterial, SamplingAgreesWithEvaluation) {
    Material m;
    m.diffuse = {0.3, 0.3, 0.3};
    m.glossy = {0.5, 0.5, 0.5};
    m.glossy_exponent = 20;
    const Vec3 n{0, 0, 1};
    for (double theta : {0.2, 0.9, 1.3}) {
        const Vec3 wo{std::sin(theta), 0, std::cos(theta)};
        const Bsdf bsdf(m, n, n, wo);
        Pcg32 rng(17, 3);
        const int count = 400000;
        double s1 = 0, q1 = 0, s2 = 0, q2 = 0;
        for (int i = 0; i < count; ++i) {
            BsdfSample s;
            double a = 0;
            if (bsdf.sample(rng.uniform(), rng.uniform(), rng.uniform(), s)) {
                a = s.weight.red;
                EXPECT_NEAR(s.pdf, bsdf.pdf(s.wi), 1e-9 * s.pdf);
            }
            s1 += a, q1 += a * a;
            const double z = rng.uniform(), phi = 2 * kPi * rng.uniform(), r = std::sqrt(1 - z * z);
            const double b = bsdf.eval({r * std::cos(phi), r * std::sin(phi), z}).red * 2 * kPi;
            s2 += b, q2 += b * b;
        }
        const double m1 = s1 / count, m2 = s2 / count;
        const double v = (q1 / count - m1 * m1 + q2 / count - m2 * m2) / count;
        EXPECT_NEAR(m1, m2, 5 * std::sqrt(v)) << "theta " << theta;
        EXPECT_LE(m2, 0.8 + 5 * std::sqrt(v));  // energy: never above diffuse + glossy albedo
    }
}

// The reversed density, as the bidirectional weights use it, against its definition: the pdf
// of the BSDF made for the other direction. Exactly equal (the same arithmetic) for materials
// with and without a mirror lobe, a glossy lobe, a bumped shading normal, directions on both
// sides.
TEST(RenderMaterial, ReversedPdfIsThePdfOfTheBsdfMadeForTheOtherDirection) {
    Material diffuse, glossy, mirror, bumped;
    diffuse.diffuse = {0.5, 0.4, 0.3};
    glossy.diffuse = {0.2, 0.2, 0.2};
    glossy.glossy = {0.5, 0.5, 0.5};
    glossy.glossy_exponent = 12;
    mirror = glossy;
    mirror.mirror_min = {0.1, 0.1, 0.1}, mirror.mirror_max = {0.8, 0.8, 0.8};
    bumped = glossy;
    bumped.bump = {0.2, -0.1, 0};
    Pcg32 rng(5, 1);
    auto direction = [&] {
        const double z = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform();
        const double r = std::sqrt(1 - z * z);
        return Vec3{r * std::cos(phi), r * std::sin(phi), z};
    };
    int positive = 0;
    for (const Material* m : {&diffuse, &glossy, &mirror, &bumped}) {
        for (int i = 0; i < 2000; ++i) {
            const Vec3 n = direction(), wo = direction(), wi = direction();
            const Vec3 shading = normalized(n + 0.2 * direction());
            const double reversed = Bsdf(*m, n, shading, wo).pdf_reversed(wi);
            EXPECT_EQ(reversed, Bsdf(*m, n, shading, wi).pdf(wo)) << "material " << m;
            positive += reversed > 0;
        }
    }
    EXPECT_GT(positive, 1500);  // about half the pairs have wi on wo's side, with a density
}

// finish { crand c } darkens the diffuse light by c u, u uniform in [0, 1) at each point
// (read back from POV-Ray: a white plane of diffuse 0.8 lit head-on shows max(0, 0.8 - c u)):
// here the albedo. Against the closed form of its mean, E max(0, a - c u) = a - c / 2 for
// c <= a, a^2 / (2 c) above, within 4.5 standard errors (two-sided normal tail 6.8e-6) over
// 20 000 random points; and against POV-Ray's render of such a plane in three quantiles, each
// within 0.015 (over 4 standard errors of a quantile of 20 000 samples of a density near 1,
// with POV-Ray's 8-bit steps of 0.004).
TEST(RenderMaterial, CrandDarkensTheDiffuseAlbedoAsPovRayDoes) {
    auto albedos = [](double crand) {
        const SceneDescription d =
            parse_scene_text("plane { y, 0 pigment { rgb 1 } finish { diffuse 0.8 crand " +
                                 std::to_string(crand) + " } }",
                             "test.pov");
        const ObjectMaterial material(d.objects.at(0), 1.0, ColourDecoding(d.global));
        Pcg32 random(7);
        std::vector<double> values;
        std::optional<Material> scratch;
        for (int i = 0; i < 20000; ++i) {
            const Vec3 p{100 * random.uniform() - 50, 0, 100 * random.uniform() - 50};
            values.push_back(material.at(p, {0, 1, 0}, scratch).diffuse.red);
        }
        return values;
    };
    for (const double crand : {0.3, 1.0}) {
        const std::vector<double> a = albedos(crand);
        double sum = 0, squares = 0;
        for (const double v : a) sum += v, squares += v * v;
        const double n = double(a.size()), mean = sum / n;
        const double se = std::sqrt((squares / n - mean * mean) / (n - 1));
        const double expected = crand <= 0.8 ? 0.8 - crand / 2 : 0.8 * 0.8 / (2 * crand);
        EXPECT_NEAR(mean, expected, 4.5 * se) << "crand " << crand;
        EXPECT_GE(*std::min_element(a.begin(), a.end()), std::max(0.0, 0.8 - crand));
        EXPECT_LE(*std::max_element(a.begin(), a.end()), 0.8);
    }

    test::ScratchDir dir;
    const std::string scene = dir.file("crand.pov");
    test::write_file(scene, R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 20, 0> look_at <0, 0, 0> right 24 * x up 16 * z sky z }
light_source { <0, 1e6, 0> colour rgb 1 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.8 crand 1 } }
)");
    std::vector<uint8_t> reference;
    std::string message;
    if (!test::povray_render(scene, 300, 200, reference, message)) GTEST_SKIP() << message;
    std::vector<double> povray;
    for (size_t i = 0; i < reference.size(); i += 3) povray.push_back(reference[i] / 255.0);
    std::vector<double> ours = albedos(1.0);
    auto quantile = [](std::vector<double> v, double q) {
        std::nth_element(v.begin(), v.begin() + long(q * double(v.size())), v.end());
        return v[size_t(q * double(v.size()))];
    };
    for (const double q : {0.1, 0.5, 0.9}) {
        std::printf("crand 1: quantile %.1f %.4f (POV-Ray %.4f)\n", q, quantile(ours, q),
                    quantile(povray, q));
        EXPECT_NEAR(quantile(ours, q), quantile(povray, q), 0.015) << "quantile " << q;
    }
}

// A metallic mirror (reflection 1, metallic 1, an orange pigment) under a white sky, seen from
// 30 to 88 degrees of incidence: what it reflects, the mirror's weight, against POV-Ray's
// render pixel for pixel (its tint fades toward white at grazing incidence), and as closed
// forms at normal incidence (the pigment) and at grazing incidence (white).
TEST(RenderMaterial, MetallicReflectionTakesThePigmentsTintAsPovRayDoes) {
    test::ScratchDir dir;
    const std::string scene_file = dir.file("metallic.pov");
    test::write_file(scene_file, R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 0, 0> angle 90 }
background { rgb 1 }
plane { y, 0 pigment { rgb <1, 0.5, 0.2> }
        finish { ambient 0 diffuse 0 reflection { 1 metallic 1 } } }
)");
    const SceneDescription d = parse_scene_file(scene_file);
    const ObjectMaterial material(d.objects.at(0), 1.0, ColourDecoding(d.global));
    const Vec3 up{0, 1, 0};
    std::optional<Material> scratch;
    auto reflected = [&](Vec3 wo) {
        const Material& m = material.at({0, 0, 0}, up, scratch);
        const BsdfOf<Rgb> bsdf(m, up, up, wo, NoWavelengths{});
        BsdfSampleOf<Rgb> sample;
        EXPECT_TRUE(bsdf.sample(0.5, 0.5, 0.5, sample));
        return sample.weight;
    };
    const Rgb normal = reflected(up);
    EXPECT_NEAR(normal.red, 1, 1e-7);  // colours are stored in single precision
    EXPECT_NEAR(normal.green, 0.5, 1e-7);
    EXPECT_NEAR(normal.blue, 0.2, 1e-7);
    const Rgb grazing = reflected(normalized(Vec3{0, 1e-9, 1}));
    EXPECT_NEAR(grazing.green, 1, 1e-6);
    EXPECT_NEAR(grazing.blue, 1, 1e-6);

    const int width = 160, height = 120;
    std::vector<uint8_t> reference;
    std::string message;
    if (!test::povray_render(scene_file, width, height, reference, message))
        GTEST_SKIP() << message;
    const SceneCamera camera(d.camera, width, height);
    int agree = 0, mirror = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const CameraRay ray = camera.ray(x + 0.5, y + 0.5);
            const bool hits_plane = ray.direction.y < 0;
            const Rgb ours = hits_plane ? reflected(-ray.direction) : Rgb{1, 1, 1};
            agree += test::agrees_with_povray(ours, &reference[3 * (size_t(y) * width + x)]);
            mirror += hits_plane;
        }
    std::printf("metallic mirror: %d of %d pixels agree (%d on the mirror)\n", agree,
                width * height, mirror);
    EXPECT_GT(mirror, width * height / 2);
    EXPECT_GE(agree, 0.98 * width * height);
}

}  // namespace
}  // namespace rayset::tracer
