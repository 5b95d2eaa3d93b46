// User-defined functions: the compiler (POV-Ray's function syntax, reference manual 3.3.1.8,
// read from the parser's token stream so that macros and identifiers work inside it) and the
// stack machine that evaluates the result. Identifiers are bound when the function is
// declared, as in POV-Ray: a declared float becomes a constant, a declared function a call.
// Evaluation follows IEEE arithmetic (sqrt(-1) is NaN, as in POV-Ray), since a function runs
// long after its declaration where no error can be reported.
#include "tracer/scene_language/functions.h"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "tracer/scene_language/appearance.h"
#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/internal_functions.h"
#include "tracer/scene_language/parser.h"
#include "tracer/scene_language/splines.h"

namespace rayset::tracer {
namespace {

using Op = UserFunction::Op;
using Instruction = UserFunction::Instruction;

constexpr double kEpsilon = 1e-10;
constexpr int kMaxStack = 256;
constexpr int kMaxParameters = 56;  // POV-Ray's limit
// Terms of one sum() or prod(), its nested loops and the loops of the functions it calls counted
// together: a bound of 1e84 (or any beyond 2^53, where the variable's step of 1 no longer moves
// it) would loop for ever. POV-Ray has no such limit.
constexpr long kMostLoopTerms = 1000000;

// The terms left to the outermost loop in progress on this thread; negative outside any.
thread_local long t_loop_terms_left = -1;

// Gives the outermost loop on this thread its budget of terms (functions without loops, such as
// an isosurface's at every step of a ray, never touch it).
class LoopTermBudget {
public:
    LoopTermBudget() : outermost_(t_loop_terms_left < 0) {
        if (outermost_) t_loop_terms_left = kMostLoopTerms;
    }
    ~LoopTermBudget() {
        if (outermost_) t_loop_terms_left = -1;
    }
    LoopTermBudget(const LoopTermBudget&) = delete;
    LoopTermBudget& operator=(const LoopTermBudget&) = delete;

private:
    bool outermost_;
};

struct Builtin {
    const char* name;
    int arity;  // -2: two or more (min, max)
};
// The float functions a function body may call (reference manual 3.3.1.8).
constexpr std::array<Builtin, 27> kBuiltins{{
    {"abs", 1},   {"acos", 1},  {"acosh", 1}, {"asin", 1},    {"asinh", 1}, {"atan", 1},
    {"atan2", 2}, {"atanh", 1}, {"ceil", 1},  {"cos", 1},     {"cosh", 1},  {"degrees", 1},
    {"exp", 1},   {"floor", 1}, {"int", 1},   {"ln", 1},      {"log", 1},   {"max", -2},
    {"min", -2},  {"mod", 2},   {"pow", 2},   {"radians", 1}, {"sin", 1},   {"sinh", 1},
    {"sqrt", 1},  {"tan", 1},   {"tanh", 1},
}};

double call_builtin(int index, const double* a, int count) {
    const std::string_view name = kBuiltins[static_cast<size_t>(index)].name;
    if (name == "max" || name == "min") {
        double r = a[0];
        for (int i = 1; i < count; ++i) r = name == "max" ? std::max(r, a[i]) : std::min(r, a[i]);
        return r;
    }
    if (name == "atan2") return std::atan2(a[0], a[1]);
    if (name == "mod") return std::fmod(a[0], a[1]);
    if (name == "pow") return std::pow(a[0], a[1]);
    const double x = a[0];
    if (name == "abs") return std::fabs(x);
    if (name == "acos") return std::acos(x);
    if (name == "acosh") return std::acosh(x);
    if (name == "asin") return std::asin(x);
    if (name == "asinh") return std::asinh(x);
    if (name == "atan") return std::atan(x);
    if (name == "atanh") return std::atanh(x);
    if (name == "ceil") return std::ceil(x);
    if (name == "cos") return std::cos(x);
    if (name == "cosh") return std::cosh(x);
    if (name == "degrees") return x * 180.0 / 3.1415926535897932384626;
    if (name == "exp") return std::exp(x);
    if (name == "floor") return std::floor(x);
    if (name == "int") return std::trunc(x);
    if (name == "ln") return std::log(x);
    if (name == "log") return std::log10(x);
    if (name == "radians") return x * 3.1415926535897932384626 / 180.0;
    if (name == "sin") return std::sin(x);
    if (name == "sinh") return std::sinh(x);
    if (name == "sqrt") return std::sqrt(x);
    if (name == "tan") return std::tan(x);
    return std::tanh(x);
}

bool truth(double value) { return std::fabs(value) > kEpsilon; }

}  // namespace

int function_builtin_index(const std::string& name) {
    for (size_t i = 0; i < kBuiltins.size(); ++i)
        if (name == kBuiltins[i].name) return static_cast<int>(i);
    return -1;
}

// ---------------------------------------------------------------- evaluation

double UserFunction::run(const Instruction* begin, const Instruction* end, const double* parameters,
                         double* locals) const {
    std::array<double, kMaxStack> stack;
    int top = 0;
    for (const Instruction* in = begin; in != end; ++in) {
        switch (in->op) {
            case Op::constant: stack[top++] = constants_[static_cast<size_t>(in->index)]; break;
            case Op::parameter: stack[top++] = parameters[in->index]; break;
            case Op::local: stack[top++] = locals[in->index]; break;
            case Op::negate: stack[top - 1] = -stack[top - 1]; break;
            case Op::add: --top, stack[top - 1] += stack[top]; break;
            case Op::subtract: --top, stack[top - 1] -= stack[top]; break;
            case Op::multiply: --top, stack[top - 1] *= stack[top]; break;
            case Op::divide: --top, stack[top - 1] /= stack[top]; break;
            case Op::less: --top, stack[top - 1] = stack[top - 1] < stack[top]; break;
            case Op::less_equal: --top, stack[top - 1] = stack[top - 1] <= stack[top]; break;
            case Op::equal: --top, stack[top - 1] = !truth(stack[top - 1] - stack[top]); break;
            case Op::not_equal: --top, stack[top - 1] = truth(stack[top - 1] - stack[top]); break;
            case Op::greater_equal: --top, stack[top - 1] = stack[top - 1] >= stack[top]; break;
            case Op::greater: --top, stack[top - 1] = stack[top - 1] > stack[top]; break;
            case Op::logical_and:
                --top, stack[top - 1] = truth(stack[top - 1]) && truth(stack[top]);
                break;
            case Op::logical_or:
                --top, stack[top - 1] = truth(stack[top - 1]) || truth(stack[top]);
                break;
            case Op::call_builtin:
                top -= in->argument_count;
                stack[top] = call_builtin(in->index, &stack[top], in->argument_count);
                ++top;
                break;
            case Op::call_function:
                top -= in->argument_count;
                stack[top] = call_function(*in, &stack[top]);
                ++top;
                break;
            case Op::select3:
                top -= 2;
                stack[top - 1] = stack[top - 1] < 0 ? stack[top] : stack[top + 1];
                break;
            case Op::select4:
                top -= 3;
                stack[top - 1] = stack[top - 1] < 0    ? stack[top]
                                 : stack[top - 1] == 0 ? stack[top + 1]
                                                       : stack[top + 2];
                break;
            case Op::sum:
            case Op::product:
                // Bounds on the stack; the body follows this instruction.
                top -= 2;
                stack[top] = run_loop(*in, stack[top], stack[top + 1], parameters, locals);
                ++top;
                in += in->length;
                break;
        }
    }
    return stack[0];
}

// The float the callee returns, or the term of its vector result the call takes (-2: its gray).
double UserFunction::call_function(const Instruction& call, const double* arguments) const {
    const UserFunction& callee = *callees_[static_cast<size_t>(call.index)];
    if (call.component == -1) return callee.evaluate_float(arguments);
    const Numeric r = callee.evaluate(arguments);
    return call.component == -2 ? 0.297 * r.v[0] + 0.589 * r.v[1] + 0.114 * r.v[2]
                                : r.v[call.component];
}

// sum() or product() of the loop body that follows `loop`, its variable from first to last.
double UserFunction::run_loop(const Instruction& loop, double first, double last,
                              const double* parameters, double* locals) const {
    const LoopTermBudget budget;
    double result = loop.op == Op::sum ? 0.0 : 1.0;
    for (double i = first; i <= last; i += 1) {
        if (--t_loop_terms_left < 0)
            throw FunctionNotSupported(
                fmt::format("sum() or prod() of more than {} terms, nested loops and called "
                            "functions' loops included (this renderer's limit)",
                            kMostLoopTerms));
        locals[loop.index] = i;
        const double term = run(&loop + 1, &loop + 1 + loop.length, parameters, locals);
        result = loop.op == Op::sum ? result + term : result * term;
    }
    return result;
}

double UserFunction::evaluate_float(const double* arguments) const {
    if (kind_ == Kind::expression) {
        std::array<double, kMaxParameters> locals{};
        return run(code_.data(), code_.data() + code_.size(), arguments, locals.data());
    }
    return evaluate(arguments).v[0];
}

Numeric UserFunction::evaluate(const double* arguments) const {
    switch (kind_) {
        case Kind::expression: return Numeric::scalar(evaluate_float(arguments));
        case Kind::internal: {
            double result = 0;
            if (!evaluate_internal_function(internal_number_, arguments, result))
                throw FunctionNotSupported(fmt::format("internal function {} ({})",
                                                       internal_number_,
                                                       internal_function_name(internal_number_)));
            return Numeric::scalar(result);
        }
        case Kind::pattern: {
            double value = 0;
            if (!evaluate_pattern(*pattern_, {arguments[0], arguments[1], arguments[2]}, value))
                throw FunctionNotSupported("evaluating this pattern function");
            return Numeric::scalar(value);
        }
        case Kind::pigment: {
            Colour c;
            if (!evaluate_pigment(*pigment_, {arguments[0], arguments[1], arguments[2]}, c))
                throw FunctionNotSupported("evaluating this pigment function");
            return Numeric{{c.red, c.green, c.blue, c.filter, c.transmit}, 5};
        }
        case Kind::transform:
            return Numeric::vector3(transform_.point({arguments[0], arguments[1], arguments[2]}));
        case Kind::spline: return spline_->evaluate(arguments[0]);
    }
    return {};
}

// ---------------------------------------------------------------- compilation

// Reads a function body from the parser's tokens into instructions.
class FunctionCompiler {
public:
    FunctionCompiler(Parser& parser, UserFunction& function, std::vector<NameId> parameters)
        : p_(parser), f_(function), parameters_(std::move(parameters)) {}

