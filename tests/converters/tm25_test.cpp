// TM-25 codec: write -> read round trips for every flag combination the format allows, the
// byte layout the encoder writes checked against formats.md offsets, and bad files.
#include "converters/formats/codecs.h"
#include "converters/formats/tm25_layout.h"
#include "converters/rays/io.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <numeric>
#include <random>

namespace rayset {
namespace {

using test::ScratchDir;

uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

template <class T>
T peek(const std::string& bytes, size_t at) {
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    return value;
}

template <class T>
void poke(const std::string& path, size_t at, T value) {
    std::string bytes = test::read_file(path);
    std::memcpy(bytes.data() + at, &value, sizeof(T));
    test::write_file(path, bytes);
}

// Rays with every column the header describes filled with seeded random values (seed fixed:
// the tests are exact, not statistical).
RayChunk make_rays(const RayHeader& h, size_t n, uint64_t first, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1, 1);
    RayChunk chunk;
    chunk.first_index = first;
    for (size_t i = 0; i < n; ++i) {
        Ray r;
        r.origin = {u(rng) * 3, u(rng) * 3, u(rng)};
        float x = u(rng), y = u(rng), z = u(rng);
        float len = std::sqrt(x * x + y * y + z * z) + 1e-3f;
        r.direction = {x / len, y / len, z / len};
        if (h.has_radiant) r.radiant = 1e-5f * (1 + u(rng));
        if (h.has_luminous) r.luminous = 2e-3f * (1 + u(rng));
        if (h.spectral == SpectralKind::per_ray_wavelength) r.wavelength = 580 + 200 * u(rng);
        if (h.spectral == SpectralKind::per_ray_table)
            r.spectrum = static_cast<int32_t>(rng() % h.spectral_tables.size());
        chunk.rays.push_back(r);
        for (size_t e = 0; e < h.extras.size(); ++e) chunk.extra.push_back(u(rng) * 100);
    }
    return chunk;
}

SpectralTable table(std::vector<float> wavelength) {
    SpectralTable t;
    t.wavelength = wavelength;
    for (size_t k = 0; k < wavelength.size(); ++k)
        t.weight.push_back(0.25f * static_cast<float>(k % 5));
    return t;
}

RayHeader base_header() {
    RayHeader h;
    h.has_radiant = true;
    h.stated_radiant = 0.125;
    h.stated_luminous = 42.5;
    h.creation_method = 1;
    h.creation_date = "2024-05-06 07:08:09";
    h.text = {"LED µ-chip", "Maker Ω GmbH",  "", "rayset test", "Goniometer 𝜆",
              "",           "25 °C, 350 mA", "", "ref"};
    return h;
}

// Writes `rays` rays in three uneven chunks; returns what the encoder dropped.
std::vector<std::string> write_file_of(const std::string& path, const RayHeader& h,
                                       std::vector<RayChunk>& written, size_t rays = 1000) {
    std::mt19937 rng(1234);
    auto encoder = create_tm25(path, h);
    written.clear();
    size_t sizes[3] = {rays / 3, rays / 2, rays - rays / 3 - rays / 2};
    uint64_t first = 0;
    for (size_t s : sizes) {
        written.push_back(make_rays(h, s, first, rng));
        encoder->write(written.back());
        first += s;
    }
    encoder->finish();
    return encoder->dropped();
}

// The decoder lists extras in file column order: Stokes, tristimulus, then additional, which
// is ExtraKind order. order[k] = which written extra the k-th decoded one is.
std::vector<size_t> decoded_order(const std::vector<ExtraColumn>& written) {
    std::vector<size_t> order(written.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return written[a].kind < written[b].kind; });
    return order;
}

