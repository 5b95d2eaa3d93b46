// The PNG preview: the 99th percentile of the lit pixels' largest channel maps to white, so a
// small bright source on black (the direct-visibility layer) is exposed for the source; a
// pixel too bright keeps its hue.
#include <cmath>

#include <gtest/gtest.h>

#include "tracer/film/film.h"
#include "tracer/film/image_writers.h"

namespace rayset::tracer {
namespace {

// sRGB encoding (IEC 61966-2-1) of a linear value in [0, 1], as an 8-bit code.
int srgb_code(double v) {
    return int(
        std::lround(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055)));
}

TEST(FilmPreview, AutomaticExposureIgnoresBlackPixels) {
    // 100 x 100 pixels, black but for 200 grey pixels of radiance 1..200 (2% of the image).
    Film film(100, 100);
    for (int k = 0; k < 200; ++k) film.add(k % 100, k / 100, {k + 1.0, k + 1.0, k + 1.0});
    film.finish_pass();
    const std::vector<uint8_t> rgb = tone_map_srgb(film, 0);
    // Of the 200 lit values the 99th percentile is the 199th smallest, 199: exposure 1/199.
    auto code = [&](int k) { return int(rgb[size_t(3 * k)]); };
    EXPECT_EQ(code(198), 255);                    // 199 / 199
    EXPECT_EQ(code(99), srgb_code(100.0 / 199));  // a mid value keeps its place
    EXPECT_EQ(code(0), srgb_code(1.0 / 199));
    EXPECT_EQ(code(5000), 0);  // black stays black
    // An explicit exposure is used as given.
    EXPECT_EQ(int(tone_map_srgb(film, 1.0 / 50)[3 * 24]), srgb_code(25.0 / 50));
}

TEST(FilmPreview, TooBrightPixelsKeepTheirHue) {
    Film film(2, 1);
    film.add(0, 0, {0.2, 0.1, 4.0});  // a bright saturated blue
    film.add(1, 0, {0.1, 0.1, 0.1});
    film.finish_pass();
    const std::vector<uint8_t> rgb = tone_map_srgb(film, 1);
    // Scaled by 1/4 as a whole: (0.05, 0.025, 1), not clamped to (0.2, 0.1, 1).
    EXPECT_EQ(int(rgb[0]), srgb_code(0.05));
    EXPECT_EQ(int(rgb[1]), srgb_code(0.025));
    EXPECT_EQ(int(rgb[2]), 255);
    EXPECT_EQ(int(rgb[3]), srgb_code(0.1));
}

}  // namespace
}  // namespace rayset::tracer
