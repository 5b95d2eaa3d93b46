// The four real TM-25 files in ../shared/data/rayfiles: their figures as data/README.md and
// formats.md state them (and, where those say nothing, as an independent Python reading of the
// bytes found them), and a byte-identical write-back through the encoder.
#include "converters/formats/codecs.h"
#include "converters/rays/ray_stream.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace rayset {
namespace {

using test::ScratchDir;

const char* const kOsram = "rayfiles/rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY";
const char* const kCyl10k = "rayfiles/Cyl10k.1.tm25ray";
const char* const kFaberge = "rayfiles/Cyl1M_Faberge.1.tm25ray";
const char* const kPointSource = "rayfiles/CreatePointSourceRayFile_farfield.TM25ray";

uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

struct Scan {
    uint64_t rays = 0;
    double radiant = 0, luminous = 0;
    float min_radiant = INFINITY, max_radiant = -INFINITY;
    double worst_direction = 0;  // largest | |k| - 1 |
};

Scan scan(RayDecoder& decoder) {
    Scan s;
    RayChunk chunk;
    while (decoder.read(chunk, 1 << 14)) {
        for (const Ray& r : chunk.rays) {
            if (decoder.header().has_radiant) {
                s.radiant += r.radiant;
                s.min_radiant = std::min(s.min_radiant, r.radiant);
                s.max_radiant = std::max(s.max_radiant, r.radiant);
            }
            if (decoder.header().has_luminous) s.luminous += r.luminous;
            const Vec3f& d = r.direction;
            double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
            s.worst_direction = std::max(s.worst_direction, std::abs(length - 1));
        }
        s.rays += chunk.size();
    }
    return s;
}

// Decodes `relative` and encodes it again with the decoder's own header; returns the offset of
// the first byte that differs, or -1 when the files are identical.
int64_t first_difference_after_rewrite(const std::string& relative) {
    std::string original = test::shared_data(relative);
    ScratchDir dir;
    std::string copy = dir.file("copy.tm25ray");
    auto decoder = open_tm25(original);
    auto encoder = create_tm25(copy, decoder->header());
    RayChunk chunk;
    while (decoder->read(chunk, 7777)) encoder->write(chunk);
    encoder->finish();
    EXPECT_TRUE(encoder->dropped().empty());
    std::string a = test::read_file(original), b = test::read_file(copy);
    auto mismatch = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
    if (mismatch.first == a.end() && mismatch.second == b.end()) return -1;
    return mismatch.first - a.begin();
}

TEST(Tm25RealData, OsramBlueChip) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto decoder = open_tm25(test::shared_data(kOsram));
    const RayHeader& h = decoder->header();
    EXPECT_EQ(h.ray_count, 100000u);
    EXPECT_EQ(h.creation_method, 1);  // measured
    EXPECT_EQ(h.stated_radiant, double(1.68f));
    EXPECT_NEAR(h.stated_luminous, 54.64, 0.005);
    EXPECT_TRUE(h.has_radiant);
    EXPECT_FALSE(h.has_luminous);
    EXPECT_TRUE(h.extras.empty());
    EXPECT_EQ(h.spectral, SpectralKind::shared_table);
    ASSERT_EQ(h.spectral_tables.size(), 1u);
    ASSERT_EQ(h.spectral_tables[0].wavelength.size(), 76u);
    EXPECT_EQ(h.spectral_tables[0].wavelength.front(), 390.0f);
    EXPECT_EQ(h.spectral_tables[0].wavelength.back(), 510.0f);
    EXPECT_EQ(h.min_wavelength, 390.0f);
    EXPECT_EQ(h.max_wavelength, 510.0f);
    EXPECT_EQ(bits(h.single_wavelength), 0x7F800001u);  // "unknown" as a signalling NaN, kept as is
    EXPECT_EQ(h.creation_date, "2016-10-13 13:24:12");
    EXPECT_EQ(h.text[0], "LERTDUW_S2WP");
    EXPECT_EQ(h.text[1], "OSRAM Opto Semiconductors GmbH");
    EXPECT_EQ(h.text[4], "Rigo 801");
    EXPECT_EQ(decoder->locate(0).str(),
              "byte 36928");  // 76-point table padded from 612 to 640 bytes

