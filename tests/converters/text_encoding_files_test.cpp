// Files whose text is not plain UTF-8: Latin-1 / Windows-1252 keywords kept byte for byte by
// conversions between 8-bit text formats and shown as UTF-8 by `rayconv info` (human and JSON);
// UTF-16 and UTF-32 files read as their UTF-8 twins; 8-bit text written into TM-25's UTF-32.
#include "converters/photometry/ies.h"
#include "converters/photometry/photometry.h"
#include "converters/rays/ray_stream.h"
#include "core/text_encoding.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace rayset {
namespace {

using test::read_file;
using test::run_command;
using test::ScratchDir;
using test::write_file;

std::string rayconv(const std::string& args) { return std::string(RAYCONV_EXE) + " " + args; }

// A small IES file whose [TEST] keyword holds `test_text` (bytes as given).
std::string ies_text(const std::string& test_text) {
    return "IESNA:LM-63-2002\r\n"
           "[TEST] " +
           test_text +
           "\r\n"
           "[MANUFAC] Maker\r\n"
           "TILT=NONE\r\n"
           "1 1000 1 3 2 1 2 0.1 0.1 0\r\n"
           "1 1 10\r\n"
           "0 45 90\r\n0 90\r\n"
           "100 80 20 100 70 10\r\n";
}

enum class Wide { utf16le, utf16be, utf32le, utf32be };

// UTF-8 text in a wide encoding, with or without its byte-order mark.
std::string encode(const std::string& utf8, Wide wide, bool mark) {
    std::u32string points;
    EXPECT_EQ(utf8_to_utf32(utf8, points), std::string::npos);
    if (mark) points.insert(points.begin(), U'\uFEFF');
    const bool little = wide == Wide::utf16le || wide == Wide::utf32le;
    const size_t unit = wide == Wide::utf16le || wide == Wide::utf16be ? 2 : 4;
    std::string out;
    auto put = [&](uint32_t value) {
        for (size_t k = 0; k < unit; ++k)
            out += char(value >> (8 * (little ? k : unit - 1 - k)) & 0xFF);
    };
    for (char32_t c : points) {
        if (unit == 2 && c >= 0x10000) {
            put(0xD800 + ((c - 0x10000) >> 10));
            put(0xDC00 + ((c - 0x10000) & 0x3FF));
        } else {
            put(c);
        }
    }
    return out;
}

TEST(TextEncodingFiles, Latin1KeywordsSurviveConversionByteForByte) {
    ScratchDir dir;
    const std::string latin1 =
        "25 \xB0"
        "C, 230 V";
    write_file(dir.file("lamp.ies"), ies_text(latin1));
    EXPECT_EQ(read_photometry(dir.file("lamp.ies")).keywords.at("TEST"), latin1);
    // IES -> EULUMDAT -> IES: the byte 0xB0 is still there, in the same place.
    ASSERT_EQ(
        run_command(rayconv("convert " + dir.file("lamp.ies") + " " + dir.file("lamp.ldt"))).status,
        0);
    EXPECT_NE(read_file(dir.file("lamp.ldt")).find(latin1), std::string::npos);
    ASSERT_EQ(
        run_command(rayconv("convert " + dir.file("lamp.ldt") + " " + dir.file("back.ies"))).status,
        0);
    EXPECT_NE(read_file(dir.file("back.ies")).find(latin1), std::string::npos);
}

TEST(TextEncodingFiles, InfoShowsLatin1TextAsUtf8) {
    ScratchDir dir;
    // 0xB0 is the degree sign in Latin-1; 0x80 the euro sign in Windows-1252.
    write_file(dir.file("lamp.ies"), ies_text("25 \xB0"
                                              "C, \x80 9"));
    const auto json = run_command(rayconv("info --json " + dir.file("lamp.ies")));
    ASSERT_EQ(json.status, 0) << json.output;
    const auto j = nlohmann::json::parse(json.output);
    EXPECT_EQ(j["keywords"]["TEST"],
              "25 \u00B0"
              "C, \u20AC 9");
    const auto human = run_command(rayconv("info " + dir.file("lamp.ies")));
    ASSERT_EQ(human.status, 0);
    EXPECT_TRUE(is_utf8(human.output));
    EXPECT_NE(human.output.find("25 \u00B0"
                                "C, \u20AC 9"),
              std::string::npos)
        << human.output;
}

TEST(TextEncodingFiles, ErrorsQuotingLatin1TextAreUtf8) {
    ScratchDir dir;
    write_file(dir.file("bad.ies"), "IESNA:LM-63-20\xB0\r\nTILT=NONE\r\n");
    try {
        read_photometry(dir.file("bad.ies"));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_TRUE(is_utf8(e.what()));
        EXPECT_NE(std::string(e.what()).find("IESNA:LM-63-20\u00B0"), std::string::npos)
            << e.what();
    }
}

TEST(TextEncodingFiles, WideIesFilesReadAsTheirUtf8Twins) {
    ScratchDir dir;
    const std::string utf8 = ies_text(
        "25 \u00B0"
        "C \u20AC \U0001F4A1");
    write_file(dir.file("utf8.ies"), utf8);
    const Photometry expected = read_photometry(dir.file("utf8.ies"));
    int n = 0;
    for (Wide wide : {Wide::utf16le, Wide::utf16be, Wide::utf32le, Wide::utf32be})
        for (bool mark : {true, false}) {
            const std::string path = dir.file("wide" + std::to_string(n++) + ".ies");
            write_file(path, encode(utf8, wide, mark));
            ASSERT_EQ(detect_photometry_format(path), PhotometryFormat::ies) << path;
            const Photometry p = read_photometry(path);
            EXPECT_EQ(p.keywords, expected.keywords) << path;
            EXPECT_EQ(p.candela, expected.candela) << path;
            EXPECT_EQ(p.vertical_deg, expected.vertical_deg) << path;
        }
}

TEST(TextEncodingFiles, WideTextNamesWhereItIsBroken) {
    ScratchDir dir;
    std::string text = encode(ies_text("x"), Wide::utf16le, true);
    // An unpaired high surrogate after the version line's 18 characters (2 + 36 bytes).
    text.insert(38, "\x3D\xD8\x41\x00", 4);
    write_file(dir.file("broken.ies"), text);
    try {
        read_ies(dir.file("broken.ies"));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("byte 38: not a Unicode character in UTF-16LE text"),
                  std::string::npos)
            << e.what();
    }
    write_file(dir.file("cut.ies"), encode(ies_text("x"), Wide::utf16le, true) + "A");
    try {
        read_ies(dir.file("cut.ies"));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("the file ends inside a character"), std::string::npos)
            << e.what();
    }
}

