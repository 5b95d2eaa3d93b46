#include "converters/rays/ray_ops.h"

#include "ray_ops_test_support.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace rayset {
namespace {

using test::numbered_rays;
using test::read_rays;
using test::same_bits;
using test::ScratchDir;
using test::write_rays;

RayHeader flux_header(bool radiant, bool luminous) {
    RayHeader h;
    h.has_radiant = radiant;
    h.has_luminous = luminous;
    return h;
}

double sum_radiant(const std::vector<Ray>& rays) {
    double s = 0;
    for (const Ray& r : rays) s += r.radiant;
    return s;
}
double sum_luminous(const std::vector<Ray>& rays) {
    double s = 0;
    for (const Ray& r : rays) s += r.luminous;
    return s;
}

// Every kept flux is one product rounded to f32: at most 2^-24 relative each, so the total is
// off by at most 2^-24 of itself (plus double summation error, 1e-16 per ray).
constexpr double kF32Rounding = 1.0 / 16777216;

std::string expect_error(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no rayset::Error thrown";
    return {};
}

// ---- subsample ---------------------------------------------------------------------------------

TEST(Subsample, KeepsExactlyTheCountAndTheTotalFlux) {
    ScratchDir dir;
    const auto rays = numbered_rays(10000, true, true);
    write_rays(dir.file("in.tm25ray"), RayFormat::tm25, flux_header(true, true), rays);
    RayOpReport report = subsample_rays(dir.file("in.tm25ray"), dir.file("out.tm25ray"),
                                        RayFormat::tm25, {1234, 0, 7});
    auto out = read_rays(dir.file("out.tm25ray"));
    ASSERT_EQ(out.rays.size(), 1234u);
    EXPECT_EQ(report.totals.rays, 1234u);
    const double radiant_in = sum_radiant(rays), luminous_in = sum_luminous(rays);
    EXPECT_NEAR(sum_radiant(out.rays), radiant_in, kF32Rounding * radiant_in);
    EXPECT_NEAR(sum_luminous(out.rays), luminous_in, kF32Rounding * luminous_in);
    EXPECT_NEAR(out.header.stated_radiant, radiant_in,
                1e-6 * radiant_in);  // the header holds an f32
}

TEST(Subsample, KeptRaysAreAnOrderedSubsetScaledByOneFactor) {
    ScratchDir dir;
    const auto rays = numbered_rays(5000, true, false);
    write_rays(dir.file("in.tm25ray"), RayFormat::tm25, flux_header(true, false), rays);
    subsample_rays(dir.file("in.tm25ray"), dir.file("out.tm25ray"), RayFormat::tm25, {500, 0, 11});
    auto out = read_rays(dir.file("out.tm25ray"));
    ASSERT_EQ(out.rays.size(), 500u);
    const double scale = sum_radiant(rays) / [&] {
        double kept = 0;
        for (const Ray& r : out.rays) kept += rays[size_t(r.origin.x)].radiant;
        return kept;
    }();
    long previous = -1;
    for (const Ray& r : out.rays) {
        const long i = long(r.origin.x);
        ASSERT_GT(i, previous);  // strictly increasing: no ray twice, order kept
        previous = i;
        EXPECT_TRUE(same_bits(r.origin, rays[i].origin));
        EXPECT_TRUE(same_bits(r.direction, rays[i].direction));
        EXPECT_EQ(r.radiant, float(rays[i].radiant * scale));
    }
}

// Which rays are kept must not depend on where they are in the file. 100000 rays, 10000 kept:
// 1000 expected in each index decile. The chi-square statistic over the ten deciles is below
// 27.88 (9 degrees of freedom, upper 0.1% point) for 99.9% of seeds when the choice is uniform
// (sampling without replacement makes the statistic smaller still, by a factor 1 - k/n).
TEST(Subsample, KeptRaysAreUniformOverTheFile) {
    ScratchDir dir;
    const size_t n = 100000, k = 10000;
    write_rays(dir.file("in.tm25ray"), RayFormat::tm25, flux_header(true, false),
               numbered_rays(n, true, false));
    subsample_rays(dir.file("in.tm25ray"), dir.file("out.tm25ray"), RayFormat::tm25, {k, 0, 2024});
    auto out = read_rays(dir.file("out.tm25ray"));
    ASSERT_EQ(out.rays.size(), k);
    std::vector<double> decile(10, 0);
    for (const Ray& r : out.rays) decile[size_t(r.origin.x) * 10 / n] += 1;
    double chi2 = 0;
    for (double c : decile) chi2 += (c - 1000) * (c - 1000) / 1000;
    EXPECT_LT(chi2, 27.88);
    // And a different seed keeps a different subset.
    subsample_rays(dir.file("in.tm25ray"), dir.file("other.tm25ray"), RayFormat::tm25,
                   {k, 0, 2025});
    auto other = read_rays(dir.file("other.tm25ray"));
    size_t differing = 0;
    for (size_t i = 0; i < k; ++i) differing += other.rays[i].origin.x != out.rays[i].origin.x;
    EXPECT_GT(differing, 0u);
}

TEST(Subsample, FractionKeepsTheRoundedShareAndTheSameSeedTheSameRays) {
    ScratchDir dir;
    write_rays(dir.file("in.tm25ray"), RayFormat::tm25, flux_header(true, false),
               numbered_rays(999, true, false));
    subsample_rays(dir.file("in.tm25ray"), dir.file("a.tm25ray"), RayFormat::tm25, {0, 0.25, 5});
    subsample_rays(dir.file("in.tm25ray"), dir.file("b.tm25ray"), RayFormat::tm25, {0, 0.25, 5});
    EXPECT_EQ(read_rays(dir.file("a.tm25ray")).rays.size(), 250u);  // round(249.75)
    EXPECT_EQ(test::read_file(dir.file("a.tm25ray")), test::read_file(dir.file("b.tm25ray")));
}

TEST(Subsample, KeepingAllRaysChangesNothing) {
    ScratchDir dir;
    const auto rays = numbered_rays(300, true, false);
    write_rays(dir.file("in.tm25ray"), RayFormat::tm25, flux_header(true, false), rays);
    subsample_rays(dir.file("in.tm25ray"), dir.file("out.tm25ray"), RayFormat::tm25, {300, 0, 1});
    auto out = read_rays(dir.file("out.tm25ray"));
    ASSERT_EQ(out.rays.size(), 300u);
    for (size_t i = 0; i < 300; ++i) EXPECT_EQ(out.rays[i].radiant, rays[i].radiant);
}

TEST(Subsample, BadRequestsNameTheFileAndTheProblem) {
    ScratchDir dir;
    const std::string in = dir.file("in.tm25ray");
    write_rays(in, RayFormat::tm25, flux_header(true, false), numbered_rays(10, true, false));
    std::string m = expect_error([&] {
        subsample_rays(in, dir.file("o"), RayFormat::tm25, {11, 0, 1});
    });
    EXPECT_NE(m.find(in), std::string::npos) << m;
    EXPECT_NE(m.find("11 rays asked for, but the file holds only 10"), std::string::npos) << m;
    m = expect_error([&] { subsample_rays(in, dir.file("o"), RayFormat::tm25, {0, 1.5, 1}); });
    EXPECT_NE(m.find("fraction to keep is 1.5, not a number in (0, 1]"), std::string::npos) << m;
    m = expect_error([&] { subsample_rays(in, dir.file("o"), RayFormat::tm25, {0, 0.01, 1}); });
    EXPECT_NE(m.find("keeps none"), std::string::npos) << m;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o")));
}

// Two rays, one dark: a seed that keeps only the dark one cannot keep the total. Selection
// sampling keeps ray 0 with probability 1/2, so among 20 seeds both outcomes occur (the chance
// that they do not is 2 x 2^-20).
TEST(Subsample, KeptRaysWithoutFluxAreAnError) {
    ScratchDir dir;
    const std::string in = dir.file("in.tm25ray");
    auto rays = numbered_rays(2, true, false);
    rays[1].radiant = 0;
    write_rays(in, RayFormat::tm25, flux_header(true, false), rays);
    int failed = 0, kept = 0;
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        try {
            subsample_rays(in, dir.file("o.tm25ray"), RayFormat::tm25, {1, 0, seed});
            auto out = read_rays(dir.file("o.tm25ray"));
            EXPECT_EQ(out.rays[0].radiant, rays[0].radiant);
            ++kept;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("carry no radiant flux"), std::string::npos)
                << e.what();
            EXPECT_NE(std::string(e.what()).find(in), std::string::npos) << e.what();
            ++failed;
        }
    }
    EXPECT_GT(failed, 0);
    EXPECT_GT(kept, 0);
}

