// Exact geometry of the simple shapes (see shape_geometry.h).
#include "tracer/scene_language/shape_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <memory>
#include <stdexcept>

#include "tracer/scene_language/functions.h"
#include "tracer/scene_language/quadratic.h"
#include "tracer/scene_language/text_outline.h"

namespace rayset::tracer {
// Moller-Trumbore.
bool triangle_crossing(Vec3 a, Vec3 b, Vec3 c, Vec3 o, Vec3 d, double& t, double& u, double& v) {
    const Vec3 e1 = b - a, e2 = c - a, pv = cross(d, e2);
    const double det = dot(e1, pv);
    if (det == 0) return false;
    const Vec3 tv = o - a;
    u = dot(tv, pv) / det;
    if (u < 0 || u > 1) return false;
    const Vec3 qv = cross(tv, e1);
    v = dot(d, qv) / det;
    if (v < 0 || u + v > 1) return false;
    t = dot(e2, qv) / det;
    return true;
}

namespace {

// Calls term(coefficient, i, j, k) for each term coefficient x^i y^j z^k of a polynomial in
// POV-Ray's order (x^order first; see grammar_shapes.cpp).
template <class Term>
void for_each_term(const PolynomialShape& poly, Term&& term) {
    size_t index = 0;
    for (int i = poly.order; i >= 0; --i)
        for (int j = poly.order - i; j >= 0; --j)
            for (int k = poly.order - i - j; k >= 0; --k) term(poly.coefficients[index++], i, j, k);
}

double polynomial_value(const PolynomialShape& poly, Vec3 p) {
    double sum = 0;
    for_each_term(poly, [&](double a, int i, int j, int k) {
        sum += a * std::pow(p.x, i) * std::pow(p.y, j) * std::pow(p.z, k);
    });
    return sum;
}

double quadric_value(const QuadricShape& q, Vec3 p) {
    return q.squares.x * p.x * p.x + q.squares.y * p.y * p.y + q.squares.z * p.z * p.z +
           q.mixed.x * p.x * p.y + q.mixed.y * p.x * p.z + q.mixed.z * p.y * p.z +
           dot(q.linear, p) + q.constant;
}

// Whether (x, z) is inside the closed outlines of a linear prism (each sub-outline closes
// where its first point repeats): an odd number of edge crossings, so that where an even
// number of outlines overlap there is a hole, as POV-Ray has it.
bool inside_outlines(const std::vector<Vec2>& points, double x, double z) {
    bool inside = false;
    size_t start = 0;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const Vec2 a = points[i], b = points[i + 1];
        if ((a.y > z) != (b.y > z) && x < a.x + (z - a.y) * (b.x - a.x) / (b.y - a.y))
            inside = !inside;
        if (b.x == points[start].x && b.y == points[start].y) start = i + 2, ++i;
    }
    return inside;
}

// A prism of linear spline between its heights; a conic one's outline scales with the height.
bool prism_inside(const PrismShape& prism, Vec3 p, bool& inside) {
    if (prism.spline != SplineKind::linear) return false;
    const double low = std::min(prism.height1, prism.height2);
    const double high = std::max(prism.height1, prism.height2);
    inside = p.y >= low && p.y <= high;
    if (!inside) return true;
    if (!prism.conic_sweep) {
        inside = inside_outlines(prism.points, p.x, p.z);
    } else {
        inside = p.y != 0 && inside_outlines(prism.points, p.x / p.y, p.z / p.y);
    }
    return true;
}

// Calls edge(a, b) for each edge of a linear prism's outlines (not the step from one closed
// outline to the next).
template <class Edge>
void for_each_outline_edge(const std::vector<Vec2>& points, Edge&& edge) {
    size_t start = 0;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        edge(points[i], points[i + 1]);
        const Vec2 b = points[i + 1];
        if (b.x == points[start].x && b.y == points[start].y) start = i + 2, ++i;
    }
}

// A linear prism's crossings: its walls (each edge swept along y, or toward the origin for a
// conic sweep: the plane through the origin and the edge lifted to y = 1) between its heights,
// and its caps where the outline holds the point (unless open). Walls' normals point out of
// the prism (checked by a step across them).
void prism_hits(const PrismShape& prism, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const double low = std::min(prism.height1, prism.height2);
    const double high = std::max(prism.height1, prism.height2);
    auto outline_point = [&](Vec3 p, double& x, double& z) {
        if (!prism.conic_sweep) {
            x = p.x, z = p.z;
            return true;
        }
        if (p.y == 0) return false;
        x = p.x / p.y, z = p.z / p.y;
        return true;
    };
    auto outward = [&](Vec3 p, Vec3 n) {
        const double step = 1e-7 * (1 + length(p));
        bool in = false;
        prism_inside(prism, p + step * normalized(n), in);
        return in ? -1 * n : n;
    };
    for_each_outline_edge(prism.points, [&](Vec2 a, Vec2 b) {
        // The wall's plane: through a and b at y = 1, and along y (linear) or through the
        // origin (conic).
        const Vec3 a3{a.x, 1, a.y}, b3{b.x, 1, b.y};
        const Vec3 n = prism.conic_sweep ? cross(a3, b3) : Vec3{b.y - a.y, 0, a.x - b.x};
        const double along = dot(n, d);
        if (along == 0 || is_zero(n)) return;
        const double t = (prism.conic_sweep ? -dot(n, o) : dot(n, a3 - o)) / along;
        const Vec3 p = o + t * d;
        if (p.y < low || p.y > high) return;
        double x = 0, z = 0;
        if (!outline_point(p, x, z)) return;
        const Vec2 edge{b.x - a.x, b.y - a.y};
        const double u =
            ((x - a.x) * edge.x + (z - a.y) * edge.y) / (edge.x * edge.x + edge.y * edge.y);
        if (u < 0 || u > 1) return;
        hits.push_back({t, outward(p, n)});
    });
    if (prism.open || d.y == 0) return;
    for (const double h : {low, high}) {
        const double t = (h - o.y) / d.y;
        const Vec3 p = o + t * d;
        double x = 0, z = 0;
        if (outline_point(p, x, z) && inside_outlines(prism.points, x, z))
            hits.push_back({t, {0, h == high ? 1.0 : -1.0, 0}});
    }
}

// One piece of a lathe's profile: radius and height as cubics in t in [0, 1] (t^0 first).
struct ProfilePiece {
    std::array<double, 4> r{}, y{};
};

double cubic_at(const std::array<double, 4>& c, double t) {
    return ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
}

// A lathe's profile as POV-Ray draws it (read back from POV-Ray with trace): straight lines
// between the points; quadratic pieces from each point to the next through the parabola that
// the point before also lies on (the first point only steers); Catmull-Rom pieces (the first
// and last points only steer); cubic Bezier pieces of four points each.
std::vector<ProfilePiece> lathe_profile(const LatheShape& lathe) {
    const std::vector<Vec2>& p = lathe.points;
    std::vector<ProfilePiece> pieces;
    auto add = [&](Vec2 c0, Vec2 c1, Vec2 c2, Vec2 c3) {
        pieces.push_back({{c0.x, c1.x, c2.x, c3.x}, {c0.y, c1.y, c2.y, c3.y}});
    };
    auto lin = [](double a, Vec2 u, double b, Vec2 v) {
        return Vec2{a * u.x + b * v.x, a * u.y + b * v.y};
    };
    const size_t n = p.size();
    switch (lathe.spline) {
        case SplineKind::linear:
            for (size_t i = 0; i + 1 < n; ++i) add(p[i], lin(1, p[i + 1], -1, p[i]), {}, {});
            break;
        case SplineKind::quadratic:
            for (size_t i = 1; i + 1 < n; ++i) {
                const Vec2 a = p[i - 1], b = p[i], c = p[i + 1];
                add(b, lin(0.5, c, -0.5, a), {0.5 * (c.x + a.x) - b.x, 0.5 * (c.y + a.y) - b.y},
                    {});
            }
            break;
        case SplineKind::cubic:
            for (size_t i = 1; i + 2 < n; ++i) {
                const Vec2 p0 = p[i - 1], p1 = p[i], p2 = p[i + 1], p3 = p[i + 2];
                add(p1, lin(0.5, p2, -0.5, p0),
                    {p0.x - 2.5 * p1.x + 2 * p2.x - 0.5 * p3.x,
                     p0.y - 2.5 * p1.y + 2 * p2.y - 0.5 * p3.y},
                    {-0.5 * p0.x + 1.5 * p1.x - 1.5 * p2.x + 0.5 * p3.x,
                     -0.5 * p0.y + 1.5 * p1.y - 1.5 * p2.y + 0.5 * p3.y});
            }
            break;
        case SplineKind::bezier:
            for (size_t i = 0; i + 3 < n; i += 4) {
                const Vec2 p0 = p[i], p1 = p[i + 1], p2 = p[i + 2], p3 = p[i + 3];
                add(p0, {3 * (p1.x - p0.x), 3 * (p1.y - p0.y)},
                    {3 * (p0.x - 2 * p1.x + p2.x), 3 * (p0.y - 2 * p1.y + p2.y)},
                    {p3.x - p0.x + 3 * (p1.x - p2.x), p3.y - p0.y + 3 * (p1.y - p2.y)});
            }
            break;
    }
    return pieces;
}

}  // namespace

struct LatheProfile {
    std::vector<ProfilePiece> pieces;
};