// Reads every ray in chunks of 333 and checks them bit for bit against what was written.
void expect_rays_equal(RayDecoder& decoder, const std::vector<RayChunk>& written,
                       const RayHeader& h) {
    std::vector<Ray> want;
    std::vector<float> want_extra;
    for (const auto& c : written) {
        want.insert(want.end(), c.rays.begin(), c.rays.end());
        want_extra.insert(want_extra.end(), c.extra.begin(), c.extra.end());
    }
    const std::vector<size_t> order = decoded_order(h.extras);
    const bool table_index = decoder.header().spectral == SpectralKind::per_ray_table;
    RayChunk chunk;
    size_t got = 0, extras = decoder.header().extras.size();
    while (decoder.read(chunk, 333)) {
        ASSERT_EQ(chunk.first_index, got);
        ASSERT_EQ(chunk.extra.size(), chunk.size() * extras);
        for (size_t i = 0; i < chunk.size(); ++i, ++got) {
            const Ray& a = chunk.rays[i];
            const Ray& b = want[got];
            ASSERT_EQ(bits(a.origin.x), bits(b.origin.x)) << "ray " << got;
            ASSERT_EQ(bits(a.origin.y), bits(b.origin.y));
            ASSERT_EQ(bits(a.origin.z), bits(b.origin.z));
            ASSERT_EQ(bits(a.direction.x), bits(b.direction.x));
            ASSERT_EQ(bits(a.direction.y), bits(b.direction.y));
            ASSERT_EQ(bits(a.direction.z), bits(b.direction.z));
            // Columns a file lacks are kUnknown on both sides, so bits compare everywhere.
            ASSERT_EQ(bits(a.radiant), bits(b.radiant));
            ASSERT_EQ(bits(a.luminous), bits(b.luminous));
            ASSERT_EQ(bits(a.wavelength), bits(b.wavelength));
            ASSERT_EQ(a.spectrum, table_index ? b.spectrum : -1);
            for (size_t e = 0; e < extras; ++e)
                ASSERT_EQ(bits(chunk.extra[i * extras + e]),
                          bits(want_extra[got * extras + order[e]]))
                    << "extra " << e;
        }
    }
    EXPECT_EQ(got, want.size());
}

void expect_header_equal(const RayHeader& a, const RayHeader& b) {
    EXPECT_EQ(a.format, RayFormat::tm25);
    EXPECT_EQ(a.unit, LengthUnit::mm);
    EXPECT_EQ(a.has_radiant, b.has_radiant);
    EXPECT_EQ(a.spectral, b.spectral);
    EXPECT_EQ(bits(a.single_wavelength), bits(b.single_wavelength));
    EXPECT_EQ(bits(a.min_wavelength), bits(b.min_wavelength));
    EXPECT_EQ(bits(a.max_wavelength), bits(b.max_wavelength));
    ASSERT_EQ(a.spectral_tables.size(), b.spectral_tables.size());
    for (size_t t = 0; t < a.spectral_tables.size(); ++t) {
        EXPECT_EQ(a.spectral_tables[t].wavelength, b.spectral_tables[t].wavelength);
        EXPECT_EQ(a.spectral_tables[t].weight, b.spectral_tables[t].weight);
    }
    ASSERT_EQ(a.extras.size(), b.extras.size());
    const std::vector<size_t> order = decoded_order(b.extras);
    for (size_t e = 0; e < a.extras.size(); ++e) {
        const ExtraColumn& want = b.extras[order[e]];
        EXPECT_EQ(a.extras[e].kind, want.kind) << e;
        if (want.kind == ExtraKind::additional) {
            EXPECT_EQ(a.extras[e].label, want.label);
        }
    }
    EXPECT_EQ(a.creation_method, b.creation_method);
    EXPECT_EQ(a.creation_date, b.creation_date);
    EXPECT_EQ(a.text, b.text);
    EXPECT_EQ(a.additional_text, b.additional_text);
}

struct Case {
    const char* name;
    std::function<void(RayHeader&)> setup;
    std::array<int32_t, 8> flags;  // expected at byte 256
    uint64_t data_start;           // 36288 + padded tables + 512 x labels + text bytes
};

