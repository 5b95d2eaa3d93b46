// Spline evaluation, each kind as POV-Ray 3.7 computes it (found by evaluating splines of
// unit points with its #debug output, which gives the weight of every point directly):
// - linear: straight lines between neighbouring points.
// - quadratic: on [t_i, t_i+1] the parabola through points i-1, i, i+1 (through 0, 1, 2 on the
//   first segment).
// - cubic: Hermite segments whose tangent at each point is the mean of the slopes of its two
//   neighbouring chords (Catmull-Rom for evenly spaced parameters); valid between the second
//   and the next-to-last point, and linear when there are only two points.
// - natural: the natural cubic spline (second derivative zero at both ends).
// Outside the valid range every kind returns the nearest valid end point.
#include "tracer/scene_language/splines.h"

#include <algorithm>

#include <fmt/format.h>

#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace {

Numeric weighted(const std::vector<Numeric>& points, int terms,
                 std::initializer_list<std::pair<int, double>> parts) {
    Numeric r;
    r.terms = terms;
    for (const auto& [index, weight] : parts)
        for (int k = 0; k < terms; ++k) r.v[k] += weight * points[static_cast<size_t>(index)].v[k];
    return r;
}

// Index i of the segment [t_i, t_i+1] holding t, for t inside [t_first, t_last].
int segment_of(const std::vector<double>& t, double x, int first, int last) {
    const auto it = std::upper_bound(t.begin() + first, t.begin() + last, x);
    return std::clamp(static_cast<int>(it - t.begin()) - 1, first, last - 1);
}

// Second derivatives of the natural cubic spline through the points, term by term (the
// tridiagonal system solved by elimination).
std::vector<Numeric> natural_second_derivatives(const std::vector<double>& t,
                                                const std::vector<Numeric>& p, int terms) {
    const size_t n = t.size();
    std::vector<Numeric> m(n), rhs(n);
    std::vector<double> diagonal(n, 1.0), upper(n, 0.0);
    for (Numeric& v : m) v.terms = terms;
    for (size_t i = 1; i + 1 < n; ++i) {
        const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
        const double lower = h0;
        diagonal[i] = 2 * (h0 + h1) - lower * upper[i - 1];
        upper[i] = h1 / diagonal[i];
        for (int k = 0; k < terms; ++k) {
            const double r =
                6 * ((p[i + 1].v[k] - p[i].v[k]) / h1 - (p[i].v[k] - p[i - 1].v[k]) / h0);
            rhs[i].v[k] = (r - lower * rhs[i - 1].v[k]) / diagonal[i];
        }
    }
    for (size_t i = n - 1; i-- > 1;)
        for (int k = 0; k < terms; ++k) m[i].v[k] = rhs[i].v[k] - upper[i] * m[i + 1].v[k];
    return m;
}

}  // namespace

Numeric Spline::evaluate(double x, Type as) const {
    const int n = static_cast<int>(points.size());
    const std::vector<double>& t = parameters;
    if (n == 1) return points[0];
    if (as == Type::cubic && n > 2) {
        // Valid between the second and the next-to-last point.
        if (x <= t[1]) return points[1];
        if (x >= t[static_cast<size_t>(n - 2)]) return points[static_cast<size_t>(n - 2)];
    } else {
        if (x <= t.front()) return points.front();
        if (x >= t.back()) return points.back();
    }
    if (as == Type::linear || n == 2) {
        const int i = segment_of(t, x, 0, n - 1);
        const double s = (x - t[i]) / (t[i + 1] - t[i]);
        return weighted(points, terms, {{i, 1 - s}, {i + 1, s}});
    }
    if (as == Type::quadratic) {
        const int i = segment_of(t, x, 0, n - 1);
        const int a = std::max(i - 1, 0), b = a + 1, c = a + 2;
        auto lagrange = [&](int j, int k, int l) {
            return (x - t[k]) * (x - t[l]) / ((t[j] - t[k]) * (t[j] - t[l]));
        };
        return weighted(points, terms,
                        {{a, lagrange(a, b, c)}, {b, lagrange(b, a, c)}, {c, lagrange(c, a, b)}});
    }
    if (as == Type::cubic) {
        const int i = segment_of(t, x, 1, n - 2);
        const double h = t[i + 1] - t[i], s = (x - t[i]) / h;
        const double h00 = (2 * s - 3) * s * s + 1, h10 = ((s - 2) * s + 1) * s,
                     h01 = (3 - 2 * s) * s * s, h11 = (s - 1) * s * s;
        // Tangents in the segment's parameter: h times the mean of the neighbouring chord slopes.
        const double a0 = t[i] - t[i - 1], a1 = h, a2 = t[i + 2] - t[i + 1];
        const double w = 0.5 * h;
        return weighted(points, terms,
                        {{i - 1, -w / a0 * h10},
                         {i, h00 + w * (1 / a0 - 1 / a1) * h10 - w / a1 * h11},
                         {i + 1, h01 + w / a1 * h10 + w * (1 / a1 - 1 / a2) * h11},
                         {i + 2, w / a2 * h11}});
    }
    // natural
    const std::vector<Numeric> m = natural_second_derivatives(t, points, terms);
    const int i = segment_of(t, x, 0, n - 1);
    const double h = t[i + 1] - t[i], a = (t[i + 1] - x) / h, b = (x - t[i]) / h;
    Numeric r;
    r.terms = terms;
    for (int k = 0; k < terms; ++k)
        r.v[k] = a * points[i].v[k] + b * points[i + 1].v[k] +
                 ((a * a * a - a) * m[i].v[k] + (b * b * b - b) * m[i + 1].v[k]) * h * h / 6;
    return r;
}