    void compile() {
        expression();
        if (max_depth_ > kMaxStack)
            p_.fail(p_.peek(), "function too deep to evaluate (simplify the expression)");
    }

private:
    void emit(Op op, int index = 0, int argument_count = 0, int component = -1) {
        Instruction in;
        in.op = op;
        in.index = index;
        in.argument_count = static_cast<uint8_t>(argument_count);
        in.component = static_cast<int16_t>(component);
        f_.code_.push_back(in);
        // Stack depth bookkeeping for the depth check.
        switch (op) {
            case Op::constant:
            case Op::parameter:
            case Op::local: ++depth_; break;
            case Op::negate: break;
            case Op::call_builtin:
            case Op::call_function: depth_ -= argument_count - 1; break;
            case Op::select3: depth_ -= 2; break;
            case Op::select4: depth_ -= 3; break;
            case Op::sum:
            case Op::product: depth_ -= 1; break;
            default: --depth_; break;
        }
        max_depth_ = std::max(max_depth_, depth_);
    }
    void constant(double value) {
        f_.constants_.push_back(value);
        emit(Op::constant, static_cast<int>(f_.constants_.size() - 1));
    }

    // FLOAT: LOGIC_AND [| LOGIC_AND]...
    void expression() {
        logical_and();
        while (p_.accept(Symbol::bar)) logical_and(), emit(Op::logical_or);
    }
    void logical_and() {
        relational();
        while (p_.accept(Symbol::ampersand)) relational(), emit(Op::logical_and);
    }
    void relational() {
        additive();
        for (;;) {
            const Token& op = p_.peek();
            Op code;
            if (op.is(Symbol::less))
                code = Op::less;
            else if (op.is(Symbol::less_equal))
                code = Op::less_equal;
            else if (op.is(Symbol::equals))
                code = Op::equal;
            else if (op.is(Symbol::not_equal))
                code = Op::not_equal;
            else if (op.is(Symbol::greater_equal))
                code = Op::greater_equal;
            else if (op.is(Symbol::greater))
                code = Op::greater;
            else
                return;
            p_.next();
            additive();
            emit(code);
        }
    }
    void additive() {
        term();
        for (;;) {
            if (p_.accept(Symbol::plus))
                term(), emit(Op::add);
            else if (p_.accept(Symbol::minus))
                term(), emit(Op::subtract);
            else
                return;
        }
    }
    void term() {
        unary();
        for (;;) {
            if (p_.accept(Symbol::star))
                unary(), emit(Op::multiply);
            else if (p_.accept(Symbol::slash))
                unary(), emit(Op::divide);
            else
                return;
        }
    }
    void unary() {
        if (p_.accept(Symbol::minus)) return unary(), emit(Op::negate);
        if (p_.accept(Symbol::plus)) return unary();  // no '!' in function syntax (as in POV-Ray)
        primary();
    }

