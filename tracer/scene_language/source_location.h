// A place in a scene file, for messages and for what the renderer reports about an object.
#pragma once

#include <string>

namespace rayset::tracer {

struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;
    std::string str() const;  // "file:line:column"
};

}  // namespace rayset::tracer
