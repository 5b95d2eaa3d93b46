// Language directives, executed when the token stream reaches them. Conditionals skip the
// tokens of the branches not taken; loops jump back to their first token; #break leaves the
// innermost loop, #switch clause or macro call. Conditions are read with their parentheses and
// nothing after them, so the token after a condition is never fetched (or expanded) early.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace fs = std::filesystem;

namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's truth and equality tolerance

bool opens_block(NameId directive) {
    return directive == id_of(Keyword::if_) || directive == id_of(Keyword::ifdef) ||
           directive == id_of(Keyword::ifndef) || directive == id_of(Keyword::while_) ||
           directive == id_of(Keyword::switch_) || directive == id_of(Keyword::macro) ||
           directive == id_of(Keyword::for_);
}

// While a directive reads its own tokens, a directive of its own file ends its expression.
class DirectiveFrame {
public:
    DirectiveFrame(size_t& frame, size_t depth) : frame_(frame), saved_(frame) { frame_ = depth; }
    ~DirectiveFrame() { frame_ = saved_; }

private:
    size_t& frame_;
    size_t saved_;
};

}  // namespace

void Parser::run_directive(const Token& directive) {
    if (word(directive).empty()) return;  // a lone '#'
    DirectiveFrame scope(directive_frame_, frames_.size());
    switch (
        static_cast<Keyword>(is_keyword(directive.name) ? directive.name : id_of(Keyword::size_))) {
        case Keyword::declare: return directive_declare(directive, false);
        case Keyword::local: return directive_declare(directive, true);
        case Keyword::if_: return directive_if(directive);
        case Keyword::ifdef: return directive_ifdef(directive, true);
        case Keyword::ifndef: return directive_ifdef(directive, false);
        case Keyword::else_:
        case Keyword::elseif: return directive_else(directive);
        case Keyword::switch_: return directive_switch(directive);
        case Keyword::case_:
        case Keyword::range: return directive_case(directive);
        case Keyword::break_: return directive_break(directive);
        case Keyword::while_: return directive_while(directive);
        case Keyword::for_: return directive_for(directive);
        case Keyword::end: return directive_end(directive);
        case Keyword::include: return directive_include(directive);
        case Keyword::version: return directive_version(directive);
        case Keyword::debug:
        case Keyword::warning:
        case Keyword::error:
        case Keyword::render:
        case Keyword::statistics: return directive_message(directive);
        case Keyword::undef: return directive_undef(directive);
        case Keyword::default_: return directive_default(directive);
        case Keyword::macro: return directive_macro(directive);
        case Keyword::fopen: return directive_fopen(directive);
        case Keyword::fclose: return directive_fclose(directive);
        case Keyword::read: return directive_read(directive);
        case Keyword::write: return directive_write(directive);
        default: break;
    }
    fail(directive, fmt::format("unknown directive '#{}'", word(directive)));
}

void Parser::directive_declare(const Token& directive, bool local) {
    const char* what = local ? "local" : "declare";
    // #declare deprecated [once] ["message"] NAME = ...
    bool deprecated = false, warn_once = false;
    std::string deprecation;
    Token name = raw_next();
    if (name.is(Keyword::deprecated)) {
        deprecated = true;
        name = raw_next();
        if (name.is(Keyword::once)) warn_once = true, name = raw_next();
        if (name.kind == TokenKind::string) deprecation = string_literal(name), name = raw_next();
    }
    if (name.kind != TokenKind::word)
        fail_expected(fmt::format("an identifier after #{}", what), name);
    check_declarable(name, name.name, what);
    if (deprecated && deprecation.empty())
        deprecation = fmt::format("identifier {} was declared deprecated", word(name));
    // POV-Ray 3.5 and later require ';' after floats, vectors and colours; it is optional after
    // anything else. The value is assigned before the ';' is looked for: the token after the
    // declaration may be a macro call that uses it.
    auto expect_semicolon = [&](bool numeric) {
        if (numeric && version_ >= 3.5 && !peek_operator().is(Symbol::semicolon))
            fail_expected(
                fmt::format("';' after the value of #{} {} (POV-Ray requires it after floats, "
                            "vectors and colours)",
                            what, word(name)),
                peek());
        if (peek_operator().is(Symbol::semicolon)) next();
    };
    if (raw_peek().is(Symbol::lbracket)) {
        const SymbolRef symbol = lookup(name.name);
        if (!symbol || !std::holds_alternative<ArrayRef>(symbol->value))
            fail(name, fmt::format("'{}' is not an array: declare it with '= array[N]' first",
                                   word(name)));
        const ArrayRef array = std::get<ArrayRef>(symbol->value);
        Value* slot = array_element(name, *array, true);
        expect(Symbol::equals, [&] { return fmt::format("after #{} {}[...]", what, word(name)); });
        const Token start = peek();
        Value value = parse_rvalue(name);
        if (const std::string why = array->mismatch(value); !why.empty())
            fail(start, fmt::format("the elements of '{}' are {} (an array holds one type)",
                                    word(name), why));
        const bool numeric = std::holds_alternative<Numeric>(value);
        array->assign(static_cast<size_t>(slot - array->elements.data()), std::move(value));
        expect_semicolon(numeric);
        return;
    }
    expect(Symbol::equals, [&] { return fmt::format("after #{} {}", what, word(name)); });
    const size_t scope = symbols_.depth();  // before a macro in the value opens its own
    Value value = parse_rvalue(name);
    const bool numeric = std::holds_alternative<Numeric>(value);
    assign(name, name.name, std::move(value), local, deprecation, warn_once, scope);
    expect_semicolon(numeric);
}