    int parameter_index(NameId name) const {
        auto find = [&](NameId n) {
            for (size_t i = 0; i < parameters_.size(); ++i)
                if (parameters_[i] == n) return static_cast<int>(i);
            return -1;
        };
        int i = find(name);
        // x and u, y and v name the same parameter (POV-Ray's rule).
        if (i < 0 && name == id_of(Keyword::u)) i = find(id_of(Keyword::x));
        if (i < 0 && name == id_of(Keyword::x)) i = find(id_of(Keyword::u));
        if (i < 0 && name == id_of(Keyword::v)) i = find(id_of(Keyword::y));
        if (i < 0 && name == id_of(Keyword::y)) i = find(id_of(Keyword::v));
        return i;
    }

    int local_index(NameId name) const {
        for (size_t i = locals_.size(); i-- > 0;)
            if (locals_[i] == name) return static_cast<int>(i);
        return -1;
    }

    // The arguments of a call, each a full function expression.
    int arguments(const Token& name) {
        const Token open = p_.open_call(name);
        int count = 0;
        if (!p_.peek_is(Symbol::rparen)) {
            do {
                expression();
                ++count;
            } while (p_.accept(Symbol::comma));
        }
        p_.close_call(name, open);
        return count;
    }

    // .x .y .z .t .u .v .red .green .blue .filter .transmit .gray after a vector result.
    int component(int terms) {
        const Token dot = p_.expect(
            Symbol::dot, "and a component (.x, .red, .gray ...) after a vector-valued function");
        const Token c = p_.next();
        int index = -1;
        if (c.is(Keyword::x) || c.is(Keyword::u) || c.is(Keyword::red))
            index = 0;
        else if (c.is(Keyword::y) || c.is(Keyword::v) || c.is(Keyword::green))
            index = 1;
        else if (c.is(Keyword::z) || c.is(Keyword::blue))
            index = 2;
        else if (c.is(Keyword::t) || c.is(Keyword::filter))
            index = 3;
        else if (c.is(Keyword::transmit))
            index = 4;
        else if (c.is(Keyword::gray))
            return -2;
        if (index < 0)
            p_.fail_expected(
                "x, y, z, t, u, v, red, green, blue, filter, transmit or gray after '.'", c);
        if (index >= terms)
            p_.fail(dot, fmt::format("'.{}' of a {}-term result", p_.word(c), terms));
        return index;
    }

