// POV-Ray's built-in constants, variables and functions (reference manual 3.3.1.5 to
// 3.3.1.9): float and vector functions here, strings and their functions below. rand() and
// seed() reproduce POV-Ray's own sequences (a 32-bit linear congruential generator, seen
// through its output) so that scenes scattering objects at random come out as in POV-Ray.
#include <algorithm>
#include <climits>
#include <cmath>
#include <ctime>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/printf.h>

#include "converters/rays/io.h"
#include "core/text_encoding.h"
#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/noise.h"
#include "tracer/scene_language/object_tree.h"
#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace fs = std::filesystem;

namespace {

constexpr double kEpsilon = 1e-10;

Keyword keyword_of(NameId name) {
    return is_keyword(name) ? static_cast<Keyword>(name) : Keyword::size_;
}

// POV-Ray converts a seed to a 32-bit int as C does on x86: values outside the range become
// INT_MIN.
uint32_t seed_state(double seed) {
    const double t = std::trunc(seed);
    const int32_t i = t >= -2147483648.0 && t <= 2147483647.0 ? static_cast<int32_t>(t) : INT32_MIN;
    return static_cast<uint32_t>(i);
}

// Days since 2000-01-01 00:00:00 UTC, POV-Ray's `now`.
double days_since_2000(std::chrono::system_clock::time_point when) {
    const double seconds = std::chrono::duration<double>(when.time_since_epoch()).count();
    return (seconds - 946684800.0) / 86400.0;
}

// C's printf with POV-Ray's str() conventions: a negative width pads with zeros, a negative
// precision is printf's default.
std::string format_float(double value, int width, int precision) {
    const bool zeros = width < 0;
    const int w = std::min(std::abs(width), 1000);
    if (precision < 0) return fmt::sprintf(zeros ? "%0*f" : "%*f", w, value);
    return fmt::sprintf(zeros ? "%0*.*f" : "%*.*f", w, std::min(precision, 100), value);
}

template <typename Entry, size_t N>
const Entry* find_entry(const Entry (&table)[N], Keyword keyword) {
    const Entry* entry = std::find_if(std::begin(table), std::end(table),
                                      [&](const Entry& e) { return e.keyword == keyword; });
    return entry == std::end(table) ? nullptr : entry;
}

}  // namespace

// The built-ins, one table entry each: constants and variables, float functions, the other
// numeric functions and the string functions. Nested in Parser for the state some of them read
// or change (random streams, identifiers, the start time that `now` counts from).
class Parser::Builtins {
public:
    class Call;
    struct Constant {
        Keyword keyword;
        Numeric value;
    };
    // The animation's clock and frames, the image size, the language version, the time.
    struct Variable {
        Keyword keyword;
        Numeric (*value)(const Parser& parser);
    };
    // A float of a float, refused outside its domain as POV-Ray's result would be meaningless.
    struct FloatFunction {
        Keyword keyword;
        double (*value)(double a);
        bool (*in_domain)(double a) = nullptr;  // null: every float
        const char* outside_domain = nullptr;
    };
    struct NumericFunction {
        Keyword keyword;
        Numeric (*call)(Call& call);
    };
    struct StringFunction {
        Keyword keyword;
        std::string (*call)(Call& call);
    };
    static const Constant kConstants[];
    static const Variable kVariables[];
    static const FloatFunction kFloatFunctions[];
    static const NumericFunction kNumericFunctions[];
    static const StringFunction kStringFunctions[];
    static Numeric evaluate(const FloatFunction& function, Call& call);

private:
    static Numeric bitwise(Call& call, long long (*combine)(long long a, long long b));
    static Numeric select(Call& call);
    static Numeric seed(Call& call);
    static Numeric rand(Call& call);
    static Numeric file_exists(Call& call);
    static ArrayRef array_argument(Call& call);
    static Numeric dimension_size(Call& call);
    static Numeric bounding_box_corner(Call& call, bool maximum);
    static Numeric inside(Call& call);
    static Numeric trace(Call& call);
    static std::string chr(Call& call);
    static std::string concat(Call& call);
    static std::string vstr(Call& call);
    static std::string substr(Call& call);
    static std::string change_case(Call& call, int (*change)(int c));
    static std::string datetime(Call& call);
};