std::vector<Case> cases() {
    return {
        {"radiant", [](RayHeader&) {}, {1, 1, 1, 0, 0, 0, 0, 0}, 36288},
        {"luminous",
         [](RayHeader& h) { h.has_radiant = false, h.has_luminous = true; },
         {1, 1, 0, 0, 1, 0, 0, 0},
         36288},
        {"both_fluxes",
         [](RayHeader& h) { h.has_luminous = true; },
         {1, 1, 1, 0, 1, 0, 0, 0},
         36288},
        {"single_wavelength",
         [](RayHeader& h) {
             h.spectral = SpectralKind::single_wavelength, h.single_wavelength = 455.5f;
         },
         {1, 1, 1, 0, 0, 0, 0, 0},
         36288},
        {"per_ray_wavelength",
         [](RayHeader& h) {
             h.spectral = SpectralKind::per_ray_wavelength, h.min_wavelength = 380,
             h.max_wavelength = 780;
         },
         {1, 1, 1, 1, 0, 0, 0, 0},
         36288},
        // 76 points: 4 + 608 = 612 bytes padded to 640, as in the OSRAM files.
        {"shared_table",
         [](RayHeader& h) {
             std::vector<float> w;
             for (int k = 0; k < 76; ++k) w.push_back(390 + 1.6f * k);
             h.spectral = SpectralKind::shared_table;
             h.spectral_tables = {table(w)};
         },
         {1, 1, 1, 0, 0, 0, 0, 0},
         36928},
        // 3 tables: 28 + 20 + 44 = 92 bytes padded to 96.
        {"per_ray_table",
         [](RayHeader& h) {
             h.spectral = SpectralKind::per_ray_table;
             h.spectral_tables = {table({450, 460, 470}), table({600, 610}),
                                  table({380, 400, 420, 440, 460})};
         },
         {1, 1, 1, 0, 0, 0, 0, 1},
         36384},
        // Stokes + 2 labelled columns (1024 bytes) + 9 code points of text (padded to 64 bytes).
        {"stokes_additional",
         [](RayHeader& h) {
             for (int k = 0; k < 6; ++k) h.extras.push_back({static_cast<ExtraKind>(k), ""});
             h.extras.push_back({ExtraKind::additional, "Temperatur °C"});
             h.extras.push_back({ExtraKind::additional, "Ωmega"});
             h.additional_text = "µ-notes 1";
         },
         {1, 1, 1, 0, 0, 1, 0, 0},
         36288 + 1024 + 64},
        {"tristimulus",
         [](RayHeader& h) {
             h.has_radiant = false, h.has_luminous = true;
             h.extras = {{ExtraKind::tristimulus_x, ""}, {ExtraKind::tristimulus_z, ""}};
         },
         {1, 1, 0, 0, 1, 0, 1, 0},
         36288},
        // Everything at once that may go together: per-ray tables, Stokes, an additional column.
        {"all_radiant_columns",
         [](RayHeader& h) {
             h.spectral = SpectralKind::per_ray_table;
             h.spectral_tables = {table({500}), table({510, 520})};
             h.extras.push_back({ExtraKind::additional, "a"});
             for (int k = 0; k < 6; ++k) h.extras.push_back({static_cast<ExtraKind>(k), ""});
             h.additional_text = "exactly8";
         },
         {1, 1, 1, 0, 0, 1, 0, 1},
         36288 + 32 + 512 + 32},
    };
}

TEST(Tm25, RoundTripEveryFlagCombination) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        ScratchDir dir;
        std::string path = dir.file("rays.tm25ray");
        RayHeader h = base_header();
        c.setup(h);
        std::vector<RayChunk> written;
        EXPECT_TRUE(write_file_of(path, h, written).empty());

        // The bytes, read against formats.md offsets rather than through the decoder.
        std::string bytes = test::read_file(path);
        int columns =
            6 + c.flags[2] + c.flags[3] + c.flags[4] + 6 * c.flags[5] + 2 * c.flags[6] + c.flags[7];
        for (const auto& e : h.extras) columns += e.kind == ExtraKind::additional;
        ASSERT_EQ(bytes.size(), c.data_start + 1000u * 4 * columns);
        EXPECT_EQ(bytes.substr(0, 4), "TM25");
        EXPECT_EQ(peek<int32_t>(bytes, 4), 2013);
        EXPECT_EQ(peek<uint64_t>(bytes, 20), 1000u);
        for (int f = 0; f < 8; ++f)
            EXPECT_EQ(peek<int32_t>(bytes, 256 + 4 * f), c.flags[f]) << "flag " << f;
        EXPECT_EQ(peek<char32_t>(bytes, 288 + 4 * 4), U'µ');     // name "LED µ-chip"
        EXPECT_EQ(peek<char32_t>(bytes, 4288 + 4 * 6), U'Ω');    // manufacturer "Maker Ω GmbH"
        EXPECT_EQ(peek<char32_t>(bytes, 16288 + 4 * 11), U'𝜆');  // equipment "Goniometer 𝜆"

        auto decoder = open_tm25(path);
        const RayHeader& got = decoder->header();
        EXPECT_EQ(decoder->locate(0).str(), "byte " + std::to_string(c.data_start));
        EXPECT_EQ(got.ray_count, 1000u);
        EXPECT_EQ(got.stated_radiant, 0.125);
        EXPECT_EQ(got.stated_luminous, 42.5);
        EXPECT_EQ(got.has_luminous, c.flags[4] == 1);
        expect_header_equal(got, h);
        expect_rays_equal(*decoder, written, h);
    }
}

TEST(Tm25, SpectralBlockIsZeroPaddedTo32Bytes) {
    // 76 points: 612 bytes of table, 28 bytes of zeros, rays at 36928 (the OSRAM layout).
    ScratchDir dir;
    std::string path = dir.file("t.tm25ray");
    RayHeader h = base_header();
    cases()[5].setup(h);
    std::vector<RayChunk> written;
    write_file_of(path, h, written, 10);
    std::string bytes = test::read_file(path);
    EXPECT_EQ(peek<int32_t>(bytes, 36288), 76);
    EXPECT_EQ(peek<float>(bytes, 36292), 390.0f);
    EXPECT_EQ(peek<float>(bytes, 36292 + 75 * 8), h.spectral_tables[0].wavelength[75]);
    EXPECT_EQ(bytes.substr(36900, 28), std::string(28, '\0'));
    EXPECT_EQ(peek<float>(bytes, 36928), written[0].rays[0].origin.x);
}