namespace {

// What a prepared shape holds (prepare_shape).
template <class T>
const T& prepared(const std::shared_ptr<const T>& data) {
    if (!data) throw std::logic_error("shape geometry asked of a shape not prepared");
    return *data;
}

// The real roots of c[0] + c[1] t + ... + c[n] t^n in [lo, hi]: each monotone piece between the
// roots of the derivative is bisected.
std::vector<double> roots_between(std::vector<double> c, double lo, double hi) {
    while (c.size() > 1 && c.back() == 0) c.pop_back();
    std::vector<double> roots;
    if (c.size() < 2) return roots;
    auto value = [&](double t) {
        double v = 0;
        for (size_t i = c.size(); i-- > 0;) v = v * t + c[i];
        return v;
    };
    std::vector<double> derivative;
    for (size_t i = 1; i < c.size(); ++i) derivative.push_back(double(i) * c[i]);
    std::vector<double> ends{lo};
    for (double t : roots_between(derivative, lo, hi)) ends.push_back(t);
    ends.push_back(hi);
    for (size_t k = 0; k + 1 < ends.size(); ++k) {
        double a = ends[k], b = ends[k + 1];
        double fa = value(a), fb = value(b);
        if (fa == 0) {
            if (roots.empty() || roots.back() != a) roots.push_back(a);
            continue;
        }
        if ((fa < 0) == (fb < 0)) continue;
        for (int iteration = 0; iteration < 200 && b - a > 1e-15 * std::max(1.0, std::abs(a));
             ++iteration) {
            const double m = 0.5 * (a + b), fm = value(m);
            if ((fm < 0) == (fa < 0))
                a = m, fa = fm;
            else
                b = m;
        }
        roots.push_back(0.5 * (a + b));
    }
    return roots;
}

// The roots of a t^2 + b t + c (quadratic.h), in increasing order.
std::vector<double> quadratic_roots(double a, double b, double c) {
    double roots[2];
    return std::vector<double>(roots, roots + solve_quadratic(a, b, c, roots));
}

// A triangle's hit; its normal is POV-Ray's, (c - a) x (b - a).
void triangle_hit(Vec3 a, Vec3 b, Vec3 c, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    double t, u, v;
    if (triangle_crossing(a, b, c, o, d, t, u, v)) hits.push_back({t, cross(c - a, b - a)});
}

void mesh_hits(const TriangleMesh& mesh, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    std::vector<ShapeHit> all;
    for (const auto& f : mesh.faces)
        triangle_hit(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]], o, d, all);
    for (const ShapeHit& hit : all)
        if (hit.t > 0) hits.push_back(hit);
}

void plane_hit(Vec3 n, double distance, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const double along = dot(n, d);
    if (along != 0) hits.push_back({(distance - dot(n, o)) / along, n});
}

void box_hits(const BoxShape& box, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const double lo[3] = {box.minimum.x, box.minimum.y, box.minimum.z};
    const double hi[3] = {box.maximum.x, box.maximum.y, box.maximum.z};
    const double origin[3] = {o.x, o.y, o.z}, dir[3] = {d.x, d.y, d.z};
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0) continue;
        for (int side = 0; side < 2; ++side) {
            const double t = ((side ? hi : lo)[axis] - origin[axis]) / dir[axis];
            const Vec3 p = o + t * d;
            const double q[3] = {p.x, p.y, p.z};
            bool on_face = true;
            for (int other = 0; other < 3; ++other)
                if (other != axis && (q[other] < lo[other] || q[other] > hi[other]))
                    on_face = false;
            if (!on_face) continue;
            Vec3 n;
            (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = side ? 1 : -1;
            hits.push_back({t, n});
        }
    }
}

// A cylinder (equal radii) or cone about base -> cap, with its caps unless open.
void cone_hits(Vec3 base, Vec3 cap, double r0, double r1, bool open, Vec3 o, Vec3 d,
               std::vector<ShapeHit>& hits) {
    const Vec3 axis = cap - base;
    const double len = length(axis);
    const Vec3 u = (1 / len) * axis;
    const double slope = (r1 - r0) / len;
    const Vec3 w = o - base;
    const double wu = dot(w, u), du = dot(d, u);
    const Vec3 wr = w - wu * u, dr = d - du * u;
    const double rw = r0 + slope * wu;
    for (double t : quadratic_roots(dot(dr, dr) - slope * slope * du * du,
                                    2 * (dot(wr, dr) - slope * rw * du), dot(wr, wr) - rw * rw)) {
        const double s = wu + t * du;
        if (s < 0 || s > len) continue;
        const Vec3 radial = wr + t * dr;
        const double rl = length(radial);
        if (rl == 0) continue;
        hits.push_back({t, (1 / rl) * radial - slope * u});
    }
    if (open || du == 0) return;
    for (int end = 0; end < 2; ++end) {
        const double t = ((end ? len : 0) - wu) / du, r = end ? r1 : r0;
        const Vec3 radial = wr + t * dr;
        if (dot(radial, radial) <= r * r) hits.push_back({t, end ? u : -u});
    }
}

std::vector<double> times(const std::vector<double>& a, const std::vector<double>& b);

// Whether (radius rho, height y) of the profile's plane is inside the lathe: an odd number of
// the profile's crossings with the half-line from it outward (POV-Ray's parity rule).
bool lathe_inside(const std::vector<ProfilePiece>& pieces, double rho, double y) {
    bool inside = false;
    for (const ProfilePiece& piece : pieces) {
        std::vector<double> c(piece.y.begin(), piece.y.end());
        c[0] -= y;
        for (double t : roots_between(c, 0, 1))
            if (t < 1 && std::abs(cubic_at(piece.r, t)) > rho) inside = !inside;
    }
    return inside;
}

// The line's crossings with the surface turned from each profile piece: x^2 + z^2 = r(t)^2 at
// height y(t). Along a line that climbs, the line's parameter is a cubic in t and the
// condition a sextic in t; along a level line, the heights' roots give t and each a circle.
void lathe_hits(const LatheShape& lathe, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const std::vector<ProfilePiece>& pieces = prepared(lathe.profile).pieces;
    auto add_hit = [&](const ProfilePiece& piece, double t, double s) {
        const Vec3 p = o + s * d;
        const double dr = (3 * piece.r[3] * t + 2 * piece.r[2]) * t + piece.r[1];
        const double dy = (3 * piece.y[3] * t + 2 * piece.y[2]) * t + piece.y[1];
        const double rho = std::hypot(p.x, p.z);
        const Vec3 radial = rho > 0 ? Vec3{p.x / rho, 0, p.z / rho} : Vec3{1, 0, 0};
        Vec3 n = dy * radial + Vec3{0, -dr, 0};  // across the profile's tangent (dr, dy)
        // Outward: a step along the normal leaves the solid.
        const double step = 1e-7 * (1 + length(p));
        const Vec3 q = p + step * normalized(n);
        if (lathe_inside(pieces, std::hypot(q.x, q.z), q.y)) n = -1 * n;
        hits.push_back({s, n});
    };
    for (const ProfilePiece& piece : pieces) {
        if (d.y != 0) {
            // s(t) = (y(t) - o.y) / d.y; X = o.x + d.x s, Z = o.z + d.z s.
            std::vector<double> sc(piece.y.begin(), piece.y.end());
            sc[0] -= o.y;
            for (double& c : sc) c /= d.y;
            std::vector<double> x(4), z(4);
            for (int k = 0; k < 4; ++k) x[k] = d.x * sc[k], z[k] = d.z * sc[k];
            x[0] += o.x, z[0] += o.z;
            const std::vector<double> r(piece.r.begin(), piece.r.end());
            std::vector<double> f = times(x, x);
            const std::vector<double> zz = times(z, z), rr = times(r, r);
            for (size_t k = 0; k < f.size(); ++k) f[k] += zz[k] - rr[k];
            for (double t : roots_between(f, 0, 1)) {
                double s = 0;
                for (int k = 3; k >= 0; --k) s = s * t + sc[k];
                add_hit(piece, t, s);
            }
        } else {
            std::vector<double> c(piece.y.begin(), piece.y.end());
            c[0] -= o.y;
            for (double t : roots_between(c, 0, 1)) {
                const double r = cubic_at(piece.r, t);
                const double a = d.x * d.x + d.z * d.z, b = 2 * (o.x * d.x + o.z * d.z),
                             cc = o.x * o.x + o.z * o.z - r * r;
                for (double s : quadratic_roots(a, b, cc)) add_hit(piece, t, s);
            }
        }
    }
}

void torus_hits(const TorusShape& torus, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const double big = torus.major_radius * torus.major_radius,
                 small = torus.minor_radius * torus.minor_radius;
    const double outer = std::abs(torus.major_radius) + std::abs(torus.minor_radius);
    const std::vector<double> span =
        quadratic_roots(dot(d, d), 2 * dot(o, d), dot(o, o) - outer * outer);
    if (span.size() < 2) return;
    // (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) along p = o + t d.
    const double a = dot(d, d), b = 2 * dot(o, d), c = dot(o, o) + big - small;
    const double dxz = d.x * d.x + d.z * d.z, odxz = o.x * d.x + o.z * d.z,
                 oxz = o.x * o.x + o.z * o.z;
    const std::vector<double> coefficients{c * c - 4 * big * oxz, 2 * b * c - 8 * big * odxz,
                                           b * b + 2 * a * c - 4 * big * dxz, 2 * a * b, a * a};
    const double margin = 1e-9 * (span[1] - span[0]);
    for (double t : roots_between(coefficients, span[0] - margin, span[1] + margin)) {
        const Vec3 p = o + t * d;
        const double ring = std::hypot(p.x, p.z);
        const Vec3 centre =
            ring > 0 ? Vec3{torus.major_radius * p.x / ring, 0, torus.major_radius * p.z / ring}
                     : Vec3{};
        hits.push_back({t, p - centre});
    }
}

