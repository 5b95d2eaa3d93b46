// The analytic sources against independent truths: irradiance closed forms against brute-force
// 2-D quadrature of the radiance, textbook special cases, the far-field limit, intensity
// against total flux, and the sampled rays against the irradiance they should deliver.
#include "converters/analytic/analytic_sources.h"
#include "synth_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace rayset::analytic {
namespace {

using test::integrate;

constexpr double kQuadratureTolerance = 1e-13;

// Brute force: E = integral over the visible emitter area of L cos_e cos_r / r^2, with the emitter
// area clipped to the receiver's front half-space through the integration bounds (so the inner
// integrand is smooth), for a one-sided emitter in z = 0 facing +z. The x extent of each
// emitter is given by x(u) and the y extent at x by [y_low(x), y_high(x)]; u_of(x) inverts x(u),
// for a receiver plane parallel to y, whose cut is a jump in x that the outer integral is split at.
double brute_planar(double radiance, Vec3 p, Vec3 n, double u0, double u1,
                    const std::function<double(double)>& x_of,
                    const std::function<double(double)>& dx_du,
                    const std::function<double(double)>& half_y,
                    const std::function<double(double)>& u_of) {
    if (!(p.z > 0)) return 0;
    const double c = dot(n, p);  // receiver front: nx x + ny y - nz p.z... written as n . X > n . P
    auto outer = [&](double u) {
        const double x = x_of(u);
        double lo = -half_y(x), hi = half_y(x);
        // n . (X - P) > 0 with X = (x, y, 0):  n.y * y > c - n.x * x
        const double rhs = c - n.x * x;
        if (n.y > 0)
            lo = std::max(lo, rhs / n.y);
        else if (n.y < 0)
            hi = std::min(hi, rhs / n.y);
        else if (!(0 > rhs))
            return 0.0;
        if (!(hi > lo)) return 0.0;
        auto inner = [&](double y) {
            const Vec3 r = Vec3{x, y, 0} - p;
            const double r2 = dot(r, r);
            return radiance * p.z * std::max(0.0, dot(n, r)) / (r2 * r2);
        };
        return integrate(inner, lo, hi, kQuadratureTolerance) * dx_du(u);
    };
    if (n.y == 0 && n.x != 0) {
        const double cut = u_of(c / n.x);
        if (cut > u0 && cut < u1)
            return test::integrate_pieces(outer, u0, cut, 64, kQuadratureTolerance) +
                   test::integrate_pieces(outer, cut, u1, 64, kQuadratureTolerance);
    }
    return test::integrate_pieces(outer, u0, u1, 64, kQuadratureTolerance);
}

double brute_disk(double radiance, double a, Vec3 p, Vec3 n) {
    // x = a sin(u) removes the square-root endpoints of the circle.
    return brute_planar(
        radiance, p, n, -kPi / 2, kPi / 2, [&](double u) { return a * std::sin(u); },
        [&](double u) { return a * std::cos(u); },
        [&](double x) { return std::sqrt(std::max(0.0, a * a - x * x)); },
        [&](double x) { return std::asin(std::clamp(x / a, -1.0, 1.0)); });
}

double brute_rectangle(double radiance, double sx, double sy, Vec3 p, Vec3 n) {
    return brute_planar(
        radiance, p, n, -sx / 2, sx / 2, [](double u) { return u; }, [](double) { return 1.0; },
        [&](double) { return sy / 2; }, [](double x) { return x; });
}

// Over the sphere's cap visible from P, in polar coordinates (theta, phi) about the axis toward
// P; for each phi the theta range is clipped to the receiver's front half-space, where
// n . X(theta) = r (A sin theta + B cos theta) exceeds n . P.
double brute_sphere(double radiance, double r, Vec3 p, Vec3 n) {
    const double d = length(p);
    const Vec3 axis = (1 / d) * p;
    Vec3 e1, e2;
    orthonormal_basis(axis, e1, e2);
    const double theta_max = std::acos(r / d);
    auto outer = [&](double phi) {
        auto inner = [&](double theta) {
            const Vec3 m = (std::sin(theta) * std::cos(phi)) * e1 +
                           (std::sin(theta) * std::sin(phi)) * e2 + std::cos(theta) * axis;
            const Vec3 to_p = p - r * m;
            const double r2 = dot(to_p, to_p), rl = std::sqrt(r2);
            const double cos_e = dot(m, to_p) / rl, cos_r = std::max(0.0, -dot(n, to_p) / rl);
            return radiance * std::max(0.0, cos_e) * cos_r / r2 * r * r * std::sin(theta);
        };
        const double a = std::cos(phi) * dot(n, e1) + std::sin(phi) * dot(n, e2), b = dot(n, axis);
        const double rho = std::hypot(a, b), q = dot(n, p) / r;
        if (q >= rho) return 0.0;
        if (q <= -rho) return integrate(inner, 0, theta_max, kQuadratureTolerance);
        const double centre = std::atan2(a, b), half = std::acos(q / rho);
        double sum = 0;
        for (double shift : {-2 * kPi, 0.0, 2 * kPi}) {
            const double lo = std::max(0.0, centre - half + shift),
                         hi = std::min(theta_max, centre + half + shift);
            if (hi > lo) sum += integrate(inner, lo, hi, kQuadratureTolerance);
        }
        return sum;
    };
    return test::integrate_pieces(outer, -kPi, kPi, 360, kQuadratureTolerance);
}

struct Case {
    Vec3 point, normal;
};

// Near (down to 0.02 of the size), across the rim, far, below the plane, receivers facing the
// source, tilted so that their plane cuts the emitter, edge-on and facing away.
std::vector<Case> cases() {
    const std::vector<Vec3> points = {{0, 0, 1},         {0.5, 0.3, 0.7}, {0.2, 0.1, 0.02},
                                      {1.05, 0.1, 0.05}, {2, 1, 0.5},     {3, -2, 4},
                                      {0.3, 0, 25},      {0.4, 0.4, -0.3}};
    const std::vector<Vec3> normals = {{0, 0, -1}, {0.3, 0.2, -0.93}, {-0.8, 0, 0.6},
                                       {1, 0, 0},  {0, 0.6, -0.8},    {0, 0, 1}};
    std::vector<Case> out;
    for (Vec3 p : points)
        for (Vec3 n : normals) out.push_back({p, normalized(n)});
    return out;
}

// Relative agreement, with an absolute floor for the cases where both are (near) zero.
void expect_close(double exact, double brute, double scale, const std::string& what) {
    EXPECT_NEAR(exact, brute, 1e-9 * std::abs(brute) + 1e-12 * scale) << what;
}

std::string describe(const Case& c) {
    return "P=(" + std::to_string(c.point.x) + "," + std::to_string(c.point.y) + "," +
           std::to_string(c.point.z) + ") n=(" + std::to_string(c.normal.x) + "," +
           std::to_string(c.normal.y) + "," + std::to_string(c.normal.z) + ")";
}

TEST(AnalyticIrradiance, DiskClosedFormMatchesBruteForceQuadrature) {
    const LambertianDisk disk(1.5, 2.0);
    for (const Case& c : cases()) {
        const Vec3 p = 1.5 * c.point;
        expect_close(disk.irradiance(p, c.normal), brute_disk(2.0, 1.5, p, c.normal), 2.0,
                     describe(c));
    }
}

TEST(AnalyticIrradiance, TiltedDiskIsTheDiskInItsOwnFrame) {
    // The quadrature of the untilted disk, at the point and normal turned back by the tilt
    // (-35 degrees about y, written out here), and the disk's normal itself.
    const double tilt = 35 * kPi / 180;
    const LambertianDisk disk(1.5, 2.0, {}, 35);
    auto untilt = [&](Vec3 v) {
        return Vec3{std::cos(tilt) * v.x - std::sin(tilt) * v.z, v.y,
                    std::sin(tilt) * v.x + std::cos(tilt) * v.z};
    };
    EXPECT_NEAR(disk.normal().x, std::sin(tilt), 1e-15);
    EXPECT_NEAR(disk.normal().z, std::cos(tilt), 1e-15);
    for (const Case& c : cases()) {
        const Vec3 p = 1.5 * c.point;
        expect_close(disk.irradiance(p, c.normal),
                     brute_disk(2.0, 1.5, untilt(p), untilt(c.normal)), 2.0, describe(c));
    }
    EXPECT_EQ(disk.radiance(disk.normal(), disk.normal()), 0.0);   // off the disk
    EXPECT_EQ(disk.radiance({0, 0, 0}, disk.normal()), 2.0);       // its centre, in front
    EXPECT_EQ(disk.radiance({0, 0, 0}, -1 * disk.normal()), 0.0);  // behind
    EXPECT_EQ(disk.radiance({std::cos(tilt), 0.5, -std::sin(tilt)}, {0, 0, 1}),
              2.0);  // in its plane
}

TEST(AnalyticIrradiance, RectangleContourSumMatchesBruteForceQuadrature) {
    const LambertianRectangle rect(2.0, 1.2, 0.7);
    for (const Case& c : cases())
        expect_close(rect.irradiance(c.point, c.normal),
                     brute_rectangle(0.7, 2.0, 1.2, c.point, c.normal), 0.7, describe(c));
}

TEST(AnalyticIrradiance, SphereLimbDiskMatchesBruteForceQuadrature) {
    const LambertianSphere sphere(1.0, 3.0);
    const std::vector<Vec3> points = {
        {0, 0, 1.02}, {0.8, 0.3, 0.9}, {2, 1, 0.5}, {3, -2, 4}, {0, 0, 30}};
    const std::vector<Vec3> normals = {
        {0, 0, -1}, {0.3, 0.2, -0.93}, {-0.8, 0, 0.6}, {1, 0, 0}, {0, 0.6, -0.8}};
    for (Vec3 p : points)
        for (Vec3 n0 : normals) {
            const Vec3 n = normalized(n0);
            expect_close(sphere.irradiance(p, n), brute_sphere(3.0, 1.0, p, n), 3.0,
                         describe({p, n}));
        }
}

TEST(AnalyticIrradiance, TextbookSpecialCases) {
    // Disk on its axis: E = pi L R^2 / (R^2 + d^2).
    const LambertianDisk disk(2.0, 1.5);
    for (double d : {1e-3, 0.5, 2.0, 100.0})
        EXPECT_NEAR(disk.irradiance({0, 0, d}, {0, 0, -1}), kPi * 1.5 * 4 / (4 + d * d),
                    1e-14 * kPi * 1.5);

    // Sphere, receiver facing the centre from outside: E = pi L R^2 / d^2 at any distance, and
    // times cos(tilt) while the whole sphere stays above the receiver's horizon.
    const LambertianSphere sphere(1.0, 2.0);
    for (double d : {1.001, 1.5, 10.0}) {
        EXPECT_NEAR(sphere.irradiance({0, d, 0}, {0, -1, 0}), kPi * 2.0 / (d * d), 1e-13);
        const double tilt = 0.2;  // rad, below 90 deg - asin(1/d) for d >= 1.5
        if (d < 1.5) continue;
        EXPECT_NEAR(sphere.irradiance({0, d, 0}, {std::sin(tilt), -std::cos(tilt), 0}),
                    kPi * 2.0 / (d * d) * std::cos(tilt), 1e-13);
    }
    EXPECT_EQ(sphere.irradiance({0, 0.5, 0}, {0, -1, 0}), 0.0);  // inside: the sphere emits outward

    // Rectangle, parallel receiver above its centre: four corner form factors
    // F = (1/2pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))],
    // A = a/h, B = b/h (Howell, catalogue of configuration factors, B-3); E = pi L F.
    const double sx = 3, sy = 1, h = 0.8, l = 1.7;
    const double a = sx / 2 / h, b = sy / 2 / h;
    const double corner = (a / std::sqrt(1 + a * a) * std::atan(b / std::sqrt(1 + a * a)) +
                           b / std::sqrt(1 + b * b) * std::atan(a / std::sqrt(1 + b * b))) /
                          (2 * kPi);
    EXPECT_NEAR(LambertianRectangle(sx, sy, l).irradiance({0, 0, h}, {0, 0, -1}),
                kPi * l * 4 * corner, 1e-14);

    // Behind one-sided emitters and facing away: nothing.
    EXPECT_EQ(disk.irradiance({0.1, 0, -1}, {0, 0, 1}), 0.0);
    EXPECT_EQ(disk.irradiance({0.1, 0, 1}, {0, 0, 1}), 0.0);
}

TEST(AnalyticIrradiance, FarFieldLimitIsIntensityTimesCosine) {
    // d^2 E(d w, -w tilted by t) -> I(w) cos t as d grows; for the disk on its axis the exact
    // ratio is d^2/(R^2+d^2), so the approach itself is checked too.
    const LambertianDisk disk(1.0, 1.0);
    for (double d : {10.0, 1e3, 1e5}) {
        const double ratio =
            d * d * disk.irradiance({0, 0, d}, {0, 0, -1}) / disk.intensity({0, 0, 1});
        EXPECT_NEAR(ratio, d * d / (1 + d * d), 1e-13);
    }
    const Vec3 w = normalized({0.3, -0.5, 0.8});
    const double tilt = 0.4;
    Vec3 e1, e2;
    orthonormal_basis(w, e1, e2);
    const Vec3 n = normalized((-std::cos(tilt)) * w + std::sin(tilt) * e1);
    const std::vector<std::unique_ptr<Source>> sources = [] {
        std::vector<std::unique_ptr<Source>> s;
        s.push_back(std::make_unique<LambertianDisk>(1.0, 1.0));
        s.push_back(std::make_unique<LambertianDisk>(1.0, 1.0, Spectrum{}, -50));
        s.push_back(std::make_unique<LambertianRectangle>(2.0, 0.5, 1.0));
        s.push_back(std::make_unique<LambertianSphere>(1.0, 1.0));
        s.push_back(std::make_unique<CosineLobe>(3.0, 1.0));
        s.push_back(std::make_unique<ChipCluster>(ChipCluster::Layout{}, std::vector<double>{0.1},
                                                  std::vector<double>{555}));
        return s;
    }();
    for (const auto& s : sources) {
        const double d = 1e5;  // the emitters are <= 10 mm across: (size/d)^2 <= 1e-8
        const double limit = d * d * s->irradiance(d * w, n);
        EXPECT_NEAR(limit / (s->intensity(w) * std::cos(tilt)), 1.0, 1e-7) << s->name();
    }
}

TEST(AnalyticSources, IntensityIntegratesToTotalFlux) {
    // Deterministic quadrature over the sphere (in cos(gamma) and C, split at the equator where
    // the untilted emitters' kinks are; the tilted disk's horizon is left to the adaptive rule).
    std::vector<std::unique_ptr<Source>> sources;
    sources.push_back(std::make_unique<LambertianDisk>(LambertianDisk::with_flux(0.7, 2.5)));
    sources.push_back(
        std::make_unique<LambertianDisk>(LambertianDisk::with_flux(0.7, 2.5, {}, 30)));
    sources.push_back(
        std::make_unique<LambertianRectangle>(LambertianRectangle::with_flux(2.0, 0.5, 1.25)));
    sources.push_back(std::make_unique<LambertianSphere>(LambertianSphere::with_flux(3.0, 4.0)));
    sources.push_back(std::make_unique<CosineLobe>(CosineLobe::with_flux(2.5, 0.8)));
    sources.push_back(std::make_unique<CosineLobe>(CosineLobe::with_flux(0.0, 0.8)));
    const std::vector<double> fluxes = {0.2, 0.1, 0.3};
    sources.push_back(std::make_unique<ChipCluster>(ChipCluster::Layout{}, fluxes,
                                                    std::vector<double>{630, 530}));
    const double cluster_total = 13 * (0.2 + 0.1 + 0.3);
    const std::vector<double> expected = {2.5, 2.5, 1.25, 4.0, 0.8, 0.8, cluster_total};
    for (size_t k = 0; k < sources.size(); ++k) {
        const Source& s = *sources[k];
        EXPECT_NEAR(s.total_flux(), expected[k], 1e-14 * expected[k]) << s.name();
        // A disk's horizon: dot(normal, d) = 0, with the normal in the x-z plane. Split at it in C
        // (cos C = -nz mu / (nx r)) and in mu where it touches the C range (mu = +-nx).
        const auto* disk = dynamic_cast<const LambertianDisk*>(&s);
        const Vec3 normal = disk ? disk->normal() : Vec3{0, 0, 1};
        auto over_c = [&](double mu) {
            const double r = std::sqrt(std::max(0.0, 1 - mu * mu));
            auto at = [&](double c) { return s.intensity({r * std::cos(c), r * std::sin(c), mu}); };
            const double q = normal.x != 0 && r > 0 ? -normal.z * mu / (normal.x * r) : 2;
            if (!(std::abs(q) < 1)) return integrate(at, 0, 2 * kPi, 1e-12);
            const double c1 = std::acos(q), c2 = 2 * kPi - c1;
            return integrate(at, 0, c1, 1e-12) + integrate(at, c1, c2, 1e-12) +
                   integrate(at, c2, 2 * kPi, 1e-12);
        };
        std::vector<double> splits = {-1, 0, 1};
        if (normal.x != 0) splits.insert(splits.end(), {-std::abs(normal.x), std::abs(normal.x)});
        std::sort(splits.begin(), splits.end());
        double flux = 0;
        for (size_t i = 0; i + 1 < splits.size(); ++i)
            flux += integrate(over_c, splits[i], splits[i + 1], 1e-12);
        EXPECT_NEAR(flux, expected[k], 1e-9 * expected[k]) << s.name();
    }
}

}  // namespace
}  // namespace rayset::analytic
