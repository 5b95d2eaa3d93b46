// SPEOS binary .ray: round trips, the totals the writer states, strict detection, bad sizes and
// headers.
#include "converters/colour/spectrum.h"
#include "converters/formats/codecs.h"
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
    while (decoder.read(chunk, 3)) {
        EXPECT_EQ(chunk.first_index, rays.size());
        rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    }
    return rays;
}

std::vector<Ray> sample_rays(size_t n) {
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> pos(-10, 10), dir(-1, 1), weight(0, 1), nm(380, 780);
    std::vector<Ray> rays(n);
    for (Ray& r : rays) {
        r.origin = {pos(rng), pos(rng), pos(rng)};
        float x = dir(rng), y = dir(rng), z = dir(rng), len = std::sqrt(x * x + y * y + z * z);
        r.direction = {x / len, y / len, z / len};
        r.radiant = weight(rng);
        r.wavelength = nm(rng);
    }
    rays[0].origin = {-0.0f, 1e-30f, -3.4e38f};
    return rays;
}

double sum_of(const std::vector<Ray>& rays) {
    double s = 0;
    for (const Ray& r : rays) s += r.radiant;
    return s;
}

void write_speos(const std::string& path, const RayHeader& h, const std::vector<Ray>& rays) {
    auto encoder = create_speos(path, h);
    RayChunk chunk;
    chunk.rays = rays;
    encoder->write(chunk);
    encoder->finish();
}

std::vector<float> header_floats(const std::string& path) {
    const std::string bytes = test::read_file(path);
    std::vector<float> h(7);
    std::memcpy(h.data(), bytes.data(), 28);
    return h;
}

// A SPEOS file by hand: header values and 8-float records.
std::string speos_bytes(std::vector<float> header, const std::vector<float>& records) {
    header.insert(header.end(), records.begin(), records.end());
    return std::string(reinterpret_cast<const char*>(header.data()), header.size() * 4);
}

TEST(Speos, RoundTripIsBitExactIncludingWavelengths) {
    ScratchDir dir;
    const auto rays = sample_rays(40);
    RayHeader h;
    h.has_radiant = true;
    h.stated_radiant = sum_of(rays);
    h.stated_luminous = 123.5;
    h.spectral = SpectralKind::per_ray_wavelength;
    const std::string path = dir.file("out.ray");
    write_speos(path, h, rays);
    EXPECT_EQ(test::read_file(path).size(), 28u + 32u * rays.size());
    EXPECT_EQ(header_floats(path),
              (std::vector<float>{float(h.stated_radiant), 2, 2, 2, 2, 2, 123.5f}));

    auto decoder = open_speos(path);
    const RayHeader& r = decoder->header();
    EXPECT_EQ(r.format, RayFormat::speos);
    EXPECT_EQ(r.ray_count, rays.size());
    EXPECT_EQ(r.unit, LengthUnit::mm);
    EXPECT_TRUE(r.has_radiant);
    EXPECT_FALSE(r.has_luminous);
    EXPECT_EQ(r.spectral, SpectralKind::per_ray_wavelength);
    EXPECT_EQ(r.stated_radiant, double(float(h.stated_radiant)));
    EXPECT_EQ(r.stated_luminous, 123.5);
    EXPECT_TRUE(decoder->flux_is_relative());
    const auto back = read_all(*decoder);
    ASSERT_EQ(back.size(), rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(bits(back[i].origin.x), bits(rays[i].origin.x));
        EXPECT_EQ(back[i].origin, rays[i].origin);
        EXPECT_EQ(back[i].direction, rays[i].direction);
        EXPECT_EQ(bits(back[i].radiant), bits(rays[i].radiant));
        EXPECT_EQ(bits(back[i].wavelength), bits(rays[i].wavelength));
    }
    EXPECT_EQ(decoder->locate(2).str(), "byte 92");
}

// With no stated luminous total the writer states what V(lambda) gives the rays: at 555 nm
// V = 1 by definition, so 683.002 lm/W times the radiant total; at 1000 nm V = 0.
TEST(Speos, LuminousTotalFollowsPhotopicEfficiencyWhenNotStated) {
    ScratchDir dir;
    auto rays = sample_rays(5);
    RayHeader h;
    h.has_radiant = true;
    h.spectral = SpectralKind::single_wavelength;
    h.single_wavelength = 555;
    write_speos(dir.file("a.ray"), h, rays);
    const auto a = header_floats(dir.file("a.ray"));
    EXPECT_EQ(a[0], float(sum_of(rays)));
    EXPECT_FLOAT_EQ(a[6], float(kMaxLuminousEfficacy * sum_of(rays)));
    auto decoder = open_speos(dir.file("a.ray"));
    for (const Ray& r : read_all(*decoder)) EXPECT_EQ(r.wavelength, 555.0f);

    h.single_wavelength = 1000;
    write_speos(dir.file("b.ray"), h, rays);
    EXPECT_EQ(header_floats(dir.file("b.ray"))[6], 0.0f);
}