// The stretch [near, far] of the line o + t d inside the box lower..upper (the slab test);
// false when the line misses it.
bool box_span(Vec3 lower, Vec3 upper, Vec3 o, Vec3 d, double& near, double& far) {
    near = -1e300, far = 1e300;
    const double origin[3] = {o.x, o.y, o.z}, direction[3] = {d.x, d.y, d.z};
    const double low[3] = {lower.x, lower.y, lower.z}, high[3] = {upper.x, upper.y, upper.z};
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] == 0) {
            if (origin[axis] < low[axis] || origin[axis] > high[axis]) return false;
            continue;
        }
        double t0 = (low[axis] - origin[axis]) / direction[axis];
        double t1 = (high[axis] - origin[axis]) / direction[axis];
        if (t0 > t1) std::swap(t0, t1);
        near = std::max(near, t0), far = std::min(far, t1);
    }
    return near <= far;
}

// The stretch of the line o + t d inside a container, [near, far]; false when it misses.
bool container_span(const ContainedBy& c, Vec3 o, Vec3 d, double& near, double& far) {
    if (c.kind == ContainedBy::Kind::sphere) {
        const Vec3 w = o - c.centre;
        const std::vector<double> t =
            quadratic_roots(dot(d, d), 2 * dot(w, d), dot(w, w) - c.radius * c.radius);
        if (t.size() < 2) return false;
        near = t[0], far = t[1];
        return true;
    }
    return box_span(c.minimum, c.maximum, o, d, near, far) && near < far;
}

// The container's outward normal at a point of its surface.
Vec3 container_normal(const ContainedBy& c, Vec3 p) {
    if (c.kind == ContainedBy::Kind::sphere) return p - c.centre;
    const Vec3 middle = 0.5 * (c.minimum + c.maximum), half = 0.5 * (c.maximum - c.minimum);
    const Vec3 q = p - middle;
    const double ax = std::abs(q.x) / half.x, ay = std::abs(q.y) / half.y,
                 az = std::abs(q.z) / half.z;
    if (ax >= ay && ax >= az) return {q.x < 0 ? -1.0 : 1.0, 0, 0};
    if (ay >= az) return {0, q.y < 0 ? -1.0 : 1.0, 0};
    return {0, 0, q.z < 0 ? -1.0 : 1.0};
}

// Crossings of the line with an implicit surface value(p) = 0 (negative inside) between t0
// and t1: the value sampled at `steps` even steps and each change of sign bisected to the last
// bit; `gradient` gives the outward normal there.
// The gradient of `value` at p (up to the factor 1 / (2 h)) by central differences over h.
template <class Value>
Vec3 central_differences(const Value& value, Vec3 p, double h) {
    return {value(p + Vec3{h, 0, 0}) - value(p - Vec3{h, 0, 0}),
            value(p + Vec3{0, h, 0}) - value(p - Vec3{0, h, 0}),
            value(p + Vec3{0, 0, h}) - value(p - Vec3{0, 0, h})};
}

template <class Value, class Gradient>
void implicit_hits(Value&& value, Gradient&& gradient, Vec3 o, Vec3 d, double t0, double t1,
                   int steps, std::vector<ShapeHit>& hits) {
    const double step = (t1 - t0) / steps;
    double t_before = t0, before = value(o + t0 * d);
    for (int i = 1; i <= steps; ++i) {
        const double t_after = i == steps ? t1 : t0 + i * step;
        const double after = value(o + t_after * d);
        if ((before < 0) != (after < 0)) {
            double lo = t_before, hi = t_after;
            const bool inside_first = before < 0;
            for (int k = 0; k < 64; ++k) {
                const double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break;
                ((value(o + mid * d) < 0) == inside_first ? lo : hi) = mid;
            }
            const double t = 0.5 * (lo + hi);
            hits.push_back({t, gradient(o + t * d)});
        }
        t_before = t_after, before = after;
    }
}

// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) - 1: negative inside the superellipsoid.
double superellipsoid_value(const SuperellipsoidShape& s, Vec3 p) {
    const double e = s.east_west, n = s.north_south;
    const double across = std::pow(std::abs(p.x), 2 / e) + std::pow(std::abs(p.y), 2 / e);
    return std::pow(across, e / n) + std::pow(std::abs(p.z), 2 / n) - 1;
}

Vec3 superellipsoid_gradient(const SuperellipsoidShape& s, Vec3 p) {
    const double e = s.east_west, n = s.north_south;
    // |v|^(k - 1) sign(v), kept finite where k < 1 and v = 0 (a point of the surface's edges).
    auto slope = [](double v, double k) {
        const double a = std::max(std::abs(v), 1e-150);
        return std::copysign(std::min(1e150, std::pow(a, k - 1)), v);
    };
    const double across = std::pow(std::abs(p.x), 2 / e) + std::pow(std::abs(p.y), 2 / e);
    const double outer = across > 0 ? std::pow(across, e / n - 1) : 0;
    return {outer * slope(p.x, 2 / e), outer * slope(p.y, 2 / e), slope(p.z, 2 / n)};
}

// The line's crossings with the superellipsoid inside its box -1..1, in kSuperellipsoidSteps
// steps across the box. Features thinner than a step along the line (the blades of exponents
// near 0 or far above 2) can be missed; the renderer's tests state the shapes they hold for.
constexpr int kSuperellipsoidSteps = 256;

void superellipsoid_hits(const SuperellipsoidShape& s, Vec3 o, Vec3 d,
                         std::vector<ShapeHit>& hits) {
    double near = 0, far = 0;
    if (!container_span(ContainedBy{}, o, d, near, far)) return;  // the box -1..1
    implicit_hits([&](Vec3 p) { return superellipsoid_value(s, p); },
                  [&](Vec3 p) { return superellipsoid_gradient(s, p); }, o, d, near, far,
                  kSuperellipsoidSteps, hits);
}

// A blob's field at `p` from its components, each moved by its transform (`to_component`: the
// inverses, in the components' order).
double blob_field(const BlobShape& blob, const std::vector<Matrix4>& to_component, Vec3 p) {
    double field = 0;
    for (size_t i = 0; i < blob.components.size(); ++i) {
        const BlobComponent& c = blob.components[i];
        const Vec3 q = to_component[i].point(p);
        Vec3 from = q - c.centre;
        if (c.kind == BlobComponent::Kind::cylinder) {
            const Vec3 axis = c.end - c.centre;
            const double along = std::clamp(dot(from, axis) / dot(axis, axis), 0.0, 1.0);
            from = from - along * axis;
        }
        const double d2 = dot(from, from) / (c.radius * c.radius);
        if (d2 < 1) field += c.strength * (1 - d2) * (1 - d2);
    }
    return field;
}

// The line's crossings with the blob's surface (field = threshold, inside above it) within its
// bounds, in kBlobSteps steps; normals by central differences over 1e-6 of the bounds' size.
constexpr int kBlobSteps = 256;

void blob_hits(const BlobShape& blob, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    ContainedBy box;
    if (!blob_bounds(blob, box.minimum, box.maximum)) return;
    double near = 0, far = 0;
    if (!container_span(box, o, d, near, far)) return;
    std::vector<Matrix4> to_component;
    for (const BlobComponent& c : blob.components) to_component.push_back(c.transform.inverse());
    auto value = [&](Vec3 p) { return blob.threshold - blob_field(blob, to_component, p); };
    const double h = 1e-6 * length(box.maximum - box.minimum);
    auto gradient = [&](Vec3 p) { return central_differences(value, p, h); };
    implicit_hits(value, gradient, o, d, near, far, kBlobSteps, hits);
}

// The line's crossings with the isosurface f = threshold inside its container, and with the
// container's surface where f is below the threshold there (unless `open`). The function's
// gradient, for normals, by central differences over 1e-5 of the container's size.
constexpr int kIsosurfaceSteps = 256;

double isosurface_value(const IsosurfaceShape& s, Vec3 p) {
    const double arguments[3] = {p.x, p.y, p.z};
    return s.function->evaluate_float(arguments) - s.threshold;
}

void isosurface_hits(const IsosurfaceShape& s, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    double near = 0, far = 0;
    if (!container_span(s.contained_by, o, d, near, far)) return;
    const ContainedBy& c = s.contained_by;
    const double size =
        c.kind == ContainedBy::Kind::sphere ? 2 * c.radius : length(c.maximum - c.minimum);
    const double h = 1e-5 * size;
    auto value = [&](Vec3 p) { return isosurface_value(s, p); };
    auto gradient = [&](Vec3 p) { return central_differences(value, p, h); };
    implicit_hits(value, gradient, o, d, near, far, kIsosurfaceSteps, hits);
    if (s.open) return;
    for (const double t : {near, far}) {
        const Vec3 p = o + t * d;
        if (value(p) < 0) hits.push_back({t, container_normal(c, p)});
    }
}

void disc_hit(const DiscShape& disc, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const double along = dot(disc.normal, d);
    if (along == 0) return;
    const double t = dot(disc.normal, disc.centre - o) / along;
    const Vec3 q = o + t * d - disc.centre;
    const double r2 = dot(q, q);
    if (r2 <= disc.radius * disc.radius && r2 >= disc.hole_radius * disc.hole_radius)
        hits.push_back({t, disc.normal});
}

