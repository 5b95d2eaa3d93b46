// Text from files written anywhere: what its bytes mean, and UTF-8 for people and JSON.
//
// Files carry their text in the encoding of the machine that wrote them: UTF-8 today,
// Windows-1252 (Latin-1's printable characters and a few more; the degree sign 0xB0 of many
// European photometric files), UTF-16 or UTF-32 where a Windows tool saved "Unicode", TM-25's
// UTF-32 by definition. The rules, in one place:
// - Text that starts with a byte-order mark is in the encoding the mark names. Without a mark,
//   text whose first characters are ASCII with zero bytes between them is UTF-16 or UTF-32 (the
//   zeros say which and which byte order); any other text is 8-bit text.
// - Readers hand 8-bit text out with its bytes as they were, so that a conversion to a format of
//   8-bit text (IES, EULUMDAT, the text ray formats) writes them back unchanged; wider text is
//   handed out as UTF-8.
// - Where text is shown to people, written as JSON or into a format of Unicode text (TM-25), it
//   is UTF-8 made by to_utf8(): every valid UTF-8 sequence is kept, every other byte is read as
//   Windows-1252 (its five unassigned bytes as the C1 controls of the same number, so nothing is
//   lost). Valid UTF-8 from a Latin-1 file is possible in principle ("Ã©" for "é") and rare in
//   practice: no rule can tell the two apart.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rayset {

enum class TextEncoding { eight_bit, utf8_with_mark, utf16le, utf16be, utf32le, utf32be };

// The encoding the first bytes of a text file announce, and how many bytes of mark to skip.
struct TextStart {
    TextEncoding encoding = TextEncoding::eight_bit;
    size_t mark_bytes = 0;
};
// The first bytes of a file are enough to tell it from this many: two UTF-32 characters.
inline constexpr size_t kTextStartBytes = 8;
TextStart text_start(std::string_view head);
// "UTF-16LE", ... for messages.
const char* to_string(TextEncoding encoding);
// Bytes per code unit: 1, 2 or 4.
size_t code_unit_bytes(TextEncoding encoding);

// One character of UTF-16 or UTF-32 text at the start of `bytes`: its code point and length in
// bytes; `bytes` 0 when the text ends inside it, `valid` false when it is not a Unicode scalar
// value (an unpaired surrogate, past U+10FFFF).
struct WideCharacter {
    char32_t code = 0;
    size_t bytes = 0;
    bool valid = true;
};
WideCharacter decode_wide(std::string_view bytes, TextEncoding encoding);
// The text of a file's first bytes as UTF-8: the byte-order mark skipped, UTF-16 and UTF-32
// transcoded up to the first character that is cut off or invalid, 8-bit text as it is.
std::string text_head_as_utf8(std::string_view head);

// The text as UTF-8: valid sequences kept, other bytes read as Windows-1252.
std::string to_utf8(std::string_view bytes);
// Whether the text is valid UTF-8 (no overlong forms, surrogates or code points past U+10FFFF).
bool is_utf8(std::string_view text);

// Appends a Unicode scalar value (at most U+10FFFF, not a surrogate) to UTF-8 text.
void append_utf8(char32_t code, std::string& out);
// UTF-32 text up to its first NUL (or all n code points) as UTF-8. Returns the index of the
// first code point that is not a Unicode scalar value, or npos when all are valid.
size_t utf32_to_utf8(const char32_t* text, size_t n, std::string& out);
// UTF-8 as code points. Returns the byte index of the first malformed sequence, or npos.
size_t utf8_to_utf32(std::string_view text, std::u32string& out);

// A copy of a JSON document (nlohmann::json) with every string, keys included, made UTF-8 by
// to_utf8(), ready to dump().
template <class Json>
Json with_utf8_strings(const Json& document) {
    if (document.is_string()) return to_utf8(document.template get<std::string>());
    if (document.is_array()) {
        Json out = Json::array();
        for (const Json& item : document) out.push_back(with_utf8_strings(item));
        return out;
    }
    if (document.is_object()) {
        Json out = Json::object();
        for (auto item = document.begin(); item != document.end(); ++item)
            out[to_utf8(item.key())] = with_utf8_strings(item.value());
        return out;
    }
    return document;
}

}  // namespace rayset