TEST(TextEncodingFiles, Utf16CsvRaysAreDetectedAndRead) {
    ScratchDir dir;
    const std::string csv =
        "# name: Leuchte \u00B0\nx,y,z,kx,ky,kz,radiant_W\n0,0,0,0,0,1,0.5\n1,2,3,0.6,0.8,0,1.5\n";
    write_file(dir.file("rays.csv"), encode(csv, Wide::utf16le, true));
    EXPECT_EQ(detect_ray_format(dir.file("rays.csv")), RayFormat::csv);
    auto reader = open_rays(dir.file("rays.csv"));
    EXPECT_EQ(reader->header().text[0], "Leuchte \u00B0");
    RayChunk chunk, all;
    while (reader->read(chunk))
        all.rays.insert(all.rays.end(), chunk.rays.begin(), chunk.rays.end());
    ASSERT_EQ(all.rays.size(), 2u);
    EXPECT_EQ(all.rays[1].origin.y, 2.0f);
    EXPECT_EQ(all.rays[1].radiant, 1.5f);
}

TEST(TextEncodingFiles, Latin1TextIsWrittenToTm25AsUnicode) {
    ScratchDir dir;
    write_file(dir.file("rays.csv"),
               "# name: 25 \xB0"
               "C \x80\nx,y,z,kx,ky,kz,radiant_W\n0,0,0,0,0,1,0.5\n");
    const auto converted =
        run_command(rayconv("convert " + dir.file("rays.csv") + " " + dir.file("rays.tm25ray")));
    ASSERT_EQ(converted.status, 0) << converted.output;
    EXPECT_EQ(open_rays(dir.file("rays.tm25ray"))->header().text[0],
              "25 \u00B0"
              "C \u20AC");
}

}  // namespace
}  // namespace rayset