SplineRef Parser::parse_spline(const Token& keyword) {
    auto spline = std::make_shared<Spline>();
    const Token open = expect_open(keyword);
    if (const SplineRef* declared = peek_declared<SplineRef>()) {
        *spline = **declared;
        next();
    }
    for (;;) {
        const Token& token = peek();
        if (token.is(Keyword::linear_spline))
            spline->type = Spline::Type::linear;
        else if (token.is(Keyword::quadratic_spline))
            spline->type = Spline::Type::quadratic;
        else if (token.is(Keyword::cubic_spline))
            spline->type = Spline::Type::cubic;
        else if (token.is(Keyword::natural_spline))
            spline->type = Spline::Type::natural;
        else
            break;
        next();
    }
    while (!peek_is(Symbol::rbrace)) {
        const double parameter = parse_float("as a spline parameter");
        accept_comma();
        const Token at = peek();
        // A float point is read as a 2-term vector <f, f> (POV-Ray's behaviour).
        Numeric point = parse_numeric();
        if (point.terms == 1) point = point.promoted(2);
        accept_comma();
        spline->terms = std::max(spline->terms, point.terms);
        const auto where =
            std::lower_bound(spline->parameters.begin(), spline->parameters.end(), parameter);
        const size_t index = static_cast<size_t>(where - spline->parameters.begin());
        if (where != spline->parameters.end() && *where == parameter) {
            spline->points[index] = point;
        } else {
            spline->parameters.insert(where, parameter);
            spline->points.insert(spline->points.begin() + static_cast<long>(index), point);
        }
        (void)at;
    }
    expect_close(keyword, open);
    if (spline->points.empty()) fail(keyword, "a spline needs at least one point");
    for (Numeric& point : spline->points) point = point.promoted(spline->terms);
    return spline;
}

Numeric Parser::call_spline(const Token& name, const Spline& spline) {
    const Token open =
        expect(Symbol::lparen, [&] { return fmt::format("after spline '{}'", word(name)); });
    const double t = parse_float(fmt::format("as the parameter of spline '{}'", word(name)));
    Spline::Type type = spline.type;
    if (accept(Symbol::comma)) {
        const Token kind = next();
        if (kind.is(Keyword::linear_spline))
            type = Spline::Type::linear;
        else if (kind.is(Keyword::quadratic_spline))
            type = Spline::Type::quadratic;
        else if (kind.is(Keyword::cubic_spline))
            type = Spline::Type::cubic;
        else if (kind.is(Keyword::natural_spline))
            type = Spline::Type::natural;
        else
            fail_expected("linear_spline, quadratic_spline, cubic_spline or natural_spline", kind);
    }
    expect(Symbol::rparen, [&] {
        return fmt::format("to close the call of '{}' opened at {}", word(name),
                           location_of(open).str());
    });
    return spline.evaluate(t, type);
}

}  // namespace rayset::tracer
