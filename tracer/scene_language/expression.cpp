// Numeric expressions with POV-Ray's precedence and promotion rules, and colours.
//
// Precedence, loosest first: c ? a : b; & and |; < <= = != >= > (also between strings); + -;
// * /; unary - + !; literals, identifiers, built-ins, <vectors>, (parentheses), with the postfix
// .x .red ... As in POV-Ray, a float or vector parameter (Parse_Float, Parse_Vector) and the
// value of #declare are read at the + - level, so `box { <0,0,0> <1,1,1> }` is two corners
// rather than a comparison; parentheses bring the full grammar back. Operators work term by
// term on vectors and colours; the shorter operand is promoted (a float repeats into every
// term, a vector pads with zeros).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "tracer/scene_language/functions.h"
#include "tracer/scene_language/parser.h"
#include "tracer/scene_language/splines.h"

namespace rayset::tracer {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON for truth and equality

bool truth(double value) { return std::fabs(value) > kEpsilon; }

Numeric combine(Numeric a, Numeric b, double (*op)(double, double)) {
    if (a.terms < b.terms)
        a = a.promoted(b.terms);
    else
        b = b.promoted(a.terms);
    for (int i = 0; i < a.terms; ++i) a.v[i] = op(a.v[i], b.v[i]);
    return a;
}

}  // namespace

bool is_colour_keyword(const Token& token) {
    constexpr Keyword kColourKeywords[] = {
        Keyword::color, Keyword::colour, Keyword::rgb,   Keyword::rgbf,   Keyword::rgbt,
        Keyword::rgbft, Keyword::srgb,   Keyword::srgbf, Keyword::srgbt,  Keyword::srgbft,
        Keyword::red,   Keyword::green,  Keyword::blue,  Keyword::filter, Keyword::transmit};
    if (token.kind != TokenKind::word || !is_keyword(token.name)) return false;
    const auto keyword = static_cast<Keyword>(token.name);
    return std::find(std::begin(kColourKeywords), std::end(kColourKeywords), keyword) !=
           std::end(kColourKeywords);
}

Numeric Numeric::promoted(int to_terms) const {
    if (terms >= to_terms) return *this;
    Numeric r = *this;
    for (int i = terms; i < to_terms; ++i) r.v[i] = terms == 1 ? v[0] : 0.0;
    r.terms = to_terms;
    return r;
}

bool Parser::starts_expression(const Token& token) {
    switch (token.kind) {
        case TokenKind::number: return true;
        case TokenKind::symbol:
            return token.is(Symbol::lparen) || token.is(Symbol::less) || token.is(Symbol::minus) ||
                   token.is(Symbol::plus) || token.is(Symbol::bang);
        case TokenKind::word: {
            if (is_keyword(token.name)) return is_numeric_builtin(token.name);
            const SymbolRef symbol = lookup(token.name);
            if (!symbol) return false;
            const Value* value = &symbol->value;
            if (const ArrayRef* array = std::get_if<ArrayRef>(value))
                return (*array)->element_type == Value(Numeric{}).index() ||
                       (*array)->element_type == Value(FunctionRef{}).index() ||
                       (*array)->element_type == Value(SplineRef{}).index();
            return std::holds_alternative<Numeric>(*value) ||
                   std::holds_alternative<FunctionRef>(*value) ||
                   std::holds_alternative<SplineRef>(*value);
        }
        default: return false;
    }
}

Numeric as_stored(Numeric value) {
    if (value.terms == 5)
        for (double& term : value.v) term = static_cast<double>(static_cast<float>(term));
    return value;
}

Value as_stored(Value value) {
    if (Numeric* n = std::get_if<Numeric>(&value)) *n = as_stored(*n);
    return value;
}

Numeric Parser::parse_expression() { return parse_conditional(); }

Numeric Parser::parse_numeric() { return parse_additive_after(parse_term()); }

Numeric Parser::parse_conditional() {
    Numeric condition = parse_logical();
    if (!peek_operator().is(Symbol::question)) return condition;
    const Token question = next();
    if (condition.terms != 1)
        fail(question, "the condition before '?' must be a float, found a vector");
    Numeric if_true = parse_conditional();
    expect(Symbol::colon, [&] {
        return fmt::format("in 'condition ? a : b' (the '?' is at {})",
                           location_of(question).str());
    });
    Numeric if_false = parse_conditional();
    return truth(condition.v[0]) ? if_true : if_false;
}

