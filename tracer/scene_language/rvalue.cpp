// What may follow '=' in #declare and #local, or be passed to a macro (POV-Ray's RVALUE):
// chosen by the first token, as POV-Ray chooses it. Arrays and their initialisers too.
#include <algorithm>

#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace {

// Arrays are copied whole by #declare B = A (POV-Ray copies every element).
ArrayRef copy_array(const Array& array) {
    auto copy = std::make_shared<Array>(array);
    for (Value& element : copy->elements)
        if (ArrayRef* inner = std::get_if<ArrayRef>(&element)) *inner = copy_array(**inner);
    return copy;
}

// The values written as a keyword and a block, and how each block is read. texture is not here:
// several texture blocks in a row are one layered texture.
struct BlockValue {
    Keyword keyword;
    Value (*parse)(Parser& parser, const Token& keyword);
};
const BlockValue kBlockValues[] = {
    {Keyword::function, [](Parser& p, const Token& k) { return Value(p.parse_function(k)); }},
    {Keyword::spline, [](Parser& p, const Token& k) { return Value(p.parse_spline(k)); }},
    {Keyword::transform,
     [](Parser& p, const Token& k) { return Value(TransformValue{p.parse_transform_block(k)}); }},
    {Keyword::pigment, [](Parser& p, const Token& k) { return Value(parse_pigment(p, k)); }},
    {Keyword::normal, [](Parser& p, const Token& k) { return Value(parse_normal(p, k)); }},
    {Keyword::finish, [](Parser& p, const Token& k) { return Value(parse_finish(p, k)); }},
    {Keyword::interior, [](Parser& p, const Token& k) { return Value(parse_interior(p, k)); }},
    {Keyword::media, [](Parser& p, const Token& k) { return Value(parse_media(p, k)); }},
    {Keyword::density, [](Parser& p, const Token& k) { return Value(parse_density(p, k)); }},
    {Keyword::material, [](Parser& p, const Token& k) { return Value(parse_material(p, k)); }},
    {Keyword::color_map, [](Parser& p, const Token& k) { return Value(parse_colour_map(p, k)); }},
    {Keyword::colour_map, [](Parser& p, const Token& k) { return Value(parse_colour_map(p, k)); }},
    {Keyword::pigment_map,
     [](Parser& p, const Token& k) { return Value(parse_pigment_map(p, k)); }},
    {Keyword::normal_map, [](Parser& p, const Token& k) { return Value(parse_normal_map(p, k)); }},
    {Keyword::slope_map, [](Parser& p, const Token& k) { return Value(parse_slope_map(p, k)); }},
    {Keyword::texture_map,
     [](Parser& p, const Token& k) { return Value(parse_texture_map(p, k)); }},
    {Keyword::density_map,
     [](Parser& p, const Token& k) { return Value(parse_density_map(p, k)); }},
    {Keyword::camera, [](Parser& p, const Token& k) { return Value(parse_camera(p, k)); }},
    {Keyword::fog, [](Parser& p, const Token& k) { return Value(parse_fog(p, k)); }},
    {Keyword::rainbow, [](Parser& p, const Token& k) { return Value(parse_rainbow(p, k)); }},
    {Keyword::sky_sphere, [](Parser& p, const Token& k) { return Value(parse_sky_sphere(p, k)); }},
};

const BlockValue* find_block_value(Keyword keyword) {
    const BlockValue* entry =
        std::find_if(std::begin(kBlockValues), std::end(kBlockValues),
                     [&](const BlockValue& block) { return block.keyword == keyword; });
    return entry == std::end(kBlockValues) ? nullptr : entry;
}

}  // namespace

Value Parser::parse_rvalue(const Token& purpose) {
    const Token token = peek();
    // Blocks may hold directives as anywhere else; only numbers and strings end at one.
    struct Restore {
        size_t& frame;
        size_t saved;
        ~Restore() { frame = saved; }
    } restore{directive_frame_, directive_frame_};

    if (token.kind == TokenKind::string) return parse_string();
    if (token.kind == TokenKind::word && is_keyword(token.name)) return parse_keyword_rvalue(token);
    if (token.kind == TokenKind::word) return parse_identifier_rvalue(token, purpose);
    if (starts_expression(token)) return parse_numeric();
    fail_expected(fmt::format("a value for '{}'", word(purpose)), token);
}