// The coefficients (t^0 first) of the product of two polynomials in t.
std::vector<double> times(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> c(a.size() + b.size() - 1, 0.0);
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
    return c;
}

Vec3 polynomial_gradient(const PolynomialShape& poly, Vec3 p) {
    Vec3 g{0, 0, 0};
    auto power = [](double v, int e) { return e <= 0 ? 1.0 : std::pow(v, e); };
    for_each_term(poly, [&](double a, int i, int j, int k) {
        if (a == 0) return;
        if (i > 0) g.x += a * i * power(p.x, i - 1) * power(p.y, j) * power(p.z, k);
        if (j > 0) g.y += a * j * power(p.x, i) * power(p.y, j - 1) * power(p.z, k);
        if (k > 0) g.z += a * k * power(p.x, i) * power(p.y, j) * power(p.z, k - 1);
    });
    return g;
}

constexpr double kFarthestRoot = 1e15;

// The polynomial along o + t d expanded in t; its real roots lie within Cauchy's bound
// 1 + max |c_i / c_n|, bisected between the roots of its derivatives.
void polynomial_hits(const PolynomialShape& poly, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const double origin[3] = {o.x, o.y, o.z}, direction[3] = {d.x, d.y, d.z};
    std::vector<std::vector<double>> powers[3];
    for (int axis = 0; axis < 3; ++axis) {
        powers[axis].push_back({1.0});
        for (int e = 1; e <= poly.order; ++e)
            powers[axis].push_back(times(powers[axis].back(), {origin[axis], direction[axis]}));
    }
    std::vector<double> c(size_t(poly.order) + 1, 0.0);
    for_each_term(poly, [&](double a, int i, int j, int k) {
        if (a == 0) return;
        const std::vector<double> term = times(times(powers[0][i], powers[1][j]), powers[2][k]);
        for (size_t q = 0; q < term.size(); ++q) c[q] += a * term[q];
    });
    while (c.size() > 1 && c.back() == 0) c.pop_back();
    if (c.size() < 2) return;
    double bound = 0;
    for (size_t q = 0; q + 1 < c.size(); ++q) bound = std::max(bound, std::abs(c[q] / c.back()));
    // A line nearly along an asymptotic direction has a leading coefficient near zero and roots
    // far out: those beyond 10^15 of the line's length unit lie beyond any scene.
    bound = std::min(bound, kFarthestRoot);
    for (double t : roots_between(c, -1 - bound, 1 + bound))
        hits.push_back({t, polynomial_gradient(poly, o + t * d)});
}

void quadric_hits(const QuadricShape& q, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    // Along o + t d the quadric is c0 + c1 t + c2 t^2, read from its values at t = 0, 1, -1.
    const double at0 = quadric_value(q, o), at1 = quadric_value(q, o + d),
                 at_minus1 = quadric_value(q, o - d);
    const double c2 = (at1 + at_minus1) / 2 - at0, c1 = (at1 - at_minus1) / 2;
    for (double t : quadratic_roots(c2, c1, at0)) {
        const Vec3 p = o + t * d;
        hits.push_back({t,
                        {2 * q.squares.x * p.x + q.mixed.x * p.y + q.mixed.y * p.z + q.linear.x,
                         2 * q.squares.y * p.y + q.mixed.x * p.x + q.mixed.z * p.z + q.linear.y,
                         2 * q.squares.z * p.z + q.mixed.y * p.x + q.mixed.z * p.y + q.linear.z}});
    }
}

// Text: the outline extruded from z = 0 to the thickness. The caps where the outline is filled;
// the walls where the line's x-y shadow crosses a piece (a quadratic in the piece's parameter),
// normals in the x-y plane toward the unfilled side.
bool text_inside(const TextShape& text, Vec3 p) {
    return p.z >= 0 && p.z <= text.thickness && text.outline->inside(p.x, p.y);
}

void text_hits(const TextShape& text, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const TextOutline& outline = *text.outline;
    if (d.z != 0)
        for (double z : {0.0, text.thickness}) {
            const double t = (z - o.z) / d.z;
            if (outline.inside(o.x + t * d.x, o.y + t * d.y))
                hits.push_back({t, {0, 0, z == 0 ? -1.0 : 1.0}});
        }
    const double planar = d.x * d.x + d.y * d.y;
    if (planar == 0) return;
    // cross(q - o, d) in x-y: zero on the line's shadow.
    auto side = [&](double x, double y) { return (x - o.x) * d.y - (y - o.y) * d.x; };
    for (const TextOutline::Piece& p : outline.pieces) {
        const double sa = side(p.ax, p.ay), sc = side(p.cx, p.cy), sb = side(p.bx, p.by);
        if ((sa > 0 && sc > 0 && sb > 0) || (sa < 0 && sc < 0 && sb < 0)) continue;
        // side(C(u)) = (sa - 2 sc + sb) u^2 + 2 (sc - sa) u + sa: a quadratic in u.
        double roots[2];
        const int n = solve_quadratic(sa - 2 * sc + sb, 2 * (sc - sa), sa, roots);
        for (int i = 0; i < n; ++i) {
            const double u = roots[i];
            if (!(u >= 0 && u < 1)) continue;
            const double t = ((p.x(u) - o.x) * d.x + (p.y(u) - o.y) * d.y) / planar;
            const double z = o.z + t * d.z;
            if (z < 0 || z > text.thickness) continue;
            const double tx = p.dx(u), ty = p.dy(u);
            hits.push_back({t, p.filled_left ? Vec3{ty, -tx, 0} : Vec3{-ty, tx, 0}});
        }
    }
}

// A Julia set of 4-D numbers cut by the hyperplane w = slice distance (the default slice):
// the points whose orbit z -> f(z) + c stays within radius 2 for max_iteration steps. In the
// quaternion algebra f is the square or cube; the hypercomplex algebra is two complex planes
// (x - w + i(y + z), x + w + i(y - z)), f applied in each.
using Quad = std::array<double, 4>;

std::complex<double> complex_function(const JuliaFractalShape& j, std::complex<double> z) {
    using F = JuliaFractalShape::Function;
    switch (j.function) {
        case F::sqr: return z * z;
        case F::cube: return z * z * z;
        case F::reciprocal: return 1.0 / z;
        case F::exp: return std::exp(z);
        case F::ln: return std::log(z);
        case F::pwr: return std::pow(z, std::complex<double>{j.power.x, j.power.y});
        case F::sin: return std::sin(z);
        case F::asin: return std::asin(z);
        case F::sinh: return std::sinh(z);
        case F::asinh: return std::asinh(z);
        case F::cos: return std::cos(z);
        case F::acos: return std::acos(z);
        case F::cosh: return std::cosh(z);
        case F::acosh: return std::acosh(z);
        case F::tan: return std::tan(z);
        case F::atan: return std::atan(z);
        case F::tanh: return std::tanh(z);
        case F::atanh: return std::atanh(z);
    }
    return z;
}

Quad julia_function(const JuliaFractalShape& j, const Quad& q) {
    if (j.algebra == JuliaFractalShape::Algebra::quaternion) {
        const double a = q[0], v2 = q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        // (a + v)^2 = a^2 - |v|^2 + 2 a v; (a + v)^3 = a^3 - 3 a |v|^2 + (3 a^2 - |v|^2) v.
        if (j.function == JuliaFractalShape::Function::cube) {
            const double s = 3 * a * a - v2;
            return {a * a * a - 3 * a * v2, s * q[1], s * q[2], s * q[3]};
        }
        return {a * a - v2, 2 * a * q[1], 2 * a * q[2], 2 * a * q[3]};
    }
    const std::complex<double> u{q[0] - q[3], q[1] + q[2]}, v{q[0] + q[3], q[1] - q[2]};
    const std::complex<double> fu = complex_function(j, u), fv = complex_function(j, v);
    return {0.5 * (fu.real() + fv.real()), 0.5 * (fu.imag() + fv.imag()),
            0.5 * (fu.imag() - fv.imag()), 0.5 * (fv.real() - fu.real())};
}

// Negative inside: log(|z_m|^2 / 4) / 2^m at the first m whose |z_m| exceeds 2, else at
// max_iteration - 1 (continuous where the orbit leaves at the last step: the set's surface).
// POV-Ray's renders agree best with max_iteration - 1 steps (97% of the pixels of a test scene
// against 95% with max_iteration, 94% with one more) and the bailout radius 2.
double julia_value(const JuliaFractalShape& j, Vec3 p) {
    Quad z{p.x, p.y, p.z, j.slice_distance};
    double scale = 1;
    for (int m = 0;; ++m) {
        const double r2 = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] + z[3] * z[3];
        if (r2 > 4 || m == j.max_iteration - 1) return std::log(std::max(r2, 1e-300) / 4) * scale;
        z = julia_function(j, z);
        for (int k = 0; k < 4; ++k) z[k] += j.parameter[k];
        scale *= 0.5;
    }
}

constexpr int kJuliaSteps = 256;

}  // namespace

bool julia_default_slice(const JuliaFractalShape& j) {
    return j.slice_normal[0] == 0 && j.slice_normal[1] == 0 && j.slice_normal[2] == 0;
}