// One call name(...) of a built-in function, from its '(' on: the arguments as the built-ins
// read them, with messages naming the function.
class Parser::Builtins::Call {
public:
    Call(Parser& parser, const Token& name)
        : parser(parser), name(name), open(parser.open_call(name)) {}

    void comma() { parser.call_comma(name); }
    bool accept_comma() { return parser.accept(Symbol::comma); }
    void close() { parser.close_call(name, open); }
    const std::string& word() const { return parser.word(name); }

    double float_argument() {
        const Token at = parser.peek();
        const Numeric n = parser.parse_expression();
        if (n.terms != 1)
            parser.fail(at, fmt::format("'{}' takes a float here, found a vector", word()));
        return n.v[0];
    }
    // A float truncated toward zero and clamped to int's range.
    int int_argument(const char* what) {
        const double value = parser.parse_float(fmt::format("as the {} of '{}'", what, word()));
        return static_cast<int>(std::clamp(std::trunc(value), -2147483648.0, 2147483647.0));
    }
    Vec3 vector_argument() {
        const Token at = parser.peek();
        const Numeric n = parser.parse_expression();
        if (n.terms > 3)
            parser.fail(at, fmt::format("'{}' takes a vector here, found a colour", word()));
        return n.promoted(3).vec3();
    }
    ObjectRef object_argument() {
        const Token at = parser.peek();
        if (const ObjectRef* object = parser.peek_declared<ObjectRef>()) {
            const ObjectRef held = *object;
            parser.next();
            return held;
        }
        parser.fail_identifier(at, fmt::format("an object identifier in '{}'", word()));
    }
    std::string string_argument() { return parser.parse_string(); }

    // The whole argument list of a function of one float, one vector or one string.
    double sole_float() {
        const double a = float_argument();
        close();
        return a;
    }
    Vec3 sole_vector() {
        const Vec3 a = vector_argument();
        close();
        return a;
    }
    std::string sole_string() {
        std::string s = string_argument();
        close();
        return s;
    }
    std::pair<double, double> two_floats() {
        const double a = float_argument();
        comma();
        const double b = float_argument();
        close();
        return {a, b};
    }
    // min, max and the bitwise functions: two floats or more.
    std::vector<double> at_least_two_floats() {
        std::vector<double> args{float_argument()};
        while (accept_comma()) args.push_back(float_argument());
        close();
        if (args.size() < 2)
            parser.fail(name, fmt::format("'{}' takes at least 2 arguments, found 1", word()));
        return args;
    }
    std::pair<Vec3, Vec3> two_vectors() {
        const Vec3 a = vector_argument();
        comma();
        const Vec3 b = vector_argument();
        close();
        return {a, b};
    }

    void domain(bool ok, const char* what) const {
        if (!ok)
            parser.fail(name, fmt::format("'{}': {} (POV-Ray would compute a meaningless number)",
                                          word(), what));
    }

    Parser& parser;
    const Token& name;
    const Token open;
};

const Parser::Builtins::Constant Parser::Builtins::kConstants[] = {
    {Keyword::pi, Numeric::scalar(kPi)},       {Keyword::true_, Numeric::scalar(1)},
    {Keyword::yes, Numeric::scalar(1)},        {Keyword::on, Numeric::scalar(1)},
    {Keyword::false_, Numeric::scalar(0)},     {Keyword::no, Numeric::scalar(0)},
    {Keyword::off, Numeric::scalar(0)},        {Keyword::x, Numeric::vector3({1, 0, 0})},
    {Keyword::y, Numeric::vector3({0, 1, 0})}, {Keyword::z, Numeric::vector3({0, 0, 1})},
    {Keyword::t, Numeric{{0, 0, 0, 1, 0}, 4}}, {Keyword::u, Numeric{{1, 0, 0, 0, 0}, 2}},
    {Keyword::v, Numeric{{0, 1, 0, 0, 0}, 2}},
};

