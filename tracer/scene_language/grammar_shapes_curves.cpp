// The shapes made of point lists (reference manual 3.4.5.1 - 3.4.5.2): lathe, prism, sor,
// sphere_sweep, polygon, bicubic_patch, and text. Counts are checked against the limits
// before anything is stored, and the point rules POV-Ray checks are checked here.
#include <filesystem>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/scene_language/object_grammar.h"
#include "tracer/scene_language/text_outline.h"

namespace rayset::tracer {
namespace {

bool same(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
bool same(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// The spline keyword of a lathe or prism, if the next token is one.
bool parse_spline_kind(Parser& p, SplineKind& kind) {
    if (p.accept(Keyword::linear_spline))
        kind = SplineKind::linear;
    else if (p.accept(Keyword::quadratic_spline))
        kind = SplineKind::quadratic;
    else if (p.accept(Keyword::cubic_spline))
        kind = SplineKind::cubic;
    else if (p.accept(Keyword::bezier_spline))
        kind = SplineKind::bezier;
    else
        return false;
    return true;
}

const char* spline_name(SplineKind kind) {
    switch (kind) {
        case SplineKind::linear: return "linear";
        case SplineKind::quadratic: return "quadratic";
        case SplineKind::cubic: return "cubic";
        case SplineKind::bezier: break;
    }
    return "Bezier";
}

// POV-Ray's point counts: at least `minimum` (per spline kind), four per segment for Bezier.
void check_spline_points(Parser& p, const Token& at, const char* shape, SplineKind kind,
                         size_t count, const std::array<size_t, 3>& minimum) {
    if (kind == SplineKind::bezier) {
        if (count == 0 || count % 4 != 0)
            p.fail(at,
                   fmt::format(
                       "{} with Bezier splines must have four points per segment, found {} points",
                       shape, count));
        return;
    }
    const size_t needed = minimum[static_cast<size_t>(kind)];
    if (count < needed)
        p.fail(at, fmt::format("{} with {} splines must have at least {} points, found {}", shape,
                               spline_name(kind), needed, count));
}

// `COUNT, <p1>, <p2>, ...`: the count and that many 2-D points.
std::vector<Vec2> parse_points2(Parser& p, const std::string& what) {
    const int count = parse_count(p, what);
    std::vector<Vec2> points;
    for (int i = 0; i < count; ++i) {
        p.accept_comma();
        points.push_back(parse_vec2(p, fmt::format("as point {} of {}", i + 1, what)));
    }
    return points;
}

// A linear prism's last sub-prism and a polygon's last sub-polygon close themselves in
// POV-Ray (a warning for the polygon): true when the points lacked the closing point.
template <typename Point>
bool close_last_loop(std::vector<Point>& points) {
    size_t start = 0;
    for (size_t i = 1; i < points.size(); ++i)
        if (same(points[i], points[start])) start = i + 1, ++i;
    if (start >= points.size()) return false;
    points.push_back(points[start]);
    return true;
}

}  // namespace

// lathe { [SPLINE] COUNT, <r, h>... } turned about y.
ObjectRef parse_lathe(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    LatheShape lathe;
    parse_spline_kind(p, lathe.spline);
    const Token at = p.peek();
    lathe.points = parse_points2(p, "lathe points");
    check_spline_points(p, at, "lathe", lathe.spline, lathe.points.size(), {2, 3, 4});
    node->shape = std::move(lathe);
    finish_shape(p, *node, keyword, open);
    return node;
}

// prism { [SPLINE] [SWEEP] HEIGHT1, HEIGHT2, COUNT, <x, z>... [open] }
ObjectRef parse_prism(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    PrismShape prism;
    for (;;) {
        if (parse_spline_kind(p, prism.spline)) continue;
        if (p.accept(Keyword::linear_sweep))
            prism.conic_sweep = false;
        else if (p.accept(Keyword::conic_sweep))
            prism.conic_sweep = true;
        else
            break;
    }
    prism.height1 = p.parse_float("as the first prism height");
    p.accept_comma();
    prism.height2 = p.parse_float("as the second prism height");
    p.accept_comma();
    const Token at = p.peek();
    prism.points = parse_points2(p, "prism points");
    check_spline_points(p, at, "prism", prism.spline, prism.points.size(), {3, 5, 6});
    if (prism.spline == SplineKind::linear && close_last_loop(prism.points))
        p.warn(at, "linear prism not closed: closing it, as POV-Ray does");
    prism.open = p.accept(Keyword::open);
    node->shape = std::move(prism);
    finish_shape(p, *node, keyword, open);
    return node;
}

// sor { COUNT, <r, h>... [open] }: POV-Ray requires rising heights (the first and last
// points, which only set slopes, may repeat their neighbour's).
ObjectRef parse_sor(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    SorShape sor;
    const Token at = p.peek();
    sor.points = parse_points2(p, "sor points");
    const size_t n = sor.points.size();
    if (n < 4)
        p.fail(at,
               fmt::format("a surface of revolution must have at least four points, found {}", n));
    for (size_t i = 0; i + 1 < n; ++i) {
        const bool end = i == 0 || i + 2 == n;
        const double h = sor.points[i].y, next = sor.points[i + 1].y;
        if (end ? next < h : next <= h)
            p.fail(at, fmt::format("incorrect point in surface of revolution: height {} of point "
                                   "{} does not rise above "
                                   "{} of point {}",
                                   next, i + 2, h, i + 1));
    }
    sor.open = p.accept(Keyword::open);
    node->shape = std::move(sor);
    finish_shape(p, *node, keyword, open);
    return node;
}

// sphere_sweep { KIND COUNT, <centre>, radius ... [tolerance T] }
ObjectRef parse_sphere_sweep(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    SphereSweepShape sweep;
    using Kind = SphereSweepShape::Kind;
    if (p.accept(Keyword::linear_spline))
        sweep.kind = Kind::linear_spline;
    else if (p.accept(Keyword::b_spline))
        sweep.kind = Kind::b_spline;
    else if (p.accept(Keyword::cubic_spline))
        sweep.kind = Kind::cubic_spline;
    else
        p.fail_expected("linear_spline, b_spline or cubic_spline in 'sphere_sweep'", p.peek());
    const Token at = p.peek();
    const int count = parse_count(p, "sphere_sweep spheres");
    for (int i = 0; i < count; ++i) {
        SphereSweepShape::Sphere sphere;
        p.accept_comma();
        sphere.centre = p.parse_vector();
        p.accept_comma();
        sphere.radius = p.parse_float("as a sphere_sweep radius");
        sweep.spheres.push_back(sphere);
    }
    const int needed = sweep.kind == Kind::linear_spline ? 2 : 4;
    if (count < needed)
        p.fail(at,
               fmt::format("too few spheres for the interpolation: {} needs at least {}, found {}",
                           sweep.kind == Kind::linear_spline ? "linear_spline"
                           : sweep.kind == Kind::b_spline    ? "b_spline"
                                                             : "cubic_spline",
                           needed, count));
    if (p.accept(Keyword::tolerance)) sweep.tolerance = p.parse_float("after 'tolerance'");
    node->shape = std::move(sweep);
    finish_shape(p, *node, keyword, open);
    return node;
}

// polygon { COUNT, <p1>, <p2>, ... }: 2-D points have z = 0.
ObjectRef parse_polygon(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    PolygonShape polygon;
    const Token at = p.peek();
    const int count = parse_count(p, "polygon points");
    if (count < 3)
        p.fail(at, fmt::format("a polygon needs at least three points, found {}", count));
    for (int i = 0; i < count; ++i) {
        p.accept_comma();
        polygon.points.push_back(p.parse_vector());
    }
    if (close_last_loop(polygon.points))
        p.warn(at, "polygon not closed: closing it, as POV-Ray does");
    node->shape = std::move(polygon);
    finish_shape(p, *node, keyword, open);
    return node;
}

// bicubic_patch { type T [flatness F] [u_steps U] [v_steps V] [uv_vectors 4 corners] 16 points }:
// the items before the points in any order, `type` required; the points start with '<' or a vector
// identifier (POV-Ray reads a number there as its old syntax without keywords).
ObjectRef parse_bicubic_patch(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    BicubicPatchShape patch;
    bool have_type = false;
    for (;;) {
        if (p.accept(Keyword::type))
            patch.type = p.parse_int("after 'type'", 0), have_type = true;
        else if (p.accept(Keyword::flatness))
            patch.flatness = p.parse_float("after 'flatness'");
        else if (p.accept(Keyword::u_steps))
            patch.u_steps = p.parse_int("after 'u_steps'", 0);
        else if (p.accept(Keyword::v_steps))
            patch.v_steps = p.parse_int("after 'v_steps'", 0);
        else if (p.accept(Keyword::uv_vectors))
            for (size_t i = 0; i < patch.corner_uvs.size(); ++i) {
                if (i > 0) p.accept_comma();
                patch.corner_uvs[i] = parse_vec2(p, "as a corner's uv vector of the bicubic_patch");
            }
        else
            break;
        p.accept_comma();
    }
    const Token first = p.peek();
    if (!first.is(Symbol::less) && !p.peek_declared<Numeric>() && p.starts_expression(first))
        p.fail_not_supported(
            first,
            "bicubic_patch parameters without their keywords (type, flatness, u_steps, "
            "v_steps)");
    if (!have_type) p.fail(first, "bicubic_patch needs 'type' (0 or 1) before its points");
    for (size_t i = 0; i < patch.points.size(); ++i) {
        if (i > 0) p.accept_comma();
        if (p.peek_is(Symbol::rbrace))
            p.fail(p.peek(), fmt::format("a bicubic_patch needs 16 points, found {}", i));
        patch.points[i] = p.parse_vector();
    }
    node->shape = patch;
    finish_shape(p, *node, keyword, open);
    return node;
}

// text { ttf "font" "string" THICKNESS, OFFSET } or text { internal N "string" ... }.
ObjectRef parse_text(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    TextShape text;
    if (p.accept(Keyword::internal)) {
        text.internal_font = p.parse_int("as the number of the internal font", 0);
    } else {
        p.expect(Keyword::ttf, "(the font type) in 'text'");
        const Token at = p.peek();
        text.font_path = p.resolve_file(p.parse_string(), at, "font file", {".ttf"});
    }
    p.accept_comma();
    text.text = p.parse_string();
    p.accept_comma();
    text.thickness = p.parse_float("as the text thickness");
    p.accept_comma();
    text.offset = p.parse_vector();
    if (!text.font_path.empty()) {
        try {
            text.outline = load_text_outline(text.font_path, text.text, text.offset);
        } catch (const Error& e) {
            p.fail(keyword, e.what());
        }
    }
    node->shape = std::move(text);
    finish_shape(p, *node, keyword, open);
    return node;
}

}  // namespace rayset::tracer
