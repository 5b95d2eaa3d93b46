#include "converters/rays/text_row_count.h"

#include "converters/rays/io.h"
#include "core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

namespace rayset {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

class LineClassifier {
public:
    LineClassifier(RowCount& count, uint64_t first_line, std::string_view end_marker)
        : count_(count), line_(first_line), end_marker_(end_marker) {}

    void line(std::string_view text) {
        size_t start = text.find_first_not_of(" \t\r");
        if (start != std::string_view::npos) {
            text.remove_prefix(start);
            if (count_.end_line) {
                if (!count_.after_end) count_.after_end = line_;
            } else if (!end_marker_.empty() && text.substr(0, end_marker_.size()) == end_marker_) {
                count_.end_line = line_;
            } else {
                ++count_.rows;
            }
        }
        count_.last_line = line_++;
    }

private:
    RowCount& count_;
    uint64_t line_;
    std::string_view end_marker_;
};

// UTF-16 and UTF-32 text, line by line as TextInput decodes it (newline bytes are not lines).
RowCount count_wide_rows(TextInput& in, uint64_t offset, uint64_t first_line,
                         std::string_view end_marker) {
    std::string line;
    while (in.offset() < offset && in.next(line)) {
    }
    RowCount count;
    LineClassifier classify(count, first_line, end_marker);
    while (in.next(line)) classify.line(line);
    return count;
}

}  // namespace

RowCount count_rows(const std::string& path, uint64_t offset, uint64_t first_line,
                    std::string_view end_marker) {
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) fail(path, std::string("cannot open: ") + std::strerror(errno));
    char head[kTextStartBytes];
    const size_t head_size = std::fread(head, 1, sizeof head, file.get());
    if (code_unit_bytes(text_start(std::string_view(head, head_size)).encoding) > 1) {
        TextInput in(path);
        return count_wide_rows(in, offset, first_line, end_marker);
    }
    if (std::fseek(file.get(), static_cast<long>(offset), SEEK_SET) != 0)
        fail(path, std::string("cannot seek: ") + std::strerror(errno));

    RowCount count;
    LineClassifier classify(count, first_line, end_marker);
    std::vector<char> block(1 << 20);
    std::string carry;  // a line split across two blocks
    size_t got;
    while ((got = std::fread(block.data(), 1, block.size(), file.get())) > 0) {
        std::string_view rest(block.data(), got);
        for (size_t nl; (nl = rest.find('\n')) != std::string_view::npos;
             rest.remove_prefix(nl + 1)) {
            if (carry.empty()) {
                classify.line(rest.substr(0, nl));
            } else {
                carry.append(rest.substr(0, nl));
                classify.line(carry);
                carry.clear();
            }
        }
        carry.append(rest);
    }
    if (std::ferror(file.get())) fail(path, std::string("read error: ") + std::strerror(errno));
    if (!carry.empty()) classify.line(carry);
    return count;
}

}  // namespace rayset