Numeric Parser::parse_logical() {
    Numeric result = parse_relational();
    for (;;) {
        const Token& op = peek_operator();
        if (op.is(Symbol::ampersand)) {
            next();
            result = combine(result, parse_relational(),
                             [](double a, double b) { return double(truth(a) && truth(b)); });
        } else if (op.is(Symbol::bar)) {
            next();
            result = combine(result, parse_relational(),
                             [](double a, double b) { return double(truth(a) || truth(b)); });
        } else {
            return result;
        }
    }
}

Numeric Parser::parse_relational() {
    using Compare = double (*)(double, double);
    auto comparison = [](const Token& op) -> Compare {
        if (op.is(Symbol::less)) return [](double a, double b) { return double(a < b); };
        if (op.is(Symbol::less_equal))
            return [](double a, double b) { return double(a <= b || !truth(a - b)); };
        if (op.is(Symbol::equals)) return [](double a, double b) { return double(!truth(a - b)); };
        if (op.is(Symbol::not_equal))
            return [](double a, double b) { return double(truth(a - b)); };
        if (op.is(Symbol::greater_equal))
            return [](double a, double b) { return double(a >= b || !truth(a - b)); };
        if (op.is(Symbol::greater)) return [](double a, double b) { return double(a > b); };
        return nullptr;
    };
    if (starts_string(peek())) {
        // Strings compare as strcmp does; the result is a float.
        const std::string left = parse_string();
        const Token op = next();
        const Compare compare = comparison(op);
        if (!compare) fail_expected("a comparison (< <= = != >= >) after a string", op);
        const std::string right = parse_string();
        const int order = left.compare(right);
        return Numeric::scalar(compare(order < 0 ? -1.0 : order > 0 ? 1.0 : 0.0, 0.0));
    }
    Numeric result = parse_additive_after(parse_term());
    for (;;) {
        const Compare compare = comparison(peek_operator());
        if (!compare) return result;
        next();
        result = combine(result, parse_additive_after(parse_term()), compare);
    }
}

Numeric Parser::parse_additive_after(Numeric result) {
    for (;;) {
        const Token& op = peek_operator();
        if (!op.is(Symbol::plus) && !op.is(Symbol::minus)) return result;
        const bool add = op.is(Symbol::plus);
        next();
        result = combine(
            result, parse_term(),
            add ? [](double a, double b) { return a + b; }
                : [](double a, double b) { return a - b; });
    }
}

Numeric Parser::parse_term() { return parse_term_after(parse_unary()); }

Numeric Parser::parse_term_after(Numeric result) {
    for (;;) {
        const Token& op = peek_operator();
        if (op.is(Symbol::star)) {
            next();
            result = combine(result, parse_unary(), [](double a, double b) { return a * b; });
        } else if (op.is(Symbol::slash)) {
            const Token slash = next();
            Numeric divisor = parse_unary();
            if (result.terms < divisor.terms)
                result = result.promoted(divisor.terms);
            else
                divisor = divisor.promoted(result.terms);
            for (int i = 0; i < result.terms; ++i) {
                if (divisor.v[i] == 0.0) fail(slash, "division by zero");
                result.v[i] /= divisor.v[i];
            }
        } else {
            return result;
        }
    }
}

Numeric Parser::parse_unary() {
    if (accept(Symbol::minus)) {
        Numeric n = parse_unary();
        for (int i = 0; i < n.terms; ++i) n.v[i] = -n.v[i];
        return n;
    }
    if (accept(Symbol::plus)) return parse_unary();
    if (accept(Symbol::bang)) {
        Numeric n = parse_unary();
        for (int i = 0; i < n.terms; ++i) n.v[i] = truth(n.v[i]) ? 0.0 : 1.0;
        return n;
    }
    return parse_primary();
}