// ---- transform ---------------------------------------------------------------------------------

TEST(Transform, AxisAngleRotationHasTheRightSenseAndComposes) {
    Matrix3 quarter = rotation_about_axis({0, 0, 2}, 90);  // x -> y, right-handed
    EXPECT_NEAR(quarter[0], 0, 1e-15);
    EXPECT_NEAR(quarter[3], 1, 1e-15);
    Matrix3 twice =
        multiply(rotation_about_axis({1, 2, 3}, 30), rotation_about_axis({1, 2, 3}, 30));
    Matrix3 once = rotation_about_axis({1, 2, 3}, 60);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(twice[i], once[i], 1e-12);
    Matrix3 back = multiply(transpose(once), once);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(back[i], kIdentity3[i], 1e-12);
    EXPECT_THROW(rotation_about_axis({0, 0, 0}, 10), Error);
}

TEST(Transform, RotationThenInverseIsTheIdentityAndKeepsUnitDirections) {
    ScratchDir dir;
    const auto rays = numbered_rays(2000, true, false);
    write_rays(dir.file("in.tm25ray"), RayFormat::tm25, flux_header(true, false), rays);
    RayTransform t;
    t.rotation =
        multiply(rotation_about_axis({0.3, -1, 0.2}, 37.5), rotation_about_axis({1, 0, 0}, -71));
    transform_rays(dir.file("in.tm25ray"), dir.file("rot.tm25ray"), RayFormat::tm25, t);
    auto rotated = read_rays(dir.file("rot.tm25ray"));
    RayTransform inverse;
    inverse.rotation = transpose(t.rotation);
    transform_rays(dir.file("rot.tm25ray"), dir.file("back.tm25ray"), RayFormat::tm25, inverse);
    auto back = read_rays(dir.file("back.tm25ray"));
    ASSERT_EQ(back.rays.size(), rays.size());
    double worst_norm = 0, worst_direction = 0, worst_origin = 0, moved = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const Vec3f& d = rotated.rays[i].direction;
        worst_norm = std::max(
            worst_norm,
            std::abs(std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z) - 1));
        const Ray &a = rays[i], &b = back.rays[i];
        worst_direction =
            std::max({worst_direction, std::abs(double(a.direction.x) - b.direction.x),
                      std::abs(double(a.direction.y) - b.direction.y),
                      std::abs(double(a.direction.z) - b.direction.z)});
        // Origins reach 2000 mm: 1e-6 relative to their length (two f32 roundings: 1.2e-7).
        const double size = std::max(
            1.0, std::sqrt(double(a.origin.x) * a.origin.x + double(a.origin.y) * a.origin.y +
                           double(a.origin.z) * a.origin.z));
        worst_origin = std::max({worst_origin, std::abs(double(a.origin.x) - b.origin.x) / size,
                                 std::abs(double(a.origin.y) - b.origin.y) / size,
                                 std::abs(double(a.origin.z) - b.origin.z) / size});
        moved = std::max(moved, std::abs(double(a.direction.z) - rotated.rays[i].direction.z));
        EXPECT_EQ(b.radiant, a.radiant);
    }
    EXPECT_LT(worst_norm, 2e-7);  // float rounding of a unit vector
    EXPECT_LT(worst_direction, 1e-6);
    EXPECT_LT(worst_origin, 1e-6);
    EXPECT_GT(moved, 0.5);  // the rotation did something
}

