// Names the rayset CSV reader (csv.cpp, which documents the format) and writer (csv_writer.cpp)
// must agree on: columns, metadata keys, and the escaping of text values.
#pragma once

#include "converters/rays/ray.h"
#include "converters/rays/ray_names.h"

#include <string>
#include <string_view>

namespace rayset::csv {

inline constexpr std::string_view kFirstLine = "# rayset CSV ray data";
inline constexpr std::string_view kPositionColumns[6] = {"x", "y", "z", "kx", "ky", "kz"};
inline constexpr std::string_view kRadiant = "radiant_W";
inline constexpr std::string_view kLuminous = "luminous_lm";
inline constexpr std::string_view kWavelength = "wavelength_nm";
inline constexpr std::string_view kSpectrum = "spectrum";

// Keys of RayHeader::text, in its order.
inline constexpr std::string_view kTextKeys[9] = {
    "name",   "manufacturer",         "model_creator",   "ray_file_creator", "equipment",
    "camera", "operating_conditions", "additional_info", "data_reference"};

// Whether `name` is a column with a fixed meaning (an additional extra may not use it).
inline bool is_reserved_column(std::string_view name) {
    for (std::string_view p : kPositionColumns)
        if (name == p) return true;
    if (name == kRadiant || name == kLuminous || name == kWavelength || name == kSpectrum)
        return true;
    for (const NamedExtra& e : kNamedExtras)
        if (name == e.name) return true;
    return false;
}

// Text metadata sits on one line: backslash, CR and LF are escaped.
inline std::string escape(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '\\')
            out += "\\\\";
        else if (c == '\n')
            out += "\\n";
        else if (c == '\r')
            out += "\\r";
        else
            out += c;
    }
    return out;
}

// Returns false on a backslash not followed by one of \ n r.
inline bool unescape(std::string_view text, std::string& out) {
    out.clear();
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\\') {
            out += text[i];
            continue;
        }
        if (++i == text.size()) return false;
        switch (text[i]) {
            case '\\': out += '\\'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            default: return false;
        }
    }
    return true;
}

}  // namespace rayset::csv