    void call(const Token& name, const FunctionRef& callee) {
        const int count = arguments(name);
        if (count != callee->parameter_count())
            p_.fail(name, fmt::format("function '{}' takes {} argument{}, found {}", p_.word(name),
                                      callee->parameter_count(),
                                      callee->parameter_count() == 1 ? "" : "s", count));
        f_.callees_.push_back(callee);
        const int index = static_cast<int>(f_.callees_.size() - 1);
        const int terms = callee->result_terms();
        emit(Op::call_function, index, count, terms == 1 ? -1 : component(terms));
    }

    // sum(i, first, last, body) and prod(...): the body runs once per value of i.
    void loop(const Token& name) {
        const Token open = p_.open_call(name);
        const Token variable = p_.next();
        if (variable.kind != TokenKind::word)
            p_.fail_expected(fmt::format("the variable of '{}'", p_.word(name)), variable);
        p_.expect(Symbol::comma,
                  [&] { return fmt::format("after the variable of '{}'", p_.word(name)); });
        expression();
        p_.expect(Symbol::comma,
                  [&] { return fmt::format("after the first value of '{}'", p_.word(name)); });
        expression();
        p_.expect(Symbol::comma,
                  [&] { return fmt::format("after the last value of '{}'", p_.word(name)); });
        if (locals_.size() >= 56)
            p_.fail(name, "more than 56 nested sum/prod loops (POV-Ray's limit)");
        locals_.push_back(variable.name);
        const int slot = static_cast<int>(locals_.size() - 1);
        f_.local_count_ = std::max(f_.local_count_, slot + 1);
        emit(name.is(Keyword::sum) ? Op::sum : Op::product, slot);
        const size_t loop_at = f_.code_.size() - 1;
        const int saved_depth = depth_;
        depth_ = 0;
        expression();
        depth_ = saved_depth;
        f_.code_[loop_at].length = static_cast<int32_t>(f_.code_.size() - loop_at - 1);
        locals_.pop_back();
        p_.close_call(name, open);
    }