TEST(Transform, TranslationMovesTheBoundingBoxExactly) {
    ScratchDir dir;
    const auto rays = numbered_rays(1000, true, false);
    write_rays(dir.file("in.tm25ray"), RayFormat::tm25, flux_header(true, false), rays);
    RayTransform t;
    t.translation = {0.5, -2, 0.125};
    t.translation_unit = LengthUnit::cm;  // 5, -20, 1.25 mm
    transform_rays(dir.file("in.tm25ray"), dir.file("out.tm25ray"), RayFormat::tm25, t);
    auto out = read_rays(dir.file("out.tm25ray"));
    auto box = [](const std::vector<Ray>& rs, float Vec3f::*axis) {
        auto [lo, hi] = std::minmax_element(rs.begin(), rs.end(), [&](const Ray& a, const Ray& b) {
            return a.origin.*axis < b.origin.*axis;
        });
        return std::pair<float, float>{lo->origin.*axis, hi->origin.*axis};
    };
    const double shift[3] = {5, -20, 1.25};
    float Vec3f::*axes[3] = {&Vec3f::x, &Vec3f::y, &Vec3f::z};
    for (int a = 0; a < 3; ++a) {
        auto before = box(rays, axes[a]), after = box(out.rays, axes[a]);
        EXPECT_EQ(after.first, float(before.first + shift[a]));
        EXPECT_EQ(after.second, float(before.second + shift[a]));
    }
    for (size_t i = 0; i < rays.size(); ++i)
        EXPECT_TRUE(same_bits(out.rays[i].direction, rays[i].direction));
}