namespace {

void julia_hits(const JuliaFractalShape& j, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    ContainedBy ball;
    ball.kind = ContainedBy::Kind::sphere;
    ball.radius = 2;
    double near = 0, far = 0;
    if (!container_span(ball, o, d, near, far)) return;
    const double h = 1e-6;
    auto value = [&](Vec3 p) { return julia_value(j, p); };
    auto gradient = [&](Vec3 p) { return central_differences(value, p, h); };
    implicit_hits(value, gradient, o, d, near, far, kJuliaSteps, hits);
}

// A surface of revolution as POV-Ray draws it (read back from POV-Ray with trace, to 1e-10):
// between points i and i + 1 (i from the second point to the third-last), r^2 is the cubic in
// the height h through r_i^2 and r_(i+1)^2 whose slopes there are 2 r_j (r_(j+1) - r_(j-1)) /
// (h_(j+1) - h_(j-1)), the slope of r^2 with r's central difference.
struct SorPiece {
    double h0, h1;
    std::array<double, 4> r2;  // r^2 as a cubic in h, h^0 first
};

std::vector<SorPiece> sor_pieces(const SorShape& sor) {
    const std::vector<Vec2>& p = sor.points;
    auto slope = [&](size_t j) {
        return 2 * p[j].x * (p[j + 1].x - p[j - 1].x) / (p[j + 1].y - p[j - 1].y);
    };
    std::vector<SorPiece> pieces;
    for (size_t i = 1; i + 2 < p.size(); ++i) {
        // Hermite form on s = (h - h0) / w, then expanded in h.
        const double h0 = p[i].y, w = p[i + 1].y - h0;
        const double v0 = p[i].x * p[i].x, v1 = p[i + 1].x * p[i + 1].x;
        const double m0 = slope(i) * w, m1 = slope(i + 1) * w;
        const double a = 2 * v0 - 2 * v1 + m0 + m1, b = -3 * v0 + 3 * v1 - 2 * m0 - m1;
        // a s^3 + b s^2 + m0 s + v0 with s = (h - h0) / w.
        const std::vector<double> s_of_h{-h0 / w, 1 / w};
        std::vector<double> value{v0}, power{1};
        for (const double c : {m0, b, a}) {
            power = times(power, s_of_h);
            value.resize(power.size(), 0.0);
            for (size_t k = 0; k < power.size(); ++k) value[k] += c * power[k];
        }
        SorPiece piece{h0, p[i + 1].y, {}};
        for (size_t k = 0; k < 4; ++k) piece.r2[k] = value[k];
        pieces.push_back(piece);
    }
    return pieces;
}

}  // namespace

struct SorProfile {
    std::vector<SorPiece> pieces;
};

namespace {

bool sor_inside(const SorShape& sor, Vec3 q) {
    const double rho2 = q.x * q.x + q.z * q.z;
    for (const SorPiece& piece : prepared(sor.profile).pieces)
        if (q.y >= piece.h0 && q.y <= piece.h1) return rho2 < cubic_at(piece.r2, q.y);
    return false;
}

// x^2 + z^2 = r^2(y) along the line, piece by piece (a cubic in t), and the caps unless open.
void sor_hits(const SorShape& sor, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const std::vector<SorPiece>& pieces = prepared(sor.profile).pieces;
    if (pieces.empty()) return;
    const std::vector<double> x{o.x, d.x}, y{o.y, d.y}, z{o.z, d.z};
    std::vector<double> rho2 = times(x, x);
    const std::vector<double> zz = times(z, z);
    for (size_t k = 0; k < rho2.size(); ++k) rho2[k] += zz[k];
    for (const SorPiece& piece : pieces) {
        std::vector<double> f = rho2, power{1};
        f.resize(4, 0.0);
        for (int k = 0; k < 4; ++k) {
            for (size_t m = 0; m < power.size(); ++m) f[m] -= piece.r2[k] * power[m];
            power = times(power, y);
        }
        double lo = -1e300, hi = 1e300;
        if (d.y != 0) {
            lo = (piece.h0 - o.y) / d.y, hi = (piece.h1 - o.y) / d.y;
            if (lo > hi) std::swap(lo, hi);
        } else if (o.y < piece.h0 || o.y > piece.h1) {
            continue;
        } else {
            // A level line: the quadratic's roots, within reach of any scene.
            lo = -1e12, hi = 1e12;
        }
        for (double t : roots_between(f, lo, hi)) {
            const Vec3 p = o + t * d;
            const double dr2 = (3 * piece.r2[3] * p.y + 2 * piece.r2[2]) * p.y + piece.r2[1];
            hits.push_back({t, {2 * p.x, -dr2, 2 * p.z}});
        }
    }
    if (sor.open || d.y == 0) return;
    for (const bool top : {false, true}) {
        const SorPiece& piece = top ? pieces.back() : pieces.front();
        const double h = top ? piece.h1 : piece.h0, t = (h - o.y) / d.y;
        const Vec3 p = o + t * d;
        if (p.x * p.x + p.z * p.z <= cubic_at(piece.r2, h))
            hits.push_back({t, {0, top ? 1.0 : -1.0, 0}});
    }
}

}  // namespace

void sor_bounds(const SorShape& sor, Vec3& lower, Vec3& upper) {
    double r2_max = 0;
    const std::vector<SorPiece>& pieces = prepared(sor.profile).pieces;
    for (const SorPiece& piece : pieces) {
        auto visit = [&](double h) { r2_max = std::max(r2_max, cubic_at(piece.r2, h)); };
        visit(piece.h0), visit(piece.h1);
        for (double h :
             roots_between({piece.r2[1], 2 * piece.r2[2], 3 * piece.r2[3]}, piece.h0, piece.h1))
            visit(h);
    }
    const double r = std::sqrt(r2_max);
    lower = {-r, pieces.empty() ? 0 : pieces.front().h0, -r};
    upper = {r, pieces.empty() ? 0 : pieces.back().h1, r};
}

namespace {}  // namespace

// A polygon's plane: Newell's normal of its points, and the axis it is least along (dropped to
// project the polygon on the plane of the other two).
struct PolygonPlane {
    Vec3 normal;
    int drop = 2;
};

namespace {

PolygonPlane polygon_plane(const PolygonShape& polygon) {
    const std::vector<Vec3>& p = polygon.points;
    PolygonPlane plane;
    for (size_t i = 0; i < p.size(); ++i) {
        const Vec3 a = p[i], b = p[(i + 1) % p.size()];
        plane.normal = plane.normal + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                                           (a.x - b.x) * (a.y + b.y)};
    }
    const double n[3] = {std::abs(plane.normal.x), std::abs(plane.normal.y),
                         std::abs(plane.normal.z)};
    plane.drop = n[0] > n[1] ? (n[0] > n[2] ? 0 : 2) : (n[1] > n[2] ? 1 : 2);
    return plane;
}

// The even-odd rule over the edges of all the polygon's loops, each loop closed by repeating
// its first point, in the plane's projection.
void polygon_hits(const PolygonShape& polygon, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    const std::vector<Vec3>& p = polygon.points;
    const PolygonPlane& plane = prepared(polygon.plane);
    const Vec3 normal = plane.normal;
    const double along = dot(normal, d);
    if (is_zero(normal) || along == 0) return;
    const double t = dot(normal, p[0] - o) / along;
    const Vec3 q = o + t * d;
    const int drop = plane.drop;
    auto uv = [drop](Vec3 v) {
        return drop == 0 ? Vec2{v.y, v.z} : drop == 1 ? Vec2{v.z, v.x} : Vec2{v.x, v.y};
    };
    const Vec2 at = uv(q);
    bool inside = false;
    size_t loop_start = 0;
    for (size_t i = 0; i + 1 < p.size(); ++i) {
        if (i > loop_start && p[i].x == p[loop_start].x && p[i].y == p[loop_start].y &&
            p[i].z == p[loop_start].z) {
            loop_start = i + 1;  // the loop closed at i: the next starts after it
            continue;
        }
        const Vec2 a = uv(p[i]), b = uv(p[i + 1]);
        if ((a.y > at.y) != (b.y > at.y) && at.x < a.x + (at.y - a.y) * (b.x - a.x) / (b.y - a.y))
            inside = !inside;
    }
    if (inside) hits.push_back({t, normal});
}

// A sphere_sweep as POV-Ray draws it (read back from POV-Ray with trace, to 1e-10): the union of
// the spheres whose centre and radius follow a spline through the given spheres, segment by
// segment with t from 0 to 1: the straight line from each sphere to the next (linear_spline),
// the uniform cubic B-spline of each four consecutive spheres (b_spline), or the Catmull-Rom
// cubic of each four from the second to the third (cubic_spline). Inside one segment the line
// o + s d is inside sphere t between the roots s0(t) <= s1(t) of |o + s d - c(t)|^2 = r(t)^2;
// over each stretch of t where they are real these intervals join into one, from the least s0
// to the greatest s1. Both are found among the stretch's ends and the roots of the polynomial
// (degree 10 at most) whose roots are where s0 or s1 is level in t, and of its derivatives; the
// normal is p - c(t) at the t that gives the hit, the envelope's (or an end sphere's) exact
// normal. POV-Ray's trace agrees with this union on every outer surface probed; inside it,
// where a ray touches one segment's envelope twice, POV-Ray also reports the ray's exit from
// the first touching sphere and entry into the second (a gap its own inside() does not see),
// which shows only through CSG cuts and is not reproduced here.
struct SweepSegment {
    std::array<std::array<double, 4>, 4> c{};  // x, y, z and radius as cubics in t, t^0 first
    Vec3 lower, upper;                         // around every sphere of the segment
};

