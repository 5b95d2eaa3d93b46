// Numeric expressions with POV-Ray's precedence and promotion rules, colours and strings.
//
// Precedence, loosest first: c ? a : b; & and |; < <= = != >= >; + -; * /; unary - + !;
// literals, identifiers, functions, <vectors>, (parentheses), and the postfix .x .red ...
// As in POV-Ray, a float or vector parameter (Parse_Float, Parse_Vector) is read at the + -
// level, so `box { <0,0,0> <1,1,1> }` is two corners rather than a comparison; parentheses
// bring the full grammar back. Operators work term by term on vectors and colours.
#include <cmath>

#include <fmt/format.h>

#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace {

constexpr double kTrueEpsilon = 1e-10;  // POV-Ray's EPSILON for truth and equality

bool truth(double value) { return std::fabs(value) > kTrueEpsilon; }

bool is_colour_keyword(const std::string& word) {
    return word == "color" || word == "colour" || word == "rgb" || word == "rgbf" || word == "rgbt" ||
           word == "rgbft" || word == "red" || word == "green" || word == "blue" || word == "filter" ||
           word == "transmit" || word == "srgb" || word == "srgbf" || word == "srgbt" || word == "srgbft";
}

bool is_function(const std::string& word) {
    static const char* const names[] = {"sin",   "cos",   "tan",     "asin",    "acos",       "atan",
                                        "atan2", "sqrt",  "pow",     "exp",     "log",        "ln",
                                        "abs",   "min",   "max",     "floor",   "ceil",       "mod",
                                        "int",   "radians", "degrees", "vlength", "vnormalize", "vdot",
                                        "vcross", "vrotate"};
    for (const char* name : names)
        if (word == name) return true;
    return false;
}

bool is_constant(const std::string& word) {
    return word == "x" || word == "y" || word == "z" || word == "t" || word == "u" || word == "v" || word == "pi" ||
           word == "true" || word == "false" || word == "yes" || word == "no" || word == "on" || word == "off";
}

Numeric combine(Numeric a, Numeric b, double (*op)(double, double)) {
    if (a.terms < b.terms) a = a.promoted(b.terms);
    else b = b.promoted(a.terms);
    for (int i = 0; i < a.terms; ++i) a.v[i] = op(a.v[i], b.v[i]);
    return a;
}

}  // namespace

bool Parser::starts_expression(const Token& token) const {
    switch (token.kind) {
        case TokenKind::number: return true;
        case TokenKind::symbol:
            return token.text == "(" || token.text == "<" || token.text == "-" || token.text == "+" || token.text == "!";
        case TokenKind::identifier: {
            if (is_constant(token.text) || is_function(token.text) || is_colour_keyword(token.text)) return true;
            const Value* value = lookup(token.text);
            return value && std::holds_alternative<Numeric>(*value);
        }
        default: return false;
    }
}

Numeric Parser::parse_expression() {
    Numeric condition = parse_logical();
    if (!peek_symbol("?")) return condition;
    const Token question = next();
    if (condition.terms != 1) fail(question, "the condition before '?' must be a float, found a vector");
    Numeric if_true = parse_expression();
    expect_symbol(":", "in 'condition ? a : b'");
    Numeric if_false = parse_expression();
    return truth(condition.v[0]) ? if_true : if_false;
}

Numeric Parser::parse_logical() {
    Numeric result = parse_relational();
    for (;;) {
        if (accept_symbol("&")) {
            result = combine(result, parse_relational(), [](double a, double b) { return double(truth(a) && truth(b)); });
        } else if (accept_symbol("|")) {
            result = combine(result, parse_relational(), [](double a, double b) { return double(truth(a) || truth(b)); });
        } else {
            return result;
        }
    }
}

Numeric Parser::parse_relational() {
    Numeric result = parse_additive();
    for (;;) {
        const Token& op = peek();
        if (op.kind != TokenKind::symbol) return result;
        double (*compare)(double, double) = nullptr;
        if (op.text == "<") compare = [](double a, double b) { return double(a < b); };
        else if (op.text == "<=") compare = [](double a, double b) { return double(a <= b || !truth(a - b)); };
        else if (op.text == "=") compare = [](double a, double b) { return double(!truth(a - b)); };
        else if (op.text == "!=") compare = [](double a, double b) { return double(truth(a - b)); };
        else if (op.text == ">=") compare = [](double a, double b) { return double(a >= b || !truth(a - b)); };
        else if (op.text == ">") compare = [](double a, double b) { return double(a > b); };
        else return result;
        next();
        result = combine(result, parse_additive(), compare);
    }
}

