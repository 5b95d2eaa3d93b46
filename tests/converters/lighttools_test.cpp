// LightTools binary ray data (LTRF) on hand-made files: the byte layout, bit-exact round trips,
// what the writer keeps and drops, and every bad-input message.
#include "lighttools_test_support.h"

namespace rayset {
namespace {

using namespace lighttools_test;
using test::ScratchDir;
using test::write_file;

TEST(LightToolsBinary, DecodesHandMadeFile) {
    ScratchDir dir;
    const std::string path = dir.file("hand.ray");
    write_file(path, binary_file(1, 0, 0, 5, 2.5f, kTwoRays7));
    auto d = open_lighttools_binary(path);
    const RayHeader& h = d->header();
    EXPECT_TRUE(d->flux_is_relative());
    EXPECT_EQ(h.format, RayFormat::lighttools_binary);
    EXPECT_EQ(h.ray_count, 2u);
    EXPECT_EQ(h.unit, LengthUnit::ft);
    EXPECT_TRUE(h.has_luminous);
    EXPECT_FALSE(h.has_radiant);
    EXPECT_EQ(h.stated_luminous, 2.5);
    EXPECT_TRUE(std::isnan(h.stated_radiant));
    EXPECT_EQ(h.spectral, SpectralKind::none);
    EXPECT_EQ(h.data_origin, (Vec3f{0.5f, 0, -1}));
    std::vector<Ray> rays = read_all(*d);
    ASSERT_EQ(rays.size(), 2u);
    EXPECT_EQ(rays[1].origin, (Vec3f{-4, 5, 6}));
    EXPECT_EQ(rays[1].direction, (Vec3f{0.6f, 0.8f, 0}));
    EXPECT_EQ(rays[0].luminous, 0.25f);
    EXPECT_EQ(rays[1].luminous, 0.75f);
    EXPECT_TRUE(std::isnan(rays[0].radiant));
    EXPECT_TRUE(std::isnan(rays[0].wavelength));
    EXPECT_EQ(d->locate(1).str(), "byte 72");  // 44 + 28
}

TEST(LightToolsBinary, SystemUnitsAreMillimetres) {
    ScratchDir dir;
    const std::string path = dir.file("system.ray");
    write_file(path, binary_file(0, 0, 0, 0, 1, kTwoRays7));
    EXPECT_EQ(open_lighttools_binary(path)->header().unit, LengthUnit::mm);
}

TEST(LightToolsBinary, RoundTripIsBitExactWithWavelength) {
    ScratchDir dir;
    const std::string path = dir.file("rt.ray");
    const std::vector<Ray> rays = make_rays(101, true, false);
    RayHeader h = make_header(true, false, LengthUnit::cm);
    auto e = create_lighttools_binary(path, h);
    write_rays(*e, rays);
    // 44-byte header + 8 floats a ray + LTRFEND: the documented layout, measured on the bytes.
    const std::string bytes = test::read_file(path);
    ASSERT_EQ(bytes.size(), 44u + 101 * 32 + 7);
    EXPECT_EQ(bytes.substr(0, 4), "LTRF");
    EXPECT_EQ(bytes.substr(bytes.size() - 7), "LTRFEND");
    auto d = open_lighttools_binary(path);
    EXPECT_EQ(d->header().ray_count, 101u);
    EXPECT_EQ(d->header().unit, LengthUnit::cm);
    EXPECT_EQ(d->header().spectral, SpectralKind::per_ray_wavelength);
    EXPECT_EQ(d->header().data_origin, h.data_origin);
    // No stated total: the header gets what the rays sum to (as f32).
    double sum = 0;
    for (const Ray& r : rays) sum += r.radiant;
    EXPECT_EQ(d->header().stated_radiant, double(float(sum)));
    expect_same_rays(rays, read_all(*d));
    EXPECT_EQ(e->dropped().size(), 1u);  // the descriptive text
}

TEST(LightToolsBinary, RoundTripPhotometricSevenColumns) {
    ScratchDir dir;
    const std::string path = dir.file("lm.ray");
    const std::vector<Ray> rays = make_rays(10, false, true);
    RayHeader h = make_header(false, true, LengthUnit::inch);
    h.stated_luminous = 123.5;
    auto e = create_lighttools_binary(path, h);
    write_rays(*e, rays);
    EXPECT_EQ(test::read_file(path).size(), 44u + 10 * 28 + 7);
    auto d = open_lighttools_binary(path);
    EXPECT_EQ(d->header().unit, LengthUnit::inch);
    EXPECT_TRUE(d->header().has_luminous);
    // The stated total disagrees with the rays' sum and so is not written: the file's relative
    // fluxes must scale back to what the writer was given.
    double sum = 0;
    for (const Ray& r : rays) sum += r.luminous;
    EXPECT_EQ(d->header().stated_luminous, double(float(sum)));
    expect_same_rays(rays, read_all(*d));
}

TEST(LightToolsBinary, StatedTotalKeptWhenRaysAgree) {
    ScratchDir dir;
    const std::string path = dir.file("agree.ray");
    std::vector<Ray> rays = make_rays(4, false, false);
    double sum = 0;
    for (const Ray& r : rays) sum += r.radiant;
    RayHeader h = make_header(false, false, LengthUnit::mm);
    h.stated_radiant = sum * (1 + 5e-5);  // within the 1e-4 rounding agreement
    write_rays(*create_lighttools_binary(path, h), rays);
    EXPECT_EQ(open_lighttools_binary(path)->header().stated_radiant,
              double(float(h.stated_radiant)));
}

TEST(LightToolsBinary, SingleWavelengthWrittenPerRay) {
    ScratchDir dir;
    const std::string path = dir.file("single.ray");
    RayHeader h = make_header(false, false, LengthUnit::mm);
    h.spectral = SpectralKind::single_wavelength;
    h.single_wavelength = 532;
    write_rays(*create_lighttools_binary(path, h), make_rays(3, false, false));
    auto d = open_lighttools_binary(path);
    EXPECT_EQ(d->header().spectral, SpectralKind::per_ray_wavelength);
    for (const Ray& r : read_all(*d)) EXPECT_EQ(r.wavelength, 532.0f);
}

TEST(LightToolsBinary, WriterReportsWhatItDrops) {
    ScratchDir dir;
    RayHeader h = make_header(false, false, LengthUnit::mm);
    h.has_luminous = true;
    h.spectral = SpectralKind::shared_table;
    h.spectral_tables.push_back({{400, 500}, {1, 1}});
    auto e = create_lighttools_binary(dir.file("drop.ray"), h);
    ASSERT_EQ(e->dropped().size(), 3u);
    EXPECT_NE(e->dropped()[0].find("luminous"), std::string::npos);
    EXPECT_NE(e->dropped()[1].find("spectral tables"), std::string::npos);
}

TEST(LightToolsBinary, WriterRejectsRaysWithoutFluxOrWavelength) {
    ScratchDir dir;
    RayHeader none;
    none.has_radiant = none.has_luminous = false;
    try {
        create_lighttools_binary(dir.file("noflux.ray"), none);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "noflux.ray: cannot write LightTools ray data: the rays carry neither"),
                  std::string::npos)
            << e.what();
    }
    std::vector<Ray> rays = make_rays(3, true, false);
    rays[2].wavelength = kUnknown;
    auto e =
        create_lighttools_binary(dir.file("nowl.ray"), make_header(true, false, LengthUnit::mm));
    try {
        write_rays(*e, rays);
        FAIL() << "no error";
    } catch (const Error& err) {
        EXPECT_NE(
            std::string(err.what()).find("nowl.ray: ray 3: wavelength nan nm cannot be written"),
            std::string::npos)
            << err.what();
    }
}