TEST(Transform, UnitChangeMillimetresToMetresAndBack) {
    ScratchDir dir;
    const auto rays = numbered_rays(500, true, false);
    RayHeader h = flux_header(true, false);
    h.data_origin = {1, 2, 3};
    write_rays(dir.file("in.csv"), RayFormat::csv, h, rays);
    RayTransform to_m;
    to_m.unit = LengthUnit::m;
    RayOpReport report =
        transform_rays(dir.file("in.csv"), dir.file("m.csv"), RayFormat::csv, to_m);
    EXPECT_EQ(report.header.unit, LengthUnit::m);
    auto metres = read_rays(dir.file("m.csv"));
    EXPECT_EQ(metres.header.unit, LengthUnit::m);
    EXPECT_EQ(metres.header.data_origin, (Vec3f{0.001f, 0.002f, 0.003f}));
    EXPECT_EQ(metres.rays[400].origin.x, 0.4f);
    RayTransform to_mm;
    to_mm.unit = LengthUnit::mm;
    transform_rays(dir.file("m.csv"), dir.file("mm.csv"), RayFormat::csv, to_mm);
    auto back = read_rays(dir.file("mm.csv"));
    EXPECT_EQ(back.header.unit, LengthUnit::mm);
    for (size_t i = 0; i < rays.size(); ++i) {
        // Two f32 roundings: within 2^-23 of the original, relative.
        const float* a = &rays[i].origin.x;
        const float* b = &back.rays[i].origin.x;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(b[k], a[k], std::abs(a[k]) * 1.2e-7) << i;
        EXPECT_TRUE(same_bits(back.rays[i].direction, rays[i].direction));
    }
}

