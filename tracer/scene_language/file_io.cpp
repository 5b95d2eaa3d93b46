// #fopen, #fclose, #read and #write. Reading is confined to the allowed roots like #include;
// writing and appending to ParseOptions::write_roots, empty by default (a scene cannot write
// files unless the user says where). #read takes the literal data POV-Ray's #read takes
// (strings, signed floats, vectors, separated by commas) and closes the file, undefining its
// handle, once its data is used up; #write writes floats as C's %g and vectors as <x,y,z>.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <fmt/printf.h>

#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace fs = std::filesystem;

FileHandle::~FileHandle() {
    if (stream) std::fclose(stream);
}

namespace {

bool within(const fs::path& path, const fs::path& root) {
    auto p = path.begin();
    for (auto r = root.begin(); r != root.end(); ++r, ++p) {
        if (r->empty()) continue;  // trailing separator
        if (p == path.end() || *p != *r) return false;
    }
    return true;
}

// #write's binary words: uint8, sint8, uint16be ... sint32le; 0 for any other token.
int binary_word_size(const Token& token) {
    if (token.is(Keyword::uint8) || token.is(Keyword::sint8)) return 1;
    if (token.is(Keyword::uint16be) || token.is(Keyword::uint16le) || token.is(Keyword::sint16be) ||
        token.is(Keyword::sint16le))
        return 2;
    if (token.is(Keyword::sint32be) || token.is(Keyword::sint32le)) return 4;
    return 0;
}

// The value rounded to the nearest integer of the word's range, in its byte order.
std::string binary_word(Keyword type, int bytes, double value) {
    const bool is_signed = type == Keyword::sint8 || type == Keyword::sint16be ||
                           type == Keyword::sint16le || type == Keyword::sint32be ||
                           type == Keyword::sint32le;
    const bool big_endian =
        type == Keyword::uint16be || type == Keyword::sint16be || type == Keyword::sint32be;
    const double range = std::ldexp(1.0, 8 * bytes);
    const double low = is_signed ? -range / 2 : 0, high = is_signed ? range / 2 - 1 : range - 1;
    const auto word = static_cast<int64_t>(std::clamp(std::round(value), low, high));
    std::string out(static_cast<size_t>(bytes), '\0');
    for (int i = 0; i < bytes; ++i) {
        const char byte = static_cast<char>((static_cast<uint64_t>(word) >> (8 * i)) & 0xFF);
        out[big_endian ? bytes - 1 - i : i] = byte;
    }
    return out;
}

// #read's data: the file's tokens, taken one by one.
const Token& take_data_token(FileHandle& file) {
    return file.read_tokens->tokens[file.read_position++];
}

// A signed float literal of a #read data file, its sign (if any) being `first`.
double read_data_number(const Parser& parser, FileHandle& file, const Token& first) {
    double sign = 1;
    Token token = first;
    if (token.is(Symbol::minus) || token.is(Symbol::plus)) {
        sign = token.is(Symbol::minus) ? -1 : 1;
        token = take_data_token(file);
    }
    if (token.kind != TokenKind::number)
        parser.fail(token, fmt::format("#read: expected a number in {}, found {}", file.path,
                                       parser.describe(token)));
    return sign * token.number;
}

// A vector literal <a, b, ...> of 2 to 5 terms of a #read data file, after its '<'.
Numeric read_data_vector(const Parser& parser, FileHandle& file, const Token& open) {
    Numeric vector;
    vector.terms = 0;
    for (;;) {
        if (vector.terms == 5)
            parser.fail(open, fmt::format("#read: a vector of more than 5 terms in {}", file.path));
        vector.v[vector.terms++] = read_data_number(parser, file, take_data_token(file));
        const Token separator = take_data_token(file);
        if (separator.is(Symbol::greater)) break;
        if (!separator.is(Symbol::comma))
            parser.fail(separator,
                        fmt::format("#read: expected ',' or '>' in a vector in {}", file.path));
    }
    if (vector.terms < 2)
        parser.fail(open, fmt::format("#read: a vector needs 2 terms or more in {}", file.path));
    return vector;
}

// The next item of a #read data file: a string, a vector or a float.
Value read_data_item(const Parser& parser, FileHandle& file) {
    const Token first = take_data_token(file);
    if (first.kind == TokenKind::string) return file.read_tokens->strings[first.string];
    if (first.is(Symbol::less)) return read_data_vector(parser, file, first);
    return Numeric::scalar(read_data_number(parser, file, first));
}

}  // namespace

