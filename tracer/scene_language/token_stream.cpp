// Tokens across files and macro bodies: one lookahead token, directives run and macros
// expanded as they are reached, identifiers resolved when they are fetched (so a macro may
// return a local identifier: it is resolved before the macro's #end removes it), and the
// helpers that turn a token into a located error message.
#include <fmt/format.h>

#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/parser.h"

namespace rayset::tracer {

void Parser::push_file(const std::string& text, const std::string& shown_path,
                       const std::string& directory, const Token* included_at) {
    auto source = std::make_shared<SourceFile>();
    source->path = shown_path;
    source->directory = directory;
    FileInfo info;
    info.source = source;
    if (included_at) {
        info.included = true;
        info.included_at = *included_at;
    }
    files_.push_back(info);
    scene_.files.push_back(shown_path);
    tokenize(text, static_cast<int>(files_.size()) - 1, *source, names_);
    Frame frame;
    frame.source = source;
    frame.blocks_at_start = blocks_.size();
    frames_.push_back(std::move(frame));
    if (included_at) symbols_.push_scope();
}

void Parser::leave_finished_files() {
    for (;;) {
        const Frame& frame = frames_.back();
        const Token& token = frame.source->tokens[frame.pos];
        if (token.kind != TokenKind::end) return;
        if (blocks_.size() > frame.blocks_at_start) {
            const Token& opened = blocks_.back().opened;
            fail(token, fmt::format("unclosed #{} opened at {}: expected #end before end of file",
                                    word(opened), location_of(opened).str()));
        }
        if (frames_.size() == 1) return;
        frames_.pop_back();  // a file frame: macro bodies end at their #end
        symbols_.pop_scope();
    }
}

Token Parser::raw_next() {
    leave_finished_files();
    Frame& frame = frames_.back();
    const Token& token = frame.source->tokens[frame.pos];
    if (token.kind == TokenKind::end) return token;
    ++frame.pos;
    if (++tokens_since_memory_check_ >= 4096) check_memory(token);
    return token;
}

const Token& Parser::raw_peek() {
    leave_finished_files();
    const Frame& frame = frames_.back();
    return frame.source->tokens[frame.pos];
}

NameId Parser::next_raw_identifier(const std::string& purpose) {
    if (have_lookahead_) give_back_lookahead();
    const Token token = raw_next();
    if (token.kind != TokenKind::word)
        fail_expected(fmt::format("an identifier {}", purpose), token);
    return token.name;
}

void Parser::give_back_lookahead() {
    // The lookahead was the last token taken from the current frame.
    --frames_.back().pos;
    have_lookahead_ = false;
}

SymbolRef Parser::resolve(NameId name) const { return is_keyword(name) ? nullptr : lookup(name); }

void Parser::fill_lookahead() {
    while (!have_lookahead_) {
        const Token token = raw_next();
        if (token.kind == TokenKind::directive) {
            if (directive_ends_expression()) {
                lookahead_ = token;
                lookahead_symbol_.reset();
                have_lookahead_ = true;
                return;
            }
            directive_position_ = frames_.back().pos - 1;
            run_directive(token);
            continue;
        }
        SymbolRef symbol = token.kind == TokenKind::word ? resolve(token.name) : nullptr;
        if (symbol) {
            if (const MacroRef* macro = std::get_if<MacroRef>(&symbol->value)) {
                invoke_macro(token, *macro);
                continue;
            }
            if (!symbol->deprecation.empty() && !(symbol->warn_once && symbol->warned)) {
                symbol->warned = true;
                warn(token, symbol->deprecation);
            }
        }
        lookahead_ = token;
        lookahead_symbol_ = std::move(symbol);
        have_lookahead_ = true;
    }
}

// Inside a directive's expression, a directive of the directive's own file ends the expression
// where an operator could follow (POV-Ray's rule: `#declare A = 1 #if ...` is an error, while
// `#declare A = #if ... #end` runs the #if).
bool Parser::directive_ends_expression() const {
    return operator_position_ && directive_frame_ != 0 && frames_.size() <= directive_frame_;
}

const Token& Parser::peek_operator() {
    operator_position_ = true;
    struct Reset {
        bool& flag;
        ~Reset() { flag = false; }
    } reset{operator_position_};
    return peek();
}

const Token& Parser::peek() {
    for (;;) {
        if (!have_lookahead_) fill_lookahead();
        // A directive handed back by a directive's expression runs once that directive is done.
        if (lookahead_.kind == TokenKind::directive && !directive_ends_expression()) {
            const Token directive = lookahead_;
            have_lookahead_ = false;
            directive_position_ = frames_.back().pos - 1;
            run_directive(directive);
            continue;
        }
        return lookahead_;
    }
}

Token Parser::next() {
    peek();
    have_lookahead_ = false;
    return lookahead_;
}

const Value* Parser::peek_value() {
    peek();
    return lookahead_symbol_ ? &lookahead_symbol_->value : nullptr;
}

bool Parser::accept(Symbol symbol) {
    if (!peek_is(symbol)) return false;
    next();
    return true;
}

bool Parser::accept(Keyword keyword) {
    if (!peek_is(keyword)) return false;
    next();
    return true;
}

Token Parser::expect(Symbol symbol, Purpose purpose) {
    if (!peek_is(symbol))
        fail_expected(fmt::format("'{}' {}", symbol_text(symbol), purpose.str()), peek());
    return next();
}

Token Parser::expect(Keyword keyword, Purpose purpose) {
    if (!peek_is(keyword))
        fail_expected(fmt::format("'{}' {}", names_.text(id_of(keyword)), purpose.str()), peek());
    return next();
}

Token Parser::expect_open(const Token& keyword) {
    const Token open =
        expect(Symbol::lbrace, [&] { return fmt::format("after '{}'", word(keyword)); });
    if (++nesting_ > options_.max_nesting)
        fail(open,
             fmt::format("nesting limit: more than {} blocks, calls and parentheses in progress "
                         "(ParseOptions::max_nesting)",
                         options_.max_nesting));
    return open;
}

void Parser::expect_close(const Token& keyword, const Token& open) {
    if (!peek_is(Symbol::rbrace))
        fail_expected(
            fmt::format("'}}' to close '{}' opened at {}", word(keyword), location_of(open).str()),
            peek());
    next();
    --nesting_;
}

Token Parser::open_call(const Token& name) {
    return expect(Symbol::lparen, [&] { return fmt::format("after '{}'", word(name)); });
}

void Parser::call_comma(const Token& name) {
    expect(Symbol::comma, [&] { return fmt::format("between the arguments of '{}'", word(name)); });
}

void Parser::close_call(const Token& name, const Token& open) {
    expect(Symbol::rparen, [&] {
        return fmt::format("to close '{}(' opened at {}", word(name), location_of(open).str());
    });
}

Parser::Nesting::Nesting(Parser& parser, const Token& at) : parser_(parser) {
    if (++parser_.nesting_ > parser_.options_.max_nesting)
        parser_.fail(
            at, fmt::format("nesting limit: more than {} blocks, calls and parentheses in progress "
                            "(ParseOptions::max_nesting)",
                            parser_.options_.max_nesting));
}

const std::string& Parser::string_literal(const Token& token) const {
    return files_[token.file].source->strings[token.string];
}

std::string Parser::describe(const Token& token) const {
    switch (token.kind) {
        case TokenKind::word: return fmt::format("'{}'", word(token));
        case TokenKind::number: return fmt::format("number {}", token.number);
        case TokenKind::string: return fmt::format("string \"{}\"", string_literal(token));
        case TokenKind::symbol: return fmt::format("'{}'", symbol_text(token.symbol));
        case TokenKind::directive: return fmt::format("'#{}'", word(token));
        case TokenKind::end: return "end of file";
    }
    return "?";
}

SourceLocation Parser::location_of(const Token& token) const {
    return {files_[token.file].source->path, token.line, token.column};
}

void Parser::fail(const Token& at, const std::string& what) const {
    std::string chain;
    for (int file = at.file; files_[file].included; file = files_[file].included_at.file)
        chain += fmt::format(" (included from {})", location_of(files_[file].included_at).str());
    // Macro calls in progress, innermost first, so an error in a library macro names the call;
    // a deep recursion is shown by its innermost calls and a count.
    constexpr int kCallsShown = 4;
    int calls = 0;
    for (auto block = blocks_.rbegin(); block != blocks_.rend(); ++block) {
        if (block->kind != Block::Kind::macro_body) continue;
        if (++calls <= kCallsShown)
            chain += fmt::format(" (in macro {} called at {})", word(block->opened),
                                 location_of(block->opened).str());
    }
    if (calls > kCallsShown)
        chain += fmt::format(" (and {} more macro calls)", calls - kCallsShown);
    throw SceneError(what, location_of(at), chain);
}

void Parser::fail_expected(const std::string& expected, const Token& found) const {
    fail(found, fmt::format("expected {}, found {}", expected, describe(found)));
}

void Parser::fail_not_supported(const Token& at, const std::string& feature) const {
    fail(at, fmt::format("not supported: {}", feature));
}

void Parser::fail_identifier(const Token& at, const std::string& expected) {
    if (at.kind == TokenKind::word && !is_keyword(at.name)) {
        if (const SymbolRef symbol = lookup(at.name))
            fail(at, fmt::format("wrong type: '{}' is {}, expected {}", word(at),
                                 type_name(symbol->value), expected));
        fail(at, fmt::format("unknown identifier '{}' (expected {})", word(at), expected));
    }
    fail_expected(expected, at);
}

void Parser::warn(const Token& at, const std::string& what) {
    const std::string text = fmt::format("{}: warning: {}\n", location_of(at).str(), what);
    if (options_.on_message)
        options_.on_message(MessageStream::warning, text);
    else
        std::fputs(text.c_str(), stderr);
}

}  // namespace rayset::tracer