Numeric Parser::parse_primary() {
    const Token token = peek();
    Nesting nesting(*this, token);
    if (token.kind == TokenKind::number) {
        next();
        return parse_postfix(Numeric::scalar(token.number));
    }
    if (token.is(Symbol::lparen)) {
        next();
        const Numeric inner = parse_conditional();
        expect(Symbol::rparen,
               [&] { return fmt::format("to close '(' opened at {}", location_of(token).str()); });
        return parse_postfix(inner);
    }
    if (token.is(Symbol::less)) {
        next();
        return parse_postfix(parse_vector_literal(token));
    }
    if (token.kind == TokenKind::word && is_keyword(token.name)) {
        if (!is_numeric_builtin(token.name)) {
            if (is_colour_keyword(token))
                fail(token,
                     fmt::format(
                         "a colour keyword ('{}') cannot be an operand: write the colour first "
                         "(rgb <...> * 0.5) or use a vector",
                         word(token)));
            fail_identifier(token, "a numeric expression");
        }
        next();
        return parse_postfix(parse_builtin_numeric(token));
    }
    if (token.kind == TokenKind::word) {
        const Value* value = peek_value();
        if (!value) fail_identifier(token, "a numeric expression");
        const Value held = *value;  // the next token may end a macro and its scope
        next();
        return parse_postfix(parse_numeric_identifier(token, held));
    }
    fail_expected("a numeric expression", token);
}

Numeric Parser::parse_numeric_identifier(const Token& token, const Value& value) {
    if (const Numeric* n = std::get_if<Numeric>(&value)) return *n;
    if (const FunctionRef* f = std::get_if<FunctionRef>(&value)) return call_function(token, **f);
    if (const SplineRef* s = std::get_if<SplineRef>(&value)) return call_spline(token, **s);
    if (const ArrayRef* array = std::get_if<ArrayRef>(&value)) {
        const ArrayRef keep = *array;
        const Value element = *array_element(token, *keep, false);
        if (!std::holds_alternative<Numeric>(element) &&
            !std::holds_alternative<FunctionRef>(element) &&
            !std::holds_alternative<SplineRef>(element))
            fail(token,
                 fmt::format(
                     "wrong type: the elements of '{}' are {}, expected a numeric expression",
                     word(token), type_name(element)));
        return parse_numeric_identifier(token, element);
    }
    fail(token, fmt::format("wrong type: '{}' is {}, expected a numeric expression", word(token),
                            type_name(value)));
}

Numeric Parser::parse_postfix(Numeric value) {
    if (!peek_operator().is(Symbol::dot)) return value;
    const Token dot = next();
    const Token component = next();
    auto is = [&](Keyword k) { return component.is(k); };
    int index = -1;
    if (is(Keyword::x) || is(Keyword::u) || is(Keyword::red))
        index = 0;
    else if (is(Keyword::y) || is(Keyword::v) || is(Keyword::green))
        index = 1;
    else if (is(Keyword::z) || is(Keyword::blue))
        index = 2;
    else if (is(Keyword::t) || is(Keyword::filter))
        index = 3;
    else if (is(Keyword::transmit))
        index = 4;
    else if (is(Keyword::gray)) {
        // POV-Ray's greyscale weights.
        const Numeric c = value.promoted(3);
        return Numeric::scalar(0.297 * c.v[0] + 0.589 * c.v[1] + 0.114 * c.v[2]);
    }
    if (index < 0)
        fail_expected("x, y, z, t, u, v, red, green, blue, filter, transmit or gray after '.'",
                      component);
    if (index >= value.terms)
        fail(dot, fmt::format("'.{}' needs at least {} terms, the value has {}", word(component),
                              index + 1, value.terms));
    return Numeric::scalar(value.v[index]);
}

Numeric Parser::parse_vector_literal(const Token& open) {
    Numeric result;
    result.terms = 0;
    for (;;) {
        const Token start = peek();
        const Numeric component = parse_numeric();
        if (component.terms != 1)
            fail(start,
                 fmt::format("expected a float as component {} of the vector, found {}",
                             result.terms + 1, component.terms <= 3 ? "a vector" : "a colour"));
        result.v[result.terms++] = component.v[0];
        accept_comma();
        if (peek_is(Symbol::greater)) break;
        if (result.terms == 5)
            fail_expected(fmt::format("'>' to close the vector opened at {} (5 terms at most)",
                                      location_of(open).str()),
                          peek());
        if (!starts_expression(peek()))
            fail_expected(fmt::format("a vector component or '>' to close the vector opened at {}",
                                      location_of(open).str()),
                          peek());
    }
    const Token close = next();
    if (result.terms < 2) fail(close, "a vector needs at least 2 components");
    return result;
}

