// SceneError and SourceLocation formatting.
#include "tracer/scene_language/parse_error.h"

#include <fmt/format.h>

namespace rayset::tracer {

namespace {

// Callers read the message as a C string (what()), which a NUL byte of quoted scene text (the
// string "\0") would cut short before the place; it is written as the scene's own escape.
std::string nul_escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\0')
            out += "\\0";
        else
            out += c;
    }
    return out;
}

}  // namespace

std::string SourceLocation::str() const { return fmt::format("{}:{}:{}", file, line, column); }

SceneError::SceneError(const std::string& what, SourceLocation where,
                       const std::string& include_chain)
    : Error(nul_escaped(fmt::format("{} at {}{}", what, where.str(), include_chain))),
      where_(std::move(where)) {}

}  // namespace rayset::tracer
