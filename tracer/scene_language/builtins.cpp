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

#include "converters/io.h"
#include "tracer/scene_language/grammar.h"
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

// The keywords that start a numeric expression: constants, built-in variables and functions.
constexpr Keyword kNumericBuiltins[] = {Keyword::pi,
                                        Keyword::true_,
                                        Keyword::false_,
                                        Keyword::yes,
                                        Keyword::no,
                                        Keyword::on,
                                        Keyword::off,
                                        Keyword::x,
                                        Keyword::y,
                                        Keyword::z,
                                        Keyword::t,
                                        Keyword::u,
                                        Keyword::v,
                                        Keyword::clock,
                                        Keyword::clock_delta,
                                        Keyword::clock_on,
                                        Keyword::frame_number,
                                        Keyword::initial_frame,
                                        Keyword::final_frame,
                                        Keyword::initial_clock,
                                        Keyword::final_clock,
                                        Keyword::image_width,
                                        Keyword::image_height,
                                        Keyword::version,
                                        Keyword::now,
                                        Keyword::abs,
                                        Keyword::acos,
                                        Keyword::acosh,
                                        Keyword::asc,
                                        Keyword::asin,
                                        Keyword::asinh,
                                        Keyword::atan,
                                        Keyword::atan2,
                                        Keyword::atanh,
                                        Keyword::bitwise_and,
                                        Keyword::bitwise_or,
                                        Keyword::bitwise_xor,
                                        Keyword::ceil,
                                        Keyword::cos,
                                        Keyword::cosh,
                                        Keyword::defined,
                                        Keyword::degrees,
                                        Keyword::dimensions,
                                        Keyword::dimension_size,
                                        Keyword::div,
                                        Keyword::exp,
                                        Keyword::file_exists,
                                        Keyword::floor,
                                        Keyword::inside,
                                        Keyword::int_,
                                        Keyword::ln,
                                        Keyword::log,
                                        Keyword::max,
                                        Keyword::min,
                                        Keyword::mod,
                                        Keyword::pow,
                                        Keyword::radians,
                                        Keyword::rand,
                                        Keyword::seed,
                                        Keyword::select,
                                        Keyword::sin,
                                        Keyword::sinh,
                                        Keyword::sqrt,
                                        Keyword::strcmp,
                                        Keyword::strlen,
                                        Keyword::tan,
                                        Keyword::tanh,
                                        Keyword::val,
                                        Keyword::vdot,
                                        Keyword::vlength,
                                        Keyword::min_extent,
                                        Keyword::max_extent,
                                        Keyword::trace,
                                        Keyword::vaxis_rotate,
                                        Keyword::vcross,
                                        Keyword::vrotate,
                                        Keyword::vnormalize,
                                        Keyword::vturbulence};

// The keywords that start a string expression.
constexpr Keyword kStringBuiltins[] = {Keyword::chr,    Keyword::concat, Keyword::datetime,
                                       Keyword::str,    Keyword::strlwr, Keyword::strupr,
                                       Keyword::substr, Keyword::vstr,   Keyword::input_file_name};

template <size_t N>
bool one_of(Keyword keyword, const Keyword (&set)[N]) {
    return std::find(std::begin(set), std::end(set), keyword) != std::end(set);
}

}  // namespace

bool Parser::is_numeric_builtin(NameId name) const {
    return one_of(keyword_of(name), kNumericBuiltins);
}

std::optional<Numeric> Parser::builtin_constant(const Token& name) const {
    const AnimationSettings& animation = options_.animation;
    switch (keyword_of(name.name)) {
        case Keyword::pi: return Numeric::scalar(3.1415926535897932384626);
        case Keyword::true_:
        case Keyword::yes:
        case Keyword::on: return Numeric::scalar(1);
        case Keyword::false_:
        case Keyword::no:
        case Keyword::off: return Numeric::scalar(0);
        case Keyword::x: return Numeric::vector3({1, 0, 0});
        case Keyword::y: return Numeric::vector3({0, 1, 0});
        case Keyword::z: return Numeric::vector3({0, 0, 1});
        case Keyword::t: return Numeric{{0, 0, 0, 1, 0}, 4};
        case Keyword::u: return Numeric{{1, 0, 0, 0, 0}, 2};
        case Keyword::v: return Numeric{{0, 1, 0, 0, 0}, 2};
        case Keyword::clock: return Numeric::scalar(animation.clock);
        case Keyword::clock_delta: return Numeric::scalar(animation.clock_delta);
        case Keyword::clock_on: return Numeric::scalar(animation.clock_on ? 1 : 0);
        case Keyword::frame_number: return Numeric::scalar(animation.frame_number);
        case Keyword::initial_frame: return Numeric::scalar(animation.initial_frame);
        case Keyword::final_frame: return Numeric::scalar(animation.final_frame);
        case Keyword::initial_clock: return Numeric::scalar(animation.initial_clock);
        case Keyword::final_clock: return Numeric::scalar(animation.final_clock);
        case Keyword::image_width: return Numeric::scalar(animation.image_width);
        case Keyword::image_height: return Numeric::scalar(animation.image_height);
        case Keyword::version: return Numeric::scalar(version_);
        case Keyword::now: return Numeric::scalar(days_since_2000(start_time_));
        default: return std::nullopt;
    }
}