TEST(Transform, ScaleRotationAndTranslationMoveTheDataOriginButNotThePlacement) {
    RayHeader h = flux_header(true, false);
    h.unit = LengthUnit::cm;
    h.data_origin = {1, 0, 0};
    h.placement.location = {4, 5, 6};
    RayTransform t;
    t.unit = LengthUnit::mm;
    t.scale = 2;
    t.rotation = rotation_about_axis({0, 0, 1}, 90);
    t.translation = {0, 0, 7};
    RayTransformer transformer(t, h, "mem");
    const RayHeader& out = transformer.header();
    EXPECT_NEAR(out.data_origin.x, 0, 1e-5);
    EXPECT_FLOAT_EQ(out.data_origin.y, 20);  // 1 cm = 10 mm, x2, then x -> y
    EXPECT_FLOAT_EQ(out.data_origin.z, 7);
    EXPECT_EQ(out.placement.location, (Vec3f{40, 50, 60}));

    RayChunk chunk;
    Ray r;
    r.origin = {0, 1, 0};
    r.direction = {1, 0, 0};
    r.radiant = 1;
    chunk.rays = {r};
    transformer.apply(chunk);
    EXPECT_NEAR(chunk.rays[0].origin.x, -20, 1e-5);
    EXPECT_NEAR(chunk.rays[0].origin.y, 0, 1e-5);
    EXPECT_NEAR(chunk.rays[0].origin.z, 7, 1e-6);
    EXPECT_NEAR(chunk.rays[0].direction.y, 1, 1e-7);
}

TEST(Transform, PolarisationEllipseAxisRotatesWithTheRay) {
    RayHeader h = flux_header(true, false);
    h.extras = {{ExtraKind::stokes_s1, "S1"},
                {ExtraKind::ellipse_x, "ex"},
                {ExtraKind::ellipse_y, "ey"},
                {ExtraKind::ellipse_z, "ez"}};
    RayTransform t;
    t.rotation = rotation_about_axis({1, 0, 0}, 90);  // y -> z
    RayTransformer transformer(t, h, "mem");
    RayChunk chunk;
    Ray r;
    r.direction = {1, 0, 0};
    r.radiant = 1;
    chunk.rays = {r};
    chunk.extra = {0.5f, 0, 1, 0};
    transformer.apply(chunk);
    EXPECT_EQ(chunk.extra[0], 0.5f);  // Stokes parameters are relative to the axis: unchanged
    EXPECT_NEAR(chunk.extra[1], 0, 1e-7);
    EXPECT_NEAR(chunk.extra[2], 0, 1e-7);
    EXPECT_NEAR(chunk.extra[3], 1, 1e-7);
}

TEST(Transform, BadTransformsNameTheFileAndTheProblem) {
    RayHeader h = flux_header(true, false);
    RayTransform stretch;
    stretch.rotation = {2, 0, 0, 0, 1, 0, 0, 0, 1};
    std::string m = expect_error([&] { RayTransformer(stretch, h, "rays.tm25ray"); });
    EXPECT_NE(m.find("rays.tm25ray"), std::string::npos) << m;
    EXPECT_NE(m.find("not a rotation"), std::string::npos) << m;
    RayTransform mirror;
    mirror.rotation = {-1, 0, 0, 0, 1, 0, 0, 0, 1};
    m = expect_error([&] { RayTransformer(mirror, h, "rays.tm25ray"); });
    EXPECT_NE(m.find("determinant -1"), std::string::npos) << m;
    RayTransform flat;
    flat.scale = 0;
    m = expect_error([&] { RayTransformer(flat, h, "rays.tm25ray"); });
    EXPECT_NE(m.find("scale factor is 0, not a positive number"), std::string::npos) << m;
    RayTransform far;
    far.translation = {0, NAN, 0};
    m = expect_error([&] { RayTransformer(far, h, "rays.tm25ray"); });
    EXPECT_NE(m.find("translation"), std::string::npos) << m;
}

}  // namespace
}  // namespace rayset
