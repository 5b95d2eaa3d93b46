// Zemax binary source files: round trips through the writer, hand-built files decoded against
// the layout in formats.md, and every kind of bad header or size.
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
    while (decoder.read(chunk, 7)) {  // small chunks: records straddle chunk boundaries
        EXPECT_EQ(chunk.first_index, rays.size());
        rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    }
    return rays;
}

void write_all(RayEncoder& encoder, const std::vector<Ray>& rays) {
    RayChunk chunk;
    for (size_t i = 0; i < rays.size(); i += 5) {
        chunk.clear();
        chunk.first_index = i;
        chunk.rays.assign(rays.begin() + i, rays.begin() + std::min(rays.size(), i + 5));
        encoder.write(chunk);
    }
    encoder.finish();
}

// Rays with awkward floats: random values plus -0, tiny and huge magnitudes.
std::vector<Ray> sample_rays(size_t n, bool wavelength) {
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<float> pos(-100, 100), dir(-1, 1), flux(1e-6f, 1), nm(380, 780);
    std::vector<Ray> rays(n);
    for (Ray& r : rays) {
        r.origin = {pos(rng), pos(rng), pos(rng)};
        float x = dir(rng), y = dir(rng), z = dir(rng), len = std::sqrt(x * x + y * y + z * z);
        r.direction = {x / len, y / len, z / len};
        r.radiant = flux(rng);
        if (wavelength) r.wavelength = nm(rng);
    }
    rays[0].origin = {-0.0f, 1e-30f, 3.4e38f};
    rays[1].radiant = 0.1f;
    return rays;
}

double radiant_sum(const std::vector<Ray>& rays) {
    double s = 0;
    for (const Ray& r : rays) s += r.radiant;
    return s;
}

// A Zemax file built by hand from the layout in formats.md, independent of the codec.
struct ZemaxFile {
    int32_t identifier = 1010;
    uint32_t count = 0;
    std::string description;
    float source_flux = 1, ray_set_flux = 1, wavelength_um = 0;
    float angles[4] = {0, 0, 0, 0};
    uint32_t units = 4;
    float location[3] = {0, 0, 0}, rotation[3] = {0, 0, 0}, scale[3] = {1, 1, 1};
    int32_t ray_format = 0, flux_type = 0;
    std::vector<float> records;  // 7 or 8 a ray
    size_t cut = 0;              // bytes removed from the end

    std::string bytes() const {
        std::string b(208, '\0');
        auto at = [&](size_t offset, const void* v, size_t n) { std::memcpy(&b[offset], v, n); };
        at(0, &identifier, 4);
        at(4, &count, 4);
        at(8, description.data(), description.size());
        at(108, &source_flux, 4);
        at(112, &ray_set_flux, 4);
        at(116, &wavelength_um, 4);
        at(120, angles, 16);
        at(136, &units, 4);
        at(140, location, 12);
        at(152, rotation, 12);
        at(164, scale, 12);
        at(192, &ray_format, 4);
        at(196, &flux_type, 4);
        b.append(reinterpret_cast<const char*>(records.data()), records.size() * 4);
        b.resize(b.size() - cut);
        return b;
    }
};

std::string write_zemax(const ScratchDir& dir, const ZemaxFile& f) {
    std::string path = dir.file("hand.sdf");
    test::write_file(path, f.bytes());
    return path;
}

RayHeader radiant_header(const std::vector<Ray>& rays, SpectralKind spectral) {
    RayHeader h;
    h.has_radiant = true;
    h.stated_radiant = radiant_sum(rays);
    h.spectral = spectral;
    h.ray_count = rays.size();
    return h;
}