Numeric Parser::parse_builtin_numeric(const Token& name) {
    const Keyword k = keyword_of(name.name);
    if (const std::optional<Numeric> constant = builtin_constant(name)) return *constant;

    const Token open = open_call(name);
    auto close = [&] { close_call(name, open); };
    auto comma = [&] { call_comma(name); };
    auto float_arg = [&]() {
        const Token at = peek();
        const Numeric n = parse_expression();
        if (n.terms != 1)
            fail(at, fmt::format("'{}' takes a float here, found a vector", word(name)));
        return n.v[0];
    };
    auto vector_arg = [&]() {
        const Token at = peek();
        const Numeric n = parse_expression();
        if (n.terms > 3)
            fail(at, fmt::format("'{}' takes a vector here, found a colour", word(name)));
        return n.promoted(3).vec3();
    };
    auto domain = [&](bool ok, const char* what) {
        if (!ok)
            fail(name, fmt::format("'{}': {} (POV-Ray would compute a meaningless number)",
                                   word(name), what));
    };
    auto object_arg = [&]() -> ObjectRef {
        const Token at = peek();
        if (const ObjectRef* object = peek_declared<ObjectRef>()) {
            const ObjectRef held = *object;
            next();
            return held;
        }
        fail_identifier(at, fmt::format("an object identifier in '{}'", word(name)));
    };
    auto one_float = [&](double (*f)(double)) {
        const double a = float_arg();
        close();
        return Numeric::scalar(f(a));
    };

    switch (k) {
        case Keyword::abs: return one_float([](double a) { return std::fabs(a); });
        case Keyword::ceil: return one_float([](double a) { return std::ceil(a); });
        case Keyword::floor: return one_float([](double a) { return std::floor(a); });
        case Keyword::int_: return one_float([](double a) { return std::trunc(a); });
        case Keyword::cos: return one_float([](double a) { return std::cos(a); });
        case Keyword::sin: return one_float([](double a) { return std::sin(a); });
        case Keyword::tan: return one_float([](double a) { return std::tan(a); });
        case Keyword::cosh: return one_float([](double a) { return std::cosh(a); });
        case Keyword::sinh: return one_float([](double a) { return std::sinh(a); });
        case Keyword::tanh: return one_float([](double a) { return std::tanh(a); });
        case Keyword::atan: return one_float([](double a) { return std::atan(a); });
        case Keyword::asinh: return one_float([](double a) { return std::asinh(a); });
        case Keyword::exp: return one_float([](double a) { return std::exp(a); });
        case Keyword::degrees:
            return one_float([](double a) { return a * 180.0 / 3.1415926535897932384626; });
        case Keyword::radians:
            return one_float([](double a) { return a * 3.1415926535897932384626 / 180.0; });
        case Keyword::asin:
        case Keyword::acos: {
            const double a = float_arg();
            close();
            domain(a >= -1 && a <= 1, "argument outside [-1, 1]");
            return Numeric::scalar(k == Keyword::asin ? std::asin(a) : std::acos(a));
        }
        case Keyword::acosh: {
            const double a = float_arg();
            close();
            domain(a >= 1, "argument below 1");
            return Numeric::scalar(std::acosh(a));
        }
        case Keyword::atanh: {
            const double a = float_arg();
            close();
            domain(a > -1 && a < 1, "argument outside (-1, 1)");
            return Numeric::scalar(std::atanh(a));
        }
        case Keyword::sqrt: {
            const double a = float_arg();
            close();
            domain(a >= 0, "negative argument");
            return Numeric::scalar(std::sqrt(a));
        }
        case Keyword::ln:
        case Keyword::log: {
            const double a = float_arg();
            close();
            domain(a > 0, "argument not positive");
            return Numeric::scalar(k == Keyword::log ? std::log10(a) : std::log(a));
        }
        case Keyword::atan2:
        case Keyword::pow:
        case Keyword::mod:
        case Keyword::div: {
            const double a = float_arg();
            comma();
            const double b = float_arg();
            close();
            if (k == Keyword::atan2) return Numeric::scalar(std::atan2(a, b));
            if (k == Keyword::pow) {
                domain(!(a < 0 && b != std::trunc(b)), "a negative number to a non-integer power");
                domain(!(a == 0 && b < 0), "zero to a negative power");
                return Numeric::scalar(std::pow(a, b));
            }
            domain(b != 0, "division by zero");
            return Numeric::scalar(k == Keyword::mod ? std::fmod(a, b) : std::trunc(a / b));
        }
        case Keyword::min:
        case Keyword::max:
        case Keyword::bitwise_and:
        case Keyword::bitwise_or:
        case Keyword::bitwise_xor: {
            std::vector<double> args{float_arg()};
            while (accept(Symbol::comma)) args.push_back(float_arg());
            close();
            if (args.size() < 2)
                fail(name, fmt::format("'{}' takes at least 2 arguments, found 1", word(name)));
            if (k == Keyword::min)
                return Numeric::scalar(*std::min_element(args.begin(), args.end()));
            if (k == Keyword::max)
                return Numeric::scalar(*std::max_element(args.begin(), args.end()));
            auto as_int = [](double a) {
                return static_cast<long long>(std::clamp(std::trunc(a), -9.2e18, 9.2e18));
            };
            long long r = as_int(args[0]);
            for (size_t i = 1; i < args.size(); ++i) {
                const long long b = as_int(args[i]);
                r = k == Keyword::bitwise_and  ? (r & b)
                    : k == Keyword::bitwise_or ? (r | b)
                                               : (r ^ b);
            }
            return Numeric::scalar(static_cast<double>(static_cast<int>(r)));
        }
        case Keyword::select: {
            const double a = float_arg();
            comma();
            const Numeric b = parse_expression();
            comma();
            const Numeric c = parse_expression();
            if (accept(Symbol::comma)) {
                const Numeric d = parse_expression();
                close();
                return a < 0 ? b : a == 0 ? c : d;
            }
            close();
            return a < 0 ? b : c;
        }
        case Keyword::seed: {
            const double s = float_arg();
            close();
            random_streams_.push_back({seed_state(s)});
            return Numeric::scalar(static_cast<double>(random_streams_.size() - 1));
        }
        case Keyword::rand: {
            const Token at = peek();
            const double s = float_arg();
            close();
            const double index = std::trunc(s);
            if (!(index >= 0 && index < static_cast<double>(random_streams_.size())))
                fail(at, fmt::format("rand({}): no such random stream (make one with seed())", s));
            RandomStream& stream = random_streams_[static_cast<size_t>(index)];
            stream.state = stream.state * 1812433253u + 12345u;
            return Numeric::scalar(static_cast<double>(stream.state) / 4294967295.0);
        }
        case Keyword::asc:
        case Keyword::strlen:
        case Keyword::val:
        case Keyword::file_exists: {
            const std::string s = parse_string();
            close();
            if (k == Keyword::asc)
                return Numeric::scalar(s.empty() ? 0 : static_cast<unsigned char>(s[0]));
            if (k == Keyword::strlen) return Numeric::scalar(static_cast<double>(s.size()));
            if (k == Keyword::val) return Numeric::scalar(std::strtod(s.c_str(), nullptr));
            try {
                resolve_file(s, name, "file");
                return Numeric::scalar(1);
            } catch (const SceneError&) {
                return Numeric::scalar(0);
            }
        }
        case Keyword::strcmp: {
            const std::string a = parse_string();
            comma();
            const std::string b = parse_string();
            close();
            const int order = a.compare(b);
            return Numeric::scalar(order < 0 ? -1 : order > 0 ? 1 : 0);
        }
        case Keyword::defined: {
            const bool defined = is_defined(name);
            close();
            return Numeric::scalar(defined ? 1 : 0);
        }
        case Keyword::dimensions:
        case Keyword::dimension_size: {
            // An array identifier, or an element of an array of arrays.
            const Token at = peek();
            const ArrayRef* array = peek_declared<ArrayRef>();
            if (!array) fail_identifier(at, fmt::format("an array identifier in '{}'", word(name)));
            ArrayRef held = *array;
            next();
            while (peek_is(Symbol::lbracket)) {
                const Value element = *array_element(at, *held, false);
                if (!std::holds_alternative<ArrayRef>(element))
                    fail(at, fmt::format("'{}': the element is {}, not an array", word(name),
                                         type_name(element)));
                held = std::get<ArrayRef>(element);
            }
            if (k == Keyword::dimensions) {
                close();
                return Numeric::scalar(static_cast<double>(held->sizes.size()));
            }
            comma();
            const Token dimension_at = peek();
            const int dimension = static_cast<int>(float_arg());
            close();
            if (dimension < 1 || dimension > static_cast<int>(held->sizes.size()))
                fail(dimension_at,
                     fmt::format(
                         "dimension_size: the array has {} dimension{}, asked for dimension {}",
                         held->sizes.size(), held->sizes.size() == 1 ? "" : "s", dimension));
            return Numeric::scalar(held->sizes[static_cast<size_t>(dimension - 1)]);
        }
        case Keyword::vdot:
        case Keyword::vcross:
        case Keyword::vrotate: {
            const Vec3 a = vector_arg();
            comma();
            const Vec3 b = vector_arg();
            close();
            if (k == Keyword::vdot) return Numeric::scalar(dot(a, b));
            if (k == Keyword::vcross) return Numeric::vector3(cross(a, b));
            return Numeric::vector3(pov_rotation(b).vector(a));
        }
        case Keyword::vlength:
        case Keyword::vnormalize: {
            const Vec3 a = vector_arg();
            close();
            if (k == Keyword::vlength) return Numeric::scalar(length(a));
            domain(length(a) > 0, "zero-length vector");
            return Numeric::vector3(normalized(a));
        }
        case Keyword::vaxis_rotate: {
            const Vec3 a = vector_arg();
            comma();
            const Vec3 axis = vector_arg();
            comma();
            const double degrees = float_arg();
            close();
            domain(length(axis) > 0, "zero-length axis");
            return Numeric::vector3(axis_rotation(axis, degrees).vector(a));
        }
        case Keyword::min_extent:
        case Keyword::max_extent: {
            const ObjectRef object = object_arg();
            close();
            Vec3 minimum, maximum;
            if (!object_bounding_box(*object, minimum, maximum))
                fail_not_supported(name, fmt::format("'{}' of this kind of object", word(name)));
            return Numeric::vector3(k == Keyword::min_extent ? minimum : maximum);
        }
        case Keyword::inside: {
            const ObjectRef object = object_arg();
            comma();
            const Vec3 point = vector_arg();
            close();
            bool inside = false;
            if (!object_inside(*object, point, inside))
                fail_not_supported(name, "'inside' of this kind of object");
            return Numeric::scalar(inside ? 1 : 0);
        }
        case Keyword::trace: {
            const ObjectRef object = object_arg();
            comma();
            const Vec3 origin = vector_arg();
            comma();
            const Vec3 direction = vector_arg();
            SymbolRef normal_symbol;
            if (accept(Symbol::comma)) {
                const Token at = raw_peek();
                const NameId normal = next_raw_identifier("to receive the normal in 'trace'");
                assign(at, normal, Numeric::vector3({0, 0, 0}), false);
                normal_symbol = lookup(normal);
            }
            close();
            Vec3 hit, normal;
            bool found = false;
            if (!object_trace(*object, origin, direction, hit, normal, found))
                fail_not_supported(name, "'trace' of this kind of object");
            if (normal_symbol)
                normal_symbol->value = Numeric::vector3(found ? normal : Vec3{0, 0, 0});
            return Numeric::vector3(found ? hit : Vec3{0, 0, 0});
        }
        case Keyword::vturbulence:
            fail_not_supported(name, "vturbulence (POV-Ray's noise function)");
        default: break;
    }
    fail_not_supported(name, fmt::format("'{}'", word(name)));
}

