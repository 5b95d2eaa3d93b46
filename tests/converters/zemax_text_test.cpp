// Zemax text source files: round trips, the tolerances the hand-made real files need, and every
// malformed line named by line and column.
#include "converters/formats/codecs.h"
#include "converters/rays/io.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

namespace rayset {
namespace {

using test::ScratchDir;

template <class F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no rayset::Error thrown";
    return {};
}

void expect_mentions(const std::string& message, std::initializer_list<std::string> parts) {
    for (const auto& p : parts)
        EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
}

uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

std::vector<Ray> read_all(RayDecoder& decoder) {
    std::vector<Ray> rays;
    RayChunk chunk;
    while (decoder.read(chunk, 4)) {
        EXPECT_EQ(chunk.first_index, rays.size());
        rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    }
    return rays;
}

std::vector<Ray> sample_rays(size_t n, bool wavelength) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> pos(-50, 50), dir(-1, 1), flux(1e-7f, 10), nm(380, 780);
    std::vector<Ray> rays(n);
    for (Ray& r : rays) {
        r.origin = {pos(rng), pos(rng), pos(rng)};
        float x = dir(rng), y = dir(rng), z = dir(rng), len = std::sqrt(x * x + y * y + z * z);
        r.direction = {x / len, y / len, z / len};
        r.radiant = flux(rng);
        if (wavelength) r.wavelength = nm(rng);
    }
    rays[0].origin = {-0.0f, 1e-30f, 3.4e38f};
    return rays;
}

