// TM-25 codec: bad files and bad requests. Every file error must name the file and the byte
// of the offending field; offsets here are computed from formats.md, not from the decoder.
#include "converters/formats/codecs.h"
#include "converters/rays/io.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace rayset {
namespace {

using test::ScratchDir;

constexpr uint64_t kRecord = 28;        // x y z kx ky kz radiant
constexpr uint64_t kDataStart = 36288;  // no tables, labels or text

template <class T>
void poke(const std::string& path, size_t at, T value) {
    std::string bytes = test::read_file(path);
    std::memcpy(bytes.data() + at, &value, sizeof(T));
    test::write_file(path, bytes);
}

RayHeader radiant_header() {
    RayHeader h;
    h.has_radiant = true;
    h.stated_radiant = 1;
    return h;
}

// A valid file of `rays` rays; ray i has origin (i, 0, 0), direction +z, flux 0.1 W and, for
// per-ray tables, table i % tables.
std::string valid_file(const ScratchDir& dir, const RayHeader& h = radiant_header(),
                       size_t rays = 10) {
    std::string path = dir.file("bad.tm25ray");
    auto encoder = create_tm25(path, h);
    RayChunk chunk;
    for (size_t i = 0; i < rays; ++i) {
        Ray r;
        r.origin = {float(i), 0, 0};
        r.direction = {0, 0, 1};
        r.radiant = 0.1f;
        if (h.spectral == SpectralKind::per_ray_table)
            r.spectrum = int32_t(i % h.spectral_tables.size());
        chunk.rays.push_back(r);
    }
    encoder->write(chunk);
    encoder->finish();
    return path;
}

std::string error_reading(const std::string& path) {
    try {
        auto decoder = open_tm25(path);
        RayChunk chunk;
        while (decoder->read(chunk, 4)) {
        }
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

// The message starts with the file's name and holds `where_what` ("byte 60: ...").
void expect_error(const std::string& path, const std::string& where_what) {
    std::string message = error_reading(path);
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(": " + where_what), std::string::npos) << message;
}

void truncate(const std::string& path, size_t size) {
    test::write_file(path, test::read_file(path).substr(0, size));
}

TEST(Tm25BadInput, WrongMagic) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<uint32_t>(path, 0, 0x4652544C);  // "LTRF"
    expect_error(path, "byte 0: not an IES TM-25 ray file");
}

TEST(Tm25BadInput, TruncatedHeader) {
    ScratchDir dir;
    auto path = valid_file(dir);
    truncate(path, 100);
    expect_error(path, "byte 88: file ends inside the reserved header bytes");
    truncate(path, 10);
    expect_error(path, "byte 8: file ends inside the creation method");
}

TEST(Tm25BadInput, TruncatedInsideATextField) {
    ScratchDir dir;
    auto path = valid_file(dir);
    truncate(path, 10000);  // the third text field runs from 8288 to 12288
    expect_error(path, "byte 8288: file ends inside the text field 'model creator'");
}

TEST(Tm25BadInput, TruncatedRaysAreFoundBeforeAnyRayIsRead) {
    ScratchDir dir;
    auto path = valid_file(dir);
    truncate(path, kDataStart + 10 * kRecord - 5);
    expect_error(
        path,
        "byte 20: the header states 10 rays of 28 bytes from byte 36288, a file of 36568 bytes, "
        "but the file has 36563 bytes: it is truncated or the ray count is wrong");
}

TEST(Tm25BadInput, CountLargerThanTheFile) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<uint64_t>(path, 20, 11);
    expect_error(
        path,
        "byte 20: the header states 11 rays of 28 bytes from byte 36288, a file of 36596 bytes, "
        "but the file has 36568 bytes");
    poke<uint64_t>(path, 20, uint64_t(1) << 62);
    expect_error(path,
                 "byte 20: the header states 4611686018427387904 rays of 28 bytes from byte 36288, "
                 "a file of "
                 "more than 18446744073709551615 bytes");
}

TEST(Tm25BadInput, CountSmallerThanTheFile) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<uint64_t>(path, 20, 9);
    expect_error(path,
                 "byte 36540: the 9 rays of 28 bytes the header states (byte 20) end here, but the "
                 "file goes "
                 "on for 28 more bytes");
}

TEST(Tm25BadInput, VersionThatIsNoYear) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 4, -1);
    expect_error(path, "byte 4: version -1 is not a year");
    poke<int32_t>(path, 4, 2019);  // accepted and read with the 2013 layout
    EXPECT_EQ(error_reading(path), "(no error)");
}

TEST(Tm25BadInput, RayStartPositionOutside0To7) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 56, 7);
    EXPECT_EQ(error_reading(path), "(no error)");
    poke<int32_t>(path, 56, 8);
    expect_error(path, "byte 56: ray start position 8 is outside 0..7");
}

TEST(Tm25BadInput, SpectralIdOutside0To4) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 60, 5);
    expect_error(path, "byte 60: spectral data id 5 is outside 0..4");
}