const Parser::Builtins::Variable Parser::Builtins::kVariables[] = {
    {Keyword::clock, [](const Parser& p) { return Numeric::scalar(p.options_.animation.clock); }},
    {Keyword::clock_delta,
     [](const Parser& p) { return Numeric::scalar(p.options_.animation.clock_delta); }},
    {Keyword::clock_on,
     [](const Parser& p) { return Numeric::scalar(p.options_.animation.clock_on ? 1 : 0); }},
    {Keyword::frame_number,
     [](const Parser& p) { return Numeric::scalar(p.options_.animation.frame_number); }},
    {Keyword::initial_frame,
     [](const Parser& p) { return Numeric::scalar(p.options_.animation.initial_frame); }},
    {Keyword::final_frame,
     [](const Parser& p) { return Numeric::scalar(p.options_.animation.final_frame); }},
    {Keyword::initial_clock,
     [](const Parser& p) { return Numeric::scalar(p.options_.animation.initial_clock); }},
    {Keyword::final_clock,
     [](const Parser& p) { return Numeric::scalar(p.options_.animation.final_clock); }},
    {Keyword::image_width,
     [](const Parser& p) { return Numeric::scalar(p.options_.animation.image_width); }},
    {Keyword::image_height,
     [](const Parser& p) { return Numeric::scalar(p.options_.animation.image_height); }},
    {Keyword::version, [](const Parser& p) { return Numeric::scalar(p.version_); }},
    {Keyword::now, [](const Parser& p) { return Numeric::scalar(days_since_2000(p.start_time_)); }},
};

const Parser::Builtins::FloatFunction Parser::Builtins::kFloatFunctions[] = {
    {Keyword::abs, [](double a) { return std::fabs(a); }},
    {Keyword::ceil, [](double a) { return std::ceil(a); }},
    {Keyword::floor, [](double a) { return std::floor(a); }},
    {Keyword::int_, [](double a) { return std::trunc(a); }},
    {Keyword::cos, [](double a) { return std::cos(a); }},
    {Keyword::sin, [](double a) { return std::sin(a); }},
    {Keyword::tan, [](double a) { return std::tan(a); }},
    {Keyword::cosh, [](double a) { return std::cosh(a); }},
    {Keyword::sinh, [](double a) { return std::sinh(a); }},
    {Keyword::tanh, [](double a) { return std::tanh(a); }},
    {Keyword::atan, [](double a) { return std::atan(a); }},
    {Keyword::asinh, [](double a) { return std::asinh(a); }},
    {Keyword::exp, [](double a) { return std::exp(a); }},
    {Keyword::degrees, [](double a) { return a * 180.0 / kPi; }},
    {Keyword::radians, [](double a) { return a * kPi / 180.0; }},
    {Keyword::asin, [](double a) { return std::asin(a); },
     [](double a) { return a >= -1 && a <= 1; }, "argument outside [-1, 1]"},
    {Keyword::acos, [](double a) { return std::acos(a); },
     [](double a) { return a >= -1 && a <= 1; }, "argument outside [-1, 1]"},
    {Keyword::acosh, [](double a) { return std::acosh(a); }, [](double a) { return a >= 1; },
     "argument below 1"},
    {Keyword::atanh, [](double a) { return std::atanh(a); },
     [](double a) { return a > -1 && a < 1; }, "argument outside (-1, 1)"},
    {Keyword::sqrt, [](double a) { return std::sqrt(a); }, [](double a) { return a >= 0; },
     "negative argument"},
    {Keyword::ln, [](double a) { return std::log(a); }, [](double a) { return a > 0; },
     "argument not positive"},
    {Keyword::log, [](double a) { return std::log10(a); }, [](double a) { return a > 0; },
     "argument not positive"},
};

