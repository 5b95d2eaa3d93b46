#include "converters/colour/spectrum.h"
#include "converters/rays/ray_stream.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rayset {
namespace {

// OSRAM's blue chip file states 1.68 W radiant and 54.644249 lm luminous, with one 76-point
// relative spectral table (390..510 nm, 1.6 nm steps). Its luminous figure must follow from the
// radiant one and the table. Measured: 54.644411 lm with Km = 683.002 lm/W (2.96e-6 relative
// above), 54.644251 lm with Km = 683 lm/W (4e-8): OSRAM used 683 and an integral as exact as
// ours. The bound covers the Km convention (683.002/683 - 1 = 2.9e-6) plus the header's f32
// rounding (7e-8); a trapezoid rule on the table's points alone (54.6260 lm, 3.4e-4 low)
// would fail it.
TEST(SpectrumRealData, OsramBlueLuminousFluxFollowsFromItsSpectralTable) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto reader = open_rays(
        test::shared_data("rayfiles/rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY"));
    const RayHeader& file = reader->file_header();
    ASSERT_EQ(file.spectral, SpectralKind::shared_table);
    ASSERT_EQ(file.spectral_tables.size(), 1u);
    ASSERT_EQ(file.spectral_tables[0].wavelength.size(), 76u);
    EXPECT_FLOAT_EQ(float(file.stated_radiant), 1.68f);
    EXPECT_FLOAT_EQ(float(file.stated_luminous), 54.644249f);

    const double efficacy = luminous_efficacy(file.spectral_tables[0]);
    EXPECT_NEAR(1.68 * efficacy / 54.644249, 1, 5e-6);
    EXPECT_NEAR(1.68 * efficacy * 683 / kMaxLuminousEfficacy / 54.644249, 1, 2e-7);

    // Per ray: radiant columns only, luminous follows; they sum to the stated figure.
    PhotometricWeights weights(reader->header());
    ASSERT_TRUE(weights.luminous_known());
    double radiant = 0, luminous = 0;
    RayChunk chunk;
    while (reader->read(chunk))
        for (const Ray& r : chunk.rays)
            radiant += weights.radiant(r), luminous += weights.luminous(r);
    EXPECT_NEAR(radiant, 1.68, 1.68 * 1e-6);
    EXPECT_NEAR(luminous / 54.644249, 1, 5e-6);
}

// The synthetic point source is monochromatic at 500 nm: every ray's efficacy is Km V(500).
TEST(SpectrumRealData, SingleWavelengthFileHasTheEfficacyOfItsLine) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto reader =
        open_rays(test::shared_data("rayfiles/CreatePointSourceRayFile_farfield.TM25ray"));
    ASSERT_EQ(reader->header().spectral, SpectralKind::single_wavelength);
    EXPECT_EQ(reader->header().single_wavelength, 500.0f);
    PhotometricWeights weights(reader->header());
    RayChunk chunk;
    ASSERT_TRUE(reader->read(chunk));
    EXPECT_DOUBLE_EQ(weights.efficacy(chunk.rays[0]), kMaxLuminousEfficacy * 0.323);
    EXPECT_DOUBLE_EQ(weights.luminous(chunk.rays[0]),
                     chunk.rays[0].radiant * kMaxLuminousEfficacy * 0.323);
}

// LightTools' simulated cylinder carries luminous flux only, no spectrum: its power is unknown.
TEST(SpectrumRealData, LuminousOnlyFileHasNoKnownRadiantFlux) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto reader = open_rays(test::shared_data("rayfiles/Cyl10k.1.tm25ray"));
    PhotometricWeights weights(reader->header());
    EXPECT_TRUE(weights.luminous_known());
    EXPECT_FALSE(weights.radiant_known());
}

}  // namespace
}  // namespace rayset