TEST(Tm25, UnstatedTotalsBecomeTheSumOfTheRays) {
    ScratchDir dir;
    std::string path = dir.file("t.tm25ray");
    RayHeader h = base_header();
    h.has_luminous = true;
    h.stated_radiant = std::nan("");
    h.stated_luminous = std::nan("");
    std::vector<RayChunk> written;
    write_file_of(path, h, written);
    double radiant = 0, luminous = 0;
    for (const auto& c : written)
        for (const auto& r : c.rays) radiant += r.radiant, luminous += r.luminous;
    auto decoder = open_tm25(path);
    EXPECT_EQ(decoder->header().stated_radiant, static_cast<float>(radiant));
    EXPECT_EQ(decoder->header().stated_luminous, static_cast<float>(luminous));
    // ~1000 rays of 1e-5 W on average and 2e-3 lm: the sums are near 0.01 W and 2 lm.
    EXPECT_NEAR(radiant, 0.01, 0.002);
    EXPECT_NEAR(luminous, 2.0, 0.4);
}

TEST(Tm25, UnstatedTotalWithoutItsColumnStaysNaN) {
    ScratchDir dir;
    std::string path = dir.file("t.tm25ray");
    RayHeader h = base_header();
    h.stated_luminous = std::nan("");
    h.stated_radiant = 0;  // 0 is what the file says: kept, not replaced by the sum
    std::vector<RayChunk> written;
    write_file_of(path, h, written, 5);
    auto decoder = open_tm25(path);
    EXPECT_TRUE(std::isnan(decoder->header().stated_luminous));
    EXPECT_EQ(decoder->header().stated_radiant, 0.0);
}

TEST(Tm25, EncoderConvertsLengthsToMillimetres) {
    ScratchDir dir;
    std::string path = dir.file("t.tm25ray");
    RayHeader h = base_header();
    h.unit = LengthUnit::cm;
    auto encoder = create_tm25(path, h);
    RayChunk chunk;
    Ray r;
    r.origin = {1.5f, -2, 0.25f};
    r.direction = {0, 0, 1};
    r.radiant = 1;
    chunk.rays = {r};
    encoder->write(chunk);
    encoder->finish();
    auto decoder = open_tm25(path);
    ASSERT_TRUE(decoder->read(chunk, 10));
    EXPECT_EQ(chunk.rays[0].origin, (Vec3f{15, -20, 2.5f}));
}

TEST(Tm25, EncoderReportsWhatItCannotWrite) {
    ScratchDir dir;
    std::string path = dir.file("t.tm25ray");
    RayHeader h = base_header();
    h.description = "a Zemax description";
    h.far_field = true;
    h.creation_date = std::string(30, '2');
    h.text[1] = std::string(1001, 'x');
    h.spectral = SpectralKind::per_ray_wavelength;
    h.has_luminous = true;
    std::vector<RayChunk> written;
    auto dropped = write_file_of(path, h, written, 3);
    std::string all;
    for (const auto& d : dropped) all += d + "\n";
    EXPECT_EQ(dropped.size(), 5u) << all;
    EXPECT_NE(all.find("description"), std::string::npos) << all;
    EXPECT_NE(all.find("far-field"), std::string::npos) << all;
    EXPECT_NE(all.find("creation date past its first 28 bytes"), std::string::npos) << all;
    EXPECT_NE(all.find("'manufacturer' past its first 1000 characters"), std::string::npos) << all;
    EXPECT_NE(all.find("luminous flux of each ray"), std::string::npos) << all;
    auto decoder = open_tm25(path);
    EXPECT_EQ(decoder->header().text[1], std::string(1000, 'x'));
    EXPECT_EQ(decoder->header().creation_date, std::string(28, '2'));
    EXPECT_FALSE(decoder->header().has_luminous);
}

TEST(Tm25, UnfinishedEncoderLeavesNoFile) {
    ScratchDir dir;
    std::string path = dir.file("t.tm25ray");
    {
        auto encoder = create_tm25(path, base_header());
        std::mt19937 rng(1);
        encoder->write(make_rays(base_header(), 10, 0, rng));
    }
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(Tm25, SniffsTheMagic) {
    EXPECT_TRUE(sniff_tm25({'T', 'M', '2', '5', 0xDD, 7}, 6));
    EXPECT_FALSE(sniff_tm25({'L', 'T', 'R', 'F'}, 4));
    EXPECT_FALSE(sniff_tm25({'T', 'M', '2'}, 3));
}

}  // namespace
}  // namespace rayset
