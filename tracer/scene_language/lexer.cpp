// The scene-language lexer.
#include "tracer/scene_language/lexer.h"

#include <cctype>
#include <cstdlib>

#include <fmt/format.h>

#include "tracer/scene_language/parse_error.h"

namespace rayset::tracer {
namespace {

class Lexer {
public:
    Lexer(const std::string& text, int file, const std::string& name) : text_(text), file_(file), name_(name) {}

    std::vector<Token> run() {
        std::vector<Token> tokens;
        for (;;) {
            skip_space_and_comments();
            Token token;
            token.file = file_;
            token.line = line_;
            token.column = column_;
            if (at_end()) {
                tokens.push_back(token);
                return tokens;
            }
            const char c = peek();
            if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
                token.kind = TokenKind::identifier;
                token.text = read_word();
            } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                       (c == '.' && std::isdigit(static_cast<unsigned char>(peek(1))))) {
                token.kind = TokenKind::number;
                token.text = read_number();
                token.number = std::strtod(token.text.c_str(), nullptr);
            } else if (c == '"') {
                token.kind = TokenKind::string;
                token.text = read_string(token);
            } else if (c == '#') {
                advance();
                if (!std::isalpha(static_cast<unsigned char>(peek())))
                    fail(token, "expected a directive name after '#'");
                token.kind = TokenKind::directive;
                token.text = read_word();
            } else {
                token.kind = TokenKind::symbol;
                token.text = read_symbol(token);
            }
            tokens.push_back(std::move(token));
        }
    }

private:
    bool at_end() const { return pos_ >= text_.size(); }
    char peek(size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
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
        throw SceneError(what, {name_, at.line, at.column}, "");
    }

    void skip_line() {
        while (!at_end() && peek() != '\n') advance();
    }

    // Called with the position just past "/*".
    void skip_block_comment(const Token& opened) {
        for (;;) {
            if (at_end()) fail(opened, "unclosed comment: expected '*/' before end of file for the comment opened");
            const char c = advance();
            if (c == '*' && peek() == '/') {
                advance();
                return;
            }
            if (c == '/' && peek() == '*') {
                Token nested{TokenKind::end, "", 0, file_, line_, column_ - 1};
                advance();
                skip_block_comment(nested);
            } else if (c == '/' && peek() == '/') {
                skip_line();
            }
        }
    }

    void skip_space_and_comments() {
        for (;;) {
            if (at_end()) return;
            const char c = peek();
            if (std::isspace(static_cast<unsigned char>(c))) {
                advance();
            } else if (c == '/' && peek(1) == '/') {
                skip_line();
            } else if (c == '/' && peek(1) == '*') {
                Token opened{TokenKind::end, "", 0, file_, line_, column_};
                advance();
                advance();
                skip_block_comment(opened);
            } else {
                return;
            }
        }
    }

    std::string read_word() {
        std::string word;
        while (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_') word += advance();
        return word;
    }

    std::string read_number() {
        std::string digits;
        while (std::isdigit(static_cast<unsigned char>(peek()))) digits += advance();
        if (peek() == '.' && std::isdigit(static_cast<unsigned char>(peek(1)))) {
            digits += advance();
            while (std::isdigit(static_cast<unsigned char>(peek()))) digits += advance();
        } else if (peek() == '.' && !std::isalpha(static_cast<unsigned char>(peek(1)))) {
            digits += advance();  // "1." is a number; "V.x" is not reached here
        }
        if ((peek() == 'e' || peek() == 'E') &&
            (std::isdigit(static_cast<unsigned char>(peek(1))) ||
             ((peek(1) == '+' || peek(1) == '-') && std::isdigit(static_cast<unsigned char>(peek(2)))))) {
            digits += advance();
            if (peek() == '+' || peek() == '-') digits += advance();
            while (std::isdigit(static_cast<unsigned char>(peek()))) digits += advance();
        }
        return digits;
    }

    std::string read_string(const Token& opened) {
        advance();  // opening quote
        std::string value;
        for (;;) {
            if (at_end() || peek() == '\n') fail(opened, "unterminated string: expected '\"' before end of line");
            const char c = advance();
            if (c == '"') return value;
            if (c == '\\' && !at_end()) {
                const char e = advance();
                switch (e) {
                    case 'n': value += '\n'; break;
                    case 't': value += '\t'; break;
                    case '\\': value += '\\'; break;
                    case '"': value += '"'; break;
                    default: value += '\\'; value += e; break;  // POV-Ray keeps unknown escapes
                }
            } else {
                value += c;
            }
        }
    }

    std::string read_symbol(const Token& at) {
        const char c = advance();
        if ((c == '<' || c == '>' || c == '!') && peek() == '=') {
            advance();
            return std::string(1, c) + "=";
        }
        static const std::string singles = "{}<>()[],;.+-*/=?:&|!";
        if (singles.find(c) == std::string::npos)
            fail(at, fmt::format("unexpected character '{}'", c));
        return std::string(1, c);
    }

    const std::string& text_;
    int file_;
    const std::string& name_;
    size_t pos_ = 0;
    int line_ = 1, column_ = 1;
};

}  // namespace

std::vector<Token> tokenize(const std::string& text, int file, const std::string& file_name) {
    return Lexer(text, file, file_name).run();
}

std::string describe(const Token& token) {
    switch (token.kind) {
        case TokenKind::identifier: return fmt::format("'{}'", token.text);
        case TokenKind::number: return fmt::format("number {}", token.text);
        case TokenKind::string: return fmt::format("string \"{}\"", token.text);
        case TokenKind::symbol: return fmt::format("'{}'", token.text);
        case TokenKind::directive: return fmt::format("'#{}'", token.text);
        case TokenKind::end: return "end of file";
    }
    return "?";
}

}  // namespace rayset::tracer
