// The shapes defined by fields and functions (reference manual 3.4.5.1): blob, height_field,
// isosurface, parametric, julia_fractal. Their own items come before the object modifiers,
// as POV-Ray reads them.
#include <cmath>

#include <fmt/format.h>

#include "tracer/scene_language/object_grammar.h"

namespace rayset::tracer {
namespace {

// blob components: sphere { <c>, r, [strength] s MODS } and cylinder { <a>, <b>, r, [strength]
// s MODS } with texture, pigment, normal, finish and transforms; `component s, r, <c>`.
BlobComponent parse_blob_component(Parser& p, const Token& keyword) {
    BlobComponent component;
    component.location = p.location_of(keyword);
    if (keyword.is(Keyword::component)) {
        component.strength = p.parse_float("as the component strength");
        p.accept_comma();
        component.radius = p.parse_float("as the component radius");
        p.accept_comma();
        component.centre = p.parse_vector();
        return component;
    }
    const Token open = p.expect_open(keyword);
    component.centre = p.parse_vector();
    p.accept_comma();
    if (keyword.is(Keyword::cylinder)) {
        component.kind = BlobComponent::Kind::cylinder;
        component.end = p.parse_vector();
        p.accept_comma();
    }
    component.radius = p.parse_float("as the blob component radius");
    p.accept_comma();
    p.accept(Keyword::strength);
    component.strength = p.parse_float("as the blob component strength");
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (p.parse_transform_item(component.transform)) continue;
        if (parse_appearance_modifier(p, component.appearance)) {
            if (component.appearance.interior)
                p.fail(token, "a blob component takes no interior (give the blob one)");
            continue;
        }
        p.fail_identifier(
            token, fmt::format("a texture, pigment, normal, finish, transform or '}}' to close the "
                               "blob component '{}' opened at {}",
                               p.word(keyword), p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    return component;
}

// The heights POV-Ray 3.7 takes from an image (read back with trace): a grey image's values
// over their maximum (8 or 16 bits), an 8-bit colour image's red and green as the high and low
// bytes of a 16-bit number, other colour images' grey 0.297 red + 0.589 green + 0.114 blue.
// A palette image's index is the high byte (POV-Ray's trace of a field of index 3: 3 x 256 /
// 65535); the indices of palette images other than PNG are not read (null: not supported).
std::shared_ptr<const HeightGrid> heights_from_image(const ImagePixels& pixels) {
    if ((pixels.palette && pixels.indices.empty()) || pixels.width < 2 || pixels.height < 2)
        return nullptr;
    auto grid = std::make_shared<HeightGrid>();
    grid->columns = pixels.width;
    grid->rows = pixels.height;
    grid->heights.reserve(size_t(pixels.width) * size_t(pixels.height));
    for (int row = pixels.height - 1; row >= 0; --row)
        for (int column = 0; column < pixels.width; ++column) {
            const float* v = pixels.pixel(column, row);
            double height = 0;
            if (pixels.palette)
                height = 256.0 *
                         pixels.indices[size_t(row) * size_t(pixels.width) + size_t(column)] /
                         65535;
            else if (pixels.grey)
                height = v[0];
            else if (pixels.bits == 8 && !pixels.floating)
                height = (std::round(255.0 * v[0]) * 256 + std::round(255.0 * v[1])) / 65535;
            else
                height = 0.297 * v[0] + 0.589 * v[1] + 0.114 * v[2];
            grid->heights.push_back(height);
        }
    return grid;
}

// height_field { [TYPE] "file" [gamma G | gamma srgb] [premultiplied B] ... }: the image is
// resolved and read.
void parse_height_field_image(Parser& p, HeightFieldShape& field) {
    static const char* const types[] = {"exr", "gif", "hdr", "iff", "jpeg", "pgm", "png",
                                        "pot", "ppm", "sys", "tga", "tiff", "bmp"};
    // exr, hdr and bmp are POV-Ray keywords the keyword table lacks: compared by their text.
    const Token first = p.peek();
    if (first.kind == TokenKind::word && !p.starts_string(first))
        for (const char* type : types)
            if (p.word(first) == type) {
                field.image_type = type;
                p.next();
                break;
            }
    const Token at = p.peek();
    if (!p.starts_string(at))
        p.fail_expected(
            "an image type (gif, tga, pot, png, pgm, ppm, jpeg, tiff, sys, exr, hdr, iff, bmp), a "
            "file "
            "name or 'function' in 'height_field'",
            at);
    field.image_path =
        resolve_image_file(p, p.parse_string(), at, field.image_type, "height_field image");
    if (const auto pixels = read_scene_image(p, field.image_path, field.image_type, at))
        field.grid = heights_from_image(*pixels);
    for (;;) {
        if (p.accept(Keyword::gamma)) {
            if (p.accept(Keyword::srgb))
                field.image_srgb = true;
            else
                field.image_gamma = p.parse_float("after 'gamma'");
        } else if (p.accept(Keyword::premultiplied)) {
            field.premultiplied = p.parse_optional_bool();
        } else {
            break;
        }
    }
}

// function W, H { F }: f(x, y) on a W x H grid.
void parse_height_field_function(Parser& p, const Token& function, HeightFieldShape& field) {
    const Token at = p.peek();
    field.function_width = p.parse_int("as the height_field function's x resolution", 1);
    p.accept_comma();
    field.function_height = p.parse_int("as the height_field function's y resolution", 1);
    if (double(field.function_width) * field.function_height >
        double(p.options().max_array_elements))
        p.fail(at, fmt::format("a height_field of {} x {} samples is more than the limit of {} "
                               "(ParseOptions::max_array_elements)",
                               field.function_width, field.function_height,
                               p.options().max_array_elements));
    field.function = p.parse_function(function);
}

// isosurface and parametric's own items; false when the next token is none of them.
bool parse_function_shape_item(Parser& p, ContainedBy& contained_by, double& max_gradient,
                               double& accuracy) {
    const Token token = p.peek();
    if (token.is(Keyword::contained_by)) {
        p.next();
        contained_by = parse_contained_by(p, token);
    } else if (token.is(Keyword::max_gradient)) {
        p.next();
        max_gradient = p.parse_float("after 'max_gradient'");
    } else if (token.is(Keyword::accuracy)) {
        p.next();
        accuracy = p.parse_float("after 'accuracy'");
    } else {
        return false;
    }
    return true;
}

bool parse_isosurface_item(Parser& p, IsosurfaceShape& iso) {
    if (parse_function_shape_item(p, iso.contained_by, iso.max_gradient, iso.accuracy)) return true;
    const Token token = p.peek();
    if (token.is(Keyword::threshold)) {
        p.next();
        iso.threshold = p.parse_float("after 'threshold'");
    } else if (token.is(Keyword::evaluate)) {
        p.next();
        iso.evaluate = true;
        for (size_t i = 0; i < 3; ++i) {
            if (i > 0) p.accept_comma();
            iso.evaluate_values[i] = p.parse_float("as a value of 'evaluate'");
        }
    } else if (token.is(Keyword::open)) {
        p.next();
        iso.open = true;
    } else if (token.is(Keyword::max_trace)) {
        p.next();
        iso.max_trace = p.parse_int("after 'max_trace'", 1);
    } else if (token.is(Keyword::all_intersections)) {
        p.next();
        iso.all_intersections = true;
    } else {
        return false;
    }
    return true;
}

constexpr int kMaxPrecomputeDepth = 20;  // POV-Ray's limit

// precompute DEPTH, [x][,][y][,][z]
void parse_precompute(Parser& p, ParametricShape& parametric) {
    const Token at = p.peek();
    parametric.precompute_depth = p.parse_int("after 'precompute'", 0);
    if (parametric.precompute_depth > kMaxPrecomputeDepth)
        p.fail(at, fmt::format("precompute depth {} is more than POV-Ray's {}",
                               parametric.precompute_depth, kMaxPrecomputeDepth));
    static const Keyword axes[] = {Keyword::x, Keyword::y, Keyword::z};
    for (;;) {
        p.accept_comma();
        bool found = false;
        for (size_t i = 0; i < 3; ++i)
            if (p.accept(axes[i])) parametric.precompute_axes[i] = found = true;
        if (!found) break;
    }
}

using JuliaFunction = JuliaFractalShape::Function;
const std::pair<const char*, JuliaFunction> kJuliaFunctions[] = {
    {"sqr", JuliaFunction::sqr},   {"cube", JuliaFunction::cube},
    {"exp", JuliaFunction::exp},   {"reciprocal", JuliaFunction::reciprocal},
    {"sin", JuliaFunction::sin},   {"asin", JuliaFunction::asin},
    {"sinh", JuliaFunction::sinh}, {"asinh", JuliaFunction::asinh},
    {"cos", JuliaFunction::cos},   {"acos", JuliaFunction::acos},
    {"cosh", JuliaFunction::cosh}, {"acosh", JuliaFunction::acosh},
    {"tan", JuliaFunction::tan},   {"atan", JuliaFunction::atan},
    {"tanh", JuliaFunction::tanh}, {"atanh", JuliaFunction::atanh},
    {"ln", JuliaFunction::ln},     {"pwr", JuliaFunction::pwr}};

const char* julia_function_name(JuliaFunction function) {
    for (const auto& [name, f] : kJuliaFunctions)
        if (f == function) return name;
    return "?";
}

bool parse_julia_item(Parser& p, JuliaFractalShape& julia) {
    const Token token = p.peek();
    if (token.kind != TokenKind::word) return false;
    if (token.is(Keyword::quaternion) || token.is(Keyword::hypercomplex)) {
        p.next();
        julia.algebra = token.is(Keyword::quaternion) ? JuliaFractalShape::Algebra::quaternion
                                                      : JuliaFractalShape::Algebra::hypercomplex;
    } else if (token.is(Keyword::max_iteration)) {
        p.next();
        julia.max_iteration = p.parse_int("after 'max_iteration'", 1);
    } else if (token.is(Keyword::precision)) {
        p.next();
        julia.precision = p.parse_float("after 'precision'");
    } else if (token.is(Keyword::slice)) {
        p.next();
        const Token at = p.peek();
        const Numeric normal = p.parse_vector_terms(4);
        for (size_t i = 0; i < 4; ++i) julia.slice_normal[i] = normal.v[i];
        if (julia.slice_normal[3] == 0)
            p.fail(at, "the slice normal's fourth (t) component must not be 0");
        p.accept_comma();
        julia.slice_distance = p.parse_float("as the slice distance");
    } else {
        for (const auto& [name, function] : kJuliaFunctions)
            if (p.word(token) == name) {
                p.next();
                julia.function = function;
                if (token.is(Keyword::pwr)) {
                    p.expect(Symbol::lparen, "after 'pwr'");
                    julia.power.x = p.parse_float("as the real part of 'pwr'");
                    p.accept_comma();
                    julia.power.y = p.parse_float("as the imaginary part of 'pwr'");
                    p.expect(Symbol::rparen, "after the exponent of 'pwr'");
                }
                return true;
            }
        return false;
    }
    return true;
}

}  // namespace

ContainedBy parse_contained_by(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    ContainedBy container;
    const Token shape = p.next();
    if (!shape.is(Keyword::box) && !shape.is(Keyword::sphere))
        p.fail_identifier(shape, "box or sphere in 'contained_by'");
    const Token shape_open = p.expect_open(shape);
    if (shape.is(Keyword::box)) {
        const Vec3 a = p.parse_vector();
        p.accept_comma();
        const Vec3 b = p.parse_vector();
        container.minimum = {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
        container.maximum = {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
    } else {
        container.kind = ContainedBy::Kind::sphere;
        container.centre = p.parse_vector();
        p.accept_comma();
        container.radius = p.parse_float("as the radius of the container sphere");
    }
    p.expect_close(shape, shape_open);
    p.expect_close(keyword, open);
    return container;
}

ObjectRef parse_blob(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    BlobShape blob;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Keyword::threshold)) {
            p.next();
            blob.threshold = p.parse_float("after 'threshold'");
        } else if (token.is(Keyword::sphere) || token.is(Keyword::cylinder) ||
                   token.is(Keyword::component)) {
            p.next();
            blob.components.push_back(parse_blob_component(p, token));
        } else {
            break;
        }
    }
    if (blob.components.empty())
        p.fail(p.peek(), "a blob needs at least one component (sphere, cylinder)");
    node->shape = std::move(blob);
    finish_shape(p, *node, keyword, open);
    return node;
}

ObjectRef parse_height_field(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    HeightFieldShape field;
    if (p.peek_is(Keyword::function))
        parse_height_field_function(p, p.next(), field);
    else
        parse_height_field_image(p, field);
    for (;;) {
        if (p.accept(Keyword::smooth))
            field.smooth = p.parse_optional_bool();
        else if (p.accept(Keyword::water_level))
            field.water_level = p.parse_float("after 'water_level'");
        else
            break;
    }
    node->shape = std::move(field);
    finish_shape(p, *node, keyword, open);
    return node;
}

// isosurface { function { F } ITEMS... }: the function first, as POV-Ray requires.
ObjectRef parse_isosurface(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    IsosurfaceShape iso;
    const Token function = p.expect(Keyword::function, "first in 'isosurface'");
    iso.function = p.parse_function(function);
    while (parse_isosurface_item(p, iso)) {
    }
    node->shape = std::move(iso);
    finish_shape(p, *node, keyword, open);
    return node;
}

// parametric { function { fx } function { fy } function { fz } <u1, v1>, <u2, v2> ITEMS... }
ObjectRef parse_parametric(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    ParametricShape parametric;
    for (size_t i = 0; i < 3; ++i) {
        if (i > 0) p.accept_comma();
        const Token function =
            p.expect(Keyword::function, "(one for each of x, y, z) in 'parametric'");
        parametric.functions[i] = p.parse_function(function);
    }
    p.accept_comma();
    parametric.uv_minimum = parse_vec2(p, "as <u1, v1> of the parametric");
    p.accept_comma();
    parametric.uv_maximum = parse_vec2(p, "as <u2, v2> of the parametric");
    for (;;) {
        if (parse_function_shape_item(p, parametric.contained_by, parametric.max_gradient,
                                      parametric.accuracy))
            continue;
        if (!p.accept(Keyword::precompute)) break;
        parse_precompute(p, parametric);
    }
    node->shape = std::move(parametric);
    finish_shape(p, *node, keyword, open);
    return node;
}

// julia_fractal { <p> ITEMS... }: a quaternion fractal takes only sqr and cube.
ObjectRef parse_julia_fractal(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    JuliaFractalShape julia;
    const Numeric parameter = p.parse_vector_terms(4);
    for (size_t i = 0; i < 4; ++i) julia.parameter[i] = parameter.v[i];
    while (parse_julia_item(p, julia)) {
    }
    if (julia.algebra == JuliaFractalShape::Algebra::quaternion &&
        julia.function != JuliaFunction::sqr && julia.function != JuliaFunction::cube)
        p.fail(
            keyword,
            fmt::format("illegal function '{}': a quaternion julia_fractal takes only sqr and cube",
                        julia_function_name(julia.function)));
    node->shape = std::move(julia);
    finish_shape(p, *node, keyword, open);
    return node;
}

}  // namespace rayset::tracer