std::string Parser::resolve_file(const std::string& name, const Token& at, const std::string& what,
                                 std::initializer_list<const char*> extensions) const {
    std::vector<fs::path> candidates;
    const fs::path given(name);
    auto add = [&](const fs::path& folder) {
        candidates.push_back(folder / given);
        if (given.extension().empty())
            for (const char* extension : extensions)
                candidates.push_back(folder / (name + extension));
    };
    if (given.is_absolute()) {
        add(fs::path());
    } else {
        add(fs::path(files_[at.file].source->directory));
        for (const std::string& folder : search_paths_) add(fs::path(folder));
    }
    for (const fs::path& candidate : candidates) {
        std::error_code error;
        if (!fs::is_regular_file(candidate, error)) continue;
        const fs::path real = fs::weakly_canonical(candidate, error);
        for (const std::string& root : allowed_roots_)
            if (within(real, fs::path(root))) return real.string();
        // POV-Ray's own include folder, installed by the system, links its fonts to the
        // system's font folder: its links are trusted (a scene's own folder's are not).
        const fs::path found = fs::absolute(candidate, error).lexically_normal();
        for (const std::string& folder : default_include_paths())
            if (within(found, fs::path(folder))) return real.string();
        std::string roots;
        for (const std::string& root : allowed_roots_) roots += (roots.empty() ? "" : ", ") + root;
        fail(at, fmt::format("{} \"{}\" resolves to {}, outside the allowed roots ({})", what, name,
                             real.string(), roots));
    }
    std::string searched;
    for (const fs::path& candidate : candidates)
        if (searched.find(candidate.parent_path().string()) == std::string::npos)
            searched += (searched.empty() ? "" : ", ") + candidate.parent_path().string();
    fail(at, fmt::format("{} \"{}\" not found (searched {})", what, name, searched));
}

void Parser::directive_fopen(const Token& directive) {
    const Token handle = raw_next();
    if (!handle.is_identifier()) fail_expected("a file handle identifier after #fopen", handle);
    const Token name_token = peek();
    const std::string name = parse_string();
    const Token mode = next();
    auto file = std::make_shared<FileHandle>();
    if (mode.is(Keyword::read)) {
        // A file the scene wrote itself is read back from where it was written; a name the
        // system cannot resolve (too long, say) is looked up as any other and not found.
        std::error_code error;
        const fs::path written = fs::weakly_canonical(fs::current_path() / name, error);
        bool in_write_root = false;
        for (const std::string& root : write_roots_)
            in_write_root = in_write_root || (!error && within(written, fs::path(root)));
        file->path = in_write_root && fs::is_regular_file(written, error)
                         ? written.string()
                         : resolve_file(name, name_token, "#fopen file");
        std::ifstream in(file->path, std::ios::binary);
        if (!in)
            fail(name_token, fmt::format("#fopen: \"{}\" cannot be read ({})", name, file->path));
        std::ostringstream text;
        text << in.rdbuf();
        file->read_tokens = std::make_shared<SourceFile>();
        file->read_tokens->path = file->path;
        FileInfo info;
        info.source = file->read_tokens;
        files_.push_back(info);
        tokenize(text.str(), static_cast<int>(files_.size()) - 1, *file->read_tokens, names_);
    } else if (mode.is(Keyword::write) || mode.is(Keyword::append)) {
        const fs::path given(name);
        // Relative to the working directory, as POV-Ray writes.
        std::error_code error;
        const fs::path target =
            fs::weakly_canonical(given.is_absolute() ? given : fs::current_path() / given, error);
        if (error)
            fail(name_token, fmt::format("#fopen \"{}\" for {}: {}", name, word(mode),
                                         error.message()));
        bool allowed = false;
        for (const std::string& root : write_roots_)
            allowed = allowed || within(target, fs::path(root));
        if (!allowed)
            fail(
                name_token,
                fmt::format(
                    "#fopen \"{}\" for {}: writing files is not allowed {} (raytrace --allow-write "
                    "DIR, or ParseOptions::write_roots)",
                    name, word(mode),
                    write_roots_.empty() ? "unless a folder is given for it"
                                         : "outside the folders given for it"));
        file->path = target.string();
        file->writing = true;
        file->stream = std::fopen(file->path.c_str(), mode.is(Keyword::write) ? "wb" : "ab");
        if (!file->stream)
            fail(name_token,
                 fmt::format("#fopen: \"{}\" cannot be opened for writing ({})", name, file->path));
    } else {
        fail_expected("read, write or append after the file name of #fopen", mode);
    }
    // File handles are always global (POV-Ray's rule).
    auto entry = std::make_shared<SymbolEntry>();
    entry->value = FileRef(std::move(file));
    symbols_.bind(handle.name, std::move(entry), 0);
}

