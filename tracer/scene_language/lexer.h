// Turns the text of one scene file into tokens with their line and column. Comments follow
// POV-Ray: `//` to the end of the line, `/* */` nested, and a `//` inside a block comment
// hides the rest of its line (so a `*/` there does not close the block). A file is tokenized
// once; loops and macros re-read its tokens by index.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tracer/scene_language/keywords.h"

namespace rayset::tracer {

enum class TokenKind : uint8_t { word, number, string, symbol, directive, end };

enum class Symbol : uint8_t {
    none,
    lbrace,
    rbrace,
    lparen,
    rparen,
    lbracket,
    rbracket,
    less,
    greater,
    less_equal,
    greater_equal,
    equals,
    not_equal,
    comma,
    semicolon,
    dot,
    plus,
    minus,
    star,
    slash,
    question,
    colon,
    ampersand,
    bar,
    bang
};

// Small and trivially copyable: words and directive names are interned ids, string literals an
// index into their file's table.
struct Token {
    TokenKind kind = TokenKind::end;
    Symbol symbol = Symbol::none;
    NameId name = 0;      // word, or a directive's name without '#'
    uint32_t string = 0;  // string literal: index into SourceFile::strings
    double number = 0;
    int file = 0;  // index into the parser's file table
    int line = 0, column = 0;

    bool is(Symbol s) const { return kind == TokenKind::symbol && symbol == s; }
    bool is(Keyword k) const { return kind == TokenKind::word && name == id_of(k); }
    bool is(ContextWord w) const { return kind == TokenKind::word && name == id_of(w); }
    bool is_directive(Keyword k) const { return kind == TokenKind::directive && name == id_of(k); }
    bool is_identifier() const { return kind == TokenKind::word && !is_keyword(name); }
};

// One file's tokens, shared by the frames that read it (the file itself, its loops, and the
// macros defined in it, which outlive the file's own reading).
struct SourceFile {
    std::string path;           // as shown in messages
    std::string directory;      // where relative names start
    std::vector<Token> tokens;  // ends with one TokenKind::end
    std::vector<std::string> strings;
};

// Throws SceneError on an unterminated string or comment, or a character outside the language.
void tokenize(const std::string& text, int file, SourceFile& out, NameTable& names);

const char* symbol_text(Symbol symbol);

}  // namespace rayset::tracer