TEST(ZemaxBinary, FluxOnlyRoundTripIsBitExactAndKeepsTheHeader) {
    ScratchDir dir;
    const auto rays = sample_rays(100, false);
    RayHeader h = radiant_header(rays, SpectralKind::none);
    h.unit = LengthUnit::inch;
    h.description = "round trip";
    h.ray_set_flux = 0.25;
    h.placement.location = {1, 2, 3};
    h.placement.rotation_rad = {0.1f, 0.2f, 0.3f};
    h.placement.scale = {0, 0, 0};
    h.placement.inclination_azimuth_deg = {0, 90, 10, 350};
    const std::string path = dir.file("out.dat");
    auto encoder = create_zemax_binary(path, h);
    write_all(*encoder, rays);
    EXPECT_TRUE(encoder->dropped().empty());
    EXPECT_EQ(test::read_file(path).size(), 208u + 28u * rays.size());

    auto decoder = open_zemax_binary(path);
    const RayHeader& r = decoder->header();
    EXPECT_EQ(r.format, RayFormat::zemax_binary);
    EXPECT_EQ(r.ray_count, rays.size());
    EXPECT_EQ(r.unit, LengthUnit::inch);
    EXPECT_EQ(r.description, "round trip");
    EXPECT_TRUE(r.has_radiant);
    EXPECT_FALSE(r.has_luminous);
    EXPECT_EQ(r.spectral, SpectralKind::none);
    EXPECT_EQ(r.stated_radiant, double(float(h.stated_radiant)));
    EXPECT_EQ(r.ray_set_flux, 0.25);
    EXPECT_EQ(r.placement.location, h.placement.location);
    EXPECT_EQ(r.placement.rotation_rad, h.placement.rotation_rad);
    EXPECT_EQ(r.placement.scale, h.placement.scale);
    EXPECT_EQ(r.placement.inclination_azimuth_deg, h.placement.inclination_azimuth_deg);
    EXPECT_TRUE(decoder->flux_is_relative());
    const auto back = read_all(*decoder);
    ASSERT_EQ(back.size(), rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(bits(back[i].origin.x), bits(rays[i].origin.x));
        EXPECT_EQ(bits(back[i].origin.y), bits(rays[i].origin.y));
        EXPECT_EQ(bits(back[i].origin.z), bits(rays[i].origin.z));
        EXPECT_EQ(back[i].direction, rays[i].direction);
        EXPECT_EQ(bits(back[i].radiant), bits(rays[i].radiant));
        EXPECT_TRUE(std::isnan(back[i].wavelength));
    }
    EXPECT_EQ(decoder->locate(3).str(), "byte " + std::to_string(208 + 3 * 28));
}

// Zemax stores um: nm -> um -> nm rounds twice, so the wavelength comes back within a float
// rounding (relative 1e-6 covers two roundings of 6e-8), everything else bit-exact.
TEST(ZemaxBinary, SpectralRoundTripKeepsWavelengthsToAFloatRounding) {
    ScratchDir dir;
    const auto rays = sample_rays(200, true);
    const std::string path = dir.file("out.sdf");
    auto encoder =
        create_zemax_binary(path, radiant_header(rays, SpectralKind::per_ray_wavelength));
    write_all(*encoder, rays);
    auto decoder = open_zemax_binary(path);
    EXPECT_EQ(decoder->header().spectral, SpectralKind::per_ray_wavelength);
    const auto back = read_all(*decoder);
    ASSERT_EQ(back.size(), rays.size());
    size_t inexact = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(back[i].direction, rays[i].direction);
        EXPECT_EQ(bits(back[i].radiant), bits(rays[i].radiant));
        EXPECT_NEAR(back[i].wavelength, rays[i].wavelength, 1e-6 * rays[i].wavelength);
        inexact += back[i].wavelength != rays[i].wavelength;
    }
    // The eighth column holds micrometres: 1 um more than the first ray's wavelength / 1000.
    const std::string bytes = test::read_file(path);
    ASSERT_EQ(bytes.size(), 208u + 32u * rays.size());
    float um;
    std::memcpy(&um, &bytes[208 + 28], 4);
    EXPECT_EQ(um, float(double(rays[0].wavelength) / 1000));
    RecordProperty("wavelengths_not_bit_exact", int(inexact));
}

TEST(ZemaxBinary, SingleWavelengthGoesInTheHeaderAndLumensSetFluxType1) {
    ScratchDir dir;
    auto rays = sample_rays(3, false);
    RayHeader h;
    h.has_luminous = true;
    h.stated_luminous = 0;
    for (Ray& r : rays) {
        r.luminous = r.radiant;
        r.radiant = kUnknown;
        h.stated_luminous += r.luminous;
    }
    h.spectral = SpectralKind::single_wavelength;
    h.single_wavelength = 550;
    const std::string path = dir.file("lm.dat");
    auto encoder = create_zemax_binary(path, h);
    write_all(*encoder, rays);
    const std::string bytes = test::read_file(path);
    float um;
    int32_t format, flux_type;
    std::memcpy(&um, &bytes[116], 4);
    std::memcpy(&format, &bytes[192], 4);
    std::memcpy(&flux_type, &bytes[196], 4);
    EXPECT_EQ(bits(um), bits(0.55f));
    EXPECT_EQ(format, 0);
    EXPECT_EQ(flux_type, 1);

    auto decoder = open_zemax_binary(path);
    const RayHeader& r = decoder->header();
    EXPECT_TRUE(r.has_luminous);
    EXPECT_FALSE(r.has_radiant);
    EXPECT_EQ(r.stated_luminous, double(float(h.stated_luminous)));
    EXPECT_EQ(r.spectral, SpectralKind::single_wavelength);
    EXPECT_EQ(r.single_wavelength, 550.0f);
    const auto back = read_all(*decoder);
    for (size_t i = 0; i < rays.size(); ++i)
        EXPECT_EQ(bits(back[i].luminous), bits(rays[i].luminous));
}

