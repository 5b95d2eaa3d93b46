// The shapes given by a few numbers (reference manual 3.4.5.1 - 3.4.5.3): sphere, box,
// cylinder, cone, torus, ovus, superellipsoid, plane, disc, triangle, smooth_triangle, poly,
// cubic, quartic, polynomial, quadric.
#include <fmt/format.h>

#include "tracer/scene_language/object_grammar.h"

namespace rayset::tracer {
namespace {

// POV-Ray's term order of a polynomial of `order`: (i, j, k) for x^i y^j z^k, lexicographically
// descending (x^order first, the constant last).
std::vector<std::array<int, 3>> polynomial_terms(int order) {
    std::vector<std::array<int, 3>> terms;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k) terms.push_back({i, j, k});
    return terms;
}

constexpr int kMaxPolynomialOrder = 35;  // POV-Ray's limit

int parse_polynomial_order(Parser& p, const Token& keyword) {
    const Token at = p.peek();
    const int order = p.parse_int(fmt::format("as the order of '{}'", p.word(keyword)), 0);
    if (order < 2 || order > kMaxPolynomialOrder)
        p.fail(at, fmt::format("the order of '{}' must lie in 2..{}, found {}", p.word(keyword),
                               kMaxPolynomialOrder, order));
    return order;
}

// `<A1, A2, ..., An>` with exactly `count` terms (more than a vector holds).
std::vector<double> parse_coefficients(Parser& p, const Token& keyword, size_t count) {
    const Token open = p.expect(Symbol::less, [&] {
        return fmt::format("before the coefficients of '{}'", p.word(keyword));
    });
    std::vector<double> coefficients;
    for (;;) {
        if (p.peek_is(Symbol::greater)) break;
        if (coefficients.size() == count)
            p.fail(p.peek(), fmt::format("'{}' takes {} coefficients here, found more",
                                         p.word(keyword), count));
        coefficients.push_back(
            p.parse_float(fmt::format("as a coefficient of '{}'", p.word(keyword))));
        p.accept_comma();
    }
    if (coefficients.size() != count)
        p.fail(p.peek(), fmt::format("'{}' takes {} coefficients here, found {}", p.word(keyword),
                                     count, coefficients.size()));
    p.expect(Symbol::greater, [&] {
        return fmt::format("to close the coefficients opened at {}", p.location_of(open).str());
    });
    return coefficients;
}

// Two ends that must differ (cylinder, cone: POV-Ray's "degenerate" error).
void check_ends(Parser& p, const Token& keyword, Vec3 base, Vec3 cap) {
    if (base.x == cap.x && base.y == cap.y && base.z == cap.z)
        p.fail(keyword,
               fmt::format("degenerate {}: its base and cap are the same point", p.word(keyword)));
}

template <typename ShapeT>
ObjectRef finish(Parser& p, const NodePtr& node, ShapeT shape, const Token& keyword,
                 const Token& open) {
    node->shape = std::move(shape);
    finish_shape(p, *node, keyword, open);
    return node;
}

}  // namespace

ObjectRef parse_sphere(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    SphereShape s;
    s.centre = p.parse_vector();
    p.accept_comma();
    s.radius = p.parse_float("as the sphere radius");
    return finish(p, node, s, keyword, open);
}

