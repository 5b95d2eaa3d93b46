// The one error type of the scene language: a message that says what was expected and where.
#pragma once

#include <string>

#include "core/error.h"
#include "tracer/scene_language/source_location.h"

namespace rayset::tracer {

class SceneError : public Error {
public:
    SceneError(const std::string& what, SourceLocation where, const std::string& include_chain);
    const SourceLocation& where() const { return where_; }

private:
    SourceLocation where_;
};

}  // namespace rayset::tracer
