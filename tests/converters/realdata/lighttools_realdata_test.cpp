// LightTools ray data exported by LightTools itself: the figures the files state, the binary and
// text exports of the same rays agreeing, the TM-25 export of Cyl10k agreeing with its text
// export, and real rays surviving our writers unchanged.
#include "converters/formats/codecs.h"
#include "converters/rays/ray_stream.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace rayset {
namespace {

using test::shared_data;

uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

std::vector<Ray> read_all(RayDecoder& decoder) {
    std::vector<Ray> rays;
    RayChunk chunk;
    while (decoder.read(chunk, 4096)) rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    return rays;
}

std::vector<Ray> read_all(RayReader& reader) {
    std::vector<Ray> rays;
    RayChunk chunk;
    while (reader.read(chunk)) rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    return rays;
}

std::array<float, 8> values(const Ray& r, bool photometric) {
    return {r.origin.x,
            r.origin.y,
            r.origin.z,
            r.direction.x,
            r.direction.y,
            r.direction.z,
            photometric ? r.luminous : r.radiant,
            r.wavelength};
}

// LightTools text exports print every float with 7 significant digits ("%.7g"): the value a text
// file holds is the binary float printed that way and read back.
float printed_7g(float binary) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", binary);
    return std::strtof(text, nullptr);
}

void expect_bit_identical(const std::vector<Ray>& a, const std::vector<Ray>& b, bool photometric) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        auto va = values(a[i], photometric), vb = values(b[i], photometric);
        for (size_t j = 0; j < va.size(); ++j) {
            if (std::isnan(va[j]) && std::isnan(vb[j])) continue;
            ASSERT_EQ(bits(va[j]), bits(vb[j])) << "ray " << i << " value " << j;
        }
    }
}

TEST(LightToolsRealData, ThreeRaysPowerOnlyFigures) {
    RAYSET_REQUIRE_SHARED_DATA();
    const std::string path = shared_data("rayfiles/RayFileConverter_ThreeRays_PowerOnly.1.ray");
    EXPECT_EQ(detect_ray_format(path), RayFormat::lighttools_binary);
    auto d = open_lighttools_binary(path);
    const RayHeader& h = d->header();
    EXPECT_TRUE(d->flux_is_relative());
    EXPECT_EQ(h.ray_count, 3u);  // (135 - 44 - 7) / 28
    EXPECT_EQ(h.unit, LengthUnit::mm);
    EXPECT_TRUE(h.has_radiant);
    EXPECT_FALSE(h.has_luminous);
    EXPECT_EQ(h.spectral, SpectralKind::none);
    EXPECT_EQ(h.data_origin, (Vec3f{0, 0, 0}));
    // The text export of these rays states 0.003106601 W (7 digits: +-5e-10).
    EXPECT_NEAR(h.stated_radiant, 0.003106601, 5e-10);
    // The decoder hands out the raw relative values, which sum to 3x the header.
    double sum = 0;
    for (const Ray& r : read_all(*d)) sum += r.radiant;
    EXPECT_NEAR(sum / h.stated_radiant, 3.0, 3e-7);  // three f32 values: a few ulp

    // The reader scales them to the header total.
    auto reader = open_rays(path);
    EXPECT_NEAR(reader->radiant_scale(), 1.0 / 3, 1e-7);
    std::vector<Ray> scaled = read_all(*reader);
    EXPECT_NEAR(reader->totals().radiant / h.stated_radiant, 1.0, 1e-6);
    EXPECT_EQ(reader->totals().rays, 3u);
}

TEST(LightToolsRealData, ThreeRaysWavelengthMatchesPowerOnly) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto power =
        open_lighttools_binary(shared_data("rayfiles/RayFileConverter_ThreeRays_PowerOnly.1.ray"));
    auto colour =
        open_lighttools_binary(shared_data("rayfiles/RayFileConverter_ThreeRays_Wavelength.1.ray"));
    EXPECT_EQ(colour->header().spectral, SpectralKind::per_ray_wavelength);
    EXPECT_EQ(colour->header().ray_count, 3u);  // (147 - 44 - 7) / 32
    EXPECT_EQ(colour->header().stated_radiant, power->header().stated_radiant);
    std::vector<Ray> p = read_all(*power), c = read_all(*colour);
    ASSERT_EQ(c.size(), 3u);
    const float nm[3] = {550, 450, 620};
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(c[i].wavelength, nm[i]);
        c[i].wavelength = kUnknown;  // the rest is the same export
    }
    expect_bit_identical(p, c, false);
}

TEST(LightToolsRealData, BinaryAndTextExportsGiveTheSameRays) {
    RAYSET_REQUIRE_SHARED_DATA();
    const std::string text_path =
        shared_data("rayfiles/RayFileConverter_ThreeRays_Wavelength.1.txt");
    EXPECT_EQ(detect_ray_format(text_path), RayFormat::lighttools_text);
    auto b =
        open_lighttools_binary(shared_data("rayfiles/RayFileConverter_ThreeRays_Wavelength.1.ray"));
    auto t = open_lighttools_text(text_path);
    const RayHeader &hb = b->header(), &ht = t->header();
    EXPECT_TRUE(t->flux_is_relative());
    EXPECT_EQ(ht.ray_count, 3u);
    EXPECT_EQ(ht.unit, hb.unit);
    EXPECT_EQ(ht.has_radiant, hb.has_radiant);
    EXPECT_EQ(ht.spectral, hb.spectral);
    EXPECT_EQ(ht.data_origin, hb.data_origin);
    EXPECT_EQ(float(ht.stated_radiant), printed_7g(float(hb.stated_radiant)));
    EXPECT_EQ(ht.description, "LightTools 2024.03\nRay Data Export File");
    EXPECT_EQ(ht.text[0], "untitledRayData");
    std::vector<Ray> rb = read_all(*b), rt = read_all(*t);
    ASSERT_EQ(rt.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        auto vb = values(rb[i], false), vt = values(rt[i], false);
        for (size_t j = 0; j < 8; ++j)
            EXPECT_EQ(bits(vt[j]), bits(printed_7g(vb[j]))) << "ray " << i << " value " << j;
    }
}

