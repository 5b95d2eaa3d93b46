// #macro definitions and calls. A definition records where its body's tokens are; a call binds
// the parameters in a new symbol table and reads the body from there, as if it were pasted at
// the call (POV-Ray's "macro substitution" of the body). A parameter given as a lone declared
// identifier is passed by reference: the parameter names the caller's own entry.
#include <fmt/format.h>

#include "tracer/scene_language/parser.h"

namespace rayset::tracer {

void Parser::directive_macro(const Token& directive) {
    auto macro = std::make_shared<Macro>();
    const Token name = raw_next();
    if (name.kind != TokenKind::word) fail_expected("the macro's name after #macro", name);
    check_declarable(name, name.name, "macro");
    macro->name = name.name;
    macro->defined_at = name;
    const Token open = raw_next();
    if (!open.is(Symbol::lparen))
        fail_expected(fmt::format("'(' after #macro {} (even with no parameters)", word(name)),
                      open);
    if (!raw_peek().is(Symbol::rparen)) {
        for (;;) {
            const Token parameter = raw_next();
            if (parameter.kind != TokenKind::word)
                fail_expected(fmt::format("a parameter name in #macro {}", word(name)), parameter);
            check_declarable(parameter, parameter.name, "macro parameter");
            for (NameId earlier : macro->parameters)
                if (earlier == parameter.name)
                    fail(parameter, fmt::format("parameter '{}' appears twice in #macro {}",
                                                word(parameter), word(name)));
            macro->parameters.push_back(parameter.name);
            // The commas are optional and a trailing one is allowed, as POV-Ray reads them
            // (shapes3.inc has both).
            if (raw_peek().is(Symbol::comma)) raw_next();
            if (raw_peek().is(Symbol::rparen)) break;
        }
    }
    raw_next();  // ')'
    const Frame& frame = frames_.back();
    macro->file = frame.source;
    macro->body_start = frame.pos;
    skip_to(directive, {Keyword::end});
    macro->body_end = frames_.back().pos - 1;
    // Macro names are global and permanent (POV-Ray's rule), like a #declare of a new name.
    auto entry = std::make_shared<SymbolEntry>();
    entry->value = MacroRef(std::move(macro));
    symbols_.unbind_everywhere(name.name);
    symbols_.bind(name.name, std::move(entry), 0);
}

void Parser::invoke_macro(const Token& name, const MacroRef& macro) {
    // A macro that calls itself twice runs 2^N times at a depth of only N: the nesting limit
    // does not stop it.
    if (++macro_calls_ > options_.max_macro_calls)
        fail(name, fmt::format("macro limit: more than {} macro calls in total "
                               "(ParseOptions::max_macro_calls)",
                               options_.max_macro_calls));
    const Token open = expect(Symbol::lparen, [&] {
        return fmt::format("after macro {} (its call needs parentheses)", word(name));
    });
    std::vector<SymbolRef> parameters(macro->parameters.size());
    for (size_t i = 0; i < macro->parameters.size(); ++i) {
        if (i > 0)
            expect(Symbol::comma, [&] {
                return fmt::format("between the arguments of {} ({} declared at {} takes {})",
                                   word(name), word(name), location_of(macro->defined_at).str(),
                                   macro->parameters.size());
            });
        if (peek_is(Symbol::rparen))
            fail(peek(),
                 fmt::format("macro {} takes {} arguments, found {} (declared at {})", word(name),
                             macro->parameters.size(), i, location_of(macro->defined_at).str()));
        // A lone declared identifier is passed by reference: the raw token after it tells.
        if (peek().is_identifier() && lookahead_symbol_) {
            const Token& after = raw_peek();
            if (after.is(Symbol::comma) || after.is(Symbol::rparen)) {
                parameters[i] = lookahead_symbol_;
                next();
                continue;
            }
        }
        auto entry = std::make_shared<SymbolEntry>();
        entry->value = as_stored(parse_rvalue(name));
        parameters[i] = std::move(entry);
    }
    if (!peek_is(Symbol::rparen))
        fail_expected(fmt::format("')' to close the call of macro {} opened at {} ({} argument{})",
                                  word(name), location_of(open).str(), macro->parameters.size(),
                                  macro->parameters.size() == 1 ? "" : "s"),
                      peek());
    have_lookahead_ = false;  // the ')': the body's first token follows it
    if (static_cast<int>(frames_.size()) + nesting_ >= options_.max_nesting)
        fail(name,
             fmt::format(
                 "nesting limit: more than {} macro calls, include files and blocks in progress "
                 "(runaway recursion in macro {}?) (ParseOptions::max_nesting)",
                 options_.max_nesting, word(name)));
    Frame frame;
    frame.source = macro->file;
    frame.pos = macro->body_start;
    frame.kind = FrameKind::macro;
    frame.blocks_at_start = blocks_.size();
    frames_.push_back(std::move(frame));
    symbols_.push_scope();
    for (size_t i = 0; i < parameters.size(); ++i)
        symbols_.bind(macro->parameters[i], std::move(parameters[i]), symbols_.depth());
    enter_block(Block::Kind::macro_body, name);
}

void Parser::leave_macro() {
    blocks_.pop_back();
    frames_.pop_back();
    symbols_.pop_scope();
}

}  // namespace rayset::tracer