// The least and greatest value of a cubic on [0, 1].
void cubic_range(const std::array<double, 4>& c, double& lo, double& hi) {
    lo = std::min(cubic_at(c, 0), cubic_at(c, 1)), hi = std::max(cubic_at(c, 0), cubic_at(c, 1));
    for (double t : roots_between({c[1], 2 * c[2], 3 * c[3]}, 0, 1)) {
        const double v = cubic_at(c, t);
        lo = std::min(lo, v), hi = std::max(hi, v);
    }
}

std::vector<SweepSegment> make_sweep_segments(const SphereSweepShape& sweep) {
    using Kind = SphereSweepShape::Kind;
    const auto& s = sweep.spheres;
    auto at = [&](size_t i, int k) {
        const Vec3 p = s[i].centre;
        return k == 0 ? p.x : k == 1 ? p.y : k == 2 ? p.z : s[i].radius;
    };
    std::vector<SweepSegment> segments;
    const bool linear = sweep.kind == Kind::linear_spline;
    const size_t last = linear ? 1 : 3;  // the segments' first spheres run up to n - 1 - last
    for (size_t i = 0; i + last < s.size(); ++i) {
        SweepSegment g;
        for (int k = 0; k < 4; ++k) {
            std::array<double, 4>& c = g.c[size_t(k)];
            if (linear) {
                c = {at(i, k), at(i + 1, k) - at(i, k), 0, 0};
                continue;
            }
            const double p0 = at(i, k), p1 = at(i + 1, k), p2 = at(i + 2, k), p3 = at(i + 3, k);
            if (sweep.kind == Kind::b_spline) {
                c = {(p0 + 4 * p1 + p2) / 6, (p2 - p0) / 2, (p0 - 2 * p1 + p2) / 2,
                     (-p0 + 3 * p1 - 3 * p2 + p3) / 6};
            } else {
                c = {p1, (p2 - p0) / 2, (2 * p0 - 5 * p1 + 4 * p2 - p3) / 2,
                     (-p0 + 3 * p1 - 3 * p2 + p3) / 2};
            }
        }
        // Per axis, the reach of the centre plus and minus the radius (either sign).
        double lo[3], hi[3];
        for (size_t k = 0; k < 3; ++k) {
            lo[k] = 1e300, hi[k] = -1e300;
            for (const double sign : {1.0, -1.0}) {
                std::array<double, 4> reach = g.c[k];
                for (size_t m = 0; m < 4; ++m) reach[m] += sign * g.c[3][m];
                double a = 0, b = 0;
                cubic_range(reach, a, b);
                lo[k] = std::min(lo[k], a), hi[k] = std::max(hi[k], b);
            }
        }
        g.lower = {lo[0], lo[1], lo[2]}, g.upper = {hi[0], hi[1], hi[2]};
        segments.push_back(g);
    }
    return segments;
}

}  // namespace

struct SweepSegments {
    std::vector<SweepSegment> segments;
};

namespace {

// Whether the line o + s d meets the box lower..upper (widened by a hair).
bool line_meets_box(Vec3 lower, Vec3 upper, Vec3 o, Vec3 d) {
    const double margin = 1e-9 * (1 + length(upper - lower));
    const Vec3 widen{margin, margin, margin};
    double near = 0, far = 0;
    return box_span(lower - widen, upper + widen, o, d, near, far);
}

// A polynomial of degree 10 at most, t^0 first, without allocation (a sweep's tests per ray).
struct SmallPoly {
    std::array<double, 11> c{};
    int degree = 0;
    double operator()(double t) const {
        double v = 0;
        for (int i = degree; i >= 0; --i) v = v * t + c[size_t(i)];
        return v;
    }
};

SmallPoly poly_product(const SmallPoly& a, const SmallPoly& b) {
    SmallPoly p;
    p.degree = a.degree + b.degree;
    for (int i = 0; i <= a.degree; ++i)
        for (int j = 0; j <= b.degree; ++j) p.c[size_t(i + j)] += a.c[size_t(i)] * b.c[size_t(j)];
    return p;
}

// a + k b
SmallPoly poly_sum(const SmallPoly& a, double k, const SmallPoly& b) {
    SmallPoly p = a;
    p.degree = std::max(a.degree, b.degree);
    for (int i = 0; i <= b.degree; ++i) p.c[size_t(i)] += k * b.c[size_t(i)];
    return p;
}

SmallPoly poly_derivative(const SmallPoly& a) {
    SmallPoly p;
    p.degree = std::max(0, a.degree - 1);
    for (int i = 1; i <= a.degree; ++i) p.c[size_t(i - 1)] = double(i) * a.c[size_t(i)];
    return p;
}

// The real roots of p in [lo, hi], in increasing order, into `roots` (returns their count):
// each monotone piece between the roots of the derivative (found the same way) that changes
// sign holds one, found by regula falsi (the Illinois variant) to the last bits. The roots of
// every derivative go to `all` too when given (a multiple root of p is a simple root of one of
// them), `n_all` counting them (at most 55 for degree 10).
int poly_roots(SmallPoly p, double lo, double hi, double* roots, double* all = nullptr,
               int* n_all = nullptr) {
    while (p.degree > 0 && p.c[size_t(p.degree)] == 0) --p.degree;
    if (p.degree == 0) return 0;
    double ends[12];
    int n_ends = 0;
    ends[n_ends++] = lo;
    if (p.degree > 1) {
        const int n = poly_roots(poly_derivative(p), lo, hi, ends + 1, all, n_all);
        if (all)
            for (int k = 0; k < n; ++k) all[(*n_all)++] = ends[1 + k];
        n_ends += n;
    }
    ends[n_ends++] = hi;
    int count = 0;
    for (int k = 0; k + 1 < n_ends; ++k) {
        double a = ends[k], b = ends[k + 1], fa = p(a), fb = p(b);
        if (fa == 0) {
            if (count == 0 || roots[count - 1] != a) roots[count++] = a;
            continue;
        }
        if ((fa < 0) == (fb < 0)) continue;
        double x = a;
        int side = 0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            const double previous = x;
            x = (a * fb - b * fa) / (fb - fa);
            if (!(x > a && x < b)) x = 0.5 * (a + b);
            const double fx = p(x);
            if (fx == 0 || b - a <= 4e-16 * std::max(1.0, std::abs(x))) break;
            if ((fx < 0) == (fa < 0)) {
                a = x, fa = fx;
                if (side == -1) fb *= 0.5;
                side = -1;
            } else {
                b = x, fb = fx;
                if (side == 1) fa *= 0.5;
                side = 1;
            }
            if (std::abs(x - previous) <= 1e-16 * std::max(1.0, std::abs(x))) break;
        }
        roots[count++] = x;
    }
    return count;
}

// The stretches of the line o + s d inside one segment's spheres, each as its entry and exit.
void segment_spans(const SweepSegment& g, Vec3 o, Vec3 d,
                   std::vector<std::pair<ShapeHit, ShapeHit>>& spans) {
    if (!line_meets_box(g.lower, g.upper, o, d)) return;
    const double a = dot(d, d);
    if (a == 0) return;
    // Measured from the point of the line nearest the box's middle, for well-kept digits.
    const double shift = dot(0.5 * (g.lower + g.upper) - o, d) / a;
    const Vec3 from = o + shift * d;
    const double origin[3] = {from.x, from.y, from.z}, direction[3] = {d.x, d.y, d.z};
    // b(t) = w.d and c(t) = w.w - r^2 with w = from - centre(t); s = (-b -+ sqrt(b^2 - a c)) / a.
    SmallPoly b, c, r;
    b.degree = 3, r.degree = 3;
    for (size_t k = 0; k < 3; ++k) {
        SmallPoly w;
        w.degree = 3;
        for (size_t m = 0; m < 4; ++m) w.c[m] = -g.c[k][m];
        w.c[0] += origin[k];
        b = poly_sum(b, direction[k], w);
        c = poly_sum(c, 1, poly_product(w, w));
    }
    for (size_t m = 0; m < 4; ++m) r.c[m] = g.c[3][m];
    c = poly_sum(c, -1, poly_product(r, r));
    const SmallPoly disc = poly_sum(poly_product(b, b), -a, c);
    // s0 or s1 is level where -b' (2 sqrt(disc)) = 2 b b' - a c', squared:
    // 4 b'^2 disc - (2 b b' - a c')^2 = 0. Where b' = 0 there (a ray square to the spline) the
    // root is double, so the roots of the polynomial's derivatives are candidates too.
    const SmallPoly db = poly_derivative(b), dc = poly_derivative(c);
    const SmallPoly slope = poly_sum(poly_product(b, db), -0.5 * a, dc);  // (2 b b' - a c') / 2
    const SmallPoly level =
        poly_sum(poly_product(poly_product(db, db), disc), -1, poly_product(slope, slope));
    double critical[64], roots[10];
    int n_critical = 0;
    const int n_roots = poly_roots(level, 0, 1, roots, critical, &n_critical);
    for (int k = 0; k < n_roots; ++k) critical[n_critical++] = roots[k];

    double ends[8];
    int n_ends = 0;
    ends[n_ends++] = 0;
    double disc_roots[6];
    const int n_disc = poly_roots(disc, 0, 1, disc_roots);
    for (int k = 0; k < n_disc; ++k)
        if (disc_roots[k] > ends[n_ends - 1]) ends[n_ends++] = disc_roots[k];
    if (ends[n_ends - 1] < 1) ends[n_ends++] = 1;
    for (int k = 0; k + 1 < n_ends; ++k) {
        const double t0 = ends[k], t1 = ends[k + 1];
        if (disc(0.5 * (t0 + t1)) < 0) continue;
        double near = 1e300, far = -1e300, t_near = t0, t_far = t0;
        auto visit = [&](double t) {
            const double root = std::sqrt(std::max(0.0, disc(t))), bt = b(t);
            const double s0 = (-bt - root) / a, s1 = (-bt + root) / a;
            if (s0 < near) near = s0, t_near = t;
            if (s1 > far) far = s1, t_far = t;
        };
        visit(t0), visit(t1);
        for (int i = 0; i < n_critical; ++i)
            if (critical[i] > t0 && critical[i] < t1) visit(critical[i]);
        auto normal = [&](double s, double t) {
            const Vec3 centre{cubic_at(g.c[0], t), cubic_at(g.c[1], t), cubic_at(g.c[2], t)};
            return from + s * d - centre;
        };
        spans.push_back({{shift + near, normal(near, t_near)}, {shift + far, normal(far, t_far)}});
    }
}