    Scan s = scan(*decoder);
    EXPECT_EQ(s.rays, 100000u);
    // Every ray carries 1.68 W / 100000 rounded to float (relative error <= 2^-24), and the
    // header total is 1.68 rounded to float: the two agree to 2^-23 relative.
    EXPECT_NEAR(s.radiant, 1.68f, 1.68 * std::ldexp(1.0, -23));
    EXPECT_EQ(s.min_radiant, s.max_radiant);  // equal-flux rays
    EXPECT_LT(s.worst_direction, 1e-6);
}

TEST(Tm25RealData, LightToolsCylinder10k) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto decoder = open_tm25(test::shared_data(kCyl10k));
    const RayHeader& h = decoder->header();
    EXPECT_EQ(h.ray_count, 10000u);
    EXPECT_EQ(h.creation_method, 0);  // simulated
    EXPECT_EQ(h.spectral, SpectralKind::none);
    EXPECT_FALSE(h.has_radiant);
    EXPECT_TRUE(h.has_luminous);
    EXPECT_EQ(h.stated_luminous, 1.0);
    EXPECT_EQ(h.stated_radiant, 0.0);  // "unknown" written as 0 by LightTools
    EXPECT_EQ(h.text[3], "LightTools 8.7.0 ");
    EXPECT_EQ(h.creation_date, "");
    EXPECT_EQ(decoder->locate(0).str(), "byte 36288");
    Scan s = scan(*decoder);
    EXPECT_EQ(s.rays, 10000u);
    // The rays sum to 10^4 times the header's total (Python: 9999.99999935).
    EXPECT_NEAR(s.luminous, 10000.0, 1e-3);
    EXPECT_LT(s.worst_direction, 1e-6);
}

TEST(Tm25RealData, LightToolsFaberge) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto decoder = open_tm25(test::shared_data(kFaberge));
    const RayHeader& h = decoder->header();
    EXPECT_EQ(h.ray_count, 126281u);
    EXPECT_EQ(h.spectral, SpectralKind::none);
    EXPECT_TRUE(h.has_luminous);
    EXPECT_FALSE(h.has_radiant);
    EXPECT_EQ(h.stated_luminous, double(0.05150245f));
    Scan s = scan(*decoder);
    EXPECT_EQ(s.rays, 126281u);
    // Python: 51502.45121; 10^6 times the header's total.
    EXPECT_NEAR(s.luminous, 51502.4512, 1e-3);
    EXPECT_LT(s.worst_direction, 1e-6);
}

TEST(Tm25RealData, PointSourceWithInconsistentHeader) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto decoder = open_tm25(test::shared_data(kPointSource));
    const RayHeader& h = decoder->header();
    EXPECT_EQ(h.ray_count, 100000u);
    EXPECT_TRUE(h.has_radiant);
    EXPECT_FALSE(h.has_luminous);
    EXPECT_EQ(h.spectral, SpectralKind::single_wavelength);
    EXPECT_EQ(h.single_wavelength, 500.0f);
    EXPECT_EQ(bits(h.min_wavelength), 0x7FC00001u);
    EXPECT_EQ(h.stated_radiant, 1.0);
    EXPECT_TRUE(std::isnan(h.stated_luminous));
    EXPECT_EQ(h.creation_date, "2025-02-24T15:22:34+0100");
    Scan s = scan(*decoder);
    EXPECT_EQ(s.rays, 100000u);
    EXPECT_NEAR(s.radiant, 31350, 0.5);  // README: rays sum to 31350 although the header says 1 W
    EXPECT_LT(s.worst_direction, 1e-6);
}

TEST(Tm25RealData, EveryFileWritesBackByteIdentical) {
    RAYSET_REQUIRE_SHARED_DATA();
    for (const char* file : {kOsram, kCyl10k, kFaberge, kPointSource})
        EXPECT_EQ(first_difference_after_rewrite(file), -1) << file;
}

// The same through the generic reader and writer (what `rayconv` does for TM-25 -> TM-25).
TEST(Tm25RealData, CopyThroughRayReaderIsByteIdentical) {
    RAYSET_REQUIRE_SHARED_DATA();
    for (const char* file : {kOsram, kPointSource}) {
        SCOPED_TRACE(file);
        ScratchDir dir;
        std::string copy = dir.file("copy.tm25ray");
        auto reader = open_rays(test::shared_data(file));
        EXPECT_EQ(reader->header().format, RayFormat::tm25);
        auto writer = create_rays(copy, RayFormat::tm25, reader->header());
        copy_rays(*reader, *writer);
        EXPECT_TRUE(test::read_file(copy) == test::read_file(test::shared_data(file)));
    }
}

}  // namespace
}  // namespace rayset