ObjectRef parse_box(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    const Vec3 a = p.parse_vector();
    p.accept_comma();
    const Vec3 b = p.parse_vector();
    const BoxShape box{{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                       {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
    return finish(p, node, box, keyword, open);
}

ObjectRef parse_cylinder(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    CylinderShape c;
    c.base = p.parse_vector();
    p.accept_comma();
    c.cap = p.parse_vector();
    p.accept_comma();
    c.radius = p.parse_float("as the cylinder radius");
    check_ends(p, keyword, c.base, c.cap);
    c.open = p.accept(Keyword::open);
    return finish(p, node, c, keyword, open);
}

ObjectRef parse_cone(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    ConeShape c;
    c.base = p.parse_vector();
    p.accept_comma();
    c.base_radius = p.parse_float("as the cone's base radius");
    p.accept_comma();
    c.cap = p.parse_vector();
    p.accept_comma();
    c.cap_radius = p.parse_float("as the cone's cap radius");
    check_ends(p, keyword, c.base, c.cap);
    c.open = p.accept(Keyword::open);
    return finish(p, node, c, keyword, open);
}

ObjectRef parse_torus(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    TorusShape t;
    t.major_radius = p.parse_float("as the torus major radius");
    p.accept_comma();
    t.minor_radius = p.parse_float("as the torus minor radius");
    return finish(p, node, t, keyword, open);
}

ObjectRef parse_ovus(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    OvusShape o;
    o.bottom_radius = p.parse_float("as the ovus bottom radius");
    p.accept_comma();
    o.top_radius = p.parse_float("as the ovus top radius");
    return finish(p, node, o, keyword, open);
}

ObjectRef parse_superellipsoid(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    const Vec2 exponents = parse_vec2(p, "<e, n> of the superellipsoid");
    return finish(p, node, SuperellipsoidShape{exponents.x, exponents.y}, keyword, open);
}

ObjectRef parse_plane(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    const Token at = p.peek();
    const Vec3 n = p.parse_vector();
    p.accept_comma();
    if (length(n) < 1e-10) p.fail(at, "degenerate plane normal (zero length)");
    return finish(p, node, PlaneShape{normalized(n), p.parse_float("as the plane distance")},
                  keyword, open);
}

ObjectRef parse_disc(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    DiscShape d;
    d.centre = p.parse_vector();
    p.accept_comma();
    d.normal = p.parse_vector();
    if (length(d.normal) > 0) d.normal = normalized(d.normal);
    p.accept_comma();
    d.radius = p.parse_float("as the disc radius");
    if (p.accept(Symbol::comma) || p.starts_expression(p.peek()))
        d.hole_radius = p.parse_float("as the hole radius");
    return finish(p, node, d, keyword, open);
}

ObjectRef parse_triangle(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    TriangleShape t;
    t.a = p.parse_vector();
    p.accept_comma();
    t.b = p.parse_vector();
    p.accept_comma();
    t.c = p.parse_vector();
    return finish(p, node, t, keyword, open);
}

ObjectRef parse_smooth_triangle(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    SmoothTriangleShape t;
    for (auto [corner, normal] :
         {std::pair{&t.a, &t.normal_a}, {&t.b, &t.normal_b}, {&t.c, &t.normal_c}}) {
        *corner = p.parse_vector();
        p.accept_comma();
        *normal = p.parse_vector();
        p.accept_comma();
    }
    return finish(p, node, t, keyword, open);
}

// poly { ORDER, <A1 ... An> }, cubic { <A1 ... A20> }, quartic { <A1 ... A35> }.
ObjectRef parse_poly(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    PolynomialShape poly;
    if (keyword.is(Keyword::poly)) {
        poly.order = parse_polynomial_order(p, keyword);
        p.accept_comma();
    } else {
        poly.order = keyword.is(Keyword::cubic) ? 3 : 4;
    }
    poly.coefficients = parse_coefficients(p, keyword, polynomial_terms(poly.order).size());
    return finish(p, node, poly, keyword, open);
}

// polynomial { ORDER, xyz(i, j, k): VALUE ... }: terms in any order, the last of a repeated
// one counts, the others are 0.
ObjectRef parse_polynomial(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    PolynomialShape poly;
    poly.order = parse_polynomial_order(p, keyword);
    p.accept_comma();
    const std::vector<std::array<int, 3>> terms = polynomial_terms(poly.order);
    poly.coefficients.assign(terms.size(), 0.0);
    while (p.peek().is(Keyword::xyz)) {
        const Token xyz = p.next();
        p.expect(Symbol::lparen, "after 'xyz'");
        std::array<int, 3> powers{};
        for (int axis = 0; axis < 3; ++axis) {
            if (axis > 0) p.expect(Symbol::comma, "between the powers of 'xyz'");
            powers[axis] = p.parse_int("as a power in 'xyz'", 0);
        }
        p.expect(Symbol::rparen, "after the powers of 'xyz'");
        p.expect(Symbol::colon, "after 'xyz(...)'");
        const double value = p.parse_float("as the coefficient of 'xyz(...)'");
        p.accept_comma();
        const auto term = std::find(terms.begin(), terms.end(), powers);
        if (term == terms.end())
            p.fail(xyz, fmt::format("xyz({},{},{}) is not a term of a polynomial of order {}",
                                    powers[0], powers[1], powers[2], poly.order));
        poly.coefficients[static_cast<size_t>(term - terms.begin())] = value;
    }
    return finish(p, node, poly, keyword, open);
}

ObjectRef parse_quadric(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword);
    QuadricShape q;
    q.squares = p.parse_vector();
    p.accept_comma();
    q.mixed = p.parse_vector();
    p.accept_comma();
    q.linear = p.parse_vector();
    p.accept_comma();
    q.constant = p.parse_float("as the quadric's constant term");
    return finish(p, node, q, keyword, open);
}

const char* shape_keyword(const Shape& shape) {
    struct Name {
        const char* operator()(const SphereShape&) const { return "sphere"; }
        const char* operator()(const BoxShape&) const { return "box"; }
        const char* operator()(const PlaneShape&) const { return "plane"; }
        const char* operator()(const TriangleShape&) const { return "triangle"; }
        const char* operator()(const MeshShape&) const { return "mesh"; }
        const char* operator()(const MeshFileShape&) const { return "mesh_file"; }
        const char* operator()(const CylinderShape&) const { return "cylinder"; }
        const char* operator()(const ConeShape&) const { return "cone"; }
        const char* operator()(const TorusShape&) const { return "torus"; }
        const char* operator()(const OvusShape&) const { return "ovus"; }
        const char* operator()(const SuperellipsoidShape&) const { return "superellipsoid"; }
        const char* operator()(const BlobShape&) const { return "blob"; }
        const char* operator()(const HeightFieldShape&) const { return "height_field"; }
        const char* operator()(const IsosurfaceShape&) const { return "isosurface"; }
        const char* operator()(const ParametricShape&) const { return "parametric"; }
        const char* operator()(const JuliaFractalShape&) const { return "julia_fractal"; }
        const char* operator()(const LatheShape&) const { return "lathe"; }
        const char* operator()(const PrismShape&) const { return "prism"; }
        const char* operator()(const SorShape&) const { return "sor"; }
        const char* operator()(const SphereSweepShape&) const { return "sphere_sweep"; }
        const char* operator()(const TextShape&) const { return "text"; }
        const char* operator()(const BicubicPatchShape&) const { return "bicubic_patch"; }
        const char* operator()(const DiscShape&) const { return "disc"; }
        const char* operator()(const SmoothTriangleShape&) const { return "smooth_triangle"; }
        const char* operator()(const PolygonShape&) const { return "polygon"; }
        const char* operator()(const PolynomialShape& s) const {
            return s.order == 3 ? "cubic" : s.order == 4 ? "quartic" : "poly";
        }
        const char* operator()(const QuadricShape&) const { return "quadric"; }
        const char* operator()(const CsgShape& s) const {
            switch (s.operation) {
                case CsgShape::Operation::merge: return "merge";
                case CsgShape::Operation::intersection: return "intersection";
                case CsgShape::Operation::difference: return "difference";
                case CsgShape::Operation::union_of: break;
            }
            return "union";
        }
    };
    return std::visit(Name{}, shape);
}

}  // namespace rayset::tracer
