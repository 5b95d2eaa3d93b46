// SceneError and SourceLocation formatting.
#include "tracer/scene_language/parse_error.h"

#include <fmt/format.h>

namespace rayset::tracer {

std::string SourceLocation::str() const { return fmt::format("{}:{}:{}", file, line, column); }

SceneError::SceneError(const std::string& what, SourceLocation where,
                       const std::string& include_chain)
    : Error(fmt::format("{} at {}{}", what, where.str(), include_chain)),
      where_(std::move(where)) {}

}  // namespace rayset::tracer