double Parser::parse_float(Purpose purpose) {
    const Token start = peek();
    const Numeric n = parse_numeric();
    if (n.terms != 1) {
        const std::string why = purpose.str();
        fail(start, fmt::format("expected a float{}{}, found {}", why.empty() ? "" : " ", why,
                                n.terms <= 3 ? "a vector" : "a colour"));
    }
    return n.v[0];
}

int Parser::parse_int(Purpose purpose, int minimum) {
    const Token start = peek();
    const double value = parse_float(purpose);
    if (!(value >= -2147483648.0 && value < 2147483648.0))
        fail(start, fmt::format("expected an integer {}, found {}", purpose.str(), value));
    const int truncated = static_cast<int>(std::trunc(value));  // POV-Ray rounds toward zero too
    if (truncated < minimum)
        fail(start,
             fmt::format("expected an integer >= {} {}, found {}", minimum, purpose.str(), value));
    return truncated;
}

Vec3 Parser::parse_vector() { return parse_vector_terms(3).vec3(); }

Numeric Parser::parse_vector_terms(int terms) {
    const Token start = peek();
    const Numeric n = parse_numeric();
    if (n.terms > terms)
        fail(start,
             fmt::format("expected {} terms, found {}",
                         terms == 3 ? "a vector (3" : fmt::format("{}", terms),
                         n.terms == 5 ? "a colour (5 terms)" : fmt::format("{} terms", n.terms)));
    return n.promoted(terms);
}

bool Parser::parse_optional_bool() {
    if (!starts_expression(peek())) return true;
    return truth(parse_float());
}

bool Parser::starts_colour(const Token& token) {
    return is_colour_keyword(token) || starts_expression(token);
}

// [color|colour] then one of: rgb/rgbf/rgbt/rgbft/srgb... with an expression; an expression
// (a colour identifier, or a float that fills all five terms); then any of red, green, blue,
// filter, transmit with a float, each replacing its term.
Colour Parser::parse_colour() {
    const Token start = peek();
    const bool keyword = accept(Keyword::color) || accept(Keyword::colour);
    Numeric c{{0, 0, 0, 0, 0}, 5};
    bool started = false;
    const Token& first = peek();
    const bool srgb = first.is(Keyword::srgb) || first.is(Keyword::srgbf) ||
                      first.is(Keyword::srgbt) || first.is(Keyword::srgbft);
    const bool rgb = first.is(Keyword::rgb) || first.is(Keyword::rgbf) || first.is(Keyword::rgbt) ||
                     first.is(Keyword::rgbft);
    if (rgb || srgb) {
        const Token model = next();
        const std::string& w = word(model);
        const std::string suffix = w.substr(srgb ? 4 : 3);  // "", "f", "t" or "ft"
        const int terms = 3 + static_cast<int>(suffix.size());
        if (srgb && !scene_.global.assumed_gamma_set)
            fail(model, fmt::format("'{}' colours need global_settings {{ assumed_gamma ... }} "
                                    "first (as in POV-Ray)",
                                    w));
        // A value of more terms than the keyword names keeps them all (POV-Ray: `rgb C` of a
        // five-term colour C keeps its filter and transmit).
        const Numeric e = parse_numeric();
        const Numeric p = e.promoted(terms);
        for (int i = 0; i < p.terms; ++i) c.v[i] = p.v[i];
        if (suffix == "t" && p.terms == 4) std::swap(c.v[3], c.v[4]);
        if (srgb)
            for (int i = 0; i < 3; ++i) c.v[i] = srgb_to_linear(c.v[i]);
        started = true;
    } else if (!is_colour_keyword(first) && starts_expression(first)) {
        c = parse_numeric().promoted(5);
        c.terms = 5;
        started = true;
    }
    for (;;) {
        const Token token = peek();
        int index = -1;
        if (token.is(Keyword::red))
            index = 0;
        else if (token.is(Keyword::green))
            index = 1;
        else if (token.is(Keyword::blue))
            index = 2;
        else if (token.is(Keyword::filter))
            index = 3;
        else if (token.is(Keyword::transmit))
            index = 4;
        if (index < 0) break;
        next();
        c.v[index] = parse_float(fmt::format("after '{}'", word(token)));
        started = true;
    }
    if (!started) {
        if (keyword) fail_expected("a colour after 'color'", peek());
        fail_identifier(start, "a colour");
    }
    c = as_stored(c);
    return {c.v[0], c.v[1], c.v[2], c.v[3], c.v[4]};
}

}  // namespace rayset::tracer