TEST(ZemaxBinary, WriterReportsWhatZemaxCannotHoldAndConvertsMicrometres) {
    ScratchDir dir;
    auto rays = sample_rays(2, true);
    rays[0].origin = {1000, -500, 250};
    for (Ray& r : rays) r.luminous = 2 * r.radiant;
    RayHeader h = radiant_header(rays, SpectralKind::per_ray_wavelength);
    h.has_luminous = true;
    h.unit = LengthUnit::um;
    const std::string path = dir.file("um.sdf");
    auto encoder = create_zemax_binary(path, h);
    write_all(*encoder, rays);
    ASSERT_EQ(encoder->dropped().size(), 2u);
    expect_mentions(encoder->dropped()[0], {"luminous"});
    expect_mentions(encoder->dropped()[1], {"um", "mm"});
    auto decoder = open_zemax_binary(path);
    EXPECT_EQ(decoder->header().unit, LengthUnit::mm);
    EXPECT_EQ(read_all(*decoder)[0].origin, (Vec3f{1, -0.5f, 0.25f}));
}

// Through the validating reader relative fluxes are scaled to the source flux: 1 : 1 : 2 of 2 W.
TEST(ZemaxBinary, ReaderScalesRelativeFluxToTheSourceFlux) {
    ScratchDir dir;
    ZemaxFile f;
    f.count = 3;
    f.source_flux = 2;
    f.records = {0, 0, 0, 0, 0, 1, 1, /**/ 0, 0, 0, 0, 1, 0, 1, /**/ 0, 0, 0, 1, 0, 0, 2};
    auto reader = open_rays(write_zemax(dir, f));
    EXPECT_EQ(reader->file_header().format, RayFormat::zemax_binary);
    RayChunk chunk;
    std::vector<float> flux;
    while (reader->read(chunk))
        for (const Ray& r : chunk.rays) flux.push_back(r.radiant);
    EXPECT_EQ(flux, (std::vector<float>{0.5f, 0.5f, 1.0f}));
    EXPECT_DOUBLE_EQ(reader->totals().radiant, 2.0);
}

TEST(ZemaxBinary, HandBuiltSpectralFileDecodesFieldByField) {
    ScratchDir dir;
    ZemaxFile f;
    f.count = 2;
    f.description = "hand made    ";  // trailing spaces are padding
    f.source_flux = 3;
    f.ray_set_flux = 1.5f;
    f.wavelength_um = std::nanf("");  // ignored in spectral files, as OpticStudio does
    f.units = 2;
    f.location[1] = 7;
    f.ray_format = 2;
    f.records = {1, 2, 3, 0, 0, 1, 0.5f, 0.5f, /**/ -1, -2, -3, 1, 0, 0, 0.25f, 0.65f};
    auto decoder = open_zemax_binary(write_zemax(dir, f));
    const RayHeader& h = decoder->header();
    EXPECT_EQ(h.ray_count, 2u);
    EXPECT_EQ(h.description, "hand made");
    EXPECT_EQ(h.unit, LengthUnit::cm);
    EXPECT_EQ(h.stated_radiant, 3.0);
    EXPECT_EQ(h.ray_set_flux, 1.5);
    EXPECT_EQ(h.placement.location, (Vec3f{0, 7, 0}));
    EXPECT_EQ(h.spectral, SpectralKind::per_ray_wavelength);
    const auto rays = read_all(*decoder);
    ASSERT_EQ(rays.size(), 2u);
    EXPECT_EQ(rays[1].origin, (Vec3f{-1, -2, -3}));
    EXPECT_EQ(rays[1].direction, (Vec3f{1, 0, 0}));
    EXPECT_EQ(rays[1].radiant, 0.25f);
    EXPECT_EQ(rays[0].wavelength, 500.0f);
    EXPECT_NEAR(rays[1].wavelength, 650.0f, 650e-6);
}

// The source flux follows the rays when they disagree with the stated total (lead's rule for
// every writer); the ray-set flux then follows it too.
TEST(ZemaxBinary, WriterTotalsFollowTheRaysWhenTheStatedTotalDisagrees) {
    ScratchDir dir;
    const auto rays = sample_rays(4, false);
    RayHeader h = radiant_header(rays, SpectralKind::none);
    h.stated_radiant = 1000;
    h.ray_set_flux = 999;
    const std::string path = dir.file("t.dat");
    auto encoder = create_zemax_binary(path, h);
    write_all(*encoder, rays);
    const std::string bytes = test::read_file(path);
    float source, ray_set;
    std::memcpy(&source, &bytes[108], 4);
    std::memcpy(&ray_set, &bytes[112], 4);
    EXPECT_EQ(source, float(radiant_sum(rays)));
    EXPECT_EQ(ray_set, source);
}