// ---------------------------------------------------------------------------------------------
TEST(LightToolsBinaryErrors, MissingEndMarker) {
    ScratchDir dir;
    const std::string path = dir.file("noend.ray");
    write_file(path, binary_file(0, 0, 0, 1, 1, kTwoRays7, false) + "LTRFENX");
    expect_open_error(open_lighttools_binary, path,
                      {"byte 100:", "does not end with the end marker LTRFEND"});
}

TEST(LightToolsBinaryErrors, NotWholeRecords) {
    ScratchDir dir;
    const std::string path = dir.file("partial.ray");
    std::vector<float> values = kTwoRays7;
    values.pop_back();  // 13 floats: 52 bytes, not a multiple of 28
    write_file(path, binary_file(0, 0, 0, 1, 1, values));
    expect_open_error(open_lighttools_binary, path,
                      {"byte 44:", "52 bytes", "not a whole number of 28-byte ray records"});
}

TEST(LightToolsBinaryErrors, BadHeaderFields) {
    ScratchDir dir;
    struct Case {
        uint32_t data_type, far_field, colour, unit;
        std::vector<std::string> parts;
    };
    const Case cases[] = {
        {2, 0, 0, 1, {"byte 12:", "unknown data type 2"}},
        {0, 0, 0, 8, {"byte 24:", "unknown length unit code 8"}},
        {0, 1, 0, 1, {"byte 16:", "far-field", "not supported"}},
        {0, 7, 0, 1, {"byte 16:", "invalid far-field flag 7"}},
        {0, 0, 1, 1, {"byte 20:", "tristimulus", "not supported"}},
        {0, 0, 3, 1, {"byte 20:", "unknown colour information 3"}},
    };
    for (const Case& c : cases) {
        const std::string path = dir.file("bad.ray");
        write_file(path, binary_file(c.data_type, c.far_field, c.colour, c.unit, 1, kTwoRays7));
        expect_open_error(open_lighttools_binary, path, c.parts);
    }
}

TEST(LightToolsBinaryErrors, MagicVersionSizeAndTotal) {
    ScratchDir dir;
    const std::string path = dir.file("bad.ray");
    std::string bytes = binary_file(0, 0, 0, 1, 1, kTwoRays7);
    write_file(path, "LTRX" + bytes.substr(4));
    expect_open_error(open_lighttools_binary, path, {"byte 0:", "does not start with 'LTRF'"});
    std::string v3 = bytes;
    v3[4] = 3;
    write_file(path, v3);
    expect_open_error(open_lighttools_binary, path, {"byte 4:", "version 3", "not supported"});
    write_file(path, bytes.substr(0, 30));
    expect_open_error(open_lighttools_binary, path, {"byte 0:", "30 bytes", "truncated"});
    write_file(path, binary_file(0, 0, 0, 1, std::nanf(""), kTwoRays7));
    expect_open_error(open_lighttools_binary, path, {"byte 40:", "total flux nan"});
}

}  // namespace
}  // namespace rayset