std::string write_rays(const ScratchDir& dir, const std::vector<Ray>& rays, SpectralKind spectral,
                       uint64_t announced) {
    RayHeader h;
    h.has_radiant = true;
    h.spectral = spectral;
    h.ray_count = announced;
    h.unit = LengthUnit::ft;
    const std::string path = dir.file("rays.txt");
    auto encoder = create_zemax_text(path, h);
    RayChunk chunk;
    chunk.rays = rays;
    encoder->write(chunk);
    encoder->finish();
    return path;
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(ZemaxText, FluxOnlyRoundTripIsBitExact) {
    ScratchDir dir;
    const auto rays = sample_rays(50, false);
    const std::string path = write_rays(dir, rays, SpectralKind::none, 50);
    const std::string text = test::read_file(path);
    // Unit ft is code 3; the line is padded so a longer count fits when it is patched in.
    EXPECT_EQ(first_line(text), "50 3 0 0        ");
    auto decoder = open_zemax_text(path);
    EXPECT_EQ(decoder->header().format, RayFormat::zemax_text);
    EXPECT_EQ(decoder->header().ray_count, 50u);
    EXPECT_EQ(decoder->header().unit, LengthUnit::ft);
    EXPECT_EQ(decoder->header().spectral, SpectralKind::none);
    EXPECT_TRUE(std::isnan(decoder->header().stated_radiant));
    const auto back = read_all(*decoder);
    ASSERT_EQ(back.size(), rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(bits(back[i].origin.x), bits(rays[i].origin.x));
        EXPECT_EQ(back[i].origin, rays[i].origin);
        EXPECT_EQ(back[i].direction, rays[i].direction);
        EXPECT_EQ(bits(back[i].radiant), bits(rays[i].radiant));
    }
    EXPECT_EQ(decoder->locate(49).str(), "line 51");
}

TEST(ZemaxText, SpectralRoundTripKeepsWavelengthsToAFloatRounding) {
    ScratchDir dir;
    const auto rays = sample_rays(50, true);
    const std::string path = write_rays(dir, rays, SpectralKind::per_ray_wavelength, 50);
    EXPECT_EQ(first_line(test::read_file(path)), "50 3 2 0        ");
    auto decoder = open_zemax_text(path);
    EXPECT_EQ(decoder->header().spectral, SpectralKind::per_ray_wavelength);
    const auto back = read_all(*decoder);
    ASSERT_EQ(back.size(), rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(back[i].direction, rays[i].direction);
        EXPECT_EQ(bits(back[i].radiant), bits(rays[i].radiant));
        EXPECT_NEAR(back[i].wavelength, rays[i].wavelength, 1e-6 * rays[i].wavelength);
    }
}

// The header's count is only announced; the count written is the rays actually written.
TEST(ZemaxText, CountIsPatchedToTheRaysWritten) {
    ScratchDir dir;
    const std::string path = write_rays(dir, sample_rays(12, false), SpectralKind::none, 3);
    EXPECT_EQ(first_line(test::read_file(path)), "12 3 0 0        ");
    auto decoder = open_zemax_text(path);
    EXPECT_EQ(read_all(*decoder).size(), 12u);
}

// Hand-made files: CRLF, tabs and spaces mixed, blank lines, a first line padded with zeros and
// written as decimals, and ray format 0 with an eighth (wavelength) column.
TEST(ZemaxText, ToleratesWhitespaceAndHandMadeFirstLines) {
    ScratchDir dir;
    const std::string path = dir.file("hand.txt");
    test::write_file(path,
                     "\r\n 2.000000\t1.000000 0.000000 0.000000 0.000000 0 0 0\r\n"
                     "1 2 3\t0 0 1  0.5\t0.55\r\n"
                     "\r\n"
                     "  -1e-3 +2 3 1 0 0 2.5e2 0.6  \r\n\r\n");
    auto decoder = open_zemax_text(path);
    EXPECT_EQ(decoder->header().unit, LengthUnit::inch);
    EXPECT_EQ(decoder->header().spectral, SpectralKind::per_ray_wavelength);
    const auto rays = read_all(*decoder);
    ASSERT_EQ(rays.size(), 2u);
    EXPECT_EQ(rays[0].origin, (Vec3f{1, 2, 3}));
    EXPECT_EQ(rays[0].radiant, 0.5f);
    EXPECT_EQ(rays[0].wavelength, 550.0f);
    EXPECT_EQ(rays[1].origin, (Vec3f{-1e-3f, 2, 3}));
    EXPECT_EQ(rays[1].radiant, 250.0f);
    EXPECT_EQ(decoder->locate(1).str(), "line 5");
}

TEST(ZemaxText, LumensAreFluxType1) {
    ScratchDir dir;
    const std::string path = dir.file("lm.txt");
    test::write_file(path, "1 4 0 1\n0 0 0 0 0 1 7\n");
    auto decoder = open_zemax_text(path);
    EXPECT_TRUE(decoder->header().has_luminous);
    EXPECT_FALSE(decoder->header().has_radiant);
    EXPECT_EQ(read_all(*decoder)[0].luminous, 7.0f);
}

TEST(ZemaxText, SniffsOnlyZemaxText) {
    auto head = [](const std::string& s) { return Head(s.begin(), s.end()); };
    const std::string good = "2 4 0 0\n0 0 0 0 0 1 1\n0 0 0 0 0 1 1\n";
    EXPECT_TRUE(sniff_zemax_text(head(good), good.size()));
    const std::string bad[] = {
        "# LightTools\n",                        // another format
        "x,y,z,kx,ky,kz,flux\n0,0,0,0,0,1,1\n",  // CSV
        "2 4 0 0 1\n0 0 0 0 0 1 1\n",            // padding that is not 0
        "2 9 0 0\n0 0 0 0 0 1 1\n",              // unit code 9
        "2 4 1 0\n0 0 0 0 0 1 1\n",              // ray format 1
        "2 4 0 0\n0 0 0 0 0 1\n",                // a 6-column ray
        "380 0.001\n",                           // a spectrum
    };
    for (const auto& b : bad) EXPECT_FALSE(sniff_zemax_text(head(b), b.size())) << b;
}

// ---- bad input: every message names the file, the line and (for one value) the column --------
TEST(ZemaxText, BadInputNamesFileLineAndColumn) {
    struct Case {
        const char* text;
        std::vector<std::string> mentions;
    };
    const Case cases[] = {
        {"", {"empty"}},
        {"2 4 0\n", {"line 1:", "3 values"}},
        {"2 4 x 0\n", {"line 1, column 5:", "'x'"}},
        {"2.5 4 0 0\n", {"line 1, column 1:", "whole number"}},
        {"2 4 0 0 0 3\n", {"line 1, column 11:", "value 6 is 3"}},
        {"2 6 0 0\n", {"line 1, column 3:", "units code 6"}},
        {"2 4 1 0\n", {"line 1, column 5:", "ray format 1"}},
        {"2 4 0 2\n", {"line 1, column 7:", "flux type 2"}},
        {"2 4 2 1\n", {"line 1, column 7:", "lumens"}},
        {"-1 4 0 0\n", {"line 1, column 1:", "ray count -1"}},
        {"2 4 0 0\n", {"line 1:", "no ray follows"}},
        {"2 4 2 0\n0 0 0 0 0 1 1\n", {"line 2:", "7 columns", "ray format 2"}},
        {"2 4 0 1\n0 0 0 0 0 1 1 0.5\n", {"line 2:", "8 columns", "lumens"}},
        {"2 4 0 0\n0 0 0 0 0 1\n", {"line 2:", "6 columns"}},
        {"2 4 0 0\n0 0 0 0 0 1 1\n0 0 0 0 0 1 1 1\n", {"line 3:", "8 columns, expected 7"}},
        {"2 4 0 0\n0 0 0 0 0 1 1\n0 0 abc 0 0 1 1\n",
         {"line 3, column 5:", "column 3 (z) 'abc' is not a number"}},
        {"2 4 0 0\n0 0 0 0 0 1 1\n0 0 0 0 0 1 1,5\n", {"line 3, column 13:", "(flux) '1,5'"}},
        {"2 4 0 0\n0 0 0 0 0 1 1\n0 0 0 0 0 1 nan\n",
         {"line 3, column 13:", "not a finite number"}},
        {"2 4 0 0\n0 0 0 0 0 1 1\n0 1e39 0 0 0 1 1\n", {"line 3, column 3:", "out of float range"}},
        {"3 4 0 0\n0 0 0 0 0 1 1\n\n0 0 0 0 0 1 1\n", {"line 4:", "ends after 2 rays", "states 3"}},
        {"1 4 0 0\n0 0 0 0 0 1 1\n0 0 0 0 0 1 1\n", {"line 3:", "more rays", "states"}},
        {"0 4 0 0\n0 0 0 0 0 1 1\n", {"line 2:", "more rays"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        ScratchDir dir;
        const std::string path = dir.file("bad.txt");
        test::write_file(path, c.text);
        const std::string message = error_of([&] {
            auto decoder = open_zemax_text(path);
            read_all(*decoder);
        });
        expect_mentions(message, {path + ": "});
        for (const auto& m : c.mentions) expect_mentions(message, {m});
    }
}

}  // namespace
}  // namespace rayset
