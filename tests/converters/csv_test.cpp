// rayset CSV rays: a hand-written file read as documented, bit-exact round trips of rays and
// header metadata, and every bad-input message.
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
using test::write_file;

uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

RayChunk read_all(RayDecoder& decoder) {
    RayChunk all, chunk;
    while (decoder.read(chunk, 3)) {
        all.rays.insert(all.rays.end(), chunk.rays.begin(), chunk.rays.end());
        all.extra.insert(all.extra.end(), chunk.extra.begin(), chunk.extra.end());
    }
    return all;
}

void expect_same_float(float a, float b, const std::string& what) {
    if (std::isnan(a) && std::isnan(b)) return;
    EXPECT_EQ(bits(a), bits(b)) << what << ": " << a << " vs " << b;
}

TEST(Csv, ReadsHandWrittenFile) {
    ScratchDir dir;
    const std::string path = dir.file("hand.csv");
    write_file(path,
               "# made by a script\r\n"
               "# unit: cm\r\n"
               "# stated_radiant_W:   2.5 \r\n"
               "# name:  padded\r\n"
               "x,y,z,kx,ky,kz,wavelength_nm,radiant_W,temperature\r\n"
               "1,2,3,0,0,1,450,0.5,20\r\n"
               "\r\n"
               " -1 , -2.5e-3 ,3,0.6,0.8,0,nan,1.5,21\r\n");
    auto d = open_csv(path);
    const RayHeader& h = d->header();
    EXPECT_FALSE(d->flux_is_relative());
    EXPECT_EQ(h.format, RayFormat::csv);
    EXPECT_EQ(h.ray_count, 2u);
    EXPECT_EQ(h.unit, LengthUnit::cm);
    EXPECT_EQ(h.stated_radiant, 2.5);
    EXPECT_EQ(h.text[0], " padded");  // one space belongs to the syntax, the next to the text
    EXPECT_TRUE(std::isnan(h.stated_luminous));
    EXPECT_TRUE(h.has_radiant);
    EXPECT_FALSE(h.has_luminous);
    EXPECT_EQ(h.spectral, SpectralKind::per_ray_wavelength);  // inferred from the column
    ASSERT_EQ(h.extras.size(), 1u);
    EXPECT_EQ(h.extras[0].kind, ExtraKind::additional);
    EXPECT_EQ(h.extras[0].label, "temperature");
    RayChunk all = read_all(*d);
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all.rays[1].origin, (Vec3f{-1, -2.5e-3f, 3}));
    EXPECT_EQ(all.rays[1].direction, (Vec3f{0.6f, 0.8f, 0}));
    EXPECT_EQ(all.rays[0].wavelength, 450);
    EXPECT_TRUE(std::isnan(all.rays[1].wavelength));
    EXPECT_EQ(all.rays[1].radiant, 1.5f);
    EXPECT_TRUE(std::isnan(all.rays[1].luminous));
    EXPECT_EQ(all.extra, (std::vector<float>{20, 21}));
    EXPECT_EQ(d->locate(1).str(), "line 8");
}

RayHeader full_header() {
    RayHeader h;
    h.unit = LengthUnit::um;
    h.has_radiant = h.has_luminous = true;
    h.stated_radiant = 0.1 + 0.2;  // a double that needs all 17 digits
    h.stated_luminous = 54.64;
    h.spectral = SpectralKind::per_ray_table;
    h.min_wavelength = 380.5f;
    h.max_wavelength = 779.25f;
    h.spectral_tables = {{{400, 500, 600}, {0.1f, 1, 0.3f}}, {{450, 550}, {1, 1.0f / 3}}};
    h.extras = {
        {ExtraKind::stokes_s1, "S1"}, {ExtraKind::additional, "a,b"}, {ExtraKind::additional, "x"}};
    h.creation_method = -1;
    h.creation_date = "2016-10-13";
    h.text = {"name", "maker",      "",   "creator\\with backslash", "Rigo 801", "",
              "25 C", "two\nlines", "ref"};
    h.additional_text = "more\r\ntext";
    h.description = "desc";
    h.far_field = true;
    h.data_origin = {1, 2, 3};
    h.placement.location = {0.1f, 0.2f, 0.3f};
    h.placement.rotation_rad = {0, 1.5f, 0};
    h.placement.scale = {2, 2, 2};
    h.placement.inclination_azimuth_deg = {0, 90, 0, 360};
    return h;
}