double Parser::parse_condition(const Token& directive) {
    const Token open = expect(Symbol::lparen, [&] {
        return fmt::format("after #{} (its condition is in parentheses)", word(directive));
    });
    const Numeric value = parse_expression();
    if (value.terms != 1)
        fail(open,
             fmt::format("the condition of #{} must be a float, found a vector", word(directive)));
    expect(Symbol::rparen, [&] {
        return fmt::format("to close the condition of #{} opened at {}", word(directive),
                           location_of(open).str());
    });
    return value.v[0];
}

void Parser::enter_block(Block::Kind kind, const Token& opened) {
    Block block;
    block.kind = kind;
    block.opened = opened;
    block.frame = frames_.size() - 1;
    blocks_.push_back(block);
}

Token Parser::skip_to(const Token& opened, std::initializer_list<Keyword> stops, int depth) {
    if (have_lookahead_) give_back_lookahead();
    Frame& frame = frames_.back();
    for (;;) {
        const Token& token = frame.source->tokens[frame.pos];
        if (token.kind == TokenKind::end)
            fail(token, fmt::format("unclosed #{} opened at {}: expected #end before end of file",
                                    word(opened), location_of(opened).str()));
        ++frame.pos;
        if (token.kind != TokenKind::directive) continue;
        if (opens_block(token.name)) {
            ++depth;
            continue;
        }
        const bool is_end = token.name == id_of(Keyword::end);
        if (depth == 0)
            for (Keyword stop : stops)
                if (token.name == id_of(stop)) return token;
        if (is_end) --depth;
    }
}

void Parser::take_branch_after(const Token& opened, bool allow_elseif) {
    for (;;) {
        const Token stop = skip_to(opened, {Keyword::else_, Keyword::elseif, Keyword::end});
        if (stop.is_directive(Keyword::end)) return;
        if (stop.is_directive(Keyword::else_)) return enter_block(Block::Kind::else_branch, opened);
        if (!allow_elseif) fail_not_supported(stop, "#elseif here");
        if (std::fabs(parse_condition(stop)) > kEpsilon)
            return enter_block(Block::Kind::if_branch, opened);
    }
}

void Parser::directive_if(const Token& directive) {
    if (std::fabs(parse_condition(directive)) > kEpsilon)
        return enter_block(Block::Kind::if_branch, directive);
    take_branch_after(directive, true);
}

bool Parser::is_defined(const Token& at) {
    const NameId name = next_raw_identifier(fmt::format("in {}", describe(at)));
    const SymbolRef symbol = resolve(name);
    if (!symbol) return false;
    if (const ArrayRef* array = std::get_if<ArrayRef>(&symbol->value);
        array && raw_peek().is(Symbol::lbracket))
        return !std::holds_alternative<std::monostate>(*array_element(at, **array, true));
    return true;
}