TEST(ZemaxBinary, UnfinishedWriterLeavesNoFile) {
    ScratchDir dir;
    const std::string path = dir.file("never.dat");
    {
        auto encoder = create_zemax_binary(path, radiant_header({}, SpectralKind::none));
        RayChunk chunk;
        chunk.rays = sample_rays(3, false);
        encoder->write(chunk);
    }
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(ZemaxBinary, WriterRefusesRaysWithoutFluxOrWavelength) {
    ScratchDir dir;
    RayHeader none;
    expect_mentions(error_of([&] { create_zemax_binary(dir.file("a.dat"), none); }),
                    {"a.dat", "neither radiant nor luminous"});
    auto rays = sample_rays(3, true);
    rays[2].wavelength = kUnknown;
    auto encoder = create_zemax_binary(dir.file("b.sdf"),
                                       radiant_header(rays, SpectralKind::per_ray_wavelength));
    expect_mentions(error_of([&] { write_all(*encoder, rays); }), {"b.sdf", "ray 3", "wavelength"});
}

// ---- bad input: every message names the file and the byte offset -------------------------------
struct BadCase {
    const char* name;
    void (*edit)(ZemaxFile&);
    std::vector<std::string> mentions;
};

ZemaxFile two_rays() {
    ZemaxFile f;
    f.count = 2;
    f.records = {0, 0, 0, 0, 0, 1, 1, /**/ 0, 0, 0, 0, 0, 1, 1};
    return f;
}

TEST(ZemaxBinary, BadInputNamesFileAndOffset) {
    const BadCase cases[] = {
        {"identifier",
         [](ZemaxFile& f) { f.identifier = 1011; },
         {"byte 0:", "identifier 1011", "1010"}},
        {"short header",
         [](ZemaxFile& f) { f.records.clear(), f.count = 0, f.cut = 100; },
         {"byte 0:", "208-byte", "truncated"}},
        {"count larger than file",
         [](ZemaxFile& f) { f.count = 5; },
         {"byte 4:", "5 rays", "140 bytes", "264 bytes", "56 bytes"}},
        {"truncated record",
         [](ZemaxFile& f) { f.cut = 10; },
         {"byte 236:", "ray 2", "18 of its 28", "254 bytes"}},
        {"trailing bytes",
         [](ZemaxFile& f) { f.count = 1; },
         {"byte 236:", "28 bytes follow", "room for 1 more"}},
        {"units", [](ZemaxFile& f) { f.units = 7; }, {"byte 136:", "units code 7"}},
        {"ray format", [](ZemaxFile& f) { f.ray_format = 1; }, {"byte 192:", "ray format 1"}},
        {"flux type", [](ZemaxFile& f) { f.flux_type = 2; }, {"byte 196:", "flux type 2"}},
        {"lumens with spectral",
         [](ZemaxFile& f) { f.flux_type = 1, f.ray_format = 2, f.records.resize(16); },
         {"byte 196:", "lumens", "ray format 2"}},
        {"wavelength",
         [](ZemaxFile& f) { f.wavelength_um = -0.5f; },
         {"byte 116:", "wavelength -0.5"}},
        {"source flux",
         [](ZemaxFile& f) { f.source_flux = INFINITY; },
         {"byte 108:", "source flux inf"}},
    };
    for (const BadCase& c : cases) {
        SCOPED_TRACE(c.name);
        ScratchDir dir;
        ZemaxFile f = two_rays();
        c.edit(f);
        const std::string path = write_zemax(dir, f);
        const std::string message = error_of([&] { open_zemax_binary(path); });
        expect_mentions(message, {path + ": "});
        for (const auto& m : c.mentions) expect_mentions(message, {m});
    }
}

// A NaN in a record is found by the validating reader, which names the record's offset.
TEST(ZemaxBinary, NonFiniteRecordValueIsReportedAtItsRecord) {
    ScratchDir dir;
    ZemaxFile f = two_rays();
    f.records[7 + 1] = std::nanf("");
    const std::string path = write_zemax(dir, f);
    const std::string message = error_of([&] {
        auto reader = open_rays(path);
        RayChunk chunk;
        while (reader->read(chunk)) {
        }
    });
    expect_mentions(message, {path + ": byte 236:", "ray 2", "origin"});
}

}  // namespace
}  // namespace rayset
