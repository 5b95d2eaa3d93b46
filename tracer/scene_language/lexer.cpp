// The scene-language lexer.
#include "tracer/scene_language/lexer.h"

#include <cctype>
#include <cstdlib>

#include <fmt/format.h>

#include "core/text_encoding.h"
#include "tracer/scene_language/parse_error.h"

namespace rayset::tracer {
namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

class Lexer {
public:
    Lexer(const std::string& text, int file, SourceFile& out, NameTable& names)
        : text_(text), file_(file), out_(out), names_(names) {
        if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;  // UTF-8 byte-order mark
    }

    void run() {
        for (;;) {
            skip_space_and_comments();
            Token token;
            token.file = file_;
            token.line = line_;
            token.column = column_;
            if (at_end()) {
                out_.tokens.push_back(token);
                return;
            }
            const char c = peek();
            if (is_alpha(c) || c == '_') {
                token.kind = TokenKind::word;
                token.name = names_.intern(read_word());
            } else if (is_digit(c) || (c == '.' && is_digit(peek(1)))) {
                token.kind = TokenKind::number;
                token.number = read_number();
            } else if (c == '"') {
                token.kind = TokenKind::string;
                token.string = static_cast<uint32_t>(out_.strings.size());
                out_.strings.push_back(read_string(token));
            } else if (c == '#') {
                advance();
                while (peek() == ' ' || peek() == '\t') advance();  // "#   debug" is "#debug"
                // A '#' with no name is a directive that does nothing, as in POV-Ray (which
                // ignores it, except that it ends an expression like any directive).
                token.kind = TokenKind::directive;
                token.name = names_.intern(is_alpha(peek()) ? read_word() : std::string_view());
            } else {
                token.kind = TokenKind::symbol;
                token.symbol = read_symbol(token);
            }
            out_.tokens.push_back(token);
        }
    }

private:
    bool at_end() const { return pos_ >= text_.size(); }
    char peek(size_t ahead = 0) const {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }
    char advance() {
        const char c = text_[pos_++];
        if (c == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
        return c;
    }

    [[noreturn]] void fail(const Token& at, const std::string& what) const {
        throw SceneError(what, {out_.path, at.line, at.column}, "");
    }

    void skip_line() {
        while (!at_end() && peek() != '\n') advance();
    }

    // Called with the position just past "/*".
    void skip_block_comment(int line, int column) {
        for (;;) {
            if (at_end()) {
                Token opened;
                opened.line = line;
                opened.column = column;
                fail(opened,
                     "unclosed comment: expected '*/' before end of file for the comment opened");
            }
            const char c = advance();
            if (c == '*' && peek() == '/') {
                advance();
                return;
            }
            if (c == '/' && peek() == '*') {
                const int nested_column = column_ - 1;
                advance();
                skip_block_comment(line_, nested_column);
            } else if (c == '/' && peek() == '/') {
                skip_line();
            }
        }
    }

    void skip_space_and_comments() {
        for (;;) {
            if (at_end()) return;
            const char c = peek();
            if (std::isspace(static_cast<unsigned char>(c)) ||
                c == '\x1a') {  // ^Z: DOS end of file
                advance();
            } else if (c == '/' && peek(1) == '/') {
                skip_line();
            } else if (c == '/' && peek(1) == '*') {
                const int line = line_, column = column_;
                advance();
                advance();
                skip_block_comment(line, column);
            } else {
                return;
            }
        }
    }

    std::string_view read_word() {
        const size_t start = pos_;
        while (is_word_char(peek())) advance();
        return std::string_view(text_).substr(start, pos_ - start);
    }

    double read_number() {
        const size_t start = pos_;
        while (is_digit(peek())) advance();
        if (peek() == '.' && is_digit(peek(1))) {
            advance();
            while (is_digit(peek())) advance();
        } else if (peek() == '.' && !is_alpha(peek(1))) {
            advance();  // "1." is a number; "V.x" is not reached here
        }
        if ((peek() == 'e' || peek() == 'E') &&
            (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
            advance();
            if (peek() == '+' || peek() == '-') advance();
            while (is_digit(peek())) advance();
        }
        return std::strtod(text_.substr(start, pos_ - start).c_str(), nullptr);
    }

    // POV-Ray's escapes; any other character after a backslash is an error, as in POV-Ray.
    std::string read_string(const Token& opened) {
        advance();  // opening quote
        std::string value;
        for (;;) {
            // A string may run over several lines (POV-Ray's include files have such).
            if (at_end()) fail(opened, "unterminated string: expected '\"' before end of file");
            const char c = advance();
            if (c == '"') return value;
            if (c != '\\') {
                value += c;
                continue;
            }
            const Token escape{TokenKind::string, Symbol::none, 0, 0, 0, file_, line_, column_ - 1};
            const char e = at_end() ? '\0' : advance();
            switch (e) {
                case 'a': value += '\a'; break;
                case 'b': value += '\b'; break;
                case 'f': value += '\f'; break;
                case 'n': value += '\n'; break;
                case 'r': value += '\r'; break;
                case 't': value += '\t'; break;
                case 'v': value += '\v'; break;
                case '0': value += '\0'; break;
                case '\\': value += '\\'; break;
                case '\'': value += '\''; break;
                case '"': value += '"'; break;
                case 'u': {
                    unsigned code = 0;
                    for (int i = 0; i < 4; ++i) {
                        const char h = peek();
                        if (!std::isxdigit(static_cast<unsigned char>(h)))
                            fail(escape,
                                 "illegal escape in string: '\\u' needs four hexadecimal digits");
                        advance();
                        code = code * 16 + static_cast<unsigned>(
                                               is_digit(h) ? h - '0' : std::tolower(h) - 'a' + 10);
                    }
                    append_utf8(code, value);
                    break;
                }
                default:
                    fail(escape,
                         fmt::format(
                             "illegal escape '\\{}' in string (write '\\\\' for a backslash)",
                             e == '\0' ? std::string("end of file") : std::string(1, e)));
            }
        }
    }

    Symbol read_symbol(const Token& at) {
        const char c = advance();
        if (peek() == '=') {
            if (c == '<') return advance(), Symbol::less_equal;
            if (c == '>') return advance(), Symbol::greater_equal;
            if (c == '!') return advance(), Symbol::not_equal;
        }
        switch (c) {
            case '{': return Symbol::lbrace;
            case '}': return Symbol::rbrace;
            case '(': return Symbol::lparen;
            case ')': return Symbol::rparen;
            case '[': return Symbol::lbracket;
            case ']': return Symbol::rbracket;
            case '<': return Symbol::less;
            case '>': return Symbol::greater;
            case '=': return Symbol::equals;
            case ',': return Symbol::comma;
            case ';': return Symbol::semicolon;
            case '.': return Symbol::dot;
            case '+': return Symbol::plus;
            case '-': return Symbol::minus;
            case '*': return Symbol::star;
            case '/': return Symbol::slash;
            case '?': return Symbol::question;
            case ':': return Symbol::colon;
            case '&': return Symbol::ampersand;
            case '|': return Symbol::bar;
            case '!': return Symbol::bang;
            default: break;
        }
        const unsigned byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte >= 0x7F)
            fail(at, fmt::format("unexpected byte 0x{:02X} outside a string or comment", byte));
        fail(at, fmt::format("unexpected character '{}'", c));
    }

    const std::string& text_;
    int file_;
    SourceFile& out_;
    NameTable& names_;
    size_t pos_ = 0;
    int line_ = 1, column_ = 1;
};

}  // namespace

void tokenize(const std::string& text, int file, SourceFile& out, NameTable& names) {
    Lexer(text, file, out, names).run();
}

const char* symbol_text(Symbol symbol) {
    switch (symbol) {
        case Symbol::none: return "";
        case Symbol::lbrace: return "{";
        case Symbol::rbrace: return "}";
        case Symbol::lparen: return "(";
        case Symbol::rparen: return ")";
        case Symbol::lbracket: return "[";
        case Symbol::rbracket: return "]";
        case Symbol::less: return "<";
        case Symbol::greater: return ">";
        case Symbol::less_equal: return "<=";
        case Symbol::greater_equal: return ">=";
        case Symbol::equals: return "=";
        case Symbol::not_equal: return "!=";
        case Symbol::comma: return ",";
        case Symbol::semicolon: return ";";
        case Symbol::dot: return ".";
        case Symbol::plus: return "+";
        case Symbol::minus: return "-";
        case Symbol::star: return "*";
        case Symbol::slash: return "/";
        case Symbol::question: return "?";
        case Symbol::colon: return ":";
        case Symbol::ampersand: return "&";
        case Symbol::bar: return "|";
        case Symbol::bang: return "!";
    }
    return "";
}

NameTable::NameTable() {
#define RAYSET_INTERN(identifier, text) intern(text);
    RAYSET_POV_KEYWORDS(RAYSET_INTERN)
    RAYSET_CONTEXT_WORDS(RAYSET_INTERN)
#undef RAYSET_INTERN
}

NameId NameTable::intern(std::string_view text) {
    auto found = ids_.find(text);
    if (found != ids_.end()) return found->second;
    const NameId id = static_cast<NameId>(texts_.size());
    texts_.emplace_back(text);
    ids_.emplace(texts_.back(), id);
    return id;
}

}  // namespace rayset::tracer
