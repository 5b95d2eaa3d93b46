// Counting the data rows of a text ray file before streaming it: the header a decoder hands out
// must know the ray count, and text formats (LightTools text, rayset CSV) do not state it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace rayset {

struct RowCount {
    uint64_t rows = 0;       // non-blank lines before the end marker
    uint64_t last_line = 0;  // number of the file's last line (0 when nothing follows `offset`)
    uint64_t end_line = 0;   // line of the end marker, 0 when there is none
    uint64_t after_end = 0;  // first non-blank line after the end marker, 0 when there is none
};

// Scans `path` from byte `offset`, which starts line `first_line`, in large blocks. A line whose
// first non-blank text starts with `end_marker` (when not empty) ends the rows.
RowCount count_rows(const std::string& path, uint64_t offset, uint64_t first_line,
                    std::string_view end_marker);

}  // namespace rayset