Numeric Parser::parse_additive() {
    Numeric result = parse_term();
    for (;;) {
        if (accept_symbol("+")) result = combine(result, parse_term(), [](double a, double b) { return a + b; });
        else if (accept_symbol("-")) result = combine(result, parse_term(), [](double a, double b) { return a - b; });
        else return result;
    }
}

Numeric Parser::parse_term() {
    Numeric result = parse_unary();
    for (;;) {
        if (accept_symbol("*")) {
            result = combine(result, parse_unary(), [](double a, double b) { return a * b; });
        } else if (peek_symbol("/")) {
            const Token slash = next();
            Numeric divisor = parse_unary();
            if (result.terms < divisor.terms) result = result.promoted(divisor.terms);
            else divisor = divisor.promoted(result.terms);
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
    if (accept_symbol("-")) {
        Numeric n = parse_unary();
        for (int i = 0; i < n.terms; ++i) n.v[i] = -n.v[i];
        return n;
    }
    if (accept_symbol("+")) return parse_unary();
    if (accept_symbol("!")) {
        Numeric n = parse_unary();
        for (int i = 0; i < n.terms; ++i) n.v[i] = truth(n.v[i]) ? 0.0 : 1.0;
        return n;
    }
    return parse_primary();
}

Numeric Parser::parse_primary() {
    const Token token = peek();
    Numeric result;
    if (token.kind == TokenKind::number) {
        next();
        result = Numeric::scalar(token.number);
    } else if (token.kind == TokenKind::symbol && token.text == "(") {
        next();
        result = parse_expression();
        expect_symbol(")", fmt::format("to close '(' opened at {}", location_of(token).str()));
    } else if (token.kind == TokenKind::symbol && token.text == "<") {
        next();
        result = parse_vector_literal(token);
    } else if (token.kind == TokenKind::identifier && is_colour_keyword(token.text)) {
        const Colour c = parse_colour(true);
        result = Numeric{{c.red, c.green, c.blue, c.filter, c.transmit}, 5};
    } else if (token.kind == TokenKind::identifier && is_function(token.text)) {
        next();
        result = parse_function(token);
    } else if (token.kind == TokenKind::identifier && is_constant(token.text)) {
        next();
        const std::string& w = token.text;
        if (w == "x") result = Numeric::vector3({1, 0, 0});
        else if (w == "y") result = Numeric::vector3({0, 1, 0});
        else if (w == "z") result = Numeric::vector3({0, 0, 1});
        else if (w == "t") result = Numeric{{0, 0, 0, 1, 0}, 4};
        else if (w == "u") result = Numeric{{1, 0, 0, 0, 0}, 2};
        else if (w == "v") result = Numeric{{0, 1, 0, 0, 0}, 2};
        else if (w == "pi") result = Numeric::scalar(analytic::kPi);
        else result = Numeric::scalar(w == "true" || w == "yes" || w == "on" ? 1.0 : 0.0);
    } else if (token.kind == TokenKind::identifier) {
        const Value* value = lookup(token.text);
        if (!value || !std::holds_alternative<Numeric>(*value)) fail_identifier(token, "a numeric expression");
        next();
        result = std::get<Numeric>(*value);
    } else {
        fail_expected("a numeric expression", token);
    }

    if (peek_symbol(".")) {
        const Token dot = next();
        const Token component = next();
        static const char* const names[] = {"x", "y", "z", "t", "u", "v", "red", "green", "blue", "filter", "transmit"};
        static const int index[] = {0, 1, 2, 3, 0, 1, 0, 1, 2, 3, 4};
        int i = -1;
        for (int k = 0; k < 11; ++k)
            if (component.kind == TokenKind::identifier && component.text == names[k]) i = index[k];
        if (component.kind == TokenKind::identifier && (component.text == "gray" || component.text == "grey")) {
            // POV-Ray's greyscale weights.
            return Numeric::scalar(0.297 * result.v[0] + 0.589 * result.v[1] + 0.114 * result.v[2]);
        }
        if (i < 0) fail_expected("x, y, z, t, u, v, red, green, blue, filter, transmit or gray after '.'", component);
        if (i >= result.terms)
            fail(dot, fmt::format("'.{}' needs at least {} terms, the value has {}", component.text, i + 1, result.terms));
        result = Numeric::scalar(result.v[i]);
    }
    return result;
}

Numeric Parser::parse_vector_literal(const Token& open) {
    Numeric result;
    result.terms = 0;
    for (;;) {
        const Token start = peek();
        const Numeric component = parse_additive();
        if (component.terms != 1)
            fail(start, fmt::format("expected a float as component {} of the vector, found {}", result.terms + 1,
                                    component.terms <= 3 ? "a vector" : "a colour"));
        result.v[result.terms++] = component.v[0];
        accept_comma();
        if (peek_symbol(">")) break;
        if (result.terms == 5)
            fail_expected(fmt::format("'>' to close the vector opened at {} (5 terms at most)", location_of(open).str()), peek());
        if (!starts_expression(peek()))
            fail_expected(fmt::format("a vector component or '>' to close the vector opened at {}", location_of(open).str()),
                          peek());
    }
    const Token close = next();
    if (result.terms < 2) fail(close, "a vector needs at least 2 components");
    return result;
}

Numeric Parser::parse_function(const Token& name) {
    expect_symbol("(", fmt::format("after '{}'", name.text));
    std::vector<Numeric> args;
    std::vector<Token> starts;
    if (!peek_symbol(")")) {
        for (;;) {
            starts.push_back(peek());
            args.push_back(parse_expression());
            if (!accept_symbol(",")) break;
        }
    }
    expect_symbol(")", fmt::format("to close the arguments of '{}'", name.text));
    const std::string& f = name.text;
    auto want = [&](size_t count) {
        if (args.size() != count) fail(name, fmt::format("'{}' takes {} argument{}, found {}", f, count, count == 1 ? "" : "s", args.size()));
    };
    auto flt = [&](size_t i) {
        if (args[i].terms != 1) fail(starts[i], fmt::format("argument {} of '{}' must be a float, found a vector", i + 1, f));
        return args[i].v[0];
    };
    auto vec = [&](size_t i) {
        if (args[i].terms > 3) fail(starts[i], fmt::format("argument {} of '{}' must be a vector, found a colour", i + 1, f));
        return args[i].promoted(3).vec3();
    };
    auto domain = [&](bool ok, const char* what) {
        if (!ok) fail(name, fmt::format("'{}': {}", f, what));
    };
    if (f == "min" || f == "max") {
        if (args.size() < 2) fail(name, fmt::format("'{}' takes at least 2 arguments, found {}", f, args.size()));
        double r = flt(0);
        for (size_t i = 1; i < args.size(); ++i) r = f == "min" ? std::min(r, flt(i)) : std::max(r, flt(i));
        return Numeric::scalar(r);
    }
    if (f == "atan2" || f == "pow" || f == "mod") {
        want(2);
        const double a = flt(0), b = flt(1);
        if (f == "atan2") return Numeric::scalar(std::atan2(a, b));
        if (f == "pow") return Numeric::scalar(std::pow(a, b));
        domain(b != 0, "division by zero");
        return Numeric::scalar(std::fmod(a, b));
    }
    if (f == "vdot" || f == "vcross" || f == "vrotate") {
        want(2);
        const Vec3 a = vec(0), b = vec(1);
        if (f == "vdot") return Numeric::scalar(dot(a, b));
        if (f == "vcross") return Numeric::vector3(cross(a, b));
        return Numeric::vector3(pov_rotation(b).vector(a));
    }
    want(1);
    if (f == "vlength") return Numeric::scalar(length(vec(0)));
    if (f == "vnormalize") {
        const Vec3 a = vec(0);
        domain(length(a) > 0, "zero-length vector");
        return Numeric::vector3(normalized(a));
    }
    const double a = flt(0);
    if (f == "sin") return Numeric::scalar(std::sin(a));
    if (f == "cos") return Numeric::scalar(std::cos(a));
    if (f == "tan") return Numeric::scalar(std::tan(a));
    if (f == "asin" || f == "acos") {
        domain(a >= -1 && a <= 1, "argument outside [-1, 1]");
        return Numeric::scalar(f == "asin" ? std::asin(a) : std::acos(a));
    }
    if (f == "atan") return Numeric::scalar(std::atan(a));
    if (f == "sqrt") {
        domain(a >= 0, "negative argument");
        return Numeric::scalar(std::sqrt(a));
    }
    if (f == "exp") return Numeric::scalar(std::exp(a));
    if (f == "log" || f == "ln") {
        domain(a > 0, "argument not positive");
        return Numeric::scalar(f == "log" ? std::log10(a) : std::log(a));
    }
    if (f == "abs") return Numeric::scalar(std::fabs(a));
    if (f == "floor") return Numeric::scalar(std::floor(a));
    if (f == "ceil") return Numeric::scalar(std::ceil(a));
    if (f == "int") return Numeric::scalar(std::trunc(a));
    if (f == "radians") return Numeric::scalar(a * analytic::kPi / 180.0);
    return Numeric::scalar(a * 180.0 / analytic::kPi);  // degrees
}

double Parser::parse_float() { return parse_float(""); }

double Parser::parse_float(const std::string& purpose) {
    const Token start = peek();
    const Numeric n = parse_additive();
    if (n.terms != 1)
        fail(start, fmt::format("expected a float{}{}, found {}", purpose.empty() ? "" : " ", purpose,
                                n.terms <= 3 ? "a vector" : "a colour"));
    return n.v[0];
}

int Parser::parse_int(const std::string& purpose, int minimum) {
    const Token start = peek();
    const double value = parse_float(purpose);
    const int truncated = static_cast<int>(std::trunc(value));  // POV-Ray rounds toward zero too
    if (truncated < minimum) fail(start, fmt::format("expected an integer >= {} {}, found {}", minimum, purpose, value));
    return truncated;
}

Vec3 Parser::parse_vector() {
    const Token start = peek();
    const Numeric n = parse_additive();
    if (n.terms > 3) fail(start, "expected a vector, found a colour (5 terms)");
    return n.promoted(3).vec3();
}

bool Parser::parse_optional_bool() {
    if (!starts_expression(peek())) return true;
    return truth(parse_float());
}

Colour Parser::parse_colour(bool with_filter_transmit) {
    const Token start = peek();
    const bool keyword = accept_word("color") || accept_word("colour");
    Numeric c{{0, 0, 0, 0, 0}, 5};
    bool started = false;
    for (;;) {
        const Token token = peek();
        const std::string& w = token.text;
        if (token.kind == TokenKind::identifier && (w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft")) {
            if (started) break;
            next();
            const int terms = w == "rgb" ? 3 : w == "rgbft" ? 5 : 4;
            const Token value_start = peek();
            const Numeric e = parse_expression();
            if (e.terms > terms)
                fail(value_start, fmt::format("expected {} terms after '{}', found {}", terms, w, e.terms));
            const Numeric p = e.promoted(terms);
            for (int i = 0; i < terms; ++i) c.v[i] = p.v[i];
            if (w == "rgbt") std::swap(c.v[3], c.v[4]);
        } else if (token.kind == TokenKind::identifier &&
                   (w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit")) {
            next();
            const int i = w == "red" ? 0 : w == "green" ? 1 : w == "blue" ? 2 : w == "filter" ? 3 : 4;
            c.v[i] = parse_float(fmt::format("after '{}'", w));
        } else if (token.kind == TokenKind::identifier && w.rfind("srgb", 0) == 0) {
            fail_not_supported(token, fmt::format("'{}' colours (write linear rgb)", w));
        } else if (!started && starts_expression(token)) {
            const Numeric e = parse_expression();
            const Numeric p = e.promoted(with_filter_transmit ? 5 : 3);
            for (int i = 0; i < p.terms; ++i) c.v[i] = p.v[i];
        } else {
            break;
        }
        started = true;
    }
    if (!started) {
        if (keyword) fail_expected("a colour after 'color'", peek());
        fail_identifier(start, "a colour");
    }
    if (!with_filter_transmit) c.v[3] = c.v[4] = 0;
    return {c.v[0], c.v[1], c.v[2], c.v[3], c.v[4]};
}

std::string Parser::parse_string() {
    const Token token = next();
    if (token.kind == TokenKind::string) return token.text;
    if (token.kind == TokenKind::identifier && token.text == "concat") {
        expect_symbol("(", "after 'concat'");
        std::string result = parse_string();
        while (accept_symbol(",")) result += parse_string();
        expect_symbol(")", "to close 'concat('");
        return result;
    }
    if (token.kind == TokenKind::identifier) {
        const Value* value = lookup(token.text);
        if (value && std::holds_alternative<std::string>(*value)) return std::get<std::string>(*value);
    }
    fail_identifier(token, "a string");
}

}  // namespace rayset::tracer