Value Parser::parse_keyword_rvalue(const Token& token) {
    if (starts_string(token)) return parse_string();
    if (starts_object(*this, token)) {
        directive_frame_ = 0;
        return parse_object(*this);
    }
    if (is_colour_keyword(token)) {
        const Colour c = parse_colour();
        return Numeric{{c.red, c.green, c.blue, c.filter, c.transmit}, 5};
    }
    const Keyword keyword = static_cast<Keyword>(token.name);
    if (keyword == Keyword::array) {
        // Not a block: what follows its sizes is looked at, and a directive there must wait
        // until the array is declared (arrays.inc writes `#local A = array[N]` followed by
        // directives that use A).
        next();
        return parse_array(token);
    }
    if (keyword == Keyword::texture) return parse_layered_texture_rvalue();
    if (const BlockValue* block = find_block_value(keyword)) {
        const Token block_keyword = next();
        directive_frame_ = 0;
        return block->parse(*this, block_keyword);
    }
    if (is_numeric_builtin(token.name)) return parse_numeric();
    fail_not_supported(token, fmt::format("'{}' as a value", word(token)));
}

// #declare T = texture { } texture { } ...: a layered texture. Inside the blocks directives run
// as anywhere; between them, as after a number, one may end the value.
Value Parser::parse_layered_texture_rvalue() {
    const size_t saved_directive_frame = directive_frame_;
    auto read_block = [&] {
        const Token keyword = next();
        directive_frame_ = 0;
        TextureRef texture = parse_texture(*this, keyword);
        directive_frame_ = saved_directive_frame;
        return std::make_pair(keyword, texture);
    };
    TextureRef texture = read_block().second;
    while (peek_operator().is(Keyword::texture)) {
        const auto [keyword, above] = read_block();
        texture = layer_textures(*this, keyword, texture, above);
    }
    return texture;
}

// A declared identifier: its value, or an expression that starts with it (an element of a
// numeric array, a call of a function or spline).
Value Parser::parse_identifier_rvalue(const Token& token, const Token& purpose) {
    const Value* value = peek_value();
    if (!value) fail_identifier(token, fmt::format("a value for '{}'", word(purpose)));
    if (std::holds_alternative<Numeric>(*value)) return parse_numeric();
    if (std::holds_alternative<std::string>(*value)) return parse_string();
    const Value held = *value;
    next();
    auto expression_from = [&](const Value& start) -> Value {
        return parse_additive_after(
            parse_term_after(parse_postfix(parse_numeric_identifier(token, start))));
    };
    auto is_callable = [](const Value& v) {
        return std::holds_alternative<FunctionRef>(v) || std::holds_alternative<SplineRef>(v);
    };
    if (const ArrayRef* array = std::get_if<ArrayRef>(&held)) {
        if (!peek_operator().is(Symbol::lbracket)) return copy_array(**array);
        Value element = *array_element(token, **array, false);
        if (std::holds_alternative<Numeric>(element) || is_callable(element))
            return expression_from(element);
        return element;
    }
    if (is_callable(held)) {
        if (!peek_operator().is(Symbol::lparen)) return held;  // the function or spline itself
        return expression_from(held);
    }
    return held;
}

std::string Array::mismatch(const Value& value) const {
    if (element_type == 0) return "";
    const Numeric* n = std::get_if<Numeric>(&value);
    if (value.index() == element_type && (!n || n->terms == element_terms)) return "";
    for (const Value& element : elements)
        if (!std::holds_alternative<std::monostate>(element))
            return fmt::format("{}, found {}", type_name(element), type_name(value));
    return fmt::format("of one type, found {}", type_name(value));
}

void Array::assign(size_t index, Value value) {
    element_type = value.index();
    if (const Numeric* n = std::get_if<Numeric>(&value)) element_terms = n->terms;
    elements[index] = as_stored(std::move(value));
}