TEST(Csv, RoundTripKeepsRaysAndMetadataBitExact) {
    ScratchDir dir;
    const std::string path = dir.file("rt.csv");
    const RayHeader h = full_header();
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1, 1);
    std::uniform_int_distribution<int> e(-40, 40);
    RayChunk chunk;
    for (int i = 0; i < 50; ++i) {
        Ray r;
        r.origin = {std::ldexp(u(rng), e(rng)), std::ldexp(u(rng), e(rng)), u(rng)};
        r.direction = {u(rng), u(rng), u(rng)};
        r.radiant = std::ldexp(std::abs(u(rng)), e(rng));
        r.luminous = i == 3 ? kUnknown : std::abs(u(rng));
        r.spectrum = i % 2;
        chunk.rays.push_back(r);
        for (int j = 0; j < 3; ++j) chunk.extra.push_back(std::ldexp(u(rng), e(rng)));
    }
    auto enc = create_csv(path, h);
    enc->write(chunk);
    enc->finish();
    // Labels that cannot be column names are renamed, and say so.
    ASSERT_EQ(enc->dropped().size(), 2u);
    EXPECT_EQ(enc->dropped()[0], "extra column label 'a,b' (written as 'a_b')");
    EXPECT_EQ(enc->dropped()[1], "extra column label 'x' (written as 'x_extra')");

    auto d = open_csv(path);
    const RayHeader& r = d->header();
    EXPECT_EQ(r.unit, h.unit);
    EXPECT_EQ(r.stated_radiant, h.stated_radiant);
    EXPECT_EQ(r.stated_luminous, h.stated_luminous);
    EXPECT_EQ(r.spectral, h.spectral);
    EXPECT_EQ(r.min_wavelength, h.min_wavelength);
    EXPECT_EQ(r.max_wavelength, h.max_wavelength);
    ASSERT_EQ(r.spectral_tables.size(), 2u);
    for (size_t t = 0; t < 2; ++t) {
        EXPECT_EQ(r.spectral_tables[t].wavelength, h.spectral_tables[t].wavelength);
        EXPECT_EQ(r.spectral_tables[t].weight, h.spectral_tables[t].weight);
    }
    ASSERT_EQ(r.extras.size(), 3u);
    EXPECT_EQ(r.extras[0].kind, ExtraKind::stokes_s1);
    EXPECT_EQ(r.extras[1].label, "a_b");
    EXPECT_EQ(r.extras[2].label, "x_extra");
    EXPECT_EQ(r.creation_method, -1);
    EXPECT_EQ(r.creation_date, h.creation_date);
    EXPECT_EQ(r.text, h.text);
    EXPECT_EQ(r.additional_text, h.additional_text);
    EXPECT_EQ(r.description, h.description);
    EXPECT_TRUE(r.far_field);
    EXPECT_EQ(r.data_origin, h.data_origin);
    EXPECT_EQ(r.placement.location, h.placement.location);
    EXPECT_EQ(r.placement.rotation_rad, h.placement.rotation_rad);
    EXPECT_EQ(r.placement.scale, h.placement.scale);
    EXPECT_EQ(r.placement.inclination_azimuth_deg, h.placement.inclination_azimuth_deg);

    RayChunk back = read_all(*d);
    ASSERT_EQ(back.size(), chunk.size());
    ASSERT_EQ(back.extra.size(), chunk.extra.size());
    for (size_t i = 0; i < chunk.size(); ++i) {
        const Ray &a = chunk.rays[i], &b = back.rays[i];
        const std::string at = "ray " + std::to_string(i);
        expect_same_float(a.origin.x, b.origin.x, at);
        expect_same_float(a.origin.y, b.origin.y, at);
        expect_same_float(a.origin.z, b.origin.z, at);
        expect_same_float(a.direction.x, b.direction.x, at);
        expect_same_float(a.direction.y, b.direction.y, at);
        expect_same_float(a.direction.z, b.direction.z, at);
        expect_same_float(a.radiant, b.radiant, at);
        expect_same_float(a.luminous, b.luminous, at);
        EXPECT_EQ(a.spectrum, b.spectrum) << at;
        for (size_t j = 0; j < 3; ++j)
            expect_same_float(chunk.extra[i * 3 + j], back.extra[i * 3 + j], at);
    }
}

TEST(Csv, DefaultHeaderRoundTrip) {
    ScratchDir dir;
    const std::string path = dir.file("min.csv");
    RayHeader h;
    h.has_luminous = true;
    auto enc = create_csv(path, h);
    RayChunk chunk;
    chunk.rays.resize(1);
    chunk.rays[0].direction = {0, 0, 1};
    chunk.rays[0].luminous = 3;
    enc->write(chunk);
    enc->finish();
    EXPECT_EQ(test::read_file(path),
              "# rayset CSV ray data\n# unit: mm\n# spectral: "
              "none\nx,y,z,kx,ky,kz,luminous_lm\n0,0,0,0,0,1,3\n");
    auto d = open_csv(path);
    EXPECT_EQ(d->header().spectral, SpectralKind::none);
    EXPECT_TRUE(std::isnan(d->header().stated_luminous));
    EXPECT_EQ(read_all(*d).rays[0].luminous, 3.0f);
}

