// Acceptance (b): real LED luminaire IES files -> rays (TM-25) -> far field -> IES reproduce
// the candela table within the statistics of the ray count. Also: the far field of OSRAM's
// measured LED ray file points along +z, as LED ray files do.
#include "converters/photometry/emit.h"
#include "converters/photometry/farfield.h"
#include "converters/synth_test_support.h"
#include "support/statistics.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

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
    EXPECT_EQ(back.candela, f.photometry.candela)
        << name << ": the IES file holds the far field exactly";
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
    std::printf(
        "[ figures  ] %s: %zu cells, worst/bound %.3f, chi-square %.3f, dof %zu, critical %.1f; "
        "flux %.6g lm "
        "(zonal sum of the table %.6g lm)\n",
        name.c_str(), c.bins, c.worst_ratio, c.chi_square, c.dof, c.critical, r.exact_total,
        r.zonal_total);
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
    expect_round_trip(
        "S01.01.02.354_MAXWELL-8-T4_LUXEON_5050_Square_with_glass-MEASURED_IESNA.ies");
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
        EXPECT_STREQ(
            e.what(),
            "flood_2.1.IES: type B photometry cannot be turned into rays: only type C is supported "
            "(convert the file to type C first)");
    }
}

TEST(FarFieldRealData, OsramLedEmitsAlongPlusZ) {
    // OSRAM's sheet: origin at the chip centre on the package top, rays leaving into air. Its
    // light must be in the +z hemisphere with the peak near gamma 0 when gamma is measured
    // from +z, and the far field must carry the file's 1.68 W exactly.
    RAYSET_REQUIRE_SHARED_DATA();
    auto reader = open_rays(
        test::shared_data("rayfiles/rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY"));
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
    std::printf(
        "[ figures  ] OSRAM LERTDUW: %.5f of the flux at gamma < 88.75 deg from +z, peak %.4g W/sr "
        "at C %g gamma %g\n",
        fraction, f.max_intensity, f.max_c_deg, f.max_gamma_deg);
}

const char* kOsramBlue = "rayfiles/rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY";

FarField smoothed_far_field(const std::string& path) {
    auto reader = open_rays(path);
    FarFieldOptions options;
    options.smoothing = FarFieldSmoothing::automatic;
    return far_field(*reader, options);
}

// The largest distance, in joint standard errors, between a far field's maximum (off the pole)
// and its 8 grid neighbours.
double maximum_against_neighbours(const FarField& f) {
    const Photometry& p = f.photometry;
    const int nc = int(p.horizontal_deg.size()) - 1;
    const int hm = int(std::lround(f.max_c_deg / 5)) % nc,
              vm = int(std::lround(f.max_gamma_deg / 2.5));
    EXPECT_GE(vm, 1);  // the neighbours below are those of a cell off the pole
    const size_t peak = p.index(size_t(hm), size_t(vm));
    double farthest = 0;
    for (int dh = -1; dh <= 1; ++dh)
        for (int dv = -1; dv <= 1; ++dv) {
            const size_t at = p.index(size_t((hm + dh + nc) % nc), size_t(vm + dv));
            farthest = std::max(farthest, std::abs(p.candela[at] - p.candela[peak]) /
                                              std::sqrt(f.variance[peak] + f.variance[at]));
        }
    return farthest;
}

// The smoothed far field of OSRAM's 1e5 rays: gamma 0 is one value in every C plane, and the
// maximum is not a cell that caught a few rays too many: its 8 grid neighbours lie within 2 joint
// standard errors of it. The binned far field's maximum (36 cd, twice its neighbours) fails the
// same check.
TEST(FarFieldRealData, OsramBlueSmoothedPoleAndMaximum) {
    RAYSET_REQUIRE_SHARED_DATA();
    const FarField f = smoothed_far_field(test::shared_data(kOsramBlue));
    const Photometry& p = f.photometry;
    for (size_t h = 1; h < p.horizontal_deg.size(); ++h)
        EXPECT_EQ(p.candela[p.index(h, 0)], p.candela[p.index(0, 0)]);
    const double smoothed = maximum_against_neighbours(f);
    auto reader = open_rays(test::shared_data(kOsramBlue));
    const double binned = maximum_against_neighbours(far_field(*reader));
    std::printf(
        "[ figures  ] OSRAM blue smoothed: maximum %.4f +- %.4f cd at C %g gamma %g; gamma 0 %.4f "
        "cd in every "
        "plane; neighbours within %.2f joint standard errors (binned: %.2f)\n",
        f.max_intensity,
        std::sqrt(f.variance[p.index(size_t(f.max_c_deg / 5), size_t(f.max_gamma_deg / 2.5))]),
        f.max_c_deg, f.max_gamma_deg, p.candela[p.index(0, 0)], smoothed, binned);
    EXPECT_LE(smoothed, 2);
    EXPECT_GT(binned, 2);
}