bool Parser::starts_string(const Token& token) {
    if (token.kind == TokenKind::string) return true;
    if (token.kind != TokenKind::word) return false;
    const Keyword keyword = keyword_of(token.name);
    if (one_of(keyword, kStringBuiltins)) return true;
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

std::string Parser::parse_builtin_string(const Token& name) {
    const Keyword k = keyword_of(name.name);
    if (k == Keyword::input_file_name)
        return fs::path(files_.front().source->path).filename().string();
    if (k != Keyword::chr && k != Keyword::concat && k != Keyword::datetime && k != Keyword::str &&
        k != Keyword::strlwr && k != Keyword::strupr && k != Keyword::substr && k != Keyword::vstr)
        fail_identifier(name, "a string");
    const Token open = open_call(name);
    auto close = [&] { close_call(name, open); };
    auto comma = [&] { call_comma(name); };
    auto int_arg = [&](const char* what) {
        const double value = parse_float(fmt::format("as the {} of '{}'", what, word(name)));
        return static_cast<int>(std::clamp(std::trunc(value), -2147483648.0, 2147483647.0));
    };
    switch (k) {
        case Keyword::chr: {
            const Token at = peek();
            const int code = int_arg("character code");
            close();
            if (code < 0 || code > 0x10FFFF)
                fail(at, fmt::format("chr({}): not a character code", code));
            std::string out;
            append_utf8(static_cast<char32_t>(code), out);
            return out;
        }
        case Keyword::concat: {
            std::string out = parse_string();
            while (accept(Symbol::comma)) {
                out += parse_string();
                if (static_cast<long>(out.size()) > options_.max_string_length)
                    fail(name, fmt::format("string limit: a string of more than {} bytes "
                                           "(ParseOptions::max_string_length)",
                                           options_.max_string_length));
            }
            close();
            return out;
        }
        case Keyword::str: {
            const double value = parse_float("as the value of 'str'");
            comma();
            const int width = int_arg("width");
            comma();
            const int precision = int_arg("precision");
            close();
            return format_float(value, width, precision);
        }
        case Keyword::vstr: {
            const int requested = int_arg("number of terms");
            comma();
            const Token at = peek();
            const Numeric vector = parse_expression();
            comma();
            const std::string separator = parse_string();
            comma();
            const int width = int_arg("width");
            comma();
            const int precision = int_arg("precision");
            close();
            const int terms = std::clamp(requested, 2, 5);
            if (vector.terms > terms)
                fail(at, fmt::format("vstr: the vector has {} terms, more than the {} asked for",
                                     vector.terms, terms));
            std::string out;
            for (int i = 0; i < terms; ++i) {
                // Missing terms are zeros, even for a float (POV-Ray's behaviour, not its
                // manual's).
                const double term = i < vector.terms ? vector.v[i] : 0.0;
                out += (i ? separator : "") + format_float(term, width, precision);
            }
            return out;
        }
        case Keyword::substr: {
            const std::string s = parse_string();
            comma();
            const Token at = peek();
            const int position = int_arg("position");
            comma();
            const int count = int_arg("length");
            close();
            if (position < 1 || count < 0 || static_cast<size_t>(position - 1 + count) > s.size())
                fail(at, fmt::format("substr: characters {} to {} of a string of {}", position,
                                     position + count - 1, s.size()));
            return s.substr(static_cast<size_t>(position - 1), static_cast<size_t>(count));
        }
        case Keyword::strupr:
        case Keyword::strlwr: {
            std::string s = parse_string();
            close();
            for (char& c : s)
                c = static_cast<char>(k == Keyword::strupr
                                          ? std::toupper(static_cast<unsigned char>(c))
                                          : std::tolower(static_cast<unsigned char>(c)));
            return s;
        }
        case Keyword::datetime: {
            const double days = parse_float("as the time of 'datetime' (days since 2000)");
            std::string format = "%Y-%m-%d %H:%M:%SZ";
            if (accept(Symbol::comma)) format = parse_string();
            close();
            const std::time_t seconds =
                static_cast<std::time_t>(std::floor(946684800.0 + days * 86400.0));
            std::tm utc{};
            gmtime_r(&seconds, &utc);
            char buffer[512];
            const size_t length = std::strftime(buffer, sizeof buffer, format.c_str(), &utc);
            return std::string(buffer, length);
        }
        default: break;
    }
    fail_identifier(name, "a string");
}

}  // namespace rayset::tracer