// ---------------------------------------------------------------------------------------------
void expect_csv_error(const std::string& path, const std::string& text,
                      const std::vector<std::string>& parts) {
    write_file(path, text);
    try {
        auto d = open_csv(path);
        RayChunk chunk;
        while (d->read(chunk, 100)) {
        }
        FAIL() << "no error for:\n" << text;
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        for (const std::string& part : parts)
            EXPECT_NE(message.find(part), std::string::npos)
                << "'" << part << "' not in: " << message;
    }
}

const std::string kColumns = "x,y,z,kx,ky,kz,radiant_W\n";
const std::string kRow = "0,0,0,0,0,1,1\n";

TEST(CsvErrors, RowsAndValues) {
    ScratchDir dir;
    const std::string path = dir.file("bad.csv");
    expect_csv_error(path, kColumns + kRow + "0,0,0,0,0,1\n",
                     {"line 3:", "expected 7 comma-separated values", "found 6"});
    expect_csv_error(path, "# unit: m\n" + kColumns + kRow + "0,0,abc,0,0,1,1\n",
                     {"line 4, column 5:", "'abc' is not a number"});
    expect_csv_error(path, kColumns + "0,0,,0,0,1,1\n", {"line 2, column 5:", "empty value"});
    expect_csv_error(path, "x,y,z,kx,ky,kz,radiant_W,spectrum\n# spectral_table: 1 1\n",
                     {"line 1:", "per_ray_table but 0 spectral_table lines"});
    expect_csv_error(
        path, "# spectral_table: 400 1\nx,y,z,kx,ky,kz,radiant_W,spectrum\n0,0,0,0,0,1,1,0.5\n",
        {"line 3, column 15:", "spectrum index '0.5' is not a whole number"});
}

TEST(CsvErrors, HeaderAndMetadata) {
    ScratchDir dir;
    const std::string path = dir.file("bad.csv");
    expect_csv_error(path, "# unti: m\n" + kColumns,
                     {"line 1, column 3:", "unknown metadata key 'unti'"});
    expect_csv_error(path, "# unit: furlong\n" + kColumns,
                     {"line 1, column 9:", "unit 'furlong' is not a length unit"});
    expect_csv_error(path, "# unit: m\n# unit: mm\n" + kColumns,
                     {"line 2, column 3:", "unit is given a second time (first on line 1)"});
    expect_csv_error(path, "# description: a\\tb\n" + kColumns,
                     {"line 1, column 16:", "description 'a\\tb' is not valid text"});
    expect_csv_error(path, "# data_origin: 1 2\n" + kColumns,
                     {"line 1, column 16:", "three finite numbers"});
    expect_csv_error(path, "# only comments\n", {"line 1:", "no column line"});
    expect_csv_error(path, "", {"the file is empty"});
    expect_csv_error(path, "x,y,kz\n", {"line 1, column 5:", "must start with x,y,z,kx,ky,kz"});
    expect_csv_error(path, "x,y,z,kx,ky,kz,radiant_W,radiant_W\n",
                     {"line 1, column 26:", "'radiant_W' appears twice"});
    expect_csv_error(path, "x,y,z,kx,ky,kz,foo\n",
                     {"line 1:", "no radiant_W or luminous_lm column"});
    expect_csv_error(path, "# spectral: none\nx,y,z,kx,ky,kz,radiant_W,wavelength_nm\n",
                     {"line 2:", "spectral kind none does not take a wavelength_nm column"});
    expect_csv_error(path, "# spectral: single_wavelength\n" + kColumns,
                     {"line 2:", "needs a positive single_wavelength_nm"});
}

Head head_of(const std::string& text) { return Head(text.begin(), text.end()); }

TEST(Csv, Sniff) {
    EXPECT_TRUE(sniff_csv(head_of("x,y,z,kx,ky,kz,radiant_W\n1,2"), 30));
    EXPECT_TRUE(sniff_csv(head_of("# free\n\n# unit: mm\r\nx,y,z,kx,ky,kz"), 40));
    EXPECT_TRUE(sniff_csv(
        head_of("# rayset CSV ray data\n# description: " + std::string(5000, 'a')), 6000));
    EXPECT_FALSE(sniff_csv(head_of("# LightTools 8.7\nlt_rdf_version: 2.0\n"), 40));
    EXPECT_FALSE(sniff_csv(head_of("a,b,c\n"), 6));
    EXPECT_FALSE(sniff_csv(head_of("LTRF\x02"), 5));
}

}  // namespace
}  // namespace rayset
