#include "converters/rays/io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>

namespace rayset {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the binary codecs assume a little-endian host");

namespace {

std::string system_error_text() { return std::strerror(errno); }

// Where a write to `path` goes, and how. A symbolic link is followed, so that the link stays a
// link and the file it names is replaced. Only a regular file (or nothing yet) is replaced by
// a temporary renamed into place: devices and pipes are written in place.
struct OutputTarget {
    std::filesystem::path file;
    bool in_place = false;
};

OutputTarget output_target(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    OutputTarget target{fs::path(path)};
    if (fs::is_symlink(target.file, ec) &&
        fs::exists(target.file, ec)) {  // a dangling link is replaced
        target.file = fs::canonical(target.file, ec);
        if (ec) fail(path, "cannot follow the symbolic link: " + ec.message());
    }
    const fs::file_status status = fs::status(target.file, ec);
    if (fs::is_directory(status)) fail(path, "is a folder, not a file");
    target.in_place = fs::exists(status) && !fs::is_regular_file(status);
    return target;
}

// A new, empty, hidden file beside `target` whose name no other writer holds:
// ".NAME.tmpNNNNNN.EXT", created with O_EXCL. The output is written there and renamed over the
// target (same folder, so the rename is atomic); the extension is kept for writers that go by it.
// Returns its open descriptor; `path` (as the user gave it) names the failure.
int create_temporary_beside(const std::string& path, const std::filesystem::path& target,
                            std::string& temporary) {
    namespace fs = std::filesystem;
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        fail(path, "cannot write: folder " + dir.string() + " does not exist");
    std::random_device random;
    int fd = -1;
    for (int attempt = 0; attempt < 16 && fd < 0; ++attempt) {
        const std::string name = "." + target.stem().string() + ".tmp" +
                                 std::to_string(random() % 1000000) + target.extension().string();
        temporary = (dir / name).string();
        fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) break;
    }
    if (fd < 0) fail(path, "cannot create a temporary file beside it: " + system_error_text());
    return fd;
}

std::FILE* open_for_reading(const std::string& path, uint64_t& size) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail(path, "is a folder, not a file");
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) fail(path, "cannot open: " + system_error_text());
    struct stat st {};
    if (::fstat(::fileno(file), &st) != 0) {
        std::fclose(file);
        fail(path, "cannot read its size: " + system_error_text());
    }
    size = static_cast<uint64_t>(st.st_size);
    // Large stdio buffers: the codecs read sequentially and this keeps syscalls few.
    std::setvbuf(file, nullptr, _IOFBF, 1 << 20);
    return file;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
BinaryInput::BinaryInput(const std::string& path) : path_(path), buffer_(size_t(64) << 10) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail(path, "is a folder, not a file");
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) fail(path, "cannot open: " + system_error_text());
    struct stat st {};
    if (::fstat(fd_, &st) != 0) {
        std::string error = system_error_text();
        ::close(fd_);
        fail(path, "cannot read its size: " + error);
    }
    size_ = static_cast<uint64_t>(st.st_size);
    // Codecs read front to back: a larger read-ahead where the file is not cached yet.
    ::posix_fadvise(fd_, 0, 0, POSIX_FADV_SEQUENTIAL);
}

BinaryInput::~BinaryInput() {
    if (fd_ >= 0) ::close(fd_);
}

void BinaryInput::seek(uint64_t offset) {
    if (offset > size_)
        fail_here("seek past the end of the file (" + std::to_string(size_) + " bytes)");
    if (::lseek(fd_, static_cast<off_t>(offset), SEEK_SET) < 0)
        fail_here("cannot seek: " + system_error_text());
    buffered_begin_ = buffered_end_ = 0;
    offset_ = offset;
}

size_t BinaryInput::fill(uint8_t* out, size_t n, const char* what) {
    size_t done = 0;
    while (done < n) {
        if (buffered_begin_ < buffered_end_) {
            size_t take = std::min(n - done, buffered_end_ - buffered_begin_);
            std::memcpy(out + done, buffer_.data() + buffered_begin_, take);
            buffered_begin_ += take;
            done += take;
            continue;
        }
        // What fills the buffer at least is read directly; less is read through the buffer.
        const bool direct = n - done >= buffer_.size();
        uint8_t* into = direct ? out + done : buffer_.data();
        ssize_t got = ::read(fd_, into, direct ? n - done : buffer_.size());
        if (got < 0 && errno == EINTR) continue;
        if (got < 0)
            fail_here((what ? std::string("read error in ") + what : std::string("read error")) +
                      ": " + system_error_text());
        if (got == 0) break;
        if (direct) {
            done += static_cast<size_t>(got);
        } else {
            buffered_begin_ = 0;
            buffered_end_ = static_cast<size_t>(got);
        }
    }
    return done;
}

void BinaryInput::read(void* out, size_t n, const char* what) {
    size_t got = fill(static_cast<uint8_t*>(out), n, what);
    if (got != n)
        fail_here(std::string("file ends inside ") + what + " (" + std::to_string(n) +
                  " bytes expected, " + std::to_string(got) + " left): the file is truncated");
    offset_ += n;
}

