#include "core/error.h"

#include "core/text_encoding.h"

namespace rayset {

namespace {

// UTF-8, and a NUL byte quoted from a file as "\0": what() is a C string, which would end there.
std::string readable(const std::string& message) {
    std::string text;
    for (const char c : to_utf8(message)) {
        if (c == '\0')
            text += "\\0";
        else
            text += c;
    }
    return text;
}

}  // namespace

Error::Error(const std::string& message) : std::runtime_error(readable(message)) {}

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