void Parser::directive_ifdef(const Token& directive, bool want_defined) {
    const Token open =
        expect(Symbol::lparen, [&] { return fmt::format("after #{}", word(directive)); });
    const bool defined = is_defined(directive);
    expect(Symbol::rparen, [&] {
        return fmt::format("to close #{}( opened at {}", word(directive), location_of(open).str());
    });
    if (defined == want_defined) return enter_block(Block::Kind::if_branch, directive);
    take_branch_after(directive, true);
}

void Parser::directive_else(const Token& directive) {
    const bool in_block = blocks_.size() > frames_.back().blocks_at_start;
    if (in_block && blocks_.back().kind == Block::Kind::switch_clause &&
        directive.is_directive(Keyword::else_))
        return;  // falling through into a switch's #else, as C does
    if (!in_block || blocks_.back().kind != Block::Kind::if_branch)
        fail(directive,
             fmt::format("#{} without a matching #if, #ifdef or #ifndef", word(directive)));
    // The taken branch ends here: skip the remaining branches to the #end.
    const Token opened = blocks_.back().opened;
    blocks_.pop_back();
    skip_to(opened, {Keyword::end});
}

void Parser::directive_switch(const Token& directive) {
    const double value = parse_condition(directive);
    for (;;) {
        const Token clause =
            skip_to(directive, {Keyword::case_, Keyword::range, Keyword::else_, Keyword::end});
        if (clause.is_directive(Keyword::end)) return;
        bool taken = clause.is_directive(Keyword::else_);
        if (clause.is_directive(Keyword::case_)) {
            taken = std::fabs(parse_condition(clause) - value) < kEpsilon;
        } else if (clause.is_directive(Keyword::range)) {
            const Token open = expect(Symbol::lparen, "after #range");
            const double low = parse_float("as the low end of #range");
            expect(Symbol::comma, "between the two ends of #range");
            const double high = parse_float("as the high end of #range");
            expect(Symbol::rparen, [&] {
                return fmt::format("to close #range( opened at {}", location_of(open).str());
            });
            taken = low <= value && value <= high;
        }
        if (taken) return enter_block(Block::Kind::switch_clause, directive);
    }
}

void Parser::directive_case(const Token& directive) {
    if (blocks_.size() <= frames_.back().blocks_at_start ||
        blocks_.back().kind != Block::Kind::switch_clause)
        fail(directive, fmt::format("#{} outside #switch", word(directive)));
    // A taken clause falls through into the next one, as C's switch does (POV-Ray's behaviour):
    // its condition is read and ignored.
    if (directive.is_directive(Keyword::case_)) {
        parse_condition(directive);
    } else {
        const Token open = expect(Symbol::lparen, "after #range");
        parse_float();
        expect(Symbol::comma, "between the two ends of #range");
        parse_float();
        expect(Symbol::rparen, [&] {
            return fmt::format("to close #range( opened at {}", location_of(open).str());
        });
    }
}

void Parser::directive_break(const Token& directive) {
    // The innermost loop, switch clause or macro call, which must be in this file or macro body.
    size_t target = blocks_.size();
    for (size_t i = blocks_.size(); i-- > frames_.back().blocks_at_start;) {
        const Block::Kind kind = blocks_[i].kind;
        if (kind == Block::Kind::while_loop || kind == Block::Kind::for_loop ||
            kind == Block::Kind::switch_clause || kind == Block::Kind::macro_body) {
            target = i;
            break;
        }
    }
    if (target == blocks_.size()) {
        // Outside any: POV-Ray ignores a #break between a #switch's clauses and elsewhere.
        return;
    }
    const Block block = blocks_[target];
    const int open_above = static_cast<int>(blocks_.size() - 1 - target);
    skip_to(block.opened, {Keyword::end}, open_above);
    blocks_.resize(target + 1);
    if (block.kind == Block::Kind::macro_body) return leave_macro();
    blocks_.pop_back();
}

void Parser::count_iteration(const Token& at) {
    if (++loop_iterations_ > options_.max_loop_iterations)
        fail(at, fmt::format("loop limit: more than {} #while and #for iterations in total "
                             "(ParseOptions::max_loop_iterations)",
                             options_.max_loop_iterations));
}

void Parser::directive_while(const Token& directive) {
    const size_t start = directive_position_;
    if (std::fabs(parse_condition(directive)) <= kEpsilon) {
        skip_to(directive, {Keyword::end});
        return;
    }
    count_iteration(directive);
    enter_block(Block::Kind::while_loop, directive);
    blocks_.back().restart = start;
}