    void primary() {
        const Token token = p_.peek();
        Parser::Nesting nesting(p_, token);
        if (token.kind == TokenKind::number) {
            p_.next();
            return constant(token.number);
        }
        if (token.is(Symbol::lparen)) {
            p_.next();
            expression();
            p_.expect(Symbol::rparen, [&] {
                return fmt::format("to close '(' opened at {}", p_.location_of(token).str());
            });
            return;
        }
        if (token.kind != TokenKind::word)
            p_.fail_expected("a number, a parameter or a function call", token);
        if (const int local = local_index(token.name); local >= 0) {
            p_.next();
            return emit(Op::local, local);
        }
        if (const int parameter = parameter_index(token.name); parameter >= 0) {
            p_.next();
            return emit(Op::parameter, parameter);
        }
        if (is_keyword(token.name)) return keyword(token);
        const Value* value = p_.peek_value();
        if (!value)
            p_.fail(token,
                    fmt::format(
                        "unknown identifier '{}' in a function (not a parameter, and not declared; "
                        "internal functions need #include \"functions.inc\")",
                        p_.word(token)));
        const Value held = *value;
        p_.next();
        if (const FunctionRef* callee = std::get_if<FunctionRef>(&held))
            return call(token, *callee);
        if (const Numeric* n = std::get_if<Numeric>(&held)) {
            if (n->terms == 1) return constant(n->v[0]);
            return constant(n->v[component(n->terms)]);
        }
        p_.fail(token,
                fmt::format("wrong type: '{}' is {}; a function may use floats and functions",
                            p_.word(token), type_name(held)));
    }

    void keyword(const Token& token) {
        const std::string& name = p_.word(token);
        if (token.is(Keyword::sum) || token.is(Keyword::prod)) {
            p_.next();
            return loop(token);
        }
        if (token.is(Keyword::select)) {
            p_.next();
            const int count = arguments(token);
            if (count != 3 && count != 4)
                p_.fail(token, fmt::format("'select' takes 3 or 4 arguments, found {}", count));
            return emit(count == 3 ? Op::select3 : Op::select4);
        }
        if (const int builtin = function_builtin_index(name); builtin >= 0) {
            p_.next();
            const int count = arguments(token);
            const int arity = kBuiltins[static_cast<size_t>(builtin)].arity;
            if ((arity > 0 && count != arity) || (arity == -2 && count < 2))
                p_.fail(token, fmt::format("'{}' takes {} argument{}, found {}", name,
                                           arity == -2 ? "2 or more" : std::to_string(arity),
                                           arity == 1 ? "" : "s", count));
            return emit(Op::call_builtin, builtin, count);
        }
        // Constants and built-in variables (pi, true, clock, image_width ...) as their value now.
        if (const std::optional<Numeric> n = p_.builtin_constant(token); n && n->terms == 1) {
            p_.next();
            return constant(n->v[0]);
        }
        p_.fail(
            token,
            fmt::format(
                "'{}' cannot be used in a function (not a parameter of this function, nor one of "
                "the functions a function may call)",
                name));
    }