// The stretches of the line inside the sweep: the segments' stretches, overlapping ones joined,
// in order along the line.
std::vector<std::pair<ShapeHit, ShapeHit>> sweep_spans(const SphereSweepShape& sweep, Vec3 o,
                                                       Vec3 d) {
    std::vector<std::pair<ShapeHit, ShapeHit>> spans, joined;
    for (const SweepSegment& g : prepared(sweep.segments).segments) segment_spans(g, o, d, spans);
    std::sort(spans.begin(), spans.end(),
              [](const auto& x, const auto& y) { return x.first.t < y.first.t; });
    for (const auto& span : spans) {
        if (!joined.empty() && span.first.t <= joined.back().second.t) {
            if (span.second.t > joined.back().second.t) joined.back().second = span.second;
        } else {
            joined.push_back(span);
        }
    }
    return joined;
}

void sphere_sweep_hits(const SphereSweepShape& sweep, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    for (const auto& span : sweep_spans(sweep, o, d)) {
        hits.push_back(span.first);
        hits.push_back(span.second);
    }
}

bool sphere_sweep_inside(const SphereSweepShape& sweep, Vec3 p) {
    for (const auto& span : sweep_spans(sweep, p, {1, 0, 0}))
        if (span.first.t < 0 && span.second.t > 0) return true;
    return false;
}

}  // namespace

void sphere_sweep_bounds(const SphereSweepShape& sweep, Vec3& lower, Vec3& upper) {
    lower = {1e300, 1e300, 1e300}, upper = {-1e300, -1e300, -1e300};
    for (const SweepSegment& g : prepared(sweep.segments).segments) {
        lower = {std::min(lower.x, g.lower.x), std::min(lower.y, g.lower.y),
                 std::min(lower.z, g.lower.z)};
        upper = {std::max(upper.x, g.upper.x), std::max(upper.y, g.upper.y),
                 std::max(upper.z, g.upper.z)};
    }
}

void lathe_bounds(const LatheShape& lathe, Vec3& lower, Vec3& upper) {
    double r_max = 0, y_min = 1e300, y_max = -1e300;
    for (const ProfilePiece& piece : prepared(lathe.profile).pieces) {
        // The extremes of a cubic on [0, 1]: its ends and its derivative's roots.
        auto extremes = [](const std::array<double, 4>& c, auto&& visit) {
            visit(cubic_at(c, 0)), visit(cubic_at(c, 1));
            for (double t : roots_between({c[1], 2 * c[2], 3 * c[3]}, 0, 1)) visit(cubic_at(c, t));
        };
        extremes(piece.r, [&](double v) { r_max = std::max(r_max, std::abs(v)); });
        extremes(piece.y,
                 [&](double v) { y_min = std::min(y_min, v), y_max = std::max(y_max, v); });
    }
    lower = {-r_max, y_min, -r_max}, upper = {r_max, y_max, r_max};
}

bool blob_bounds(const BlobShape& blob, Vec3& lower, Vec3& upper) {
    lower = {1e300, 1e300, 1e300}, upper = {-1e300, -1e300, -1e300};
    for (const BlobComponent& c : blob.components) {
        if (c.strength <= 0) continue;  // negative components only take away
        const double r = std::abs(c.radius);
        const Vec3 lo{std::min(c.centre.x, c.end.x) - r, std::min(c.centre.y, c.end.y) - r,
                      std::min(c.centre.z, c.end.z) - r};
        const Vec3 hi{std::max(c.centre.x, c.end.x) + r, std::max(c.centre.y, c.end.y) + r,
                      std::max(c.centre.z, c.end.z) + r};
        const bool cylinder = c.kind == BlobComponent::Kind::cylinder;
        const Vec3 a = cylinder ? lo : c.centre - Vec3{r, r, r};
        const Vec3 b = cylinder ? hi : c.centre + Vec3{r, r, r};
        for (int k = 0; k < 8; ++k) {
            const Vec3 corner =
                c.transform.point({k & 1 ? b.x : a.x, k & 2 ? b.y : a.y, k & 4 ? b.z : a.z});
            lower = {std::min(lower.x, corner.x), std::min(lower.y, corner.y),
                     std::min(lower.z, corner.z)};
            upper = {std::max(upper.x, corner.x), std::max(upper.y, corner.y),
                     std::max(upper.z, corner.z)};
        }
    }
    return lower.x <= upper.x;
}

bool shape_inside(const Shape& shape, Vec3 p, bool& inside) {
    if (const auto* prism = std::get_if<PrismShape>(&shape)) return prism_inside(*prism, p, inside);
    if (const auto* s = std::get_if<SphereShape>(&shape)) {
        const Vec3 q = p - s->centre;
        inside = dot(q, q) < s->radius * s->radius;
    } else if (const auto* b = std::get_if<BoxShape>(&shape)) {
        inside = p.x >= b->minimum.x && p.x <= b->maximum.x && p.y >= b->minimum.y &&
                 p.y <= b->maximum.y && p.z >= b->minimum.z && p.z <= b->maximum.z;
    } else if (const auto* c = std::get_if<CylinderShape>(&shape)) {
        const Vec3 axis = c->cap - c->base, q = p - c->base;
        const double s = dot(q, axis) / dot(axis, axis);
        const Vec3 radial = q - s * axis;
        inside = s >= 0 && s <= 1 && dot(radial, radial) < c->radius * c->radius;
    } else if (const auto* c = std::get_if<ConeShape>(&shape)) {
        const Vec3 axis = c->cap - c->base, q = p - c->base;
        const double s = dot(q, axis) / dot(axis, axis);
        const double r = c->base_radius + s * (c->cap_radius - c->base_radius);
        const Vec3 radial = q - s * axis;
        inside = s >= 0 && s <= 1 && dot(radial, radial) < r * r;
    } else if (const auto* t = std::get_if<TorusShape>(&shape)) {
        const double ring = std::hypot(p.x, p.z) - t->major_radius;
        inside = ring * ring + p.y * p.y < t->minor_radius * t->minor_radius;
    } else if (const auto* se = std::get_if<SuperellipsoidShape>(&shape)) {
        inside = superellipsoid_value(*se, p) < 0;
    } else if (const auto* lathe = std::get_if<LatheShape>(&shape)) {
        inside = lathe_inside(prepared(lathe->profile).pieces, std::hypot(p.x, p.z), p.y);
    } else if (const auto* sor = std::get_if<SorShape>(&shape)) {
        inside = sor_inside(*sor, p);
    } else if (const auto* sweep = std::get_if<SphereSweepShape>(&shape)) {
        inside = sphere_sweep_inside(*sweep, p);
    } else if (const auto* julia = std::get_if<JuliaFractalShape>(&shape)) {
        if (!julia_default_slice(*julia)) return false;
        inside = julia_value(*julia, p) < 0;
    } else if (const auto* blob = std::get_if<BlobShape>(&shape)) {
        std::vector<Matrix4> to_component;
        for (const BlobComponent& c : blob->components)
            to_component.push_back(c.transform.inverse());
        inside = blob_field(*blob, to_component, p) > blob->threshold;
    } else if (const auto* iso = std::get_if<IsosurfaceShape>(&shape)) {
        if (!iso->function) return false;
        double near = 0, far = 0;  // inside the container: a zero-length stretch through p
        inside = container_span(iso->contained_by, p, {1, 0, 0}, near, far) && near <= 0 &&
                 far >= 0 && isosurface_value(*iso, p) < 0;
    } else if (const auto* plane = std::get_if<PlaneShape>(&shape)) {
        inside = dot(plane->normal, p) < plane->distance;
    } else if (const auto* disc = std::get_if<DiscShape>(&shape)) {
        inside =
            dot(disc->normal, p - disc->centre) < 0;  // its plane's inside, whatever the radius
    } else if (const auto* q = std::get_if<QuadricShape>(&shape)) {
        inside = quadric_value(*q, p) < 0;
    } else if (const auto* text = std::get_if<TextShape>(&shape)) {
        if (!text->outline) return false;
        inside = text_inside(*text, p);
    } else if (const auto* poly = std::get_if<PolynomialShape>(&shape)) {
        inside = polynomial_value(*poly, p) < 0;
    } else if (const auto* field = std::get_if<HeightFieldShape>(&shape)) {
        // Below the surface over the unit square; water_level's inside is not POV-Ray's plain
        // rule (its inside() counts points above the surface but below the water as in).
        if (!field->grid || field->water_level > 0) return false;
        inside = height_field_inside(*field, p);
    } else if (const auto* mesh = std::get_if<MeshShape>(&shape)) {
        // POV-Ray counts the crossings of a ray along inside_vector: odd is inside.
        if (!mesh->mesh->has_inside_vector) return false;
        std::vector<ShapeHit> hits;
        mesh_hits(*mesh->mesh, p, mesh->mesh->inside_vector, hits);
        inside = hits.size() % 2 == 1;
    } else {
        return false;
    }
    return true;
}