const Parser::Builtins::NumericFunction Parser::Builtins::kNumericFunctions[] = {
    {Keyword::atan2,
     [](Call& call) {
         const auto [a, b] = call.two_floats();
         return Numeric::scalar(std::atan2(a, b));
     }},
    {Keyword::pow,
     [](Call& call) {
         const auto [a, b] = call.two_floats();
         call.domain(!(a < 0 && b != std::trunc(b)), "a negative number to a non-integer power");
         call.domain(!(a == 0 && b < 0), "zero to a negative power");
         return Numeric::scalar(std::pow(a, b));
     }},
    {Keyword::mod,
     [](Call& call) {
         const auto [a, b] = call.two_floats();
         call.domain(b != 0, "division by zero");
         return Numeric::scalar(std::fmod(a, b));
     }},
    {Keyword::div,
     [](Call& call) {
         const auto [a, b] = call.two_floats();
         call.domain(b != 0, "division by zero");
         return Numeric::scalar(std::trunc(a / b));
     }},
    {Keyword::min,
     [](Call& call) {
         const std::vector<double> args = call.at_least_two_floats();
         return Numeric::scalar(*std::min_element(args.begin(), args.end()));
     }},
    {Keyword::max,
     [](Call& call) {
         const std::vector<double> args = call.at_least_two_floats();
         return Numeric::scalar(*std::max_element(args.begin(), args.end()));
     }},
    {Keyword::bitwise_and,
     [](Call& call) { return bitwise(call, [](long long a, long long b) { return a & b; }); }},
    {Keyword::bitwise_or,
     [](Call& call) { return bitwise(call, [](long long a, long long b) { return a | b; }); }},
    {Keyword::bitwise_xor,
     [](Call& call) { return bitwise(call, [](long long a, long long b) { return a ^ b; }); }},
    {Keyword::select, select},
    {Keyword::seed, seed},
    {Keyword::rand, rand},
    {Keyword::asc,
     [](Call& call) {
         const std::string s = call.sole_string();
         return Numeric::scalar(s.empty() ? 0 : static_cast<unsigned char>(s[0]));
     }},
    {Keyword::strlen,
     [](Call& call) { return Numeric::scalar(static_cast<double>(call.sole_string().size())); }},
    {Keyword::val,
     [](Call& call) { return Numeric::scalar(std::strtod(call.sole_string().c_str(), nullptr)); }},
    {Keyword::file_exists, file_exists},
    {Keyword::strcmp,
     [](Call& call) {
         const std::string a = call.string_argument();
         call.comma();
         const std::string b = call.string_argument();
         call.close();
         const int order = a.compare(b);
         return Numeric::scalar(order < 0 ? -1 : order > 0 ? 1 : 0);
     }},
    {Keyword::defined,
     [](Call& call) {
         const bool defined = call.parser.is_defined(call.name);
         call.close();
         return Numeric::scalar(defined ? 1 : 0);
     }},
    {Keyword::dimensions,
     [](Call& call) {
         const ArrayRef array = array_argument(call);
         call.close();
         return Numeric::scalar(static_cast<double>(array->sizes.size()));
     }},
    {Keyword::dimension_size, dimension_size},
    {Keyword::vdot,
     [](Call& call) {
         const auto [a, b] = call.two_vectors();
         return Numeric::scalar(dot(a, b));
     }},
    {Keyword::vcross,
     [](Call& call) {
         const auto [a, b] = call.two_vectors();
         return Numeric::vector3(cross(a, b));
     }},
    {Keyword::vrotate,
     [](Call& call) {
         const auto [a, b] = call.two_vectors();
         return Numeric::vector3(pov_rotation(b).vector(a));
     }},
    {Keyword::vlength, [](Call& call) { return Numeric::scalar(length(call.sole_vector())); }},
    {Keyword::vnormalize,
     [](Call& call) {
         const Vec3 a = call.sole_vector();
         call.domain(length(a) > 0, "zero-length vector");
         return Numeric::vector3(normalized(a));
     }},
    {Keyword::vaxis_rotate,
     [](Call& call) {
         const Vec3 a = call.vector_argument();
         call.comma();
         const Vec3 axis = call.vector_argument();
         call.comma();
         const double degrees = call.float_argument();
         call.close();
         call.domain(length(axis) > 0, "zero-length axis");
         return Numeric::vector3(axis_rotation(axis, degrees).vector(a));
     }},
    {Keyword::min_extent, [](Call& call) { return bounding_box_corner(call, false); }},
    {Keyword::max_extent, [](Call& call) { return bounding_box_corner(call, true); }},
    {Keyword::inside, inside},
    {Keyword::trace, trace},
    {Keyword::vturbulence,
     [](Call& call) {  // vturbulence(Lambda, Omega, Octaves, A)
         const double lambda = call.float_argument();
         call.comma();
         const double omega = call.float_argument();
         call.comma();
         const int octaves = call.int_argument("octaves");
         call.comma();
         const Vec3 point = call.vector_argument();
         call.close();
         return Numeric::vector3(vector_turbulence(point, octaves, omega, lambda));
     }},
};

Numeric Parser::Builtins::evaluate(const FloatFunction& function, Call& call) {
    const double a = call.sole_float();
    if (function.in_domain) call.domain(function.in_domain(a), function.outside_domain);
    return Numeric::scalar(function.value(a));
}

