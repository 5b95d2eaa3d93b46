// Turns the text of one scene file into tokens with their line and column. Comments follow
// POV-Ray: `//` to the end of the line, `/* */` nested, and a `//` inside a block comment
// hides the rest of its line (so a `*/` there does not close the block).
#pragma once

#include <string>
#include <vector>

namespace rayset::tracer {

enum class TokenKind { identifier, number, string, symbol, directive, end };

struct Token {
    TokenKind kind = TokenKind::end;
    std::string text;   // identifier, symbol ("<=", "{"), directive name without '#', string contents
    double number = 0;
    int file = 0;       // index into the parser's file table
    int line = 0, column = 0;
};

// Throws SceneError on an unterminated string or comment, or a character outside the language.
std::vector<Token> tokenize(const std::string& text, int file, const std::string& file_name);

// How a token reads in a message: "'{'", "identifier 'Foo'", "end of file", ...
std::string describe(const Token& token);

}  // namespace rayset::tracer
