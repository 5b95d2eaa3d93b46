// Rays from photometry: the sampled distribution against Photometry::intensity() (a separate
// implementation of the same interpolation), its exact flux against quadrature, the emitted
// rays' far field against the distribution within the statistics of the ray count.
#include "converters/photometry/emit.h"

#include "converters/photometry/farfield.h"
#include "core/geometry.h"
#include "synth_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rayset {
namespace {

constexpr double kDeg = kPi / 180;

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// A type C table with the given angles and a smooth, asymmetric, non-negative intensity.
Photometry table(std::vector<double> horizontal, std::vector<double> vertical) {
    Photometry p;
    p.horizontal_deg = std::move(horizontal);
    p.vertical_deg = std::move(vertical);
    for (double h : p.horizontal_deg)
        for (double v : p.vertical_deg)
            p.candela.push_back(100 + 80 * std::cos(v * kDeg) +
                                30 * std::sin(h * kDeg * 1.3 + 0.4) * std::sin(v * kDeg));
    return p;
}

std::vector<double> steps(double first, double last, double step) {
    std::vector<double> out;
    for (double a = first; a <= last + 1e-9; a += step) out.push_back(a);
    return out;
}

// Every symmetry LM-63 defines for type C, and a full table that does not close the circle.
std::vector<std::pair<std::string, Photometry>> symmetric_tables() {
    return {{"axial", table({0}, steps(0, 180, 10))},
            {"quadrant", table(steps(0, 90, 22.5), steps(0, 90, 15))},
            {"bilateral 0-180", table(steps(0, 180, 30), steps(0, 180, 20))},
            {"bilateral 90-270", table(steps(90, 270, 45), steps(30, 150, 10))},
            {"full", table(steps(0, 360, 40), steps(0, 180, 30))},
            {"open full", table(steps(0, 330, 30), steps(0, 120, 7.5))}};
}

TEST(IntensityDistribution, InterpolatesLikePhotometryIntensity) {
    Pcg32 rng(17);
    for (const auto& [name, p] : symmetric_tables()) {
        const IntensityDistribution d(p, name);
        for (int i = 0; i < 20000; ++i) {
            const double c = 720 * rng.uniform() - 360, g = 180 * rng.uniform();
            ASSERT_NEAR(d.intensity(c, g), p.intensity(c, g), 1e-12 * 200)
                << name << " C " << c << " gamma " << g;
        }
    }
}

TEST(IntensityDistribution, TotalFluxIsTheExactIntegral) {
    // Isotropic: 4 pi I.
    Photometry iso;
    iso.horizontal_deg = {0};
    iso.vertical_deg = {0, 90, 180};
    iso.candela = {5, 5, 5};
    EXPECT_NEAR(IntensityDistribution(iso, "iso").total_flux(), 4 * kPi * 5, 1e-13);
    // Against adaptive quadrature of Photometry::intensity() over the sphere, split at the grid.
    for (const auto& [name, p] : symmetric_tables()) {
        std::vector<double> c_cuts{0, 360};
        for (double h : p.horizontal_deg)
            for (double image : {h, 180 - h, 180 + h, 360 - h})
                if (image > 0 && image < 360) c_cuts.push_back(image);
        std::sort(c_cuts.begin(), c_cuts.end());
        double flux = 0;
        for (size_t a = 0; a + 1 < c_cuts.size(); ++a)
            for (size_t b = 0; b + 1 < p.vertical_deg.size(); ++b)
                flux +=
                    test::integrate(
                        [&](double c) {
                            return test::integrate(
                                [&](double g) { return p.intensity(c, g) * std::sin(g * kDeg); },
                                p.vertical_deg[b], p.vertical_deg[b + 1], 1e-12);
                        },
                        c_cuts[a], c_cuts[a + 1], 1e-11) *
                    kDeg * kDeg;
        EXPECT_NEAR(IntensityDistribution(p, name).total_flux(), flux, 1e-10 * flux) << name;
    }
}

TEST(IntensityDistribution, RefusesWhatItCannotSample) {
    Photometry b = table(steps(-90, 90, 45), steps(-90, 90, 45));
    b.type = PhotometricType::B;
    EXPECT_EQ(error_of([&] { IntensityDistribution(b, "flood.ies"); }),
              "flood.ies: type B photometry cannot be turned into rays: only type C is supported "
              "(convert the file to type C first)");
    b.type = PhotometricType::A;
    EXPECT_EQ(error_of([&] { IntensityDistribution(b, "a.ies"); }),
              "a.ies: type A photometry cannot be turned into rays: only type C is supported "
              "(convert the file to type C first)");
    Photometry negative = table({0}, {0, 90});
    negative.candela[1] = -3;
    EXPECT_EQ(error_of([&] { IntensityDistribution(negative, "n.ies"); }),
              "n.ies: candela value -3 is not a number >= 0");
    Photometry nan = table({0}, {0, 90});
    nan.candela[0] = std::nan("");
    EXPECT_EQ(error_of([&] { IntensityDistribution(nan, "nan.ies"); }),
              "nan.ies: candela value nan is not a number >= 0");
    Photometry dark = table({0, 90}, {0, 90});
    std::fill(dark.candela.begin(), dark.candela.end(), 0.0);
    EXPECT_EQ(
        error_of([&] { IntensityDistribution(dark, "dark.ies"); }),
        "dark.ies: the intensity table is zero everywhere: there is no light to turn into rays");
    EXPECT_EQ(error_of([&] { IntensityDistribution(table({0}, {0}), "one.ies"); }),
              "one.ies: rays need at least two vertical angles and one horizontal angle");
    EXPECT_EQ(error_of([&] {
                  IntensityDistribution(table({0}, {0, 190}), "v.ies");
              }),
              "v.ies: vertical angle 190 is not ascending within 0..180 degrees");
    EXPECT_EQ(error_of([&] {
                  IntensityDistribution(table({0, 200, 400}, {0, 90}), "h.ies");
              }),
              "h.ies: the horizontal angles span more than 360 degrees");
}

// ---------------------------------------------------------------------------------------------

TEST(Emit, FarFieldOfTheRaysReproducesEveryTable) {
    // 5e5 rays per table and polar axis; each far field is checked cell by cell (family-wise
    // >= 99.9% per far field, see test::check_counts).
    const uint64_t n = 500000;
    for (const auto& [name, p] : symmetric_tables()) {
        for (PolarAxis axis : {PolarAxis::plus_z, PolarAxis::minus_z}) {
            EmitOptions options;
            options.axis = axis;
            options.name = name;
            test::MemoryEncoder out;
            const uint64_t seed = axis == PolarAxis::plus_z ? 2024 : 2025;
            emit_rays(p, n, seed, out, options);
            ASSERT_TRUE(out.finished);
            const RayHeader header = emit_header(p, n, seed, options);
            auto reader = test::memory_reader(header, std::move(out.rays));
            FarFieldOptions ff;
            ff.axis = axis;
            const FarField f = far_field(*reader, ff);

            const double total = IntensityDistribution(p, name).total_flux();
            const double ray_flux = float(total / double(n));
            EXPECT_EQ(header.stated_luminous, total);
            EXPECT_NEAR(reader->totals().luminous, total, 6e-8 * total);  // one float rounding
            const auto expected = test::expected_cell_flux(p, f);
            double expected_total = 0;
            for (double e : expected) expected_total += e;
            EXPECT_NEAR(expected_total, total, 1e-9 * total) << name;
            std::vector<double> fraction(expected.size());
            for (size_t k = 0; k < expected.size(); ++k) fraction[k] = expected[k] / expected_total;
            size_t fractional = 0;
            const auto counts = test::cell_counts(f, f.flux, ray_flux, fractional);
            ASSERT_EQ(fractional, 0u);
            const test::CountCheck c = test::check_counts(fraction, counts, double(n));
            EXPECT_EQ(c.outside, 0u) << name;
            EXPECT_EQ(c.beyond_bound, 0u) << name << ": worst deviation / bound " << c.worst_ratio;
            EXPECT_LT(c.chi_square, c.critical) << name << " dof " << c.dof;
            std::printf(
                "[ figures  ] %s (%s): worst/bound %.3f, chi-square %.1f, dof %zu, critical %.1f\n",
                name.c_str(), axis == PolarAxis::plus_z ? "+z" : "-z", c.worst_ratio, c.chi_square,
                c.dof, c.critical);
        }
    }
}

TEST(Emit, TheCheckRejectsRaysOfAnotherTable) {
    // Rays of the "full" table against a table whose C variation is a third larger: the check
    // must see the difference, so it has the power to see a wrong sampler.
    const uint64_t n = 500000;
    const Photometry p = symmetric_tables()[4].second;
    Photometry other = p;
    for (size_t h = 0; h < p.horizontal_deg.size(); ++h)
        for (size_t v = 0; v < p.vertical_deg.size(); ++v) {
            const double base = 100 + 80 * std::cos(p.vertical_deg[v] * kDeg);
            other.candela[other.index(h, v)] = base + (p.candela[p.index(h, v)] - base) * 4 / 3;
        }
    test::MemoryEncoder out;
    emit_rays(p, n, 1, out);
    auto reader = test::memory_reader(emit_header(p, n, 1), std::move(out.rays));
    const FarField f = far_field(*reader);
    const auto expected = test::expected_cell_flux(other, f);
    double total = 0;
    for (double e : expected) total += e;
    std::vector<double> fraction(expected.size());
    for (size_t k = 0; k < expected.size(); ++k) fraction[k] = expected[k] / total;
    size_t fractional = 0;
    const auto counts = test::cell_counts(
        f, f.flux, float(IntensityDistribution(p, "p").total_flux() / double(n)), fractional);
    const test::CountCheck c = test::check_counts(fraction, counts, double(n));
    EXPECT_GT(c.chi_square, c.critical);  // measured 6985 against 5210 (dof 4885)
}

TEST(Emit, OriginsFillTheEmitterShape) {
    Photometry p = table(steps(0, 90, 30), steps(0, 90, 30));
    p.length_m = 0.2;
    p.width_m = 0.1;
    auto origins = [&](EmitOptions options) {
        test::MemoryEncoder out;
        emit_rays(p, 20000, 3, out, options);
        return out.rays;
    };
    EmitOptions o;
    for (const Ray& r : origins(o)) ASSERT_TRUE(r.origin == Vec3f{});
    o.shape = EmitterShape::disk;
    o.radius_mm = 4;
    double max_r = 0;
    for (const Ray& r : origins(o)) {
        ASSERT_EQ(r.origin.z, 0.0f);
        max_r = std::max(max_r, std::hypot(double(r.origin.x), double(r.origin.y)));
    }
    EXPECT_LE(max_r, 4.0 * (1 + 1e-7));
    EXPECT_GT(max_r, 3.99);  // and reaches the rim
    o.shape = EmitterShape::opening;
    double max_x = 0, max_y = 0;
    for (const Ray& r : origins(o)) {
        max_x = std::max(max_x, std::abs(double(r.origin.x)));
        max_y = std::max(max_y, std::abs(double(r.origin.y)));
    }
    EXPECT_LE(max_x, 100.0);  // length 0.2 m along C0-C180 = x
    EXPECT_GT(max_x, 99.5);
    EXPECT_LE(max_y, 50.0);  // width 0.1 m along C90-C270 = y
    EXPECT_GT(max_y, 49.5);
    p.round = true;
    for (const Ray& r : origins(o)) {
        const double e = std::pow(r.origin.x / 100.0, 2) + std::pow(r.origin.y / 50.0, 2);
        ASSERT_LE(e, 1 + 1e-6);
    }
    o.shape = EmitterShape::rectangle;
    o.size_x_mm = 0;
    o.size_y_mm = 1;
    EXPECT_EQ(error_of([&] { origins(o); }),
              "photometry: the emitter size x must be a positive number of mm, not 0");
    test::MemoryEncoder out;
    EXPECT_EQ(error_of([&] { emit_rays(p, 0, 1, out, {}); }),
              "photometry: the ray count must be at least 1");
}

TEST(Emit, HeaderAndRadiometricTables) {
    Photometry p = table(steps(0, 90, 30), steps(0, 90, 30));
    p.keywords["LUMINAIRE"] = "test luminaire";
    p.keywords["MANUFAC"] = "maker";
    const RayHeader h = emit_header(p, 500, 9);
    EXPECT_TRUE(h.has_luminous);
    EXPECT_FALSE(h.has_radiant);
    EXPECT_EQ(h.spectral, SpectralKind::none);
    EXPECT_EQ(h.unit, LengthUnit::mm);
    EXPECT_EQ(h.text[0], "test luminaire");
    EXPECT_EQ(h.text[1], "maker");
    EXPECT_EQ(h.text[7],
              "rays from the far field of photometry: point, gamma 0 along +z, rays=500 seed=9");
    p.keywords["_RADIOMETRIC"] = "candela values are radiant intensities in W/sr";
    const RayHeader r = emit_header(p, 500, 9);
    EXPECT_TRUE(r.has_radiant);
    EXPECT_FALSE(r.has_luminous);
    test::MemoryEncoder out;
    emit_rays(p, 500, 9, out);
    EXPECT_EQ(out.rays[0].radiant, float(r.stated_radiant / 500));
    EXPECT_TRUE(std::isnan(out.rays[0].luminous));
}

}  // namespace
}  // namespace rayset