Value Parser::parse_array(const Token& keyword) {
    auto array = std::make_shared<Array>();
    long total = 1;
    while (peek_operator().is(Symbol::lbracket)) {
        const Token open = next();
        const Token at = peek();
        const double size = parse_float("as the size of the array");
        expect(Symbol::rbracket,
               [&] { return fmt::format("to close '[' opened at {}", location_of(open).str()); });
        if (!(size >= 1))
            fail(at, fmt::format("an array dimension must be at least 1, found {}", size));
        if (array->sizes.size() == 5) fail(open, "an array has at most 5 dimensions");
        if (size > static_cast<double>(options_.max_array_elements) ||
            total * static_cast<long>(size) > options_.max_array_elements)
            fail(at, fmt::format(
                         "array limit: more than {} elements (ParseOptions::max_array_elements)",
                         options_.max_array_elements));
        array->sizes.push_back(static_cast<int>(size));
        total *= static_cast<long>(size);
    }
    if (array->sizes.empty()) fail_expected("'[' with the size of the array after 'array'", peek());
    check_memory(keyword, static_cast<double>(total) * sizeof(Value));
    array->elements.resize(static_cast<size_t>(total));
    if (peek_operator().is(Symbol::lbrace)) {
        size_t index = 0;
        parse_array_initialiser(*array, 0, index, keyword);
    }
    return array;
}

void Parser::parse_array_initialiser(Array& array, size_t dimension, size_t& index,
                                     const Token& keyword) {
    const Token open = expect_open(keyword);
    const int count = array.sizes[dimension];
    for (int i = 0; i < count; ++i) {
        if (i > 0) accept_comma();  // optional, as in POV-Ray (its sample scenes leave some out)
        if (peek_is(Symbol::rbrace))
            fail(peek(),
                 fmt::format(
                     "the array initialiser opened at {} has {} element{}, the array {} in this "
                     "dimension",
                     location_of(open).str(), i, i == 1 ? "" : "s", count));
        if (dimension + 1 < array.sizes.size()) {
            parse_array_initialiser(array, dimension + 1, index, keyword);
            continue;
        }
        const Token at = peek();
        Value value = parse_rvalue(keyword);
        if (const std::string why = array.mismatch(value); !why.empty())
            fail(at,
                 fmt::format("the elements of this array are {} (an array holds one type)", why));
        array.assign(index++, std::move(value));
    }
    accept_comma();
    if (!peek_is(Symbol::rbrace))
        fail_expected(fmt::format("'}}' after the {} elements of the initialiser opened at {}",
                                  count, location_of(open).str()),
                      peek());
    expect_close(keyword, open);
}

std::string type_name(const Value& value) {
    struct Namer {
        std::string operator()(const std::monostate&) const {
            return "nothing (an unassigned array element)";
        }
        std::string operator()(const Numeric& n) const {
            if (n.terms == 1) return "a float";
            if (n.terms <= 3) return "a vector";
            return n.terms == 4 ? "a 4-term vector" : "a colour";
        }
        std::string operator()(const std::string&) const { return "a string"; }
        std::string operator()(const ArrayRef&) const { return "an array"; }
        std::string operator()(const MacroRef&) const { return "a macro"; }
        std::string operator()(const FunctionRef&) const { return "a function"; }
        std::string operator()(const SplineRef&) const { return "a spline"; }
        std::string operator()(const FileRef&) const { return "a file handle"; }
        std::string operator()(const TransformValue&) const { return "a transform"; }
        std::string operator()(const ObjectRef&) const { return "an object"; }
        std::string operator()(const TextureRef&) const { return "a texture"; }
        std::string operator()(const PigmentRef&) const { return "a pigment"; }
        std::string operator()(const NormalRef&) const { return "a normal"; }
        std::string operator()(const FinishRef&) const { return "a finish"; }
        std::string operator()(const InteriorRef&) const { return "an interior"; }
        std::string operator()(const MediaRef&) const { return "a media"; }
        std::string operator()(const MaterialRef&) const { return "a material"; }
        std::string operator()(const CameraRef&) const { return "a camera"; }
        std::string operator()(const FogRef&) const { return "a fog"; }
        std::string operator()(const RainbowRef&) const { return "a rainbow"; }
        std::string operator()(const SkySphereRef&) const { return "a sky_sphere"; }
        std::string operator()(const DensityRef&) const { return "a density"; }
        std::string operator()(const ColourMapRef&) const { return "a color_map"; }
        std::string operator()(const PigmentMapRef&) const { return "a pigment_map"; }
        std::string operator()(const NormalMapRef&) const { return "a normal_map"; }
        std::string operator()(const SlopeMapRef&) const { return "a slope_map"; }
        std::string operator()(const TextureMapRef&) const { return "a texture_map"; }
        std::string operator()(const DensityMapRef&) const { return "a density_map"; }
    };
    return std::visit(Namer{}, value);
}

}  // namespace rayset::tracer
