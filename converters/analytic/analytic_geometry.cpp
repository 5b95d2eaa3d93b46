#include "converters/analytic/analytic_geometry.h"

#include <cmath>

namespace rayset::analytic {

// Both emitters use Lambert's contour form of the irradiance of a uniform Lambertian surface:
//   E = -(L/2) * contour integral of n . (R x dR) / |R|^2,   R = X - P,
// with the contour run counter-clockwise seen from the emitting side. It is the projected
// solid angle of the surface seen from P, so it is exact for any receiver orientation once
// the surface is clipped to the receiver's front half-space (where n . R > 0).

namespace {

// The contour integral along the straight edge from a to b: the angle the edge subtends at P
// times the cosine between n and the normal of the plane through P and the edge.
double edge_term(Vec3 a, Vec3 b, Vec3 point, Vec3 normal) {
    const Vec3 ra = a - point, rb = b - point;
    const Vec3 c = cross(ra, rb);
    const double cn = length(c);
    if (cn == 0) return 0;
    return std::atan2(cn, dot(ra, rb)) * dot(normal, c) / cn;
}

// Integrals over t in [t1, t2] of 1, cos t and sin t divided by D(t) = Q - B cos t, with
// Q > B >= 0. The antiderivative of 1/D is (t + 2 A(t)) / S, S = sqrt(Q^2 - B^2),
// A(t) = atan((k-1) sin t / ((k+1) - (k-1) cos t)), k = sqrt((Q+B)/(Q-B)): continuous in t
// (no branch of tan(t/2)), and written so that nothing cancels when B << Q (far field).
struct ArcIntegrals {
    double one, cos, sin;
};

ArcIntegrals arc_integrals(double q, double b, double t1, double t2) {
    const double qm = q - b, qp = q + b;
    const double s = std::sqrt(qm * qp);
    const double sqm = std::sqrt(qm), sqp = std::sqrt(qp);
    const double km1 = 2 * b / ((sqp + sqm) * sqm);
    const double kp1 = km1 + 2;
    auto a_of = [&](double t) { return std::atan(km1 * std::sin(t) / (kp1 - km1 * std::cos(t))); };
    const double dt = t2 - t1;
    const double da = a_of(t2) - a_of(t1);
    ArcIntegrals r;
    r.one = (dt + 2 * da) / s;
    // cos t / D = (Q/D - 1) / B; the two parts are rearranged so the 1/B is exact.
    r.cos =
        b > 0 ? dt * b / ((q + s) * s) + 2 * q * da / (s * b) : (std::sin(t2) - std::sin(t1)) / q;
    // sin t / D integrates to ln(D(t2)/D(t1)) / B, written with log1p for small B.
    const double d1 = q - b * std::cos(t1);
    const double dc = std::cos(t1) - std::cos(t2);
    const double x = b * dc / d1;
    r.sin = dc / d1 * (x == 0 ? 1 : std::log1p(x) / x);
    return r;
}

}  // namespace

double polygon_irradiance(double radiance, const std::vector<Vec3>& vertices, Vec3 point,
                          Vec3 normal) {
    const size_t n = vertices.size();
    if (n < 3) return 0;
    // Newell's normal points to the side from which the vertices run counter-clockwise.
    Vec3 emitting;
    for (size_t i = 0; i < n; ++i) emitting = emitting + cross(vertices[i], vertices[(i + 1) % n]);
    if (!(dot(emitting, point - vertices[0]) > 0))
        return 0;  // behind the emitting side or in its plane

    std::vector<Vec3> clipped;
    clipped.reserve(n + 2);
    for (size_t i = 0; i < n; ++i) {
        const Vec3 a = vertices[i], b = vertices[(i + 1) % n];
        const double sa = dot(normal, a - point), sb = dot(normal, b - point);
        if (sa > 0) clipped.push_back(a);
        if ((sa > 0) != (sb > 0)) clipped.push_back(a + (sa / (sa - sb)) * (b - a));
    }
    if (clipped.size() < 3) return 0;
    double sum = 0;
    for (size_t i = 0; i < clipped.size(); ++i)
        sum += edge_term(clipped[i], clipped[(i + 1) % clipped.size()], point, normal);
    return std::max(0.0, -0.5 * radiance * sum);
}

double disk_irradiance(double radiance, Vec3 centre, Vec3 axis, double radius, Vec3 point,
                       Vec3 normal) {
    Vec3 e1, e2;
    orthonormal_basis(axis, e1, e2);
    const Vec3 d = point - centre;
    const double px = dot(d, e1), py = dot(d, e2), h = dot(d, axis);
    if (!(h > 0)) return 0;
    const double nx = dot(normal, e1), ny = dot(normal, e2), nz = dot(normal, axis);
    const double a = radius;

    // The receiver's plane meets the disk's plane in the line nx x + ny y = c; the disk sees
    // the receiver's front where nx x + ny y > c.
    const double c = nx * px + ny * py + nz * h;
    const double m = std::hypot(nx, ny);
    double phi1 = -kPi, phi2 = kPi;  // the visible arc
    bool chord = false;
    if (m * a <= c) return 0;
    if (-m * a < c) {
        const double centre_angle = std::atan2(ny, nx);
        const double half = std::acos(c / (m * a));
        phi1 = centre_angle - half;
        phi2 = centre_angle + half;
        chord = true;
    }

    // Along the circle X(phi) = a (cos phi, sin phi, 0):
    //   n . (R x dR/dphi) = a [nz a + p cos phi + q sin phi],
    //   |R|^2 = Q - 2 a rho cos(phi - psi),  Q = a^2 + rho^2 + h^2.
    const double rho = std::hypot(px, py);
    const double psi = rho > 0 ? std::atan2(py, px) : 0;
    const double p = h * nx - nz * px, q = h * ny - nz * py;
    const double c1 = p * std::cos(psi) + q * std::sin(psi);
    const double s1 = q * std::cos(psi) - p * std::sin(psi);
    const double big_q = a * a + rho * rho + h * h, big_b = 2 * a * rho;
    double arc;
    if (!chord) {
        // Full circle: the sin part vanishes and the others have closed forms.
        const double s = std::sqrt((big_q - big_b) * (big_q + big_b));
        arc = a * (nz * a * 2 * kPi / s + c1 * 2 * kPi * big_b / ((big_q + s) * s));
    } else {
        const ArcIntegrals i = arc_integrals(big_q, big_b, phi1 - psi, phi2 - psi);
        arc = a * (nz * a * i.one + c1 * i.cos + s1 * i.sin);
    }
    double sum = arc;
    if (chord) {
        // The chord closes the contour from the arc's end back to its start (in world space).
        auto at = [&](double phi) {
            return centre + (a * std::cos(phi)) * e1 + (a * std::sin(phi)) * e2;
        };
        sum += edge_term(at(phi2), at(phi1), point, normal);
    }
    return std::max(0.0, -0.5 * radiance * sum);
}

}  // namespace rayset::analytic
