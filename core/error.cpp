#include "core/error.h"

#include "core/text_encoding.h"

namespace rayset {

Error::Error(const std::string& message) : std::runtime_error(to_utf8(message)) {}

std::string Location::str() const {
    switch (kind) {
        case Kind::byte: return "byte " + std::to_string(value);
        case Kind::line:
            return "line " + std::to_string(value) +
                   (column ? ", column " + std::to_string(column) : "");
        case Kind::none: break;
    }
    return {};
}

void fail(const std::string& file, const Location& where, const std::string& what) {
    if (where.kind == Location::Kind::none) fail(file, what);
    throw Error(file + ": " + where.str() + ": " + what);
}

void fail(const std::string& file, const std::string& what) { throw Error(file + ": " + what); }

}  // namespace rayset