// The floats are truncated to 64-bit integers, combined, and the result cut to an int.
Numeric Parser::Builtins::bitwise(Call& call, long long (*combine)(long long a, long long b)) {
    const std::vector<double> args = call.at_least_two_floats();
    auto as_int = [](double a) {
        return static_cast<long long>(std::clamp(std::trunc(a), -9.2e18, 9.2e18));
    };
    long long r = as_int(args[0]);
    for (size_t i = 1; i < args.size(); ++i) r = combine(r, as_int(args[i]));
    return Numeric::scalar(static_cast<double>(static_cast<int>(r)));
}

Numeric Parser::Builtins::select(Call& call) {
    const double a = call.float_argument();
    call.comma();
    const Numeric b = call.parser.parse_expression();
    call.comma();
    const Numeric c = call.parser.parse_expression();
    if (call.accept_comma()) {
        const Numeric d = call.parser.parse_expression();
        call.close();
        return a < 0 ? b : a == 0 ? c : d;
    }
    call.close();
    return a < 0 ? b : c;
}

Numeric Parser::Builtins::seed(Call& call) {
    const double s = call.sole_float();
    call.parser.random_streams_.push_back({seed_state(s)});
    return Numeric::scalar(static_cast<double>(call.parser.random_streams_.size() - 1));
}

Numeric Parser::Builtins::rand(Call& call) {
    const Token at = call.parser.peek();
    const double s = call.sole_float();
    std::vector<RandomStream>& streams = call.parser.random_streams_;
    const double index = std::trunc(s);
    if (!(index >= 0 && index < static_cast<double>(streams.size())))
        call.parser.fail(at,
                         fmt::format("rand({}): no such random stream (make one with seed())", s));
    RandomStream& stream = streams[static_cast<size_t>(index)];
    stream.state = stream.state * 1812433253u + 12345u;
    return Numeric::scalar(static_cast<double>(stream.state) / 4294967295.0);
}

Numeric Parser::Builtins::file_exists(Call& call) {
    const std::string s = call.sole_string();
    try {
        call.parser.resolve_file(s, call.name, "file");
        return Numeric::scalar(1);
    } catch (const SceneError&) {
        return Numeric::scalar(0);
    }
}

// An array identifier, or an element of an array of arrays.
ArrayRef Parser::Builtins::array_argument(Call& call) {
    Parser& parser = call.parser;
    const Token at = parser.peek();
    const ArrayRef* array = parser.peek_declared<ArrayRef>();
    if (!array) parser.fail_identifier(at, fmt::format("an array identifier in '{}'", call.word()));
    ArrayRef held = *array;
    parser.next();
    while (parser.peek_is(Symbol::lbracket)) {
        const Value element = *parser.array_element(at, *held, false);
        if (!std::holds_alternative<ArrayRef>(element))
            parser.fail(at, fmt::format("'{}': the element is {}, not an array", call.word(),
                                        type_name(element)));
        held = std::get<ArrayRef>(element);
    }
    return held;
}

Numeric Parser::Builtins::dimension_size(Call& call) {
    const ArrayRef array = array_argument(call);
    call.comma();
    const Token dimension_at = call.parser.peek();
    const int dimension = call.int_argument("dimension");
    call.close();
    const size_t dimensions = array->sizes.size();
    if (dimension < 1 || dimension > static_cast<int>(dimensions))
        call.parser.fail(
            dimension_at,
            fmt::format("dimension_size: the array has {} dimension{}, asked for dimension {}",
                        dimensions, dimensions == 1 ? "" : "s", dimension));
    return Numeric::scalar(array->sizes[static_cast<size_t>(dimension - 1)]);
}

Numeric Parser::Builtins::bounding_box_corner(Call& call, bool maximum) {
    const ObjectRef object = call.object_argument();
    call.close();
    Vec3 minimum_corner, maximum_corner;
    if (!object_bounding_box(*object, minimum_corner, maximum_corner))
        call.parser.fail_not_supported(call.name,
                                       fmt::format("'{}' of this kind of object", call.word()));
    return Numeric::vector3(maximum ? maximum_corner : minimum_corner);
}

Numeric Parser::Builtins::inside(Call& call) {
    const ObjectRef object = call.object_argument();
    call.comma();
    const Vec3 point = call.vector_argument();
    call.close();
    bool inside = false;
    if (!object_inside(*object, point, inside))
        call.parser.fail_not_supported(call.name, "'inside' of this kind of object");
    return Numeric::scalar(inside ? 1 : 0);
}

