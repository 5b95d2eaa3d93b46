// Files as the codecs see them: a buffered binary input that knows its byte offset, a text
// input that knows its line number, and an output that appears only when it is complete.
#pragma once

#include "core/error.h"
#include "core/text_encoding.h"

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace rayset {

// Sequential little-endian reads with the offset of every failure in the error message.
// Small reads (header fields) come from a buffer; large ones (ray records) go from the file
// straight into the caller's memory, so the bytes are copied once.
class BinaryInput {
public:
    explicit BinaryInput(const std::string& path);
    ~BinaryInput();
    BinaryInput(const BinaryInput&) = delete;
    BinaryInput& operator=(const BinaryInput&) = delete;

    const std::string& path() const { return path_; }
    uint64_t size() const { return size_; }
    uint64_t offset() const { return offset_; }
    uint64_t remaining() const { return size_ - offset_; }

    void seek(uint64_t offset);
    // Reads exactly n bytes or fails naming `what` was being read and where the file ended.
    void read(void* out, size_t n, const char* what);
    // Reads up to n bytes; returns how many (0 at the end).
    size_t read_some(void* out, size_t n);

    template <class T>
    T read(const char* what) {
        T value;
        read(&value, sizeof(T),
             what);  // little-endian host (x86_64, aarch64): static_assert in io.cpp
        return value;
    }

    [[noreturn]] void fail_at(uint64_t offset, const std::string& what) const {
        rayset::fail(path_, Location::byte(offset), what);
    }
    [[noreturn]] void fail_here(const std::string& what) const { fail_at(offset_, what); }

private:
    // Up to n bytes into `out`, fewer only at the end of the file; `what` (if any) names a read
    // error.
    size_t fill(uint8_t* out, size_t n, const char* what);

    std::string path_;
    int fd_ = -1;
    uint64_t size_ = 0;
    uint64_t offset_ = 0;
    std::vector<uint8_t> buffer_;
    size_t buffered_begin_ = 0, buffered_end_ = 0;  // the unread part of buffer_
};

// Line-oriented text input; strips "\r\n" and "\n". Line numbers are 1-based. A byte-order
// mark is skipped; UTF-16 and UTF-32 text (with a mark, or recognised by its zero bytes) is
// handed out as UTF-8, 8-bit text as its bytes are (core/text_encoding.h).
class TextInput {
public:
    explicit TextInput(const std::string& path);
    ~TextInput();
    TextInput(const TextInput&) = delete;
    TextInput& operator=(const TextInput&) = delete;

    const std::string& path() const { return path_; }
    // Next line into `line`; false at the end of the file.
    bool next(std::string& line);
    uint64_t line_number() const { return line_number_; }  // of the line last returned
    uint64_t offset() const { return offset_; }            // byte offset after it
    uint64_t size() const { return size_; }
    TextEncoding encoding() const { return encoding_; }

    [[noreturn]] void fail_here(const std::string& what, uint32_t column = 0) const {
        rayset::fail(path_, Location::line(line_number_, column), what);
    }

private:
    int get_byte();  // the next byte of the file, or EOF
    bool next_wide(std::string& line);

    std::string path_;
    std::FILE* file_ = nullptr;
    uint64_t size_ = 0;
    uint64_t offset_ = 0;
    uint64_t line_number_ = 0;
    TextEncoding encoding_ = TextEncoding::eight_bit;
    std::string head_;  // the first bytes, read to tell the encoding, not yet handed out
    size_t head_used_ = 0;
    char* line_buffer_ = nullptr;  // getline's, grown to the longest line
    size_t line_buffer_size_ = 0;
};

// For writers that take a file name (OpenVDB, VTK): `write` gets the path of an empty temporary
// file beside `path` (hidden, same extension, named as AtomicOutput names its own) to overwrite,
// and returns whether it succeeded; the file is then renamed into place. On failure, an
// exception or an output left empty, the temporary file is removed, whatever was at `path` is
// untouched, and rayset::Error names `path`. Like AtomicOutput, it writes through a symbolic
// link to the file it names, and into a device or pipe (/dev/null, a FIFO) in place.
void write_atomically(const std::string& path,
                      const std::function<bool(const std::string&)>& write);

// Writes to a temporary file beside the target and renames it into place on commit(). If the
// object is destroyed without commit() (an error was thrown), the temporary file is removed and
// whatever was at the target path before is untouched. commit() flushes the file to the disk
// (fsync) before the rename, so that a crash cannot leave a half-written file under the name.
// Small writes are gathered in a buffer; large ones go from the caller's memory to the file.
// A symbolic link stays a link: the file it names is the one replaced. A device or pipe
// (/dev/null, a FIFO) is written in place - renaming over it would replace the device itself,
// and it holds nothing to protect; patch() then fails on a pipe, which cannot go back.
class AtomicOutput {
public:
    explicit AtomicOutput(const std::string& path);
    ~AtomicOutput();
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;

    const std::string& path() const { return path_; }
    void write(const void* data, size_t n);
    void write(std::string_view text) { write(text.data(), text.size()); }
    template <class T>
    void put(const T& value) {
        write(&value, sizeof(T));
    }
    // Overwrites bytes already written (for counts and totals known only at the end).
    void patch(uint64_t offset, const void* data, size_t n);
    uint64_t offset() const { return offset_; }
    void commit();

private:
    void flush();
    void write_fully(const uint8_t* data, size_t n, uint64_t at);

    std::string path_;
    std::string temp_path_;   // empty when writing a device or pipe in place
    std::string final_path_;  // where the temporary goes: path_, or the file its link names
    int fd_ = -1;
    uint64_t offset_ = 0;    // bytes written, buffered ones included
    uint64_t appended_ = 0;  // bytes written to the file in order (not patches)
    std::vector<uint8_t> buffer_;
    size_t buffered_ = 0;  // bytes waiting in buffer_, the last ones of offset_
    bool committed_ = false;
};

// Reads the first up-to-n bytes of a file (for format detection).
std::vector<uint8_t> read_head(const std::string& path, size_t n);
uint64_t file_size(const std::string& path);

// Text <-> number helpers shared by the text codecs. Parses a whole token as a number; returns
// false for anything else (trailing junk, empty, out of range). "nan" and "inf" parse.
bool parse_double(std::string_view token, double& out);
bool parse_float(std::string_view token, float& out);
// Splits on spaces, tabs and (if commas) commas; empty fields between commas are kept.
std::vector<std::string_view> split_fields(std::string_view line, bool commas = false);
// Shortest decimal text that reads back to the same float (round trips are bit-exact).
std::string format_float(float value);
std::string format_double(double value);

}  // namespace rayset
