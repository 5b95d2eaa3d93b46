// Tokens across included files: one lookahead token, directives executed as they are reached,
// and the helpers that turn a token into a located error message.
#include <fmt/format.h>

#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/parser.h"
#include "tracer/scene_language/pov_keywords.h"

namespace rayset::tracer {

void Parser::push_file(const std::string& text, const std::string& shown_path, const std::string& directory,
                       const Token* included_at) {
    if (!lookahead_.empty()) {
        // The lookahead was read from the including file just before the directive ended; give it
        // back so that it follows the included text.
        --frames_.back().pos;
        lookahead_.clear();
    }
    FileInfo info;
    info.path = shown_path;
    info.directory = directory;
    if (included_at) {
        info.included = true;
        info.included_at = *included_at;
    }
    files_.push_back(info);
    scene_.files.push_back(shown_path);
    Frame frame;
    frame.file = static_cast<int>(files_.size()) - 1;
    frame.tokens = tokenize(text, frame.file, shown_path);
    frame.conditionals_at_start = conditionals_.size();
    frames_.push_back(std::move(frame));
    if (included_at) scopes_.emplace_back();
}

Token Parser::raw_next() {
    for (;;) {
        Frame& frame = frames_.back();
        const Token& token = frame.tokens[frame.pos];
        if (token.kind != TokenKind::end) {
            ++frame.pos;
            return token;
        }
        if (conditionals_.size() > frame.conditionals_at_start) {
            const Token& opened = conditionals_.back().opened;
            fail(token, fmt::format("unclosed #{} opened at {}: expected #end before end of file", opened.text,
                                    location_of(opened).str()));
        }
        if (frames_.size() == 1) return token;
        frames_.pop_back();
        scopes_.pop_back();
    }
}

const Token& Parser::peek() {
    for (;;) {
        if (lookahead_.empty()) lookahead_.push_back(raw_next());
        if (lookahead_.back().kind == TokenKind::directive && directive_depth_ == 0) {
            const Token directive = lookahead_.back();
            lookahead_.clear();
            run_directive(directive);
            continue;
        }
        return lookahead_.back();
    }
}

Token Parser::next() {
    peek();
    Token token = lookahead_.back();
    lookahead_.clear();
    return token;
}

bool Parser::peek_symbol(const char* symbol) {
    const Token& token = peek();
    return token.kind == TokenKind::symbol && token.text == symbol;
}

bool Parser::accept_symbol(const char* symbol) {
    if (!peek_symbol(symbol)) return false;
    next();
    return true;
}

bool Parser::peek_word(const char* word) {
    const Token& token = peek();
    return token.kind == TokenKind::identifier && token.text == word;
}

bool Parser::accept_word(const char* word) {
    if (!peek_word(word)) return false;
    next();
    return true;
}

Token Parser::expect_symbol(const char* symbol, const std::string& purpose) {
    if (!peek_symbol(symbol)) fail_expected(fmt::format("'{}' {}", symbol, purpose), peek());
    return next();
}

Token Parser::expect_open(const Token& keyword) {
    return expect_symbol("{", fmt::format("after '{}'", keyword.text));
}

void Parser::expect_close(const Token& keyword, const Token& open) {
    if (peek_symbol("}")) {
        next();
        return;
    }
    fail_expected(fmt::format("'}}' to close '{}' opened at {}", keyword.text, location_of(open).str()), peek());
}

SourceLocation Parser::location_of(const Token& token) const {
    return {files_[token.file].path, token.line, token.column};
}

void Parser::fail(const Token& at, const std::string& what) const {
    std::string chain;
    for (int file = at.file; files_[file].included; file = files_[file].included_at.file)
        chain += fmt::format(" (included from {})", location_of(files_[file].included_at).str());
    throw SceneError(what, location_of(at), chain);
}

void Parser::fail_expected(const std::string& expected, const Token& found) const {
    fail(found, fmt::format("expected {}, found {}", expected, describe(found)));
}

void Parser::fail_not_supported(const Token& at, const std::string& feature) const {
    fail(at, fmt::format("not supported: {}", feature));
}

void Parser::fail_identifier(const Token& at, const std::string& expected) const {
    if (at.kind == TokenKind::identifier) {
        if (const Value* value = lookup(at.text))
            fail(at, fmt::format("wrong type: '{}' is {}, expected {}", at.text, type_name(*value), expected));
        if (is_pov_keyword(at.text) && !is_subset_keyword(at.text)) fail_not_supported(at, fmt::format("'{}'", at.text));
        if (is_pov_keyword(at.text)) fail_expected(expected, at);
        fail(at, fmt::format("unknown identifier '{}' (expected {})", at.text, expected));
    }
    fail_expected(expected, at);
}

}  // namespace rayset::tracer
