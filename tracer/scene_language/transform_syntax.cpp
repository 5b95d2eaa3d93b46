// The transformation statements (reference manual 3.3.1.12): translate, rotate, scale, matrix
// and transform, which compose in writing order, and transform { ... } blocks.
#include <fmt/format.h>

#include "core/error.h"
#include "tracer/scene_language/parser.h"

namespace rayset::tracer {

bool Parser::parse_transform_item(Matrix4& transform) {
    const Token keyword = peek();
    if (keyword.is(Keyword::translate)) {
        next();
        transform = translation(parse_vector()) * transform;
    } else if (keyword.is(Keyword::rotate)) {
        next();
        transform = pov_rotation(parse_vector()) * transform;
    } else if (keyword.is(Keyword::scale)) {
        next();
        const Token at = peek();
        Vec3 s = parse_vector();
        for (double* c : {&s.x, &s.y, &s.z})
            if (*c == 0) {
                // POV-Ray's own handling: a warning, and the factor becomes 1.
                warn(at, "scale by 0: changed to 1, as POV-Ray does");
                *c = 1;
            }
        transform = scaling(s) * transform;
    } else if (keyword.is(Keyword::matrix)) {
        next();
        const Token open = expect(Symbol::less, "after 'matrix'");
        std::array<double, 12> values{};
        for (int i = 0; i < 12; ++i) {
            if (i > 0) accept_comma();
            if (peek_is(Symbol::greater))
                fail(peek(), fmt::format("'matrix' needs 12 values, found {}", i));
            values[static_cast<size_t>(i)] = parse_float("in 'matrix'");
        }
        accept_comma();
        expect(Symbol::greater, [&] {
            return fmt::format("to close the 12 values of 'matrix' opened at {}",
                               location_of(open).str());
        });
        transform = pov_matrix(values) * transform;
    } else if (keyword.is(Keyword::transform)) {
        next();
        transform = parse_transform_block(keyword) * transform;
    } else {
        return false;
    }
    return true;
}

Matrix4 Parser::parse_transform_block(const Token& keyword) {
    if (const TransformValue* value = peek_declared<TransformValue>()) {
        const Matrix4 matrix = value->matrix;
        next();
        return matrix;
    }
    const Token open = expect_open(keyword);
    Matrix4 result;
    bool inverse = false;
    for (;;) {
        if (peek_is(Symbol::rbrace)) break;
        if (accept(Keyword::inverse)) {
            inverse = true;
        } else if (const TransformValue* value = peek_declared<TransformValue>()) {
            result = value->matrix * result;
            next();
        } else if (!parse_transform_item(result)) {
            fail_identifier(
                peek(),
                fmt::format("translate, rotate, scale, matrix, transform, inverse or '}}' to "
                            "close 'transform' opened at {}",
                            location_of(open).str()));
        }
    }
    expect_close(keyword, open);
    if (!inverse) return result;
    try {
        return result.inverse();
    } catch (const Error&) {
        fail(open, "'inverse' of a singular transform");
    }
}

}  // namespace rayset::tracer