bool shape_hits(const Shape& shape, Vec3 o, Vec3 d, std::vector<ShapeHit>& hits) {
    if (const auto* poly = std::get_if<PolynomialShape>(&shape)) {
        polynomial_hits(*poly, o, d, hits);
    } else if (const auto* q = std::get_if<QuadricShape>(&shape)) {
        quadric_hits(*q, o, d, hits);
    } else if (const auto* s = std::get_if<SphereShape>(&shape)) {
        const Vec3 w = o - s->centre;
        for (double t :
             quadratic_roots(dot(d, d), 2 * dot(w, d), dot(w, w) - s->radius * s->radius))
            hits.push_back({t, w + t * d});
    } else if (const auto* b = std::get_if<BoxShape>(&shape)) {
        box_hits(*b, o, d, hits);
    } else if (const auto* c = std::get_if<CylinderShape>(&shape)) {
        cone_hits(c->base, c->cap, c->radius, c->radius, c->open, o, d, hits);
    } else if (const auto* c = std::get_if<ConeShape>(&shape)) {
        cone_hits(c->base, c->cap, c->base_radius, c->cap_radius, c->open, o, d, hits);
    } else if (const auto* t = std::get_if<TorusShape>(&shape)) {
        torus_hits(*t, o, d, hits);
    } else if (const auto* se = std::get_if<SuperellipsoidShape>(&shape)) {
        superellipsoid_hits(*se, o, d, hits);
    } else if (const auto* iso = std::get_if<IsosurfaceShape>(&shape)) {
        if (!iso->function) return false;
        isosurface_hits(*iso, o, d, hits);
    } else if (const auto* blob = std::get_if<BlobShape>(&shape)) {
        blob_hits(*blob, o, d, hits);
    } else if (const auto* prism = std::get_if<PrismShape>(&shape)) {
        if (prism->spline != SplineKind::linear) return false;
        prism_hits(*prism, o, d, hits);
    } else if (const auto* lathe = std::get_if<LatheShape>(&shape)) {
        lathe_hits(*lathe, o, d, hits);
    } else if (const auto* sor = std::get_if<SorShape>(&shape)) {
        sor_hits(*sor, o, d, hits);
    } else if (const auto* sweep = std::get_if<SphereSweepShape>(&shape)) {
        sphere_sweep_hits(*sweep, o, d, hits);
    } else if (const auto* julia = std::get_if<JuliaFractalShape>(&shape)) {
        if (!julia_default_slice(*julia)) return false;
        julia_hits(*julia, o, d, hits);
    } else if (const auto* polygon = std::get_if<PolygonShape>(&shape)) {
        polygon_hits(*polygon, o, d, hits);
    } else if (const auto* plane = std::get_if<PlaneShape>(&shape)) {
        plane_hit(plane->normal, plane->distance, o, d, hits);
    } else if (const auto* disc = std::get_if<DiscShape>(&shape)) {
        disc_hit(*disc, o, d, hits);
    } else if (const auto* t = std::get_if<TriangleShape>(&shape)) {
        triangle_hit(t->a, t->b, t->c, o, d, hits);
    } else if (const auto* text = std::get_if<TextShape>(&shape)) {
        if (!text->outline) return false;
        text_hits(*text, o, d, hits);
    } else if (const auto* field = std::get_if<HeightFieldShape>(&shape)) {
        if (!field->grid) return false;
        height_field_hits(*field, o, d, hits);
    } else if (const auto* mesh = std::get_if<MeshShape>(&shape)) {
        if (!mesh->mesh->normals.empty()) return false;  // smooth triangles' normals: not here
        std::vector<ShapeHit> all;
        for (const auto& f : mesh->mesh->faces)
            triangle_hit(mesh->mesh->vertices[f[0]], mesh->mesh->vertices[f[1]],
                         mesh->mesh->vertices[f[2]], o, d, all);
        hits.insert(hits.end(), all.begin(), all.end());
    } else {
        return false;
    }
    return true;
}

namespace {

// A normal through the transpose of frame -> local: the inverse transpose of local -> frame.
Vec3 normal_to_frame(const Matrix4& frame_to_local, Vec3 n) {
    const Matrix4& m = frame_to_local;
    return {m(0, 0) * n.x + m(1, 0) * n.y + m(2, 0) * n.z,
            m(0, 1) * n.x + m(1, 1) * n.y + m(2, 1) * n.z,
            m(0, 2) * n.x + m(1, 2) * n.y + m(2, 2) * n.z};
}

SolidTree::Kind kind_of(CsgShape::Operation operation) {
    switch (operation) {
        case CsgShape::Operation::union_of: return SolidTree::Kind::union_of;
        case CsgShape::Operation::merge: return SolidTree::Kind::merge;
        case CsgShape::Operation::intersection: return SolidTree::Kind::intersection;
        case CsgShape::Operation::difference: break;
    }
    return SolidTree::Kind::difference;
}

}  // namespace

int SolidTree::add_shape(const Shape& shape, const Matrix4& frame_to_local, bool inverse) {
    Node node;
    node.shape = &shape;
    node.frame_to_local = frame_to_local;
    node.inverse = inverse;
    nodes_.push_back(std::move(node));
    return int(nodes_.size()) - 1;
}

int SolidTree::add_csg(CsgShape::Operation operation, bool inverse) {
    Node node;
    node.kind = kind_of(operation);
    node.inverse = inverse;
    nodes_.push_back(std::move(node));
    return int(nodes_.size()) - 1;
}

bool SolidTree::keeps(const Node& node, size_t from, Vec3 p, bool& keep) const {
    keep = true;
    for (size_t j = 0; j < node.children.size() && keep; ++j) {
        if (j == from) continue;
        bool in = false;
        if (!inside_of(node.children[j], p, in)) return false;
        switch (node.kind) {
            case Kind::merge: keep = !in; break;
            case Kind::intersection: keep = in; break;
            case Kind::difference: keep = j == 0 ? in : !in; break;
            case Kind::union_of:
            case Kind::shape: break;
        }
    }
    return true;
}

bool SolidTree::hits_of(int index, Vec3 o, Vec3 d, std::vector<ShapeHit>& out) const {
    const Node& node = nodes_[size_t(index)];
    std::vector<ShapeHit> found;
    if (node.kind == Kind::shape) {
        if (!shape_hits(*node.shape, node.frame_to_local.point(o), node.frame_to_local.vector(d),
                        found))
            return false;
        for (ShapeHit& hit : found) {
            hit.normal = normal_to_frame(node.frame_to_local, hit.normal);
            hit.part = index;
        }
    } else {
        for (size_t i = 0; i < node.children.size(); ++i) {
            std::vector<ShapeHit> child_hits;
            if (!hits_of(node.children[i], o, d, child_hits)) return false;
            const bool subtracted = node.kind == Kind::difference && i > 0;
            for (ShapeHit& hit : child_hits) {
                bool keep = false;
                if (!keeps(node, i, o + hit.t * d, keep)) return false;
                if (!keep) continue;
                if (subtracted) hit.normal = -hit.normal;
                found.push_back(hit);
            }
        }
    }
    for (ShapeHit& hit : found) {
        if (node.inverse) hit.normal = -hit.normal;
        bool keep = true;
        for (int clip : node.clips) {
            bool in = false;
            if (!inside_of(clip, o + hit.t * d, in)) return false;
            keep = keep && in;
        }
        if (keep) out.push_back(hit);
    }
    return true;
}

bool SolidTree::inside_of(int index, Vec3 p, bool& in) const {
    const Node& node = nodes_[size_t(index)];
    if (node.kind == Kind::shape) {
        if (!shape_inside(*node.shape, node.frame_to_local.point(p), in)) return false;
    } else {
        const bool any = node.kind == Kind::union_of || node.kind == Kind::merge;
        in = !any;
        for (size_t i = 0; i < node.children.size(); ++i) {
            bool child = false;
            if (!inside_of(node.children[i], p, child)) return false;
            if (node.kind == Kind::difference && i > 0) child = !child;
            in = any ? in || child : in && child;
        }
    }
    if (node.inverse) in = !in;
    for (int clip : node.clips) {
        bool clip_in = false;
        if (!inside_of(clip, p, clip_in)) return false;
        in = in && clip_in;
    }
    return true;
}

void prepare_shape(Shape& shape) {
    if (auto* lathe = std::get_if<LatheShape>(&shape))
        lathe->profile = std::make_shared<const LatheProfile>(LatheProfile{lathe_profile(*lathe)});
    else if (auto* sor = std::get_if<SorShape>(&shape))
        sor->profile = std::make_shared<const SorProfile>(SorProfile{sor_pieces(*sor)});
    else if (auto* sweep = std::get_if<SphereSweepShape>(&shape))
        sweep->segments =
            std::make_shared<const SweepSegments>(SweepSegments{make_sweep_segments(*sweep)});
    else if (auto* polygon = std::get_if<PolygonShape>(&shape))
        polygon->plane = std::make_shared<const PolygonPlane>(polygon_plane(*polygon));
}

}  // namespace rayset::tracer
