// The one-pass summary behind `rayconv info`, on analytic sources whose answers are known.
#include <gtest/gtest.h>

#include "converters/analytic/synth.h"
#include "converters/rays/ray_summary.h"
#include "converters/rays/simd.h"
#include "ray_ops_test_support.h"
#include "support/test_support.h"

#include <cmath>

namespace {

using namespace rayset;

std::string write_source(const std::string& name, const SourceParameters& parameters, uint64_t rays,
                         test::ScratchDir& dir) {
    auto source = make_source(name, parameters);
    const std::string path = dir.file(name + ".tm25ray");
    SynthOptions radiant_only;  // luminous flux must then come from the spectrum
    radiant_only.luminous = false;
    auto out = create_rays(path, RayFormat::tm25, synth_header(*source, rays, 7, radiant_only));
    synthesize(*source, rays, 7, *out, radiant_only);
    return path;
}

RaySummary summarise_source(const std::string& name, const SourceParameters& parameters,
                            uint64_t rays, test::ScratchDir& dir) {
    auto reader = open_rays(write_source(name, parameters, rays, dir));
    return summarise_rays(*reader);
}

TEST(RaySummary, SphereReachesEveryDirectionAndIsBoundedByItsRadius) {
    test::ScratchDir dir;
    // A Lambertian sphere's far field is isotropic: with 400k rays each of the 20000 cells
    // expects 20 rays, so the chance that any cell is empty is below 20000 e^-20 = 4e-5.
    RaySummary s = summarise_source("sphere", {{"radius", "2"}, {"flux", "3"}}, 400000, dir);
    EXPECT_EQ(s.rays, 400000u);
    EXPECT_NEAR(s.radiant, 3.0, 3.0 * 1e-6);
    EXPECT_NEAR(s.sphere_coverage, 1.0, 1e-12);  // a sum of 20000 cell solid angles
    // Origins on the surface: the box is the sphere's, reached to within 0.5% by 400k rays.
    for (float lo : {s.min_origin.x, s.min_origin.y, s.min_origin.z}) {
        EXPECT_GE(lo, -2.0f * (1 + 1e-6f));
        EXPECT_LT(lo, -1.99f);
    }
    for (float hi : {s.max_origin.x, s.max_origin.y, s.max_origin.z}) {
        EXPECT_LE(hi, 2.0f * (1 + 1e-6f));
        EXPECT_GT(hi, 1.99f);
    }
    EXPECT_EQ(s.min_wavelength, 555.0f);
    EXPECT_EQ(s.max_wavelength, 555.0f);
}

TEST(RaySummary, LambertianDiskCoversAHemisphereAroundPlusZ) {
    test::ScratchDir dir;
    RaySummary s = summarise_source("disk", {{"radius", "1"}}, 200000, dir);
    // Mean direction of a cosine-weighted hemisphere: (0, 0, 1). Each transverse component of
    // a ray has variance E[sin^2 theta cos^2 phi] = 1/4, so the mean of 2e5 rays has standard
    // deviation 1/sqrt(8e5) = 0.0011; 5 sigma gives 0.0056 (two-sided 1 - 6e-7).
    EXPECT_NEAR(s.mean_direction.x, 0, 0.0056);
    EXPECT_NEAR(s.mean_direction.y, 0, 0.0056);
    EXPECT_NEAR(s.mean_direction.z, 1, 1e-4);
    // No ray goes below the disk's plane, so at most the upper half of the sphere is reached;
    // near the horizon the cosine law leaves cells empty, but the upper 90% of z is full.
    EXPECT_LE(s.sphere_coverage, 0.5 + 1e-12);
    EXPECT_GE(s.sphere_coverage, 0.45);
    // The widest direction lies at the horizon, measured to cell centres (a cell is < 1.5 deg).
    EXPECT_GT(s.max_angle_from_mean_deg, 87.0);
    EXPECT_LT(s.max_angle_from_mean_deg, 90.0);
    EXPECT_EQ(s.min_origin.z, 0.0f);
    EXPECT_EQ(s.max_origin.z, 0.0f);
    // A single wavelength of 555 nm: luminous flux is 683.002 lm per W (V(555) = 1).
    EXPECT_NEAR(s.luminous_from_spectrum, 683.002 * s.radiant, 1e-6 * 683.002);
}

TEST(RaySummary, PartsReadOnSeveralThreadsGiveTheSummaryOfOnePart) {
    test::ScratchDir dir;
    const std::string path = write_source("cluster", {}, 300000, dir);  // per-ray wavelengths
    RayReadOptions one, eight;
    one.chunk_size = 1 << 20;  // a single chunk and part
    eight.chunk_size = 1000;   // 8 parts of 37500 rays
    auto whole = open_rays(path, one), split = open_rays(path, eight);
    ASSERT_EQ(whole->parts(), 1u);
    ASSERT_EQ(split->parts(), 8u);
    const RaySummary a = summarise_rays(*whole), b = summarise_rays(*split);
    // Counts, extremes and reached cells do not depend on the order of the rays; sums do, by
    // rounding alone: a sum of n positive terms in any order is within (n - 1) u of the exact
    // one (u = 2^-53; Higham, Accuracy and Stability, 4.2), so the two within 2 n u of each other.
    EXPECT_EQ(a.rays, b.rays);
    EXPECT_EQ(a.zero_flux_rays, b.zero_flux_rays);
    EXPECT_EQ(a.unknown_wavelength_rays, b.unknown_wavelength_rays);
    EXPECT_EQ(a.min_wavelength, b.min_wavelength);
    EXPECT_EQ(a.max_wavelength, b.max_wavelength);
    EXPECT_LT(a.min_wavelength, a.max_wavelength);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ((&a.min_origin.x)[k], (&b.min_origin.x)[k]);
        EXPECT_EQ((&a.max_origin.x)[k], (&b.max_origin.x)[k]);
    }
    EXPECT_EQ(a.sphere_coverage, b.sphere_coverage);
    // The mean direction against the flux-weighted sum of the directions taken here in double
    // (m). The summary sums products rounded to float in float, at most 8 to a lane before
    // adding them in double, so each component is within 9 u_f S of m's (u_f = 2^-24, S the
    // sum of |w d|), and the normalised axis within 2 * 9 u_f |S| / |m| of m / |m|, plus its
    // rounding to float.
    double m[3] = {}, abs_sum[3] = {};
    auto reader = open_rays(path);
    for (RayChunk chunk; reader->read(chunk);)
        for (const Ray& ray : chunk.rays)
            for (int k = 0; k < 3; ++k) {
                const double product = double(ray.radiant) * (&ray.direction.x)[k];
                m[k] += product, abs_sum[k] += std::abs(product);
            }
    const double norm = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    const double u_f = std::ldexp(1.0, -24);
    const double axis_bound =
        2 * 9 * u_f *
            std::sqrt(abs_sum[0] * abs_sum[0] + abs_sum[1] * abs_sum[1] + abs_sum[2] * abs_sum[2]) /
            norm +
        u_f;
    for (const RaySummary* s : {&a, &b})
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR((&s->mean_direction.x)[k], m[k] / norm, axis_bound) << k;
    // The widest angle is measured from the axis to the same cell centres, so the two differ by
    // at most the angle between their axes.
    // (atan2 of the cross and dot products: exact for tiny angles, where acos is not).
    const double ax = a.mean_direction.x, ay = a.mean_direction.y, az = a.mean_direction.z;
    const double bx = b.mean_direction.x, by = b.mean_direction.y, bz = b.mean_direction.z;
    const double cross = std::hypot(ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx);
    const double axes_deg = std::atan2(cross, ax * bx + ay * by + az * bz) / kRadiansPerDegree;
    EXPECT_NEAR(a.max_angle_from_mean_deg, b.max_angle_from_mean_deg, axes_deg + 1e-9);
    const double bound = 2 * 300000 * std::ldexp(1.0, -53);
    EXPECT_NEAR(a.radiant, b.radiant, bound * a.radiant);
    EXPECT_NEAR(a.luminous_from_spectrum, b.luminous_from_spectrum,
                bound * a.luminous_from_spectrum);
}