// trace(object, origin, direction [, normal]): the identifier after the third comma receives the
// normal at the hit, or <0,0,0> when the ray misses.
Numeric Parser::Builtins::trace(Call& call) {
    Parser& parser = call.parser;
    const ObjectRef object = call.object_argument();
    call.comma();
    const Vec3 origin = call.vector_argument();
    call.comma();
    const Vec3 direction = call.vector_argument();
    SymbolRef normal_symbol;
    if (call.accept_comma()) {
        const Token at = parser.raw_peek();
        const NameId normal = parser.next_raw_identifier("to receive the normal in 'trace'");
        parser.assign(at, normal, Numeric::vector3({0, 0, 0}), false);
        normal_symbol = parser.lookup(normal);
    }
    call.close();
    Vec3 hit, normal;
    bool found = false;
    if (!object_trace(*object, origin, direction, hit, normal, found))
        parser.fail_not_supported(call.name, "'trace' of this kind of object");
    if (normal_symbol) normal_symbol->value = Numeric::vector3(found ? normal : Vec3{0, 0, 0});
    return Numeric::vector3(found ? hit : Vec3{0, 0, 0});
}

bool Parser::is_numeric_builtin(NameId name) const {
    const Keyword keyword = keyword_of(name);
    return find_entry(Builtins::kConstants, keyword) || find_entry(Builtins::kVariables, keyword) ||
           find_entry(Builtins::kFloatFunctions, keyword) ||
           find_entry(Builtins::kNumericFunctions, keyword);
}

std::optional<Numeric> Parser::builtin_constant(const Token& name) const {
    const Keyword keyword = keyword_of(name.name);
    if (const Builtins::Constant* constant = find_entry(Builtins::kConstants, keyword))
        return constant->value;
    if (const Builtins::Variable* variable = find_entry(Builtins::kVariables, keyword))
        return variable->value(*this);
    return std::nullopt;
}

Numeric Parser::parse_builtin_numeric(const Token& name) {
    if (const std::optional<Numeric> constant = builtin_constant(name)) return *constant;
    Builtins::Call call(*this, name);
    const Keyword keyword = keyword_of(name.name);
    if (const Builtins::FloatFunction* function = find_entry(Builtins::kFloatFunctions, keyword))
        return Builtins::evaluate(*function, call);
    if (const Builtins::NumericFunction* function =
            find_entry(Builtins::kNumericFunctions, keyword))
        return function->call(call);
    fail_not_supported(name, fmt::format("'{}'", word(name)));
}

const Parser::Builtins::StringFunction Parser::Builtins::kStringFunctions[] = {
    {Keyword::chr, chr},
    {Keyword::concat, concat},
    {Keyword::str,
     [](Call& call) {
         const double value = call.parser.parse_float("as the value of 'str'");
         call.comma();
         const int width = call.int_argument("width");
         call.comma();
         const int precision = call.int_argument("precision");
         call.close();
         return format_float(value, width, precision);
     }},
    {Keyword::vstr, vstr},
    {Keyword::substr, substr},
    {Keyword::strupr,
     [](Call& call) { return change_case(call, [](int c) { return std::toupper(c); }); }},
    {Keyword::strlwr,
     [](Call& call) { return change_case(call, [](int c) { return std::tolower(c); }); }},
    {Keyword::datetime, datetime},
};

bool Parser::starts_string(const Token& token) {
    if (token.kind == TokenKind::string) return true;
    if (token.kind != TokenKind::word) return false;
    const Keyword keyword = keyword_of(token.name);
    if (keyword == Keyword::input_file_name || find_entry(Builtins::kStringFunctions, keyword))
        return true;
    if (keyword != Keyword::size_) return false;  // any other keyword
    const SymbolRef symbol = lookup(token.name);
    if (!symbol) return false;
    if (const ArrayRef* array = std::get_if<ArrayRef>(&symbol->value))
        return (*array)->element_type == Value(std::string()).index();
    return std::holds_alternative<std::string>(symbol->value);
}