TEST(LightToolsRealData, Cyl10kTextFigures) {
    RAYSET_REQUIRE_SHARED_DATA();
    const std::string path = shared_data("rayfiles/Cyl10k.1.ray");
    ASSERT_NE(test::read_file(path).find("lt_startofdata\r\n"), std::string::npos);  // CRLF file
    EXPECT_EQ(detect_ray_format(path), RayFormat::lighttools_text);
    auto d = open_lighttools_text(path);
    const RayHeader& h = d->header();
    EXPECT_EQ(h.ray_count, 10000u);
    EXPECT_TRUE(h.has_luminous);
    EXPECT_FALSE(h.has_radiant);
    EXPECT_EQ(h.stated_luminous, 1.0);  // "lt_radiant_flux: 1" beside "lt_datatype: luminous_flux"
    EXPECT_EQ(h.spectral, SpectralKind::none);
    EXPECT_EQ(h.description, "LightTools 8.7.0\nRay Data Export File");
    double sum = 0;
    std::vector<Ray> rays = read_all(*d);
    for (const Ray& r : rays) sum += r.luminous;
    EXPECT_NEAR(sum, 10000,
                1e-2);  // 10000 values of 7 digits each: rounding errors of ~1e-7 relative
    EXPECT_EQ(rays[0].origin,
              (Vec3f{-5.912486f, 7.240707e-16f, 1.935107f}));  // first row of the file
    EXPECT_EQ(rays[9999].luminous, 1.21945f);                  // last row
}

// The TM-25 export of the same LightTools source: same rays, fluxes on another scale.
TEST(LightToolsRealData, Cyl10kTextMatchesTm25Export) {
    RAYSET_REQUIRE_SHARED_DATA();
    RayReadOptions options;
    options.flux_policy = FluxPolicy::stated;  // both files state 1 lm; their rays sum to 10000
    auto text = open_rays(shared_data("rayfiles/Cyl10k.1.ray"), options);
    auto tm25 = open_rays(shared_data("rayfiles/Cyl10k.1.tm25ray"), options);
    std::vector<Ray> rt = read_all(*text), rm = read_all(*tm25);
    ASSERT_EQ(rt.size(), 10000u);
    ASSERT_EQ(rm.size(), 10000u);
    EXPECT_NEAR(text->totals().luminous, 1.0, 1e-6);
    EXPECT_NEAR(tm25->totals().luminous, 1.0, 1e-6);
    for (size_t i = 0; i < rt.size(); ++i) {
        auto vt = values(rt[i], true), vm = values(rm[i], true);
        for (size_t j = 0; j < 6; ++j)
            ASSERT_EQ(bits(vt[j]), bits(printed_7g(vm[j]))) << "ray " << i << " value " << j;
        // 7 printed digits: at most 5e-7 relative, plus f32 rounding of the scaled values.
        ASSERT_NEAR(vt[6] / vm[6], 1.0, 1e-6) << "ray " << i;
    }
}

// Real rays through our writers and back: nothing changes, bit for bit.
TEST(LightToolsRealData, RealRaysSurviveEveryWriter) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    const struct {
        const char* file;
        bool photometric;
    } sources[] = {{"rayfiles/RayFileConverter_ThreeRays_Wavelength.1.ray", false},
                   {"rayfiles/Cyl10k.1.ray", true}};
    for (const auto& source : sources) {
        auto original = open_rays(shared_data(source.file));
        const RayHeader header = original->header();
        std::vector<Ray> rays = read_all(*original);
        for (RayFormat format :
             {RayFormat::lighttools_binary, RayFormat::lighttools_text, RayFormat::csv}) {
            SCOPED_TRACE(std::string(source.file) + " as " + to_string(format));
            const std::string out = dir.file(std::string("copy.") + to_string(format));
            auto in = open_rays(shared_data(source.file));
            auto writer = create_rays(out, format, in->header());
            copy_rays(*in, *writer);
            auto back = open_rays(out);
            EXPECT_EQ(detect_ray_format(out), format);
            EXPECT_EQ(back->header().unit, header.unit);
            EXPECT_EQ(back->header().spectral, header.spectral);
            if (format != RayFormat::lighttools_binary && !header.description.empty()) {
                EXPECT_EQ(back->header().description, header.description);
            }
            EXPECT_EQ(back->radiant_scale(), 1.0);  // the written total agrees with the rays
            EXPECT_EQ(back->luminous_scale(), 1.0);
            expect_bit_identical(rays, read_all(*back), source.photometric);
        }
    }
}

}  // namespace
}  // namespace rayset