size_t BinaryInput::read_some(void* out, size_t n) {
    size_t got = fill(static_cast<uint8_t*>(out), n, nullptr);
    offset_ += got;
    return got;
}

// ---------------------------------------------------------------------------------------------
TextInput::TextInput(const std::string& path) : path_(path) {
    file_ = open_for_reading(path, size_);
    char head[kTextStartBytes];
    head_.assign(head, std::fread(head, 1, sizeof head, file_));
    const TextStart start = text_start(head_);
    encoding_ = start.encoding;
    head_used_ = start.mark_bytes;
    offset_ = start.mark_bytes;
}

TextInput::~TextInput() {
    if (file_) std::fclose(file_);
    std::free(line_buffer_);
}

int TextInput::get_byte() {
    if (head_used_ < head_.size()) return static_cast<unsigned char>(head_[head_used_++]);
    return std::getc(file_);
}

// Eight-bit text a line at a time through getline (a byte at a time through getc costs a third
// of reading a CSV file), after the bytes read to tell the encoding.
bool TextInput::next(std::string& line) {
    if (code_unit_bytes(encoding_) > 1) return next_wide(line);
    line.clear();
    size_t bytes = 0;
    bool ended = false;
    while (head_used_ < head_.size() && !ended) {
        const char c = head_[head_used_++];
        ++bytes;
        ended = c == '\n';
        if (!ended) line.push_back(c);
    }
    if (!ended) {
        const ssize_t n = ::getline(&line_buffer_, &line_buffer_size_, file_);
        if (n < 0 && std::ferror(file_))
            fail(path_, Location::byte(offset_ + bytes), "cannot read: " + system_error_text());
        if (n > 0) {
            bytes += size_t(n);
            ended = line_buffer_[n - 1] == '\n';
            line.append(line_buffer_, size_t(n) - ended);
        }
    }
    if (bytes == 0) return false;
    offset_ += bytes;
    ++line_number_;
    if (std::memchr(line.data(), 0, line.size()))
        fail_here("NUL byte in a text file: is this a binary file?");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
}

bool TextInput::next_wide(std::string& line) {
    line.clear();
    std::string window;  // the bytes of the next character, at most 4
    bool any = false;
    for (;;) {
        for (int c; window.size() < 4 && (c = get_byte()) != EOF;)
            window.push_back(static_cast<char>(c));
        if (window.empty()) break;
        any = true;
        const WideCharacter c = decode_wide(window, encoding_);
        if (!c.bytes || !c.valid) {
            ++line_number_;
            fail(path_, Location::byte(offset_),
                 std::string(c.bytes ? "not a Unicode character"
                                     : "the file ends inside a character") +
                     " in " + to_string(encoding_) + " text");
        }
        offset_ += c.bytes;
        window.erase(0, c.bytes);
        if (c.code == '\n') break;
        if (c.code == 0) {
            ++line_number_;
            fail_here(std::string("NUL character in ") + to_string(encoding_) + " text");
        }
        append_utf8(c.code, line);
    }
    // Bytes read past the line's end go back in front of the file's.
    head_ = window + head_.substr(head_used_);
    head_used_ = 0;
    if (!any) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    ++line_number_;
    return true;
}

// ---------------------------------------------------------------------------------------------
AtomicOutput::AtomicOutput(const std::string& path) : path_(path), buffer_(size_t(64) << 10) {
    const OutputTarget target = output_target(path);
    if (target.in_place) {
        fd_ = ::open(target.file.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd_ < 0) fail(path, "cannot open for writing: " + system_error_text());
        return;
    }
    fd_ = create_temporary_beside(path, target.file, temp_path_);
    final_path_ = target.file.string();
}

AtomicOutput::~AtomicOutput() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_ && !temp_path_.empty()) std::remove(temp_path_.c_str());
}

void AtomicOutput::write_fully(const uint8_t* data, size_t n, uint64_t at) {
    // Appends with write(), which a pipe takes too; only a patch goes back, with pwrite().
    const bool append = at == appended_;
    while (n > 0) {
        ssize_t done =
            append ? ::write(fd_, data, n) : ::pwrite(fd_, data, n, static_cast<off_t>(at));
        if (done < 0 && errno == EINTR) continue;
        if (done < 0 && errno == ESPIPE)
            fail(path_,
                 "cannot write this format to a pipe: its header is completed after the rays, "
                 "which needs a "
                 "file (write to a file, or choose csv)");
        if (done <= 0) fail(path_, "write failed: " + system_error_text());
        data += done, n -= static_cast<size_t>(done), at += static_cast<uint64_t>(done);
        if (append) appended_ += static_cast<uint64_t>(done);
    }
}

void AtomicOutput::flush() {
    write_fully(buffer_.data(), buffered_, offset_ - buffered_);
    buffered_ = 0;
}

