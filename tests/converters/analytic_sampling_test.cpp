// The sampled rays of the analytic sources against their exact emission: the flux the rays
// carry onto receivers in the near field against the integral of the exact irradiance, the
// radiance integrated by an independent Monte Carlo against the total flux, and the lobe's
// cumulative angular distribution.
#include "converters/analytic/analytic_sources.h"
#include "synth_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rayset::analytic {
namespace {

std::vector<std::unique_ptr<Source>> all_sources() {
    std::vector<std::unique_ptr<Source>> s;
    s.push_back(std::make_unique<LambertianDisk>(LambertianDisk::with_flux(1.5, 1.0)));
    s.push_back(
        std::make_unique<LambertianRectangle>(LambertianRectangle::with_flux(3.0, 1.0, 1.0)));
    s.push_back(std::make_unique<LambertianSphere>(LambertianSphere::with_flux(1.0, 1.0)));
    s.push_back(std::make_unique<CosineLobe>(CosineLobe::with_flux(4.0, 1.0)));
    s.push_back(std::make_unique<ChipCluster>(ChipCluster::Layout{},
                                              std::vector<double>{0.02, 0.04},
                                              std::vector<double>{630, 530, 460}));
    return s;
}

struct Receiver {
    Vec3 centre, normal;
    double side;
};

// Receivers close to the sources (1 to 3 source sizes away), tilted, off axis.
std::vector<Receiver> receivers() {
    return {{{0.5, 0.3, 2.0}, normalized({0.2, -0.1, -1}), 1.5},
            {{3.0, -1.0, 4.0}, normalized({-0.6, 0.2, -0.7}), 2.0},
            {{-1.0, 2.5, 9.0}, normalized({0.1, -0.3, -1}), 4.0}};
}

bool hits(const Ray& ray, const Receiver& r, Vec3 e1, Vec3 e2) {
    const Vec3 o{ray.origin.x, ray.origin.y, ray.origin.z},
        d{ray.direction.x, ray.direction.y, ray.direction.z};
    const double facing = dot(d, r.normal);
    if (!(facing < 0)) return false;  // light arrives against the receiver's normal
    const double t = dot(r.centre - o, r.normal) / facing;
    if (!(t > 0)) return false;
    const Vec3 h = o + t * d - r.centre;
    return std::abs(dot(h, e1)) <= r.side / 2 && std::abs(dot(h, e2)) <= r.side / 2;
}

TEST(AnalyticSampling, RaysDeliverTheExactIrradianceToNearReceivers) {
    // 1e6 rays per source; the count of rays hitting a receiver is Binomial(N, p) with
    // p = (integral of E over the receiver) / total flux. 18 checks at alpha = 1e-4 each with
    // Bernstein's bound: the family passes with probability >= 99.82% if the sampling is right.
    const uint64_t n = 1000000;
    std::vector<std::unique_ptr<Source>> sources = all_sources();
    sources.push_back(
        std::make_unique<LambertianDisk>(LambertianDisk::with_flux(1.5, 1.0, {}, 30)));
    for (const auto& source : sources) {
        const std::vector<Receiver> rs = receivers();
        std::vector<Vec3> e1(rs.size()), e2(rs.size());
        std::vector<double> counts(rs.size(), 0);
        for (size_t k = 0; k < rs.size(); ++k) orthonormal_basis(rs[k].normal, e1[k], e2[k]);
        Pcg32 rng(20240601);
        for (uint64_t i = 0; i < n; ++i) {
            const Ray ray = source->sample_ray(rng);
            for (size_t k = 0; k < rs.size(); ++k) counts[k] += hits(ray, rs[k], e1[k], e2[k]);
        }
        for (size_t k = 0; k < rs.size(); ++k) {
            const Receiver& r = rs[k];
            auto row = [&](double u) {
                return test::integrate(
                    [&](double v) {
                        return source->irradiance(r.centre + u * e1[k] + v * e2[k], r.normal);
                    },
                    -r.side / 2, r.side / 2, 1e-12);
            };
            const double flux = test::integrate(row, -r.side / 2, r.side / 2, 1e-12);
            const double p = flux / source->total_flux();
            ASSERT_GT(p, 1e-3) << source->name() << " receiver " << k
                               << ": the check needs light on it";
            EXPECT_NEAR(counts[k], n * p, test::bernstein_bound(double(n), p, 1e-4))
                << source->name() << " receiver " << k << " expected fraction " << p;
        }
    }
}

TEST(AnalyticSampling, RadianceIntegratesToTotalFlux) {
    // An independent estimator of the total flux from radiance() alone: uniform points over a
    // box around the emitter's surface and uniform directions, mean of L |cos| x area x 4 pi.
    // 4e5 samples; |mean - exact| < 4.5 standard errors (normal approximation, two-sided
    // probability of a false failure 7e-6 per source).
    const int n = 400000;
    std::vector<std::unique_ptr<Source>> sources = all_sources();
    sources.erase(sources.begin() + 3);  // the point lobe has no radiance (checked below)
    for (const auto& source : sources) {
        Pcg32 rng(7);
        double sum = 0, square = 0;
        for (int i = 0; i < n; ++i) {
            Vec3 point, surface_normal;
            double area;
            if (source->name() == "sphere") {
                const double mu = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform(),
                             s = std::sqrt(1 - mu * mu);
                surface_normal = {s * std::cos(phi), s * std::sin(phi), mu};
                point = surface_normal;  // radius 1
                area = 4 * kPi;
            } else {
                const double half = source->name() == "cluster" ? 7 : 1.6;  // covers the emitter
                point = {(2 * rng.uniform() - 1) * half, (2 * rng.uniform() - 1) * half, 0};
                surface_normal = {0, 0, 1};
                area = 4 * half * half;
            }
            const double mu = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform(),
                         s = std::sqrt(1 - mu * mu);
            const Vec3 direction{s * std::cos(phi), s * std::sin(phi), mu};
            const double value = source->radiance(point, direction) *
                                 std::abs(dot(direction, surface_normal)) * area * 4 * kPi;
            sum += value;
            square += value * value;
        }
        const double mean = sum / n, error = std::sqrt((square / n - mean * mean) / n);
        EXPECT_NEAR(mean, source->total_flux(), 4.5 * error) << source->name();
        EXPECT_LT(error, 0.02 * source->total_flux())
            << source->name() << ": the check is too weak";
    }
    EXPECT_TRUE(std::isnan(CosineLobe(2, 1).radiance({0, 0, 0}, {0, 0, 1})));
}

TEST(AnalyticSampling, LobeDirectionsFollowCosinePower) {
    // Fraction of the flux within theta of the axis: 1 - cos^(n+1)(theta). Bernstein bound,
    // alpha = 1e-4 for each of the 3 angles x 3 exponents.
    const uint64_t n = 400000;
    for (double exponent : {0.0, 1.0, 7.5}) {
        const CosineLobe lobe(exponent, 1.0);
        Pcg32 rng(99);
        const double angles[3] = {0.2, 0.6, 1.2};
        double counts[3] = {0, 0, 0};
        for (uint64_t i = 0; i < n; ++i) {
            const Ray ray = lobe.sample_ray(rng);
            ASSERT_GE(ray.direction.z, 0.0f);
            for (int k = 0; k < 3; ++k) counts[k] += ray.direction.z >= std::cos(angles[k]);
        }
        for (int k = 0; k < 3; ++k) {
            const double p = 1 - std::pow(std::cos(angles[k]), exponent + 1);
            EXPECT_NEAR(counts[k], n * p, test::bernstein_bound(double(n), p, 1e-4))
                << "n=" << exponent;
        }
    }
}

TEST(AnalyticSampling, RaysStartOnTheEmitterAndLeaveItsFront) {
    Pcg32 rng(3);
    for (const auto& source : all_sources()) {
        for (int i = 0; i < 20000; ++i) {
            const Ray ray = source->sample_ray(rng);
            const Vec3 o{ray.origin.x, ray.origin.y, ray.origin.z},
                d{ray.direction.x, ray.direction.y, ray.direction.z};
            ASSERT_NEAR(length(d), 1.0, 1e-6);
            if (source->name() == "lobe") {
                ASSERT_EQ(length(o), 0.0);
                continue;
            }
            // Float origins sit within float rounding of the surface: nudge the test point.
            const Vec3 on = source->name() == "sphere" ? normalized(o) : Vec3{o.x, o.y, 0};
            ASSERT_GT(source->radiance(on, d), 0) << source->name() << " ray " << i;
        }
    }
    const LambertianDisk tilted(1.5, 1.0, {}, -40);
    const Vec3 n = tilted.normal();
    for (int i = 0; i < 20000; ++i) {
        const Ray ray = tilted.sample_ray(rng);
        const Vec3 o{ray.origin.x, ray.origin.y, ray.origin.z},
            d{ray.direction.x, ray.direction.y, ray.direction.z};
        ASSERT_NEAR(dot(o, n), 0.0, 1e-6) << "ray " << i;  // in the disk's plane
        ASSERT_LE(length(o), 1.5 * (1 + 1e-6)) << "ray " << i;
        ASSERT_GT(dot(d, n), 0.0) << "ray " << i;  // out of its front
        ASSERT_GT(tilted.radiance(o - dot(o, n) * n, d), 0) << "ray " << i;
    }
}

}  // namespace
}  // namespace rayset::analytic
