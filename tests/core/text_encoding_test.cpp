// The text-encoding rules (core/text_encoding.h) against the published code tables: Unicode's
// UTF-8/16/32 forms and Windows-1252 as the WHATWG encoding standard defines it.
#include "core/text_encoding.h"

#include "core/error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace rayset {
namespace {

using namespace std::string_literals;

TEST(TextEncoding, Utf32ConversionCoversEveryEncodingLength) {
    const std::u32string points = {0x41, 0x7F, 0x80, 0x7FF, 0x800, 0xFFFF, 0x10000, 0x10FFFF};
    std::string utf8;
    EXPECT_EQ(utf32_to_utf8(points.data(), points.size(), utf8), std::string::npos);
    // Lengths 1+1+2+2+3+3+4+4 and the bytes of U+10FFFF.
    EXPECT_EQ(utf8.size(), 20u);
    EXPECT_EQ(utf8.substr(16), "\xF4\x8F\xBF\xBF");
    std::u32string back;
    EXPECT_EQ(utf8_to_utf32(utf8, back), std::string::npos);
    EXPECT_EQ(back, points);
    // Overlong, surrogate, past U+10FFFF, cut short, stray continuation byte.
    for (const char* bad :
         {"ab\xC0\x80", "ab\xED\xA0\x80", "ab\xF4\x90\x80\x80", "ab\xE2\x82", "ab\x80"})
        EXPECT_EQ(utf8_to_utf32(bad, back), 2u) << bad;
    const std::u32string surrogate = {0x41, 0xDC00};
    EXPECT_EQ(utf32_to_utf8(surrogate.data(), 2, utf8), 1u);
}

TEST(TextEncoding, EightBitTextBecomesUtf8ByWindows1252) {
    // The degree sign of a Latin-1 file, and the euro sign and curly quotes only Windows-1252 has.
    EXPECT_EQ(to_utf8("25 \xB0"
                      "C"),
              "25 \u00B0C");
    EXPECT_EQ(to_utf8("\x80 \x93x\x94 \x9F"), "\u20AC \u201Cx\u201D \u0178");
    // Unassigned bytes are the C1 controls of the same number: nothing is lost.
    EXPECT_EQ(to_utf8("\x81\x8D\x8F\x90\x9D"), "\u0081\u008D\u008F\u0090\u009D");
    // Every Latin-1 letter from 0xA0 up is its own code point.
    for (int b = 0xA0; b < 0x100; ++b) {
        std::string expected;
        append_utf8(char32_t(b), expected);
        EXPECT_EQ(to_utf8(std::string(1, char(b))), expected) << b;
    }
}

TEST(TextEncoding, ValidUtf8IsKeptAndOnlyBadBytesAreRead) {
    const std::string utf8 = "caf\u00E9 \u20AC \U0001F4A1";
    EXPECT_TRUE(is_utf8(utf8));
    EXPECT_EQ(to_utf8(utf8), utf8);
    // A UTF-8 name beside a Latin-1 byte: the one is kept, the other read as Windows-1252.
    EXPECT_FALSE(is_utf8(utf8 + " \xB0"));
    EXPECT_EQ(to_utf8(utf8 + " \xB0"), utf8 + " \u00B0");
    // Overlong forms and encoded surrogates are not UTF-8: byte by byte.
    EXPECT_EQ(to_utf8("\xC0\x80"), "\u00C0\u20AC");
    EXPECT_EQ(to_utf8("\xED\xA0\x80"), "\u00ED\u00A0\u20AC");
    EXPECT_TRUE(is_utf8(to_utf8("\xC0\x80\xED\xA0\x80\xF4\x90\x80\x80\xE2\x82")));
}

TEST(TextEncoding, ByteOrderMarksAndZeroBytesNameTheEncoding) {
    const auto encoding = [](const std::string& head) { return text_start(head).encoding; };
    EXPECT_EQ(encoding("\xEF\xBB\xBFIES"), TextEncoding::utf8_with_mark);
    EXPECT_EQ(text_start("\xEF\xBB\xBFIES").mark_bytes, 3u);
    EXPECT_EQ(encoding("\xFF\xFEI\0"s), TextEncoding::utf16le);
    EXPECT_EQ(encoding("\xFE\xFF\0I"s), TextEncoding::utf16be);
    EXPECT_EQ(encoding("\xFF\xFE\0\0I\0\0\0"s), TextEncoding::utf32le);
    EXPECT_EQ(encoding("\0\0\xFE\xFF\0\0\0I"s), TextEncoding::utf32be);
    EXPECT_EQ(text_start("\0\0\xFE\xFF"s).mark_bytes, 4u);
    // Without a mark: ASCII with zeros between.
    EXPECT_EQ(encoding("I\0E\0"s), TextEncoding::utf16le);
    EXPECT_EQ(encoding("\0I\0E"s), TextEncoding::utf16be);
    EXPECT_EQ(encoding("I\0\0\0E\0\0\0"s), TextEncoding::utf32le);
    EXPECT_EQ(encoding("\0\0\0I\0\0\0E"s), TextEncoding::utf32be);
    EXPECT_EQ(text_start("I\0E\0"s).mark_bytes, 0u);
    // 8-bit text, and binary data that is not ASCII with zeros between.
    EXPECT_EQ(encoding("IESNA:LM-63"), TextEncoding::eight_bit);
    EXPECT_EQ(encoding("\xEA\x03\0\0\x10\0\0\0"s), TextEncoding::eight_bit);
    EXPECT_EQ(encoding(""), TextEncoding::eight_bit);
}

TEST(TextEncoding, WideTextDecodesToTheSameUtf8) {
    // "°C €" and a character outside the basic plane (a surrogate pair in UTF-16).
    const std::string utf8 =
        "\u00B0"
        "C \u20AC\U0001F4A1";
    const std::string le16 = "\xFF\xFE\xB0\0C\0 \0\xAC\x20\x3D\xD8\xA1\xDC"s;
    const std::string be16 = "\xFE\xFF\0\xB0\0C\0 \x20\xAC\xD8\x3D\xDC\xA1"s;
    const std::string le32 = "\xFF\xFE\0\0\xB0\0\0\0C\0\0\0 \0\0\0\xAC\x20\0\0\xA1\xF4\x01\0"s;
    EXPECT_EQ(text_head_as_utf8(le16), utf8);
    EXPECT_EQ(text_head_as_utf8(be16), utf8);
    EXPECT_EQ(text_head_as_utf8(le32), utf8);
    // A head cut inside a character ends before it; 8-bit text is returned as it is.
    EXPECT_EQ(text_head_as_utf8(le16.substr(0, 11)),
              "\u00B0"
              "C \u20AC");
    EXPECT_EQ(text_head_as_utf8("\xEF\xBB\xBFIES \xB0"), "IES \xB0");
    // An unpaired surrogate and a value past U+10FFFF are not characters.
    const WideCharacter lone = decode_wide("\x3D\xD8\x41\0"s, TextEncoding::utf16le);
    EXPECT_FALSE(lone.valid);
    EXPECT_FALSE(decode_wide("\0\0\x11\0"s, TextEncoding::utf32le).valid);
    EXPECT_EQ(decode_wide("\x3D\xD8"s, TextEncoding::utf16le).bytes, 0u);
}

TEST(TextEncoding, JsonStringsAndKeysBecomeUtf8) {
    nlohmann::json j;
    j["file"] = "Leuchte \xE4.ies";
    j["keywords"] = {{"TEST\xB0",
                      "25 \xB0"
                      "C"},
                     {"LAMP", "LED"}};
    EXPECT_THROW(j.dump(), nlohmann::json::type_error);
    const nlohmann::json utf8 = with_utf8_strings(j);
    const nlohmann::json back = nlohmann::json::parse(utf8.dump());
    EXPECT_EQ(back["file"], "Leuchte \u00E4.ies");
    EXPECT_EQ(back["keywords"]["TEST\u00B0"], "25 \u00B0C");
    EXPECT_EQ(back["keywords"]["LAMP"], "LED");
}

TEST(TextEncoding, ErrorsQuotingANulByteKeepTheirWholeMessage) {
    // A scene's string "disk.\0x" quoted in a message that ends with where it is.
    const Error e("ray file \"disk.\0x\" not found at scene.pov:3:1"s);
    EXPECT_STREQ(e.what(), "ray file \"disk.\\0x\" not found at scene.pov:3:1");
}

}  // namespace
}  // namespace rayset
