// Acceptance (b): real LED luminaire IES files -> rays (TM-25) -> far field -> IES reproduce
// the candela table within the statistics of the ray count. Also: the far field of OSRAM's
// measured LED ray file points along +z, as LED ray files do.
#include "converters/emit.h"
#include "converters/farfield.h"
#include "support/test_support.h"
#include "converters/synth_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rayset {
namespace {

struct RoundTrip {
    test::CountCheck check;
    double exact_total = 0, quadrature_total = 0, zonal_total = 0;
};

// The file's intensity as rays from its luminous opening with gamma 0 along -z (the IES nadir),
// 1e6 rays, binned on the default grid and written to IES and read back.
RoundTrip round_trip(const std::string& name) {
    RoundTrip r;
    test::ScratchDir dir;
    const Photometry p = read_photometry(test::shared_data("photometry/" + name));
    EmitOptions options;
    options.axis = PolarAxis::minus_z;
    options.shape = EmitterShape::opening;
    options.name = name;
    const uint64_t n = 1000000, seed = 77;
    const std::string rays = dir.file("rays.tm25ray"), ies = dir.file("back.ies");
    {
        auto out = create_rays(rays, RayFormat::tm25, emit_header(p, n, seed, options));
        emit_rays(p, n, seed, *out, options);
    }
    auto reader = open_rays(rays);
    FarFieldOptions far_options;
    far_options.axis = PolarAxis::minus_z;
    const FarField f = far_field(*reader, far_options);
    write_photometry(ies, f.photometry, PhotometryFormat::ies);
    const Photometry back = read_photometry(ies);
    EXPECT_EQ(back.candela, f.photometry.candela) << name << ": the IES file holds the far field exactly";
    EXPECT_TRUE(reader->warnings().empty()) << name;

    r.exact_total = IntensityDistribution(p, name).total_flux();
    r.zonal_total = p.total_flux();
    const double ray_flux = float(r.exact_total / double(n));
    std::vector<double> cell_flux(back.candela.size());
    for (size_t k = 0; k < cell_flux.size(); ++k) cell_flux[k] = back.candela[k] * f.solid_angle[k];
    size_t fractional = 0;
    const auto counts = test::cell_counts(f, cell_flux, ray_flux, fractional);
    EXPECT_EQ(fractional, 0u) << name;
    const auto expected = test::expected_cell_flux(p, f);
    for (double e : expected) r.quadrature_total += e;
    std::vector<double> fraction(expected.size());
    for (size_t k = 0; k < expected.size(); ++k) fraction[k] = expected[k] / r.quadrature_total;
    r.check = test::check_counts(fraction, counts, double(n));
    return r;
}

// Per file: every cell within Bernstein's bound at alpha = 1e-3 / cells (all cells together
// with probability >= 99.9%), chi-square below its 99.9% critical value, and the emitted flux
// equal to the exact integral of the interpolated table (quadrature to 1e-9).
void expect_round_trip(const std::string& name) {
    const RoundTrip r = round_trip(name);
    const test::CountCheck& c = r.check;
    EXPECT_NEAR(r.quadrature_total, r.exact_total, 1e-9 * r.exact_total) << name;
    EXPECT_EQ(c.outside, 0u) << name << ": light where the table has none";
    EXPECT_EQ(c.beyond_bound, 0u) << name << ": worst deviation / bound " << c.worst_ratio;
    EXPECT_LT(c.chi_square, c.critical) << name << " dof " << c.dof;
    std::printf("[ figures  ] %s: %zu cells, worst/bound %.3f, chi-square %.3f, dof %zu, critical %.1f; flux %.6g lm "
                "(zonal sum of the table %.6g lm)\n",
                name.c_str(), c.bins, c.worst_ratio, c.chi_square, c.dof, c.critical, r.exact_total, r.zonal_total);
}

TEST(EmitRealData, RoundTrip1) {
    RAYSET_REQUIRE_SHARED_DATA();
    expect_round_trip("1.IES");
}

TEST(EmitRealData, RoundTrip2) {
    RAYSET_REQUIRE_SHARED_DATA();
    expect_round_trip("2.IES");
}

TEST(EmitRealData, RoundTrip3) {
    RAYSET_REQUIRE_SHARED_DATA();
    expect_round_trip("3.IES");
}

TEST(EmitRealData, RoundTrip7) {
    RAYSET_REQUIRE_SHARED_DATA();
    expect_round_trip("7.IES");
}

TEST(EmitRealData, RoundTripAbsoluteLed) {
    RAYSET_REQUIRE_SHARED_DATA();
    expect_round_trip("ABSOLUTE_LED.ies");
}

TEST(EmitRealData, RoundTripLuxeon) {
    RAYSET_REQUIRE_SHARED_DATA();
    expect_round_trip("S01.01.02.354_MAXWELL-8-T4_LUXEON_5050_Square_with_glass-MEASURED_IESNA.ies");
}

TEST(EmitRealData, TypeBIsRefusedWithAClearError) {
    RAYSET_REQUIRE_SHARED_DATA();
    const Photometry p = read_photometry(test::shared_data("photometry/flood_2.1.IES"));
    ASSERT_EQ(p.type, PhotometricType::B);
    EmitOptions options;
    options.name = "flood_2.1.IES";
    test::MemoryEncoder out;
    try {
        emit_rays(p, 10, 1, out, options);
        FAIL() << "type B accepted";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "flood_2.1.IES: type B photometry cannot be turned into rays: only type C is supported "
                               "(convert the file to type C first)");
    }
}

TEST(FarFieldRealData, OsramLedEmitsAlongPlusZ) {
    // OSRAM's sheet: origin at the chip centre on the package top, rays leaving into air. Its
    // light must be in the +z hemisphere with the peak near gamma 0 when gamma is measured
    // from +z, and the far field must carry the file's 1.68 W exactly.
    RAYSET_REQUIRE_SHARED_DATA();
    auto reader = open_rays(test::shared_data("rayfiles/rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY"));
    FarFieldOptions options;
    options.quantity = FarFieldQuantity::radiometric;
    const FarField f = far_field(*reader, options);
    EXPECT_EQ(f.rays, 100000u);
    EXPECT_NEAR(f.total_flux, reader->totals().radiant, 1e-9 * f.total_flux);
    EXPECT_NEAR(f.total_flux, 1.68, 1e-4 * 1.68);
    const Photometry& p = f.photometry;
    double upper = 0;
    for (size_t h = 0; h + 1 < p.horizontal_deg.size(); ++h)
        for (size_t v = 0; v < p.vertical_deg.size(); ++v)
            if (p.vertical_deg[v] < 90) upper += f.flux[p.index(h, v)];
    const double fraction = upper / f.total_flux;
    EXPECT_GT(fraction, 0.99);
    EXPECT_LE(f.max_gamma_deg, 30.0);
    std::printf("[ figures  ] OSRAM LERTDUW: %.5f of the flux at gamma < 88.75 deg from +z, peak %.4g W/sr at C %g gamma %g\n",
                fraction, f.max_intensity, f.max_c_deg, f.max_gamma_deg);
}

}  // namespace
}  // namespace rayset