// The two halves of the file (rays 1-50000 and 50001-100000) measure one LED: their smoothed far
// fields must agree within their stated standard errors. Estimates at nearby directions share
// rays through their kernels, so the test uses directions at least 4 bandwidths apart (the
// kernels' correlation there is below 0.15), in the hemisphere that carries 99.5% of the flux:
// the sum of their squared z-scores must stay below the chi-square 99.9% quantile.
TEST(FarFieldRealData, OsramBlueHalvesAgreeWithinTheirErrors) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    const std::string halves[2] = {dir.file("first.tm25ray"), dir.file("second.tm25ray")};
    {
        auto reader = open_rays(test::shared_data(kOsramBlue));
        std::vector<Ray> rays;
        RayChunk chunk;
        while (reader->read(chunk)) rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
        ASSERT_EQ(rays.size(), 100000u);
        for (int half = 0; half < 2; ++half) {
            RayChunk part;
            part.rays.assign(rays.begin() + half * 50000, rays.begin() + (half + 1) * 50000);
            RayHeader header = reader->header();
            header.ray_count = part.rays.size();
            header.stated_radiant = header.stated_luminous = std::nan("");
            auto out = create_rays(halves[half], RayFormat::tm25, header);
            out->write(part);
            out->finish();
        }
    }
    const FarField a = smoothed_far_field(halves[0]), b = smoothed_far_field(halves[1]);
    const Photometry& p = a.photometry;
    const double deg = kRadiansPerDegree;
    auto direction = [&](size_t h, size_t v) {
        const double c = p.horizontal_deg[h] * deg, g = p.vertical_deg[v] * deg;
        return std::array<double, 3>{std::sin(g) * std::cos(c), std::sin(g) * std::sin(c),
                                     std::cos(g)};
    };
    struct Chosen {
        std::array<double, 3> w;
        double sigma;
    };
    std::vector<Chosen> chosen;
    double chi2 = 0, all_z2 = 0;
    size_t all = 0;
    for (size_t v = 0; p.vertical_deg[v] <= 85; ++v)
        for (size_t h = 0; h + 1 < p.horizontal_deg.size(); ++h) {
            const size_t at = p.index(h, v);
            const double z2 = std::pow(a.photometry.candela[at] - b.photometry.candela[at], 2) /
                              (a.variance[at] + b.variance[at]);
            all_z2 += z2, ++all;
            const auto w = direction(h, v);
            const double sigma = std::max(a.sigma_deg[at], b.sigma_deg[at]) * deg;
            const bool apart = std::all_of(chosen.begin(), chosen.end(), [&](const Chosen& c) {
                const double cosine = w[0] * c.w[0] + w[1] * c.w[1] + w[2] * c.w[2];
                return std::acos(std::clamp(cosine, -1.0, 1.0)) >= 4 * std::max(sigma, c.sigma);
            });
            if (!apart) continue;
            chosen.push_back({w, sigma});
            chi2 += z2;
        }
    const double critical = test::chi_square_critical(double(chosen.size()), 3.0902);
    std::printf(
        "[ figures  ] OSRAM blue halves: chi-square %.1f over %zu directions 4 bandwidths apart "
        "(99.9%% "
        "critical %.1f); mean squared z over all %zu cells up to gamma 85: %.2f\n",
        chi2, chosen.size(), critical, all, all_z2 / double(all));
    ASSERT_GE(chosen.size(), 5u);
    EXPECT_LT(chi2, critical);
}

}  // namespace
}  // namespace rayset