// E is relative: the reader scales the weights to the radiant total, 1 : 3 of 2 W.
TEST(Speos, ReaderScalesWeightsToTheRadiantTotal) {
    ScratchDir dir;
    const std::string path = dir.file("w.ray");
    test::write_file(path, speos_bytes({2, 2, 2, 2, 2, 2, 1366},
                                       {0, 0, 0, 0, 0, 1, 555, 1, /**/ 0, 0, 0, 0, 0, 1, 555, 3}));
    auto reader = open_rays(path);
    EXPECT_EQ(reader->file_header().format, RayFormat::speos);
    RayChunk chunk;
    std::vector<float> flux;
    while (reader->read(chunk))
        for (const Ray& r : chunk.rays) flux.push_back(r.radiant);
    EXPECT_EQ(flux, (std::vector<float>{0.5f, 1.5f}));
}

TEST(Speos, WriterRefusesRaysItCannotHold) {
    ScratchDir dir;
    RayHeader luminous_only;
    luminous_only.has_luminous = true;
    luminous_only.spectral = SpectralKind::per_ray_wavelength;
    expect_mentions(error_of([&] { create_speos(dir.file("a.ray"), luminous_only); }),
                    {"a.ray", "no radiant flux"});
    RayHeader no_wavelength;
    no_wavelength.has_radiant = true;
    expect_mentions(error_of([&] { create_speos(dir.file("b.ray"), no_wavelength); }),
                    {"b.ray", "needs a wavelength"});
    RayHeader h;
    h.has_radiant = true;
    h.spectral = SpectralKind::per_ray_wavelength;
    auto rays = sample_rays(3);
    rays[1].wavelength = kUnknown;
    expect_mentions(error_of([&] { write_speos(dir.file("c.ray"), h, rays); }),
                    {"c.ray", "ray 2", "wavelength"});
    EXPECT_FALSE(std::filesystem::exists(dir.file("c.ray")));
}

// No magic, so detection must be strict: only 28 + 32k bytes with the five 2.0 values.
TEST(Speos, SniffsOnlyExactSizeAndTheFiveConstants) {
    const std::string good = speos_bytes({1, 2, 2, 2, 2, 2, 600}, std::vector<float>(16, 0));
    auto head = [](const std::string& s) { return Head(s.begin(), s.end()); };
    EXPECT_TRUE(sniff_speos(head(good), good.size()));
    EXPECT_TRUE(sniff_speos(head(good.substr(0, 28)), 28));  // a header and no rays
    EXPECT_FALSE(sniff_speos(head(good), good.size() + 4));
    EXPECT_FALSE(sniff_speos(head(good.substr(0, 20)), 20));
    for (size_t i = 1; i <= 5; ++i) {
        std::string bad = good;
        const float v = 2.5f;
        std::memcpy(&bad[4 * i], &v, 4);
        EXPECT_FALSE(sniff_speos(head(bad), bad.size())) << "constant " << i;
    }
}

TEST(Speos, BadInputNamesFileAndOffset) {
    struct Case {
        const char* name;
        std::string bytes;
        std::vector<std::string> mentions;
    };
    const std::vector<float> ray = {0, 0, 0, 0, 0, 1, 550, 1};
    const Case cases[] = {
        {"short", speos_bytes({1, 2, 2}, {}), {"byte 12:", "12 bytes", "28-byte"}},
        {"size not 28 + 32k",
         speos_bytes({1, 2, 2, 2, 2, 2, 600, 0, 0}, ray),
         {"byte 60:", "68 bytes", "8 bytes left over"}},
        {"constant",
         speos_bytes({1, 2, 2, 3, 2, 2, 600}, ray),
         {"byte 12:", "value 4 is 3", "2.0"}},
        {"radiant total",
         speos_bytes({-1, 2, 2, 2, 2, 2, 600}, ray),
         {"byte 0:", "radiant total -1"}},
        {"luminous total",
         speos_bytes({1, 2, 2, 2, 2, 2, NAN}, ray),
         {"byte 24:", "luminous total nan"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        ScratchDir dir;
        const std::string path = dir.file("bad.ray");
        test::write_file(path, c.bytes);
        const std::string message = error_of([&] { open_speos(path); });
        expect_mentions(message, {path + ": "});
        for (const auto& m : c.mentions) expect_mentions(message, {m});
    }
}

}  // namespace
}  // namespace rayset