TEST(Tm25BadInput, FlagThatIsNeither0Nor1) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 272, 2);
    expect_error(path, "byte 272: luminous flux flag is 2, not 0 or 1");
}

TEST(Tm25BadInput, PositionAndDirectionFlagsMustBeSet) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 260, 0);
    expect_error(path, "byte 260: direction flag is 0 but every TM-25 ray needs it");
    poke<int32_t>(path, 256, 0);
    expect_error(path, "byte 256: position flag is 0");
}

TEST(Tm25BadInput, NoFluxFlag) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 264, 0);
    expect_error(
        path,
        "byte 264: neither the radiant flux flag nor the luminous flux flag (byte 272) is set");
}

TEST(Tm25BadInput, PerRayWavelengthNeedsTheWavelengthFlag) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 60, 2);
    expect_error(path, "byte 60: spectral data id 2 needs the wavelength flag (byte 268)");
}

TEST(Tm25BadInput, PerRaySpectraAllowRadiantFluxOnly) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 60, 2);
    poke<int32_t>(path, 268, 1);
    poke<int32_t>(path, 272, 1);
    expect_error(path,
                 "byte 60: spectral data id 2 needs the radiant flux flag (byte 264) and no "
                 "luminous flux flag (byte 272)");
    poke<int32_t>(path, 60, 4);
    poke<int32_t>(path, 264, 0);
    poke<int32_t>(path, 268, 0);
    poke<int32_t>(path, 284, 1);
    expect_error(path, "byte 60: spectral data id 4 needs the radiant flux flag (byte 264)");
}

TEST(Tm25BadInput, WavelengthFlagNeedsSpectralId2) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 268, 1);
    expect_error(
        path,
        "byte 268: wavelength flag is set but per-ray wavelengths need spectral data id 2, not 0");
}

TEST(Tm25BadInput, SpectrumIndexFlagExactlyWithId4) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 284, 1);
    expect_error(path,
                 "byte 284: spectrum index flag is 1 but the spectral data id (byte 60) is 0");
    poke<int32_t>(path, 284, 0);
    poke<int32_t>(path, 60, 4);
    expect_error(path,
                 "byte 284: spectrum index flag is 0 but the spectral data id (byte 60) is 4");
}

TEST(Tm25BadInput, StokesNeedsRadiantFlux) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 264, 0);
    poke<int32_t>(path, 272, 1);
    poke<int32_t>(path, 276, 1);
    expect_error(path, "byte 276: Stokes flag needs the radiant flux flag (byte 264)");
}

TEST(Tm25BadInput, TristimulusNeedsLuminousFluxAndNoSpectrum) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 280, 1);
    expect_error(path, "byte 280: tristimulus flag needs the luminous flux flag (byte 272)");
    poke<int32_t>(path, 264, 0);
    poke<int32_t>(path, 272, 1);
    poke<int32_t>(path, 60, 1);
    poke<float>(path, 64, 500.0f);
    expect_error(path, "byte 280: tristimulus flag needs spectral data id 0 (byte 60), not 1");
}

TEST(Tm25BadInput, SingleWavelengthNeedsAWavelength) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 60, 1);
    poke<float>(path, 64, 0.0f);
    expect_error(
        path,
        "byte 64: spectral data id 1 (single wavelength) needs a positive wavelength here, not 0");
}

TEST(Tm25BadInput, SpectralTablesMissingOrImpossible) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 60, 3);
    expect_error(path,
                 "byte 76: spectral data id 3 (byte 60) needs spectral tables, but there are none");
    poke<int32_t>(path, 76, -1);
    expect_error(path,
                 "byte 76: number of spectral tables -1 is negative or more than the rest of the "
                 "file can hold");
    poke<int32_t>(path, 76, 1000000);
    expect_error(path, "byte 76: number of spectral tables 1000000 is negative");
}

TEST(Tm25BadInput, SpectralTableValues) {
    ScratchDir dir;
    RayHeader h = radiant_header();
    h.spectral = SpectralKind::shared_table;
    h.spectral_tables = {{{450, 460, 470}, {0.5f, 1, 0.5f}}};
    auto path = valid_file(dir, h);
    // Table at 36288: count, then (wavelength, weight) pairs from 36292.
    poke<float>(path, 36292 + 2 * 8, 455.0f);
    expect_error(path,
                 "byte 36308: spectral table 1, point 3: wavelength 455 nm does not ascend from "
                 "the point before (460 nm)");
    poke<float>(path, 36292 + 2 * 8, 470.0f);
    poke<float>(path, 36292 + 1 * 8 + 4, -1.0f);
    expect_error(path, "byte 36304: spectral table 1, point 2: weight -1 is not a number >= 0");
    poke<int32_t>(path, 36288, 0);
    expect_error(path, "byte 36288: spectral table 1 has 0 points");
    poke<int32_t>(path, 36288, 5000000);
    expect_error(path,
                 "byte 36288: spectral table 1 has 5000000 points: not positive or more than the "
                 "rest of the file holds");
}

