// The colour of emitted light (lightmodel/colour.h) against independent truths: CIE 1931
// table values, the tabulated V(lambda) the photometry uses, and the sRGB standard's own
// forward matrix (its primaries and white must come back as pure channels and grey).
#include <cmath>

#include <gtest/gtest.h>

#include "converters/colour/spectrum.h"
#include "lightmodel/colour.h"

namespace rayset::lightmodel {
namespace {

TEST(Colour, MatchingFunctionsFollowTheCieTables) {
    // CIE 1931 2-degree values (CIE 15:2004 table) at a few wavelengths; the analytic fit is
    // stated to be within a few hundredths of the peak values.
    struct Row {
        double nm, x, y, z;
    };
    const Row table[] = {{450, 0.3362, 0.0380, 1.7721},
                         {500, 0.0049, 0.3230, 0.2720},
                         {550, 0.4334, 0.9950, 0.0087},
                         {600, 1.0622, 0.6310, 0.0008},
                         {650, 0.2835, 0.1070, 0.0000}};
    for (const Row& r : table) {
        const Xyz c = colour_matching(r.nm);
        EXPECT_NEAR(c.x, r.x, 0.03) << r.nm;
        EXPECT_NEAR(c.y, r.y, 0.03) << r.nm;
        EXPECT_NEAR(c.z, r.z, 0.04) << r.nm;
    }
    // y-bar is V(lambda): the fit against the table the photometry uses, every nanometre.
    double worst = 0;
    for (int nm = 380; nm <= 780; ++nm)
        worst = std::max(worst, std::fabs(colour_matching(nm).y - photopic_efficiency(nm)));
    EXPECT_LT(worst, 0.03);
}

TEST(Colour, SrgbPrimariesAndWhiteComeBackPure) {
    // XYZ of the sRGB primaries and of D65 (IEC 61966-2-1): each must give one channel alone,
    // or grey, with the luminance asked for.
    const double efficacy = 300;  // lm per unit
    const double y = efficacy / kRgbLumensPerWatt;
    const Rgb red = colour_per_flux({0.4124, 0.2126, 0.0193}, efficacy);
    const Rgb green = colour_per_flux({0.3576, 0.7152, 0.1192}, efficacy);
    const Rgb blue = colour_per_flux({0.1805, 0.0722, 0.9505}, efficacy);
    const Rgb white = colour_per_flux({0.95047, 1.0, 1.08883}, efficacy);
    EXPECT_NEAR(red.red, y / 0.2126, 1e-3 * y / 0.2126);
    EXPECT_NEAR(red.green, 0, 1e-3);
    EXPECT_NEAR(red.blue, 0, 1e-3);
    EXPECT_NEAR(green.green, y / 0.7152, 1e-3 * y / 0.7152);
    EXPECT_NEAR(green.red, 0, 1e-3);
    EXPECT_NEAR(green.blue, 0, 1e-3);
    EXPECT_NEAR(blue.blue, y / 0.0722, 1e-3 * y / 0.0722);
    EXPECT_NEAR(blue.red, 0, 1e-3);
    EXPECT_NEAR(blue.green, 0, 1e-3);
    for (double channel : {white.red, white.green, white.blue}) EXPECT_NEAR(channel, y, 1e-3 * y);
    // Unknown spectrum: grey.
    const Rgb grey = colour_per_flux({}, efficacy);
    EXPECT_EQ(grey.red, y);
    EXPECT_EQ(grey.green, y);
    EXPECT_EQ(grey.blue, y);
}

TEST(Colour, SpectralColoursKeepTheirLuminanceAndHue) {
    // Monochromatic light lies outside the gamut: desaturated until no channel is negative,
    // with the luminance (so lux and cd/m^2) unchanged and the dominant channel kept.
    SpectralBins bins;
    for (int b = 0; b < bins.count; ++b) {
        const double efficacy = kMaxLuminousEfficacy * photopic_efficiency(bins.centre(b));
        const Rgb c = colour_per_flux(bin_colour_matching(bins, b), efficacy);
        EXPECT_NEAR(luminance(c), efficacy / kRgbLumensPerWatt, 1e-9 * (1 + efficacy))
            << bins.centre(b);
        EXPECT_GE(std::min({c.red, c.green, c.blue}), -1e-12) << bins.centre(b);
    }
    auto colour_at = [&](double nm) {
        return colour_per_flux(bin_colour_matching(bins, bins.bin_of(nm)), 1);
    };
    const Rgb red = colour_at(630), green = colour_at(530), blue = colour_at(460);
    EXPECT_GT(red.red, 5 * red.green);
    EXPECT_GT(red.red, 5 * red.blue);
    EXPECT_GT(green.green, 2 * green.red);
    EXPECT_GT(green.green, 2 * green.blue);
    EXPECT_GT(blue.blue, 5 * blue.red);
    EXPECT_GT(blue.blue, 5 * blue.green);
}

}  // namespace
}  // namespace rayset::lightmodel