std::string Parser::parse_string() {
    const Token token = peek();
    if (token.kind == TokenKind::string) {
        next();
        return string_literal(token);
    }
    if (token.kind == TokenKind::word && is_keyword(token.name)) {
        next();
        std::string text = parse_builtin_string(token);
        if (static_cast<long>(text.size()) > options_.max_string_length)
            fail(token, fmt::format("string limit: a string of more than {} bytes "
                                    "(ParseOptions::max_string_length)",
                                    options_.max_string_length));
        return text;
    }
    if (token.kind == TokenKind::word) {
        if (const Value* value = peek_value()) {
            if (const std::string* s = std::get_if<std::string>(value)) {
                std::string text = *s;
                next();
                return text;
            }
            if (const ArrayRef* array = std::get_if<ArrayRef>(value)) {
                const ArrayRef held = *array;
                next();
                const Value element = *array_element(token, *held, false);
                if (const std::string* s = std::get_if<std::string>(&element)) return *s;
                fail(token,
                     fmt::format("wrong type: the elements of '{}' are {}, expected a string",
                                 word(token), type_name(element)));
            }
        }
    }
    fail_identifier(token, "a string");
}

std::string Parser::Builtins::chr(Call& call) {
    const Token at = call.parser.peek();
    const int code = call.int_argument("character code");
    call.close();
    if (code < 0 || code > 0x10FFFF)
        call.parser.fail(at, fmt::format("chr({}): not a character code", code));
    std::string out;
    append_utf8(static_cast<char32_t>(code), out);
    return out;
}

std::string Parser::Builtins::concat(Call& call) {
    const long limit = call.parser.options_.max_string_length;
    std::string out = call.string_argument();
    while (call.accept_comma()) {
        out += call.string_argument();
        if (static_cast<long>(out.size()) > limit)
            call.parser.fail(call.name, fmt::format("string limit: a string of more than {} bytes "
                                                    "(ParseOptions::max_string_length)",
                                                    limit));
    }
    call.close();
    return out;
}

std::string Parser::Builtins::vstr(Call& call) {
    const int requested = call.int_argument("number of terms");
    call.comma();
    const Token at = call.parser.peek();
    const Numeric vector = call.parser.parse_expression();
    call.comma();
    const std::string separator = call.string_argument();
    call.comma();
    const int width = call.int_argument("width");
    call.comma();
    const int precision = call.int_argument("precision");
    call.close();
    const int terms = std::clamp(requested, 2, 5);
    if (vector.terms > terms)
        call.parser.fail(at,
                         fmt::format("vstr: the vector has {} terms, more than the {} asked for",
                                     vector.terms, terms));
    std::string out;
    for (int i = 0; i < terms; ++i) {
        // Missing terms are zeros, even for a float (POV-Ray's behaviour, not its manual's).
        const double term = i < vector.terms ? vector.v[i] : 0.0;
        out += (i ? separator : "") + format_float(term, width, precision);
    }
    return out;
}

std::string Parser::Builtins::substr(Call& call) {
    const std::string s = call.string_argument();
    call.comma();
    const Token at = call.parser.peek();
    const int position = call.int_argument("position");
    call.comma();
    const int count = call.int_argument("length");
    call.close();
    if (position < 1 || count < 0 || static_cast<size_t>(position - 1 + count) > s.size())
        call.parser.fail(at, fmt::format("substr: characters {} to {} of a string of {}", position,
                                         position + count - 1, s.size()));
    return s.substr(static_cast<size_t>(position - 1), static_cast<size_t>(count));
}

// strupr and strlwr: byte by byte, in the C locale's sense of letters.
std::string Parser::Builtins::change_case(Call& call, int (*change)(int c)) {
    std::string s = call.sole_string();
    for (char& c : s) c = static_cast<char>(change(static_cast<unsigned char>(c)));
    return s;
}

std::string Parser::Builtins::datetime(Call& call) {
    const double days = call.parser.parse_float("as the time of 'datetime' (days since 2000)");
    std::string format = "%Y-%m-%d %H:%M:%SZ";
    if (call.accept_comma()) format = call.string_argument();
    call.close();
    const std::time_t seconds = static_cast<std::time_t>(std::floor(946684800.0 + days * 86400.0));
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char buffer[512];
    const size_t length = std::strftime(buffer, sizeof buffer, format.c_str(), &utc);
    return std::string(buffer, length);
}

std::string Parser::parse_builtin_string(const Token& name) {
    const Keyword keyword = keyword_of(name.name);
    if (keyword == Keyword::input_file_name)
        return fs::path(files_.front().source->path).filename().string();
    const Builtins::StringFunction* function = find_entry(Builtins::kStringFunctions, keyword);
    if (!function) fail_identifier(name, "a string");
    Builtins::Call call(*this, name);
    return function->call(call);
}

}  // namespace rayset::tracer