TEST(Tm25BadInput, AdditionalItemsAndText) {
    ScratchDir dir;
    auto path = valid_file(dir);
    poke<int32_t>(path, 80, -1);
    expect_error(path, "byte 80: number of additional ray items is negative (-1)");
    poke<int32_t>(path, 80, 1000);
    expect_error(path,
                 "byte 80: 1000 additional ray items need more column labels than the rest of the "
                 "file holds");
    poke<int32_t>(path, 80, 0);
    poke<int32_t>(path, 84, 33);
    expect_error(path, "byte 84: additional text size 33 is negative, not a multiple of 32");
}

TEST(Tm25BadInput, TextThatIsNotUtf32) {
    ScratchDir dir;
    RayHeader h = radiant_header();
    h.text[1] = "Maker";
    auto path = valid_file(dir, h);
    poke<uint32_t>(path, 4288 + 8, 0x110000);  // third code point of the manufacturer
    expect_error(path,
                 "byte 4296: the text field 'manufacturer' holds 0x110000, which is not a Unicode "
                 "code point");
    poke<uint32_t>(path, 4288 + 8, 0xD800);
    expect_error(path, "byte 4296: the text field 'manufacturer' holds 0xD800");
}

TEST(Tm25BadInput, SpectrumIndexOutsideTheTables) {
    ScratchDir dir;
    RayHeader h = radiant_header();
    h.spectral = SpectralKind::per_ray_table;
    h.spectral_tables = {{{450, 460, 470}, {1, 1, 1}}, {{600, 610}, {1, 1}}};
    auto path = valid_file(dir, h);
    // Tables 28 + 20 bytes padded to 64: rays from 36352, 8 columns; index in column 7.
    const uint64_t ray3_index = 36352 + 2 * 32 + 7 * 4;
    EXPECT_EQ(error_reading(path), "(no error)");
    for (float bad : {3.0f, 0.0f, 1.5f, std::nanf("")}) {
        poke<float>(path, ray3_index, bad);
        expect_error(path, "byte 36444: ray 3: spectrum index " + format_float(bad) +
                               " is not a table number 1..2");
    }
}

TEST(Tm25BadInput, EncoderRefusesHeadersTm25CannotHold) {
    ScratchDir dir;
    std::string path = dir.file("out.tm25ray");
    auto expect_refused = [&](const RayHeader& h, const std::string& what) {
        std::string message = "(no error)";
        try {
            create_tm25(path, h);
        } catch (const Error& e) {
            message = e.what();
        }
        EXPECT_EQ(message, path + ": cannot write TM-25: " + what);
        EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
    };
    RayHeader h = radiant_header();
    h.has_radiant = false;
    expect_refused(h, "the rays carry neither radiant nor luminous flux");
    h = radiant_header();
    h.extras = {{ExtraKind::stokes_s1, ""}, {ExtraKind::stokes_s2, ""}};
    expect_refused(
        h, "TM-25 stores Stokes S1 S2 S3 and the polarisation ellipse axis only all six together");
    h.extras = {{ExtraKind::tristimulus_x, ""}, {ExtraKind::tristimulus_x, ""}};
    expect_refused(h, "two extra columns are both tristimulus X");
    h.extras = {{ExtraKind::tristimulus_x, ""}, {ExtraKind::tristimulus_z, ""}};
    h.has_luminous = true;
    h.spectral = SpectralKind::single_wavelength;
    h.single_wavelength = 500;
    expect_refused(
        h, "tristimulus columns need luminous flux (Y) per ray and no spectral information");
    h = radiant_header();
    h.has_radiant = false;
    h.has_luminous = true;
    for (int k = 0; k < 6; ++k) h.extras.push_back({static_cast<ExtraKind>(k), ""});
    expect_refused(h, "Stokes columns need radiant flux per ray");
    h.extras.clear();
    h.spectral = SpectralKind::per_ray_wavelength;
    expect_refused(h, "spectral data id 2 needs radiant flux per ray, which the rays do not carry");
    h = radiant_header();
    h.spectral = SpectralKind::per_ray_table;
    expect_refused(h, "spectral data id 4 needs spectral tables, but there are none");
    h.spectral_tables = {{{500, 490}, {1, 1}}};
    expect_refused(h,
                   "spectral table 1, point 2: wavelength 490 nm does not ascend from the point "
                   "before (500 nm)");
}

TEST(Tm25BadInput, EncoderRefusesASpectrumIndexOutsideTheTables) {
    ScratchDir dir;
    std::string path = dir.file("out.tm25ray");
    RayHeader h = radiant_header();
    h.spectral = SpectralKind::per_ray_table;
    h.spectral_tables = {{{500}, {1}}};
    auto encoder = create_tm25(path, h);
    RayChunk chunk;
    chunk.first_index = 7;
    chunk.rays.resize(2);
    chunk.rays[1].spectrum = 1;
    chunk.rays[0].spectrum = 0;
    try {
        encoder->write(chunk);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(
            std::string(e.what()),
            path +
                ": cannot write TM-25: ray 9 has spectrum index 2 but there are 1 spectral tables");
    }
}

}  // namespace
}  // namespace rayset
