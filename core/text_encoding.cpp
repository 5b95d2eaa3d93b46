#include "core/text_encoding.h"

#include <cstdint>

namespace rayset {

namespace {

// The length of the valid UTF-8 sequence at text[i] and its code point, or 0 if there is none.
size_t utf8_sequence(std::string_view text, size_t i, char32_t& code) {
    auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    size_t length;
    char32_t min;
    if (lead < 0x80) {
        code = lead;
        return 1;
    } else if ((lead & 0xE0) == 0xC0) {
        length = 2, code = lead & 0x1F, min = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
        length = 3, code = lead & 0x0F, min = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
        length = 4, code = lead & 0x07, min = 0x10000;
    } else {
        return 0;
    }
    if (i + length > text.size()) return 0;
    for (size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (byte(i + k) & 0x3F);
    }
    // Overlong forms, surrogates and values past U+10FFFF are not text.
    if (code < min || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
    return length;
}

// Windows-1252's bytes 0x80-0x9F; its unassigned ones (0x81, 0x8D, 0x8F, 0x90, 0x9D) are the C1
// controls of the same number, as the WHATWG encoding standard maps them.
constexpr char16_t kWindows1252High[32] = {
    0x20AC, 0x0081, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0x008D, 0x017D, 0x008F, 0x0090, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0x009D, 0x017E, 0x0178};

char32_t windows_1252(unsigned char byte) {
    return byte >= 0x80 && byte < 0xA0 ? kWindows1252High[byte - 0x80] : char32_t(byte);
}

bool ascii_with_zeros(std::string_view head, size_t unit, size_t ascii_at) {
    if (head.size() < 2 * unit) return false;
    for (size_t u = 0; u < 2; ++u)
        for (size_t k = 0; k < unit; ++k) {
            const auto b = static_cast<unsigned char>(head[u * unit + k]);
            if (k == ascii_at ? (b == 0 || b >= 0x80) : b != 0) return false;
        }
    return true;
}

}  // namespace

TextStart text_start(std::string_view head) {
    auto starts = [&](std::string_view mark) { return head.substr(0, mark.size()) == mark; };
    using namespace std::string_view_literals;
    // UTF-32LE's mark starts with UTF-16LE's: test it first.
    if (starts("\xFF\xFE\0\0"sv)) return {TextEncoding::utf32le, 4};
    if (starts("\0\0\xFE\xFF"sv)) return {TextEncoding::utf32be, 4};
    if (starts("\xFF\xFE"sv)) return {TextEncoding::utf16le, 2};
    if (starts("\xFE\xFF"sv)) return {TextEncoding::utf16be, 2};
    if (starts("\xEF\xBB\xBF"sv)) return {TextEncoding::utf8_with_mark, 3};
    if (ascii_with_zeros(head, 4, 0)) return {TextEncoding::utf32le, 0};
    if (ascii_with_zeros(head, 4, 3)) return {TextEncoding::utf32be, 0};
    if (ascii_with_zeros(head, 2, 0)) return {TextEncoding::utf16le, 0};
    if (ascii_with_zeros(head, 2, 1)) return {TextEncoding::utf16be, 0};
    return {};
}

const char* to_string(TextEncoding encoding) {
    switch (encoding) {
        case TextEncoding::eight_bit: return "8-bit text";
        case TextEncoding::utf8_with_mark: return "UTF-8";
        case TextEncoding::utf16le: return "UTF-16LE";
        case TextEncoding::utf16be: return "UTF-16BE";
        case TextEncoding::utf32le: return "UTF-32LE";
        case TextEncoding::utf32be: return "UTF-32BE";
    }
    return "?";
}

size_t code_unit_bytes(TextEncoding encoding) {
    switch (encoding) {
        case TextEncoding::utf16le:
        case TextEncoding::utf16be: return 2;
        case TextEncoding::utf32le:
        case TextEncoding::utf32be: return 4;
        default: return 1;
    }
}

WideCharacter decode_wide(std::string_view bytes, TextEncoding encoding) {
    const size_t unit = code_unit_bytes(encoding);
    const bool little = encoding == TextEncoding::utf16le || encoding == TextEncoding::utf32le;
    auto unit_at = [&](size_t at) {
        char32_t value = 0;
        for (size_t k = 0; k < unit; ++k) {
            const auto b = static_cast<unsigned char>(bytes[at + (little ? unit - 1 - k : k)]);
            value = (value << 8) | b;
        }
        return value;
    };
    WideCharacter c;
    if (bytes.size() < unit) return c;
    c.code = unit_at(0);
    c.bytes = unit;
    if (unit == 2 && c.code >= 0xD800 && c.code < 0xDC00) {  // a high surrogate and its pair
        if (bytes.size() < 4) return {};
        const char32_t low = unit_at(2);
        if (low < 0xDC00 || low > 0xDFFF) {
            c.valid = false;
            return c;
        }
        c.code = 0x10000 + ((c.code - 0xD800) << 10) + (low - 0xDC00);
        c.bytes = 4;
        return c;
    }
    c.valid = c.code <= 0x10FFFF && !(c.code >= 0xD800 && c.code <= 0xDFFF);
    return c;
}

std::string text_head_as_utf8(std::string_view head) {
    const TextStart start = text_start(head);
    head.remove_prefix(start.mark_bytes);
    if (code_unit_bytes(start.encoding) == 1) return std::string(head);
    std::string out;
    for (;;) {
        const WideCharacter c = decode_wide(head, start.encoding);
        if (!c.bytes || !c.valid) return out;
        append_utf8(c.code, out);
        head.remove_prefix(c.bytes);
    }
}

std::string to_utf8(std::string_view bytes) {
    std::string out;
    out.reserve(bytes.size());
    for (size_t i = 0; i < bytes.size();) {
        char32_t code;
        if (const size_t length = utf8_sequence(bytes, i, code)) {
            out.append(bytes, i, length);
            i += length;
        } else {
            append_utf8(windows_1252(static_cast<unsigned char>(bytes[i])), out);
            ++i;
        }
    }
    return out;
}

bool is_utf8(std::string_view text) {
    char32_t code;
    for (size_t i = 0; i < text.size();) {
        const size_t length = utf8_sequence(text, i, code);
        if (!length) return false;
        i += length;
    }
    return true;
}

void append_utf8(char32_t code, std::string& out) {
    const auto c = static_cast<uint32_t>(code);
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

size_t utf32_to_utf8(const char32_t* text, size_t n, std::string& out) {
    out.clear();
    for (size_t i = 0; i < n; ++i) {
        const char32_t c = text[i];
        if (c == 0) break;
        if (c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return i;
        append_utf8(c, out);
    }
    return std::string::npos;
}

size_t utf8_to_utf32(std::string_view text, std::u32string& out) {
    out.clear();
    for (size_t i = 0; i < text.size();) {
        char32_t code;
        const size_t length = utf8_sequence(text, i, code);
        if (!length) return i;
        out += code;
        i += length;
    }
    return std::string::npos;
}

}  // namespace rayset
