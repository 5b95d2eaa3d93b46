// Errors a user can act on: which file, where in it, what is wrong.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rayset {

// Thrown for anything wrong with an input file or a request. what() reads
// "FILE: byte 1234: expected ..." or "FILE:12: ...", ready to print: UTF-8 even where the
// message quotes a file's 8-bit text (to_utf8, core/text_encoding.h), with a quoted NUL byte
// written "\0" so that the C string what() returns holds the whole message.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message);
};

// Where in a file: a byte offset for binary formats, a line (and column) for text.
struct Location {
    enum class Kind { none, byte, line } kind = Kind::none;
    uint64_t value = 0;
    uint32_t column = 0;

    static Location byte(uint64_t offset) { return {Kind::byte, offset, 0}; }
    static Location line(uint64_t line, uint32_t column = 0) { return {Kind::line, line, column}; }
    std::string str() const;
};

[[noreturn]] void fail(const std::string& file, const Location& where, const std::string& what);
[[noreturn]] void fail(const std::string& file, const std::string& what);

}  // namespace rayset