void AtomicOutput::write(const void* data, size_t n) {
    const uint8_t* bytes = static_cast<const uint8_t*>(data);
    if (buffered_ + n <= buffer_.size()) {
        std::memcpy(buffer_.data() + buffered_, bytes, n);
        buffered_ += n;
    } else {
        flush();
        if (n < buffer_.size()) {
            std::memcpy(buffer_.data(), bytes, n);
            buffered_ = n;
        } else {
            write_fully(bytes, n, offset_);
        }
    }
    offset_ += n;
}

void AtomicOutput::patch(uint64_t offset, const void* data, size_t n) {
    if (offset + n > offset_) fail(path_, "internal error: patch beyond the written data");
    flush();
    write_fully(static_cast<const uint8_t*>(data), n, offset);
}

void AtomicOutput::commit() {
    if (committed_) return;
    flush();
    // A device or pipe has no disk to flush to (fsync fails on some); a file must reach its disk.
    if (!temp_path_.empty() && ::fsync(fd_) != 0)
        fail(path_, "write failed: " + system_error_text());
    int closed = ::close(fd_);
    fd_ = -1;
    if (closed != 0) fail(path_, "write failed: " + system_error_text());
    if (!temp_path_.empty() && std::rename(temp_path_.c_str(), final_path_.c_str()) != 0)
        fail(path_, "cannot move the finished file into place: " + system_error_text());
    committed_ = true;
}

// ---------------------------------------------------------------------------------------------
std::vector<uint8_t> read_head(const std::string& path, size_t n) {
    BinaryInput in(path);
    std::vector<uint8_t> head(std::min<uint64_t>(n, in.size()));
    if (!head.empty()) in.read(head.data(), head.size(), "the start of the file");
    return head;
}

uint64_t file_size(const std::string& path) {
    std::error_code ec;
    auto size = std::filesystem::file_size(path, ec);
    if (ec) fail(path, "cannot open: " + ec.message());
    return size;
}

namespace {
template <class T>
bool parse_number(std::string_view token, T& out) {
    if (token.empty()) return false;
    const char* begin = token.data();
    const char* end = begin + token.size();
    if (*begin == '+') ++begin;  // from_chars does not take a leading '+', files do
    auto [ptr, ec] = std::from_chars(begin, end, out);
    return ec == std::errc() && ptr == end;
}
}  // namespace

bool parse_double(std::string_view token, double& out) { return parse_number(token, out); }
bool parse_float(std::string_view token, float& out) { return parse_number(token, out); }

std::vector<std::string_view> split_fields(std::string_view line, bool commas) {
    std::vector<std::string_view> fields;
    size_t i = 0, n = line.size();
    auto is_space = [](char c) { return c == ' ' || c == '\t'; };
    if (commas) {
        while (true) {
            size_t end = line.find(',', i);
            std::string_view field =
                line.substr(i, end == std::string_view::npos ? n - i : end - i);
            while (!field.empty() && is_space(field.front())) field.remove_prefix(1);
            while (!field.empty() && is_space(field.back())) field.remove_suffix(1);
            fields.push_back(field);
            if (end == std::string_view::npos) break;
            i = end + 1;
        }
        return fields;
    }
    while (i < n) {
        while (i < n && is_space(line[i])) ++i;
        size_t start = i;
        while (i < n && !is_space(line[i])) ++i;
        if (i > start) fields.push_back(line.substr(start, i - start));
    }
    return fields;
}

std::string format_float(float value) {
    char buffer[64];
    auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, ptr);
}

std::string format_double(double value) {
    char buffer[64];
    auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, ptr);
}

void write_atomically(const std::string& path,
                      const std::function<bool(const std::string&)>& write) {
    namespace fs = std::filesystem;
    const OutputTarget target = output_target(path);
    // A device or a pipe is written in place; anything else through a temporary file beside it,
    // made empty here (which reserves its name) and written by `write`.
    std::string temporary;
    if (!target.in_place) ::close(create_temporary_beside(path, target.file, temporary));
    const fs::path to = target.in_place ? target.file : fs::path(temporary);
    auto fail = [&](const std::string& why) {
        std::error_code ignored;
        if (!target.in_place) fs::remove(to, ignored);
        throw Error(path + ": cannot write" + (why.empty() ? "" : ": " + why));
    };
    // A writer that reports success but leaves the temporary empty (some fail silently) must
    // not replace what the user had.
    bool written = false;
    try {
        written = write(to.string());
        std::error_code ec;
        if (written && !target.in_place) written = fs::file_size(to, ec) > 0 && !ec;
    } catch (const std::exception& e) {
        fail(e.what());
    }
    if (!written) fail("");
    if (target.in_place) return;
    // Writers that go through a file name do not flush to the disk: a disk that fills up while
    // the kernel writes the data back must fail here, not after the rename.
    const int fd = ::open(to.c_str(), O_RDONLY | O_CLOEXEC);
    const bool synced = fd >= 0 && ::fsync(fd) == 0;
    const std::string sync_error = synced ? "" : system_error_text();
    if (fd >= 0) ::close(fd);
    if (!synced) fail(sync_error);
    std::error_code error;
    fs::rename(to, target.file, error);
    if (error) fail(error.message());
}

}  // namespace rayset