void Parser::directive_fclose(const Token& directive) {
    const Token handle = raw_next();
    const SymbolRef symbol = handle.kind == TokenKind::word ? resolve(handle.name) : nullptr;
    if (!symbol || !std::holds_alternative<FileRef>(symbol->value)) {
        (void)directive;
        return;  // closing a file that is not open does nothing, as in POV-Ray
    }
    symbols_.unbind_everywhere(handle.name);
}

void Parser::directive_read(const Token& directive) {
    expect(Symbol::lparen, "after #read");
    const Token handle = raw_next();
    const SymbolRef symbol = handle.kind == TokenKind::word ? resolve(handle.name) : nullptr;
    if (!symbol || !std::holds_alternative<FileRef>(symbol->value))
        fail_expected("a file handle opened by #fopen ... read", handle);
    const FileRef file = std::get<FileRef>(symbol->value);
    if (file->writing)
        fail(handle, fmt::format("#read from a file opened for writing ({})", file->path));
    const std::vector<Token>& data = file->read_tokens->tokens;
    auto at_end = [&] { return data[file->read_position].kind == TokenKind::end; };
    // The file closes, undefining its handle, when a read meets its end: after an item with no
    // comma after it, or where an item should be (POV-Ray's rule).
    bool ended = false;
    // Commas between the items are optional, as POV-Ray reads them.
    for (accept_comma(); !peek_is(Symbol::rparen); accept_comma()) {
        if (have_lookahead_) give_back_lookahead();  // the identifier is read raw
        const Token variable = raw_next();
        if (!variable.is_identifier()) fail_expected("an identifier to read into", variable);
        if (at_end()) {
            ended = true;
            break;
        }
        Value value = read_data_item(*this, *file);
        if (data[file->read_position].is(Symbol::comma))
            ++file->read_position;
        else
            ended = at_end();
        const SymbolRef existing = lookup(variable.name);
        if (existing && existing->value.index() != value.index())
            fail(variable, fmt::format("#read: '{}' is {}, the file gives {}", word(variable),
                                       type_name(existing->value), type_name(value)));
        assign(variable, variable.name, std::move(value), false);
    }
    expect(Symbol::rparen, "to close #read(");
    if (ended) symbols_.unbind_everywhere(handle.name);
    (void)directive;
}

void Parser::directive_write(const Token& directive) {
    expect(Symbol::lparen, "after #write");
    const Token handle = raw_next();
    const SymbolRef symbol = handle.kind == TokenKind::word ? resolve(handle.name) : nullptr;
    if (!symbol || !std::holds_alternative<FileRef>(symbol->value))
        fail_expected("a file handle opened by #fopen ... write", handle);
    const FileRef file = std::get<FileRef>(symbol->value);
    if (!file->writing)
        fail(handle, fmt::format("#write to a file opened for reading ({})", file->path));
    std::string text;
    // Commas between the items are optional, as POV-Ray reads them (#write (F Header)).
    for (accept_comma(); !peek_is(Symbol::rparen); accept_comma()) {
        const Token& item = peek();
        if (const int bytes = binary_word_size(item); bytes != 0) {
            const Keyword type = static_cast<Keyword>(next().name);
            text += binary_word(type, bytes, parse_float("to write as a binary word"));
            continue;
        }
        if (starts_string(item)) {
            text += parse_string();
            continue;
        }
        const Numeric value = parse_numeric();
        if (value.terms == 1) {
            text += fmt::format("{}", fmt::sprintf("%g", value.v[0]));
        } else {
            text += "<";
            for (int i = 0; i < value.terms; ++i)
                text += (i ? "," : "") + fmt::sprintf("%g", value.v[i]);
            text += "> ";
        }
    }
    expect(Symbol::rparen, "to close #write(");
    if (std::fwrite(text.data(), 1, text.size(), file->stream) != text.size())
        fail(directive, fmt::format("#write: writing {} failed", file->path));
}

}  // namespace rayset::tracer