void Parser::directive_for(const Token& directive) {
    const Token open = expect(Symbol::lparen, "after #for");
    const Token variable = raw_next();
    if (!variable.is_identifier())
        fail_expected("the loop variable (an identifier) after #for(", variable);
    expect(Symbol::comma, "after the loop variable of #for");
    const double first = parse_float("as the start of #for");
    expect(Symbol::comma, "after the start of #for");
    const double last = parse_float("as the end of #for");
    double step = 1;
    if (accept(Symbol::comma)) step = parse_float("as the step of #for");
    expect(Symbol::rparen,
           [&] { return fmt::format("to close #for( opened at {}", location_of(open).str()); });
    if (step == 0) fail(directive, "#for with a step of 0 would never end");
    assign(variable, variable.name, Numeric::scalar(first), true);
    if (step > 0 ? first > last : first < last) {
        skip_to(directive, {Keyword::end});
        return;
    }
    count_iteration(directive);
    enter_block(Block::Kind::for_loop, directive);
    Block& block = blocks_.back();
    block.restart = frames_.back().pos;
    block.variable = variable.name;
    block.last = last;
    block.step = step;
}

void Parser::directive_end(const Token& directive) {
    if (blocks_.size() <= frames_.back().blocks_at_start)
        fail(directive,
             "#end without an open #if, #ifdef, #ifndef, #switch, #while, #for or #macro here");
    Block& block = blocks_.back();
    switch (block.kind) {
        case Block::Kind::while_loop:
            frames_.back().pos = block.restart;
            blocks_.pop_back();
            return;
        case Block::Kind::for_loop: {
            const SymbolRef symbol = lookup(block.variable);
            const Numeric* counter = symbol ? std::get_if<Numeric>(&symbol->value) : nullptr;
            if (!counter || counter->terms != 1)
                fail(directive, fmt::format("the #for variable '{}' is no longer a float",
                                            names_.text(block.variable)));
            const double value = counter->v[0] + block.step;
            symbol->value = Numeric::scalar(value);
            if (block.step > 0 ? value > block.last : value < block.last) {
                blocks_.pop_back();
                return;
            }
            count_iteration(directive);
            frames_.back().pos = block.restart;
            return;
        }
        case Block::Kind::macro_body: return leave_macro();
        default: blocks_.pop_back(); return;
    }
}

void Parser::directive_include(const Token& directive) {
    const std::string name = parse_string();
    int depth = 0;
    for (const Frame& frame : frames_) depth += frame.kind == FrameKind::file;
    if (depth >= options_.max_include_depth)
        fail(directive,
             fmt::format(
                 "include depth limit: more than {} nested #include levels (recursive include "
                 "of \"{}\"?) (ParseOptions::max_include_depth)",
                 options_.max_include_depth, name));
    const std::string path = resolve_file(name, directive, "include file", {".inc"});
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(directive, fmt::format("include file \"{}\" cannot be read ({})", name, path));
    std::ostringstream text;
    text << in.rdbuf();
    if (have_lookahead_) give_back_lookahead();
    push_file(text.str(), path, fs::path(path).parent_path().string(), &directive);
}

void Parser::directive_version(const Token& directive) {
    const double version = parse_float("after #version");
    accept(Symbol::semicolon);
    if (version < 1 || version > 3.7 + kEpsilon)
        warn(directive,
             fmt::format("#version {} outside 1.0 to 3.7: read as POV-Ray 3.7 reads it", version));
    version_ = version;
    version_seen_ = true;
    scene_.version = version;
}

void Parser::directive_message(const Token& directive) {
    const std::string text = parse_string();
    if (directive.is_directive(Keyword::error)) fail(directive, fmt::format("#error: {}", text));
    if (directive.is_directive(Keyword::warning)) return warn(directive, text);
    if (options_.on_message)
        options_.on_message(MessageStream::debug, text);
    else
        std::fputs(text.c_str(), stderr);
}

void Parser::directive_undef(const Token& directive) {
    const NameId name = next_raw_identifier("after #undef");
    (void)directive;
    symbols_.unbind_most_local(name);
}

void Parser::directive_default(const Token& directive) { parse_default(*this, directive); }

}  // namespace rayset::tracer