// The summary's AVX2 kernel (where the CPU has it) against the portable one: the same IEEE
// operations in the same order, so every figure is the same to the bit. The rays are random
// directions with, among them, the directions where cells meet: the axes, +-0 components,
// the quadrant diagonals, z = +-1, and a ray count that leaves a tail of 5 past a multiple of 8.
TEST(RaySummary, FastestKernelGivesThePortableKernelsFigures) {
    // Without AVX2 both are the portable kernel, and the comparison could not fail.
    if (!cpu_has_avx2())
        GTEST_SKIP() << "this CPU has no AVX2: the fastest kernel is the portable one";
    test::ScratchDir dir;
    std::vector<Ray> rays = test::numbered_rays(20000 + 5, true, false);
    const float h = float(std::sqrt(0.5)),
                edges[][3] = {{1, 0, 0},     {-1, 0, 0},   {0, 1, 0},
                              {0, -1, 0},    {0, 0, 1},    {0, 0, -1},
                              {-0.f, 1, 0},  {1, -0.f, 0}, {-1, -0.f, 0},
                              {-0.f, -1, 0}, {h, h, 0},    {-h, h, 0},
                              {-h, -h, 0},   {h, -h, 0},   {-0.5f, 6.1e-17f, -0.8660254f}};
    for (size_t e = 0; e < std::size(edges); ++e) {
        rays[e * 997].direction = {edges[e][0], edges[e][1], edges[e][2]};  // spread over blocks
        rays[rays.size() - 1 - e % 5].direction = {edges[e][0], edges[e][1],
                                                   edges[e][2]};  // and the tail
    }
    for (size_t i = 0; i < rays.size(); i += 3)
        rays[i].wavelength = float(380 + i % 400);  // some unknown
    RayHeader header;
    header.has_radiant = true;
    header.spectral = SpectralKind::per_ray_wavelength;
    const std::string path = dir.file("edges.tm25ray");
    test::write_rays(path, RayFormat::tm25, header, rays);
    RayReadOptions options;
    options.chunk_size = 100;  // 8 parts
    auto fastest = open_rays(path, options), portable = open_rays(path, options);
    const RaySummary a = summarise_rays(*fastest),
                     b = summarise_rays(*portable, {}, SummaryKernel::portable);
    EXPECT_EQ(a.unknown_wavelength_rays, b.unknown_wavelength_rays);
    EXPECT_EQ(a.unknown_wavelength_rays, rays.size() - (rays.size() + 2) / 3);
    EXPECT_EQ(a.min_wavelength, b.min_wavelength);
    EXPECT_EQ(a.max_wavelength, b.max_wavelength);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ((&a.min_origin.x)[k], (&b.min_origin.x)[k]);
        EXPECT_EQ((&a.max_origin.x)[k], (&b.max_origin.x)[k]);
        EXPECT_EQ((&a.mean_direction.x)[k], (&b.mean_direction.x)[k]);
    }
    EXPECT_EQ(a.sphere_coverage, b.sphere_coverage);
    EXPECT_EQ(a.max_angle_from_mean_deg, b.max_angle_from_mean_deg);
    // The axes reach the cells at the poles and the edges: the widest angle is near 180 deg.
    EXPECT_GT(a.max_angle_from_mean_deg, 175.0);
}

}  // namespace
