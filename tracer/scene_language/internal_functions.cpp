// POV-Ray 3.7's internal functions (functions.inc, reference manual 3.4.9.1.7). The manual
// names each surface and its parameters but seldom gives a formula; the formulas below are
// POV-Ray's observed behaviour, each one checked against `povray` 3.7.0.10 at hundreds of
// random arguments to 10 significant digits or better (the test keeps a sample:
// tests/scene_language/internal_functions_test.cpp).
// Where POV-Ray departs from the textbook surface (integer-division constants, clamps,
// offsets) the departure is kept and said in a comment.
#include "tracer/scene_language/internal_functions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include "core/geometry.h"
#include "tracer/scene_language/noise.h"

namespace rayset::tracer {
namespace {

constexpr double kSqrt3 = 1.73205080756887729353;

double sqr(double v) { return v * v; }
double cube(double v) { return v * v * v; }
double radians(double degrees) { return degrees * (kPi / 180.0); }

// Arguments of one call: x, y, z, then P0, P1, ...
struct Args {
    const double* a;
    double x() const { return a[0]; }
    double y() const { return a[1]; }
    double z() const { return a[2]; }
    double p(int i) const { return a[3 + i]; }
};

// "Field Strength" (manual 3.4.9.1.7.3): the surface's polynomial times P0. POV-Ray also keeps
// the product within [-10, 10].
double field(double strength, double value) {
    return std::max(-10.0, std::min(10.0, strength * value));
}

// The 2d curve's plane for the algebraic cylinders and the *_2d functions (manual
// 3.4.9.1.7.5-7): with the SOR switch off the curve is extruded along z; on, it is swept
// around the y axis after being shifted by the SOR offset along x and rotated by the SOR angle
// (degrees) about z.
struct CurvePoint {
    double x, y;
};
CurvePoint curve_point(const Args& a, double sor_switch, double offset, double angle) {
    if (sor_switch <= 0) return {a.x(), a.y()};
    const double u = std::hypot(a.x(), a.z()) - offset;
    const double s = std::sin(radians(angle)), c = std::cos(radians(angle));
    return {u * c - a.y() * s, u * s + a.y() * c};
}

// ---- Algebraic cylinders: P0 field strength, P1 field limit, P2-P4 SOR. ----

// The field limit bounds the value to [-P1, P1]. f_algbr_cyl1 applies the lower bound last,
// the other three the upper bound last (visible only for a negative limit).
double limit_low_last(double v, double lim) { return std::max(-lim, std::min(lim, v)); }
double limit_high_last(double v, double lim) { return std::min(lim, std::max(-lim, v)); }

template <double (*curve)(double, double), double (*limit)(double, double)>
double algebraic_cylinder(const double* a) {
    const Args args{a};
    const CurvePoint c = curve_point(args, args.p(2), args.p(3), args.p(4));
    return limit(args.p(0) * curve(c.x, c.y), args.p(1));
}
// A figure of eight.
double cyl1_curve(double x, double y) { return cube(std::fabs(x)) - x * x + y * y; }
double cyl2_curve(double x, double y) {
    return -y * y + 2 * cube(y) + 3 * x * x * y - sqr(y * y) - 2 * sqr(x * x);
}
double cyl3_curve(double x, double y) {
    return -y * y + x * y * y + 2 * x * x * y - x * x * y * y - sqr(x * x);
}
double cyl4_curve(double x, double y) {
    return cube(y) - 3 * x * x * y - sqr(y * y) - 2 * x * x * y * y - sqr(x * x);
}

// ---- The *_2d curves: P0 field strength, then the curve's parameters, then the SOR ones. ----

template <double (*curve)(double, double, const Args&), int curve_params>
double curve_2d(const double* a) {
    const Args args{a};
    const CurvePoint c = curve_point(args, args.p(curve_params + 1), args.p(curve_params + 2),
                                     args.p(curve_params + 3));
    return field(args.p(0), curve(c.x, c.y, args));
}
double devils_curve_2d(double x, double y, const Args& a) {
    return sqr(a.p(1) * x) - sqr(a.p(2) * y) + sqr(y * y) - sqr(x * x);
}
double folium_surface_2d(double x, double y, const Args& a) {
    return -y * y - x * x * (1 + a.p(2)) + x * y * y * (4 * a.p(1) - a.p(2));
}
double kampyle_of_eudoxus_2d(double x, double y, const Args& a) {
    const double dimple = a.p(1), closeness = a.p(2);
    return -y * y - dimple * cube(closeness) * x * x + sqr(closeness) * sqr(x * x);
}
double lemniscate_of_gerono_2d(double x, double y, const Args& a) {
    const double size = a.p(1), width = a.p(2);
    return sqr(width * x) * (sqr(size) - x * x) - y * y;
}
double piriform_2d(double x, double y, const Args& a) {
    return sqr(a.p(3)) * (a.p(1) * cube(x) + a.p(2) * sqr(x * x)) - y * y;
}
double strophoid_2d(double x, double y, const Args& a) {
    const double size = a.p(1), sharpness = a.p(2), fatness = a.p(3);
    return (x - sharpness) * y * y + sqr(fatness) * (size * x * x + cube(x));
}
double witch_of_agnesi_2d(double x, double y, const Args& a) {
    return a.p(2) - y * (sqr(a.p(1)) + x * x);
}

// ---- Surfaces whose value is P0, the field strength, times a function of x, y, z, P1... ----

template <double (*surface)(double, double, double, const Args&)>
double field_surface(const double* a) {
    const Args args{a};
    return field(args.p(0), surface(args.x(), args.y(), args.z(), args));
}
double bicorn(double x, double y, double z, const Args& a) {
    const double s = a.p(1), rho2 = x * x + z * z;
    return y * y * (s * s - rho2) - sqr(rho2 + 2 * s * y - s * s);
}
double bifolia(double x, double y, double z, const Args& a) {
    return a.p(1) * y * (x * x + z * z) - sqr(x * x + y * y + z * z);
}
// Apéry's sextic for Boy's surface. P1 multiplies the value: it does not scale the shape, as
// the manual says it does.
double boy_surface(double x, double y, double z, const Args& a) {
    const double s2 = std::sqrt(2.0), r2 = x * x + y * y, w = 1 - z;
    const double value =
        64 * cube(w) * cube(z) - 48 * sqr(w) * z * z * (3 * r2 + 2 * z * z) +
        12 * w * z *
            (27 * r2 * r2 - 24 * z * z * r2 + 36 * s2 * y * z * (y * y - 3 * x * x) +
             4 * sqr(z * z)) +
        (9 * r2 - 2 * z * z) * (-81 * r2 * r2 - 72 * z * z * r2 +
                                108 * s2 * x * z * (x * x - 3 * y * y) + 4 * sqr(z * z));
    return a.p(1) * value;
}
double crossed_trough(double x, double y, double z, const Args&) { return x * x * z * z - y; }
double cubic_saddle(double x, double y, double z, const Args&) { return z + cube(y) - cube(x); }
// f_cushion and f_odd evaluate the same polynomial.
double cushion(double x, double y, double z, const Args&) {
    return z * z * x * x - sqr(z * z) - 2 * z * x * x + 2 * cube(z) + x * x - z * z -
           sqr(x * x - z) - sqr(y * y) - 2 * x * x * y * y - y * y * z * z + 2 * y * y * z + y * y;
}
double devils_curve(double x, double y, double z, const Args&) {
    return 0.36 * x * x - 0.25 * y * y + sqr(y * y) - sqr(x * x + z * z);
}
// A Dupin cyclid as the torus (major P1, minor P2) displaced by (P3, P4, 0) and inverted in
// the sphere of radius P5 about the origin, with denominators cleared. POV-Ray's expansion
// differs from that inversion by the last term (the y displacement's product with
// P1^2 - P2^2 has the opposite sign); it is kept.
double dupin_cyclid(double x, double y, double z, const Args& a) {
    const double major = a.p(1), minor = a.p(2), dx = a.p(3), dy = a.p(4), e2 = sqr(a.p(5));
    const double k = major * major - minor * minor, r2 = x * x + y * y + z * z;
    const double s = e2 * e2 - 2 * e2 * (dx * x + dy * y) + (dx * dx + dy * dy + k) * r2;
    const double qx = e2 * x - dx * r2;
    return -(s * s - 4 * major * major * (qx * qx + sqr(e2 * z)) + 8 * e2 * k * dy * y * r2);
}
// Enneper's surface, ((y^2-x^2)/2z + 2z^2/9 + 2/3)^3 = 6((y^2-x^2)/4z - (x^2+y^2+8z^2/9)/4 +
// 2/9)^2, as POV-Ray computes it: the constants 2/3, 1/4 and 2/9 are lost (integer
// division), and z is taken as 0.2 in the denominators where |z| < 0.2.
double enneper(double x, double y, double z, const Args&) {
    const double u = y * y - x * x;
    const double d = std::fabs(z) < 0.2 ? 0.2 : z;
    const double a = u / (2 * d) + 2.0 / 9.0 * z * z;
    const double b = u / (4 * d);
    return -(cube(a) - 6 * b * b);
}
double folium_surface(double x, double y, double z, const Args& a) {
    const double neck = a.p(1), divergence = a.p(2), yz2 = y * y + z * z;
    return x * x * (1 + divergence) + yz2 + x * yz2 * (divergence - 4 * neck);
}
double glob(double x, double y, double z, const Args&) {
    return 0.5 * sqr(x * x) * (1 + x) - y * y - z * z;
}
double heart(double x, double y, double z, const Args&) {
    return -(cube(2 * x * x + y * y + z * z - 1) - 0.1 * x * x * cube(z) - y * y * cube(z));
}
double hunt_surface(double x, double y, double z, const Args&) {
    return -(4 * cube(x * x + y * y + z * z - 13) + 27 * sqr(3 * x * x + y * y - 4 * z * z - 12));
}
double hyperbolic_torus(double x, double y, double z, const Args& a) {
    const double major = a.p(1), minor = a.p(2);
    return 4 * major * major * (x * x - z * z) -
           sqr(x * x + y * y - z * z + major * major - minor * minor);
}
double kampyle_of_eudoxus(double x, double y, double z, const Args& a) {
    const double dimple = a.p(1), closeness = a.p(2);
    return sqr(closeness) * (sqr(x * x) - sqr(dimple * x)) - y * y - z * z;
}
double klein_bottle(double x, double y, double z, const Args&) {
    const double r2 = x * x + y * y + z * z;
    return -((r2 + 2 * y - 1) * (sqr(r2 - 2 * y - 1) - 8 * z * z) + 16 * x * z * (r2 - 2 * y - 1));
}
double kummer_surface_v1(double x, double y, double z, const Args&) {
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    return -1 + x2 + y2 + z2 - x2 * x2 - y2 * y2 - z2 * z2 + x2 * y2 + y2 * z2 + x2 * z2;
}
double kummer_surface_v2(double x, double y, double z, const Args& a) {
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    return 1 - a.p(1) * (x2 + y2 + z2) - (x2 * x2 + y2 * y2 + z2 * z2) -
           a.p(2) * (x2 * y2 + y2 * z2 + x2 * z2) - a.p(3) * x * y * z;
}
double lemniscate_of_gerono(double x, double y, double z, const Args&) {
    return x * x - sqr(x * x) - y * y - z * z;
}
double mitre(double x, double y, double z, const Args&) {
    return y * y - y * y * z * z - sqr(y * y) - 4 * x * x * (x * x + y * y + z * z);
}
double nodal_cubic(double, double y, double z, const Args&) {
    return 6 * y * z - cube(y) - cube(z);
}
double ovals_of_cassini(double x, double y, double z, const Args& a) {
    const double major = a.p(1), filling = a.p(2), thickness = a.p(3);
    return sqr(filling) - sqr(x * x + y * y + z * z + major * major) +
           thickness * major * major * (x * x + z * z);
}
double paraboloid(double x, double y, double z, const Args&) { return y - x * x - z * z; }
double parabolic_torus(double x, double y, double z, const Args& a) {
    const double m2 = sqr(a.p(1)), n2 = sqr(a.p(2)), w = x * x + y * y - z;
    return n2 * w + m2 * (x * x - y * y - z) - w * w - sqr(m2 - n2);
}
double pillow(double x, double y, double z, const Args&) {
    return sqr(x * x) + sqr(y * y) + sqr(z * z) - x * x - y * y - z * z;
}
double piriform(double x, double y, double z, const Args&) {
    return sqr(x * x) - cube(x) + y * y + z * z;
}
double quartic_paraboloid(double x, double y, double z, const Args&) {
    return y - sqr(x * x) - sqr(z * z);
}
double quartic_saddle(double x, double y, double z, const Args&) {
    return y + sqr(z * z) - sqr(x * x);
}
double quartic_cylinder(double x, double y, double z, const Args& a) {
    const double d2 = sqr(a.p(1)), w2 = sqr(a.p(2));
    return w2 * d2 - (x * x + z * z) * (w2 + y * y);
}
double steiners_roman(double x, double y, double z, const Args&) {
    return -(x * x * y * y + y * y * z * z + x * x * z * z + x * y * z);
}
double strophoid(double x, double y, double z, const Args& a) {
    const double size = a.p(1), sharpness = a.p(2), fatness = a.p(3);
    return (x - sharpness) * (y * y + z * z) + sqr(fatness) * (size * x * x + cube(x));
}
double torus2(double x, double y, double z, const Args& a) {
    const double major = a.p(1), minor = a.p(2);
    return 4 * major * major * (x * x + z * z) -
           sqr(x * x + y * y + z * z + major * major - minor * minor);
}
double torus_gumdrop(double x, double y, double z, const Args&) {
    const double yz2 = y * y + z * z;
    return -17 + 20 * (x * x + yz2) - 4 * yz2 * yz2 - 17 * x * x * yz2 - 4 * sqr(x * x);
}
double umbrella(double x, double y, double z, const Args&) { return y * z * z - x * x; }
double witch_of_agnesi(double x, double y, double z, const Args& a) {
    return a.p(1) * (1 - y) - y * (x * x + z * z);
}

// ---- Blobs and crossed ellipsoids. ----

// One component of f_blob: POV-Ray's blob field (1 - (d/radius)^2)^2 inside the radius.
double blob_component(double d2, double strength, double inverse_radius) {
    const double t = sqr(inverse_radius) * d2;
    return t < 1 ? strength * sqr(1 - t) : 0.0;
}
// Two components at (-P0/2, 0, 0) and (P0/2, 0, 0).
double blob(const double* a) {
    const Args args{a};
    const double h = args.p(0) / 2, yz2 = sqr(args.y()) + sqr(args.z());
    return -(blob_component(sqr(args.x() + h) + yz2, args.p(1), args.p(2)) +
             blob_component(sqr(args.x() - h) + yz2, args.p(3), args.p(4)));
}
// Two gaussian components, at the origin and at (P0, 0, 0).
double blob2(const double* a) {
    const Args args{a};
    const double yz2 = sqr(args.y()) + sqr(args.z());
    const double inverse_size = args.p(1), strength = args.p(2), threshold = args.p(3);
    return threshold - strength * (std::exp(-inverse_size * (sqr(args.x()) + yz2)) +
                                   std::exp(-inverse_size * (sqr(args.x() - args.p(0)) + yz2)));
}

// The gaussians of the three ellipsoids along x, y and z: exp(-k (u^2 + e (v^2 + w^2))) for
// eccentricity e and inverse size k.
std::array<double, 3> axis_gaussians(const Args& a, double eccentricity, double inverse_size) {
    const double x2 = sqr(a.x()), y2 = sqr(a.y()), z2 = sqr(a.z());
    return {std::exp(-inverse_size * (x2 + eccentricity * (y2 + z2))),
            std::exp(-inverse_size * (y2 + eccentricity * (x2 + z2))),
            std::exp(-inverse_size * (z2 + eccentricity * (x2 + y2)))};
}
// P0 eccentricity, P1 inverse size, P2 diameter (the gaussians' height), P3 threshold.
double cross_ellipsoids(const double* a) {
    const Args args{a};
    const auto g = axis_gaussians(args, args.p(0), args.p(1));
    return args.p(3) - args.p(2) * std::max({g[0], g[1], g[2]});
}
double isect_ellipsoids(const double* a) {
    const Args args{a};
    const auto g = axis_gaussians(args, args.p(0), args.p(1));
    return args.p(3) - args.p(2) * std::min({g[0], g[1], g[2]});
}
// P0 spikiness, P1 inverse size, P2 flange (the gaussians' height), P3 threshold.
double flange_cover(const double* a) {
    const Args args{a};
    const auto g = axis_gaussians(args, args.p(0), args.p(1));
    return args.p(3) - args.p(2) * (g[0] + g[1] + g[2]);
}
// P0 spikiness, P1 hollowness (inverse size of the ellipsoids), P2 size (a factor), P3
// roundness (inverse size of a central sphere), P4 fatness (that sphere's weight).
double spikes(const double* a) {
    const Args args{a};
    const auto g = axis_gaussians(args, args.p(0), args.p(1));
    const double r2 = sqr(args.x()) + sqr(args.y()) + sqr(args.z());
    return args.p(2) * (g[0] + g[1] + g[2] - args.p(4) * std::exp(-args.p(3) * r2));
}

// ---- Helices and spirals. ----

// The "Cross section type" t (manual 3.4.9.1.7.2) is the 2/t-norm of the offset from the
// tube's centre line: 0 square, 1 circle, 2 diamond, 3 concave diamond.
double cross_section(double u, double v, double type) {
    if (type == 0) return std::max(std::fabs(u), std::fabs(v));
    const double p = 2 / type;
    return std::pow(std::pow(std::fabs(u), p) + std::pow(std::fabs(v), p), 1 / p);
}

// P0 helices of minor radius P2 about a circle of radius P3 around y, turning P1 radians per
// unit of y; the offset along y is divided by the shape P4 and the cross section (P5) rotated
// by P6 degrees. Helix i passes angle pi/P0 + 2 pi i/P0 (measured from x towards z) at y = 0.
// POV-Ray caps the distance at that through the axis, |p| + P3.
double helix1(const double* a) {
    const Args args{a};
    const double count = args.p(0), period = args.p(1), minor = args.p(2), major = args.p(3);
    const double r = std::hypot(args.x(), args.z());
    const double step = 2 * kPi / count;
    double turn = kPi / count - std::atan2(args.z(), args.x()) - period * args.y();
    turn -= step * std::round(turn / step);
    const double radial = r - major, along = turn / period / args.p(4);
    const double s = std::sin(radians(args.p(6))), c = std::cos(radians(args.p(6)));
    const double d = cross_section(radial * c + along * s, along * c - radial * s, args.p(5));
    return std::min(r + major, d) - minor;  // the cap also when d is NaN (P0 or P1 zero)
}
// One helix, measured in the horizontal plane: the tube's centre at height y is
// P3 (cos P1 y, sin P1 y); the offset is split into its radial and tangential parts. P0, P4
// and the rotation P6 have no effect (the manual calls P6 the cross section's rotation).
double helix2(const double* a) {
    const Args args{a};
    const double angle = args.p(1) * args.y(), major = args.p(3);
    const double c = std::cos(angle), s = std::sin(angle);
    const double dx = args.x() - major * c, dz = args.z() - major * s;
    return cross_section(dx * c + dz * s, dz * c - dx * s, args.p(5)) - args.p(2);
}
// An Archimedean spiral in the xz plane, P0 apart between windings, whose tube of radius P1
// has cross section P5, within the sphere of radius P2. P3 and P4 have no effect. As for
// f_helix1, POV-Ray caps the distance, here at that to the origin; on the y axis it takes the
// distance from the axis as 1e-6.
double spiral(const double* a) {
    const Args args{a};
    const double spacing = args.p(0);
    const double r = args.x() == 0 && args.z() == 0 ? 1e-6 : std::hypot(args.x(), args.z());
    const double centre = std::sqrt(r * r + sqr(args.y()));
    double winding = r / spacing + std::atan2(args.z(), args.x()) / (2 * kPi) - 0.5;
    winding -= std::round(winding);
    const double tube = std::min(cross_section(spacing * winding, args.y(), args.p(5)), centre);
    return std::max(centre - args.p(2), tube - args.p(1));  // the sphere when P0 = 0 (NaN)
}

// ---- Grids. ----

// Hexagonal cylinders along z, centres sqrt(3) apart on rows 1.5 apart (alternate rows
// shifted by sqrt(3)/2): the hexagonal distance (apothem 1 at value 1) to the nearest centre.
double hex_x(const double* a) {
    const Args args{a};
    const double x = args.x(), y = args.y();
    const auto hexagonal = [](double dx, double dy) {
        return std::max(std::fabs(dx), std::fabs(dx) / 2 + std::fabs(dy) * kSqrt3 / 2);
    };
    double best = HUGE_VAL;
    for (int row = 0; row < 2; ++row) {
        const double j = std::floor(y / 1.5) + row;
        const double shift = std::fmod(std::fabs(j), 2) * kSqrt3 / 2;
        for (int column = 0; column < 2; ++column) {
            const double i = std::floor((x - shift) / kSqrt3) + column;
            best = std::min(best, hexagonal(x - shift - kSqrt3 * i, y - 1.5 * j));
        }
    }
    return best;
}
// The distance to the nearest line of the triangular grid joining those centres (lines along
// x 1.5 apart and their copies turned by +-60 degrees).
double hex_y(const double* a) {
    const Args args{a};
    const auto to_line = [](double t) { return std::fabs(t - 1.5 * std::round(t / 1.5)); };
    const double u = args.x() * kSqrt3 / 2;
    return std::min({to_line(args.y()), to_line(u - args.y() / 2), to_line(u + args.y() / 2)});
}
// Woven threads: along x at z = j P1 and along z at x = i P0, their centre lines waving in
// y by P3 cos(pi * position / spacing), alternately up and down; P2 and P4 scale the
// horizontal and vertical offsets. The two nearest threads of each direction are measured.
double mesh1(const double* a) {
    const Args args{a};
    const double x = args.x(), y = args.y(), z = args.z();
    const double dx = args.p(0), dz = args.p(1), across = args.p(2), wave = args.p(3),
                 up = args.p(4);
    const auto sign = [](double n) { return std::fmod(std::fabs(n), 2) == 0 ? 1.0 : -1.0; };
    double best = HUGE_VAL;
    for (int k = 0; k < 2; ++k) {
        const double j = std::floor(z / dz) + k;
        const double centre = wave * std::cos(kPi * x / dx) * sign(j);
        best = std::min(best, std::hypot(across * (z - j * dz), up * (y - centre)));
    }
    for (int k = 0; k < 2; ++k) {
        const double i = std::floor(x / dx) + k;
        const double centre = -wave * std::cos(kPi * z / dz) * sign(i);
        best = std::min(best, std::hypot(across * (x - i * dx), up * (y - centre)));
    }
    return best;
}

// ---- Surfaces of revolution and tubes. ----

double polynomial4(const Args& a, int first) {
    const double y = a.y();
    return a.p(first) +
           y * (a.p(first + 1) + y * (a.p(first + 2) + y * (a.p(first + 3) + y * a.p(first + 4))));
}
// Revolves x = P0 + P1 y + ... + P4 y^4 about y; POV-Ray floors the polynomial at -5.
double poly4(const double* a) {
    const Args args{a};
    return std::hypot(args.x(), args.z()) - std::max(polynomial4(args, 0), -5.0);
}
// int(P0) tubes around y, the k-th centred at distance P(y) = P1 + P2 y + ... + P5 y^4 in
// the direction 2 pi k / P0 (measured from z towards x; a non-integer P0 leaves a gap). The
// value is the distance to the nearest centre line, at most 10000.
double polytubes(const double* a) {
    const Args args{a};
    constexpr double kFar = 10000;
    const double tubes = std::trunc(args.p(0));
    if (!(tubes >= 1)) return kFar;
    const double step = 2 * kPi / args.p(0), radius = polynomial4(args, 1);
    const auto distance = [&](double k) {
        const double angle = k * step;
        return std::hypot(args.x() - radius * std::sin(angle), args.z() - radius * std::cos(angle));
    };
    // The centres lie at increasing angles below 2 pi, so the nearest is a neighbour of the
    // point's angle (turned by pi for a negative radius) or one of the two ends.
    double angle = std::atan2(args.x(), args.z()) + (radius < 0 ? kPi : 0.0);
    angle = std::fmod(angle + 2 * kPi, 2 * kPi);
    const double below = std::min(std::floor(angle / step), tubes - 1);
    double best = std::min(distance(0), distance(tubes - 1));
    best = std::min({best, distance(below), distance(std::min(below + 1, tubes - 1))});
    return std::min(best, kFar);
}

// ---- Simple shapes. ----

double ellipsoid(const double* a) {
    const Args args{a};
    return std::sqrt(sqr(args.p(0) * args.x()) + sqr(args.p(1) * args.y()) +
                     sqr(args.p(2) * args.z()));
}
// Latitude: the angle from the +y axis.
double ph(const double* a) {
    const Args args{a};
    return std::atan2(std::hypot(args.x(), args.z()), args.y());
}
double r(const double* a) {
    const Args args{a};
    return std::sqrt(sqr(args.x()) + sqr(args.y()) + sqr(args.z()));
}
// Longitude: the angle about y from +z towards +x.
double th(const double* a) {
    const Args args{a};
    return std::atan2(args.x(), args.z());
}
double sphere(const double* a) { return r(a) - Args{a}.p(0); }
// POV-Ray's solid noise at x, y, z (noise.h): f_noise3d with the default generator (POV-Ray
// takes global_settings' there), f_noise_generator with generator P0.
double noise3d(const double* a) { return solid_noise({a[0], a[1], a[2]}, kDefaultNoiseGenerator); }
double noise_generator(const double* a) {
    return solid_noise({a[0], a[1], a[2]}, static_cast<int>(Args{a}.p(0)));
}
double torus(const double* a) {
    const Args args{a};
    return std::hypot(std::hypot(args.x(), args.z()) - args.p(0), args.y()) - args.p(1);
}
// The box of half-sizes P1-P3 with edges rounded to radius P0, by its distance; POV-Ray
// measures 0 inside the rounded core and subtracts a further 1e-6.
double rounded_box(const double* a) {
    const Args args{a};
    const double radius = args.p(0);
    const double qx = std::max(std::fabs(args.x()) - (args.p(1) - radius), 0.0);
    const double qy = std::max(std::fabs(args.y()) - (args.p(2) - radius), 0.0);
    const double qz = std::max(std::fabs(args.z()) - (args.p(3) - radius), 0.0);
    return std::sqrt(qx * qx + qy * qy + qz * qz) - radius - 1e-6;
}
// 1 - ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2), e = P0 (east-west), n = P1.
double superellipsoid(const double* a) {
    const Args args{a};
    const double e = args.p(0), n = args.p(1);
    const double xy = std::pow(
        std::pow(std::fabs(args.x()), 2 / e) + std::pow(std::fabs(args.y()), 2 / e), e / n);
    return 1 - std::pow(xy + std::pow(std::fabs(args.z()), 2 / n), n / 2);
}
// The density of a d orbital about y, r^4 (3 cos^2 - 1)^2 e^(-4r/3), below 1.2. POV-Ray's decay
// constant is 1.33333332, not 4/3 (this form agrees with it to 11 digits).
double quantum(const double* a) {
    const Args args{a};
    const double r2 = sqr(args.x()) + sqr(args.y()) + sqr(args.z());
    return 1.2 - 1.6 * sqr(3 * sqr(args.y()) - r2) * std::exp(-1.33333332 * std::sqrt(r2));
}
// y minus P0 cos(P1 x) cos(P2 z) e^(-P3 (x^2 + z^2)).
double spikes_2d(const double* a) {
    const Args args{a};
    const double x = args.x(), z = args.z();
    return args.y() - args.p(0) * std::cos(args.p(1) * x) * std::cos(args.p(2) * z) *
                          std::exp(-args.p(3) * (x * x + z * z));
}

// ---- The table. ----

using Evaluator = double (*)(const double*);

struct InternalFunction {
    int number;
    const char* name;
    int arity;           // x, y, z and the extra parameters
    Evaluator evaluate;  // nullptr: not implemented
};

// Every internal(N) of POV-Ray 3.7, in functions.inc's order. internal(77) exists (three
// parameters) but functions.inc declares no name for it.
constexpr InternalFunction kFunctions[] = {
    {0, "f_algbr_cyl1", 8, algebraic_cylinder<cyl1_curve, limit_low_last>},
    {1, "f_algbr_cyl2", 8, algebraic_cylinder<cyl2_curve, limit_high_last>},
    {2, "f_algbr_cyl3", 8, algebraic_cylinder<cyl3_curve, limit_high_last>},
    {3, "f_algbr_cyl4", 8, algebraic_cylinder<cyl4_curve, limit_high_last>},
    {4, "f_bicorn", 5, field_surface<bicorn>},
    {5, "f_bifolia", 5, field_surface<bifolia>},
    {6, "f_blob", 8, blob},
    {7, "f_blob2", 7, blob2},
    {8, "f_boy_surface", 5, field_surface<boy_surface>},
    {9, "f_comma", 4, nullptr},
    {10, "f_cross_ellipsoids", 7, cross_ellipsoids},
    {11, "f_crossed_trough", 4, field_surface<crossed_trough>},
    {12, "f_cubic_saddle", 4, field_surface<cubic_saddle>},
    {13, "f_cushion", 4, field_surface<cushion>},
    {14, "f_devils_curve", 4, field_surface<devils_curve>},
    {15, "f_devils_curve_2d", 9, curve_2d<devils_curve_2d, 2>},
    {16, "f_dupin_cyclid", 9, field_surface<dupin_cyclid>},
    {17, "f_ellipsoid", 6, ellipsoid},
    {18, "f_enneper", 4, field_surface<enneper>},
    {19, "f_flange_cover", 7, flange_cover},
    {20, "f_folium_surface", 6, field_surface<folium_surface>},
    {21, "f_folium_surface_2d", 9, curve_2d<folium_surface_2d, 2>},
    {22, "f_glob", 4, field_surface<glob>},
    {23, "f_heart", 4, field_surface<heart>},
    {24, "f_helical_torus", 13, nullptr},
    {25, "f_helix1", 10, helix1},
    {26, "f_helix2", 10, helix2},
    {27, "f_hex_x", 4, hex_x},
    {28, "f_hex_y", 4, hex_y},
    {29, "f_hetero_mf", 9, nullptr},
    {30, "f_hunt_surface", 4, field_surface<hunt_surface>},
    {31, "f_hyperbolic_torus", 6, field_surface<hyperbolic_torus>},
    {32, "f_isect_ellipsoids", 7, isect_ellipsoids},
    {33, "f_kampyle_of_eudoxus", 6, field_surface<kampyle_of_eudoxus>},
    {34, "f_kampyle_of_eudoxus_2d", 9, curve_2d<kampyle_of_eudoxus_2d, 2>},
    {35, "f_klein_bottle", 4, field_surface<klein_bottle>},
    {36, "f_kummer_surface_v1", 4, field_surface<kummer_surface_v1>},
    {37, "f_kummer_surface_v2", 7, field_surface<kummer_surface_v2>},
    {38, "f_lemniscate_of_gerono", 4, field_surface<lemniscate_of_gerono>},
    {39, "f_lemniscate_of_gerono_2d", 9, curve_2d<lemniscate_of_gerono_2d, 2>},
    {40, "f_mesh1", 8, mesh1},
    {41, "f_mitre", 4, field_surface<mitre>},
    {42, "f_nodal_cubic", 4, field_surface<nodal_cubic>},
    {43, "f_odd", 4, field_surface<cushion>},
    {44, "f_ovals_of_cassini", 7, field_surface<ovals_of_cassini>},
    {45, "f_paraboloid", 4, field_surface<paraboloid>},
    {46, "f_parabolic_torus", 6, field_surface<parabolic_torus>},
    {47, "f_ph", 3, ph},
    {48, "f_pillow", 4, field_surface<pillow>},
    {49, "f_piriform", 4, field_surface<piriform>},
    {50, "f_piriform_2d", 10, curve_2d<piriform_2d, 3>},
    {51, "f_poly4", 8, poly4},
    {52, "f_polytubes", 9, polytubes},
    {53, "f_quantum", 4, quantum},
    {54, "f_quartic_paraboloid", 4, field_surface<quartic_paraboloid>},
    {55, "f_quartic_saddle", 4, field_surface<quartic_saddle>},
    {56, "f_quartic_cylinder", 6, field_surface<quartic_cylinder>},
    {57, "f_r", 3, r},
    {58, "f_ridge", 9, nullptr},
    {59, "f_ridged_mf", 9, nullptr},
    {60, "f_rounded_box", 7, rounded_box},
    {61, "f_sphere", 4, sphere},
    {62, "f_spikes", 8, spikes},
    {63, "f_spikes_2d", 7, spikes_2d},
    {64, "f_spiral", 9, spiral},
    {65, "f_steiners_roman", 4, field_surface<steiners_roman>},
    {66, "f_strophoid", 7, field_surface<strophoid>},
    {67, "f_strophoid_2d", 10, curve_2d<strophoid_2d, 3>},
    {68, "f_superellipsoid", 5, superellipsoid},
    {69, "f_th", 3, th},
    {70, "f_torus", 5, torus},
    {71, "f_torus2", 6, field_surface<torus2>},
    {72, "f_torus_gumdrop", 4, field_surface<torus_gumdrop>},
    {73, "f_umbrella", 4, field_surface<umbrella>},
    {74, "f_witch_of_agnesi", 5, field_surface<witch_of_agnesi>},
    {75, "f_witch_of_agnesi_2d", 9, curve_2d<witch_of_agnesi_2d, 2>},
    {76, "f_noise3d", 3, noise3d},
    {77, "", 3, nullptr},
    {78, "f_noise_generator", 4, noise_generator},
};

const InternalFunction* find(int number) {
    constexpr int kCount = sizeof(kFunctions) / sizeof(kFunctions[0]);
    static_assert(kFunctions[kCount - 1].number == kCount - 1, "kFunctions is indexed by number");
    return number >= 0 && number < kCount ? &kFunctions[number] : nullptr;
}

}  // namespace

int internal_function_arity(int number) {
    const InternalFunction* f = find(number);
    return f ? f->arity : -1;
}

const char* internal_function_name(int number) {
    const InternalFunction* f = find(number);
    return f ? f->name : "";
}

bool evaluate_internal_function(int number, const double* args, double& result) {
    const InternalFunction* f = find(number);
    if (!f || !f->evaluate) return false;
    result = f->evaluate(args);
    return true;
}

}  // namespace rayset::tracer