    Parser& p_;
    UserFunction& f_;
    std::vector<NameId> parameters_;
    std::vector<NameId> locals_;
    int depth_ = 0, max_depth_ = 0;
};

FunctionRef Parser::parse_function(const Token& keyword) {
    auto function = std::make_shared<UserFunction>();
    std::vector<NameId> parameters{id_of(Keyword::x), id_of(Keyword::y), id_of(Keyword::z)};
    bool explicit_parameters = false;
    if (peek_is(Symbol::lparen)) {
        const Token open = next();
        explicit_parameters = true;
        parameters.clear();
        do {
            // An identifier, or x, y, z, u, v (POV-Ray refuses other reserved words here).
            const Token name = next();
            const bool axis = name.is(Keyword::x) || name.is(Keyword::y) || name.is(Keyword::z) ||
                              name.is(Keyword::u) || name.is(Keyword::v);
            if (!name.is_identifier() && !axis)
                fail_expected("a parameter name (an identifier, or x, y, z, u, v)", name);
            for (NameId earlier : parameters)
                if (earlier == name.name)
                    fail(name, fmt::format("parameter '{}' appears twice", word(name)));
            parameters.push_back(name.name);
        } while (accept(Symbol::comma));
        expect(Symbol::rparen, [&] {
            return fmt::format("to close the parameters opened at {}", location_of(open).str());
        });
        if (parameters.size() > static_cast<size_t>(kMaxParameters))
            fail(open, fmt::format("a function takes at most {} parameters (POV-Ray's limit)",
                                   kMaxParameters));
    }
    const Token open = expect_open(keyword);
    const Token first = peek();
    using Kind = UserFunction::Kind;
    if (first.is(Keyword::internal)) {
        next();
        expect(Symbol::lparen, "after 'internal'");
        const Token at = peek();
        const int number = parse_int("as the number of the internal function", 0);
        expect(Symbol::rparen, "after the number of the internal function");
        const int arity = internal_function_arity(number);
        if (arity < 0) fail(at, fmt::format("POV-Ray 3.7 has no internal function {}", number));
        function->kind_ = Kind::internal;
        function->internal_number_ = number;
        function->parameter_count_ = arity;
    } else if (first.is(Keyword::pattern)) {
        next();
        function->kind_ = Kind::pattern;
        function->pattern_ = parse_function_pattern(*this, first);
    } else if (first.is(Keyword::pigment)) {
        next();
        function->kind_ = Kind::pigment;
        function->pigment_ = parse_pigment(*this, first);
        function->result_terms_ = 5;
    } else if (first.is(Keyword::transform)) {
        next();
        function->kind_ = Kind::transform;
        function->transform_ = parse_transform_block(first);
        function->result_terms_ = 3;
    } else if (first.is(Keyword::spline)) {
        next();
        function->kind_ = Kind::spline;
        function->spline_ = parse_spline(first);
        function->parameter_count_ = 1;
        function->result_terms_ = function->spline_->terms;
    } else {
        function->parameter_count_ = static_cast<int>(parameters.size());
        FunctionCompiler(*this, *function, parameters).compile();
        if (function->code_.empty()) fail_expected("the function's expression", first);
    }
    if (explicit_parameters && function->kind_ != Kind::expression &&
        function->kind_ != Kind::internal)
        fail(open, "a pattern, pigment, transform or spline function takes no parameter list");
    expect_close(keyword, open);
    return function;
}

Numeric Parser::call_function(const Token& name, const UserFunction& function) {
    const Token open =
        expect(Symbol::lparen, [&] { return fmt::format("after function '{}'", word(name)); });
    std::vector<double> arguments;
    if (!peek_is(Symbol::rparen)) {
        do {
            arguments.push_back(
                parse_float(fmt::format("as an argument of function '{}'", word(name))));
        } while (accept(Symbol::comma));
    }
    expect(Symbol::rparen, [&] {
        return fmt::format("to close the call of '{}' opened at {}", word(name),
                           location_of(open).str());
    });
    if (static_cast<int>(arguments.size()) != function.parameter_count())
        fail(name, fmt::format("function '{}' takes {} argument{}, found {}", word(name),
                               function.parameter_count(),
                               function.parameter_count() == 1 ? "" : "s", arguments.size()));
    try {
        return function.evaluate(arguments.data());
    } catch (const FunctionNotSupported& e) {
        fail_not_supported(name, e.what());
    }
}

}  // namespace rayset::tracer
