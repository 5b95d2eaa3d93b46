// Far-field photometry of ray files: exact cell solid angles, conservation of flux, and the
// acceptance test that a synthetic Lambertian disk's far-field IES file follows the cosine law
// within the statistics of its ray count.
#include "converters/photometry/farfield.h"
#include "converters/photometry/farfield_smoothing.h"

#include "converters/analytic/synth.h"
#include "converters/colour/spectrum.h"
#include "converters/rays/io.h"
#include "support/test_support.h"
#include "synth_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

FarFieldOptions grid_options(double c_step, double gamma_step, PolarAxis axis = PolarAxis::plus_z,
                             FarFieldQuantity quantity = FarFieldQuantity::photometric) {
    FarFieldOptions o;
    o.c_step_deg = c_step;
    o.gamma_step_deg = gamma_step;
    o.axis = axis;
    o.quantity = quantity;
    return o;
}

// Rays of `source` held in memory and a reader over them.
std::unique_ptr<RayReader> synthetic_reader(const analytic::Source& source, uint64_t n,
                                            uint64_t seed) {
    test::MemoryEncoder out;
    synthesize(source, n, seed, out);
    return test::memory_reader(synth_header(source, n, seed), std::move(out.rays));
}

TEST(FarFieldGrid, CellsTileTheSphereWithExactSolidAngles) {
    const FarFieldGrid grid(FarFieldOptions{});
    ASSERT_EQ(grid.c_count(), 72u);
    ASSERT_EQ(grid.gamma_count(), 73u);
    double total = 0;
    for (size_t j = 0; j < grid.gamma_count(); ++j)
        total += grid.solid_angle(j) * double(grid.c_count());
    EXPECT_NEAR(total, 4 * kPi, 1e-13);
    // The reference 1 - cos(1.25 deg) = 2.4e-4 loses about 4e-13 to cancellation: hence 1e-12
    // relative.
    EXPECT_NEAR(grid.solid_angle(0), 5 * kDeg * (1 - std::cos(1.25 * kDeg)),
                1e-12 * grid.solid_angle(0));
    EXPECT_NEAR(grid.solid_angle(36), 5 * kDeg * (std::cos(88.75 * kDeg) - std::cos(91.25 * kDeg)),
                1e-16);
    EXPECT_EQ(grid.gamma_low(72), 178.75);
    EXPECT_EQ(grid.gamma_high(72), 180.0);

    // Cell edges: lower edges belong to the cell, C wraps around 0.
    size_t i, j;
    auto at = [&](double c_deg, double gamma_deg, PolarAxis axis = PolarAxis::plus_z) {
        const double s = std::sin(gamma_deg * kDeg), z = std::cos(gamma_deg * kDeg);
        grid.locate(s * std::cos(c_deg * kDeg), s * std::sin(c_deg * kDeg),
                    axis == PolarAxis::plus_z ? z : -z, axis, i, j);
        return std::make_pair(i, j);
    };
    EXPECT_EQ(at(0, 0), std::make_pair(size_t(0), size_t(0)));
    EXPECT_EQ(at(358, 1.2), std::make_pair(size_t(0), size_t(0)));
    EXPECT_EQ(at(2.6, 1.3), std::make_pair(size_t(1), size_t(1)));
    EXPECT_EQ(at(90, 90), std::make_pair(size_t(18), size_t(36)));
    EXPECT_EQ(at(200, 179.9), std::make_pair(size_t(40), size_t(72)));
    EXPECT_EQ(at(90, 30, PolarAxis::minus_z), std::make_pair(size_t(18), size_t(12)));

    EXPECT_EQ(error_of([] { FarFieldGrid(grid_options(7, 2.5)); }),
              "far field: the C step 7 degrees must divide 360 degrees");
    EXPECT_EQ(error_of([] { FarFieldGrid(grid_options(5, 0)); }),
              "far field: the gamma step 0 degrees must divide 180 degrees");
    EXPECT_EQ(error_of([] { FarFieldGrid(grid_options(-5, 2.5)); }),
              "far field: the C step -5 degrees must divide 360 degrees");
}

TEST(FarField, ConservesTheRaysFluxExactly) {
    // The default cluster: three wavelengths per ray, so the luminous flux differs ray by ray.
    const auto cluster = make_source("cluster", {});
    for (FarFieldQuantity quantity :
         {FarFieldQuantity::photometric, FarFieldQuantity::radiometric}) {
        auto reader = synthetic_reader(*cluster, 200000, 4);
        FarFieldOptions options;
        options.quantity = quantity;
        options.c_step_deg = 10;
        options.gamma_step_deg = 5;
        const FarField f = far_field(*reader, options);
        const Photometry& p = f.photometry;
        const double rays_total = quantity == FarFieldQuantity::photometric
                                      ? reader->totals().luminous
                                      : reader->totals().radiant;
        double sum = 0;  // sum of I x solid angle, without the repeated 360 plane
        for (size_t h = 0; h + 1 < p.horizontal_deg.size(); ++h)
            for (size_t v = 0; v < p.vertical_deg.size(); ++v)
                sum += p.candela[p.index(h, v)] * f.solid_angle[p.index(h, v)];
        EXPECT_NEAR(sum, rays_total, 1e-9 * rays_total);
        EXPECT_NEAR(f.total_flux, rays_total, 1e-9 * rays_total);
        EXPECT_EQ(f.rays, 200000u);
        EXPECT_EQ(p.type, PhotometricType::C);
        EXPECT_EQ(p.rated_lumens, -1);
        ASSERT_EQ(p.horizontal_deg.size(), 37u);
        EXPECT_EQ(p.horizontal_deg.back(), 360.0);
        for (size_t v = 0; v < p.vertical_deg.size(); ++v)
            EXPECT_EQ(p.candela[p.index(36, v)], p.candela[p.index(0, v)]);
        EXPECT_EQ(p.keywords.count("_RADIOMETRIC"),
                  quantity == FarFieldQuantity::radiometric ? 1u : 0u);
        EXPECT_EQ(f.max_intensity, *std::max_element(p.candela.begin(), p.candela.end()));
    }
}

TEST(FarField, VarianceAndAxisConventions) {
    const auto disk = make_source("disk", {{"radius", "0.5"}, {"flux", "2"}});
    const uint64_t n = 50000;
    auto up = far_field(*synthetic_reader(*disk, n, 8),
                        grid_options(10, 5, PolarAxis::plus_z, FarFieldQuantity::radiometric));
    auto down = far_field(*synthetic_reader(*disk, n, 8),
                          grid_options(10, 5, PolarAxis::minus_z, FarFieldQuantity::radiometric));
    const double f = float(2.0 / n);
    const Photometry& p = up.photometry;
    const size_t nv = p.vertical_deg.size();
    for (size_t h = 0; h < p.horizontal_deg.size(); ++h)
        for (size_t v = 0; v < nv; ++v) {
            const size_t at = p.index(h, v);
            // Equal-flux rays: sum of squares / omega^2 = count f^2 / omega^2 = I f / omega, with
            // the polar caps' omega that of the whole cap.
            const bool cap = v == 0 || v + 1 == nv;
            const double omega =
                up.solid_angle[at] * (cap ? double(p.horizontal_deg.size() - 1) : 1.0);
            EXPECT_NEAR(up.variance[at], p.candela[at] * f / omega, 1e-12 * up.variance[at]);
            if (p.vertical_deg[v] > 90) {
                EXPECT_EQ(up.flux[at], 0.0);
            }
            // Measured from -z, the same rays fill the mirrored cells.
            EXPECT_EQ(down.flux[p.index(h, nv - 1 - v)], up.flux[at]);
        }
    EXPECT_LT(up.max_gamma_deg, 30.0);
    EXPECT_GT(down.max_gamma_deg, 150.0);
}

// Root of the flux-weighted mean squared relative error against the closed form's cell means,
// over the brightest cells that carry 99% of the flux.
double flux_weighted_error(const analytic::Source& source, const FarField& f) {
    const Photometry& p = f.photometry;
    std::vector<std::array<double, 3>> cells;  // truth, estimate, solid angle
    double total = 0;
    for (size_t h = 0; h + 1 < p.horizontal_deg.size(); ++h)
        for (size_t v = 0; v < p.vertical_deg.size(); ++v) {
            const size_t at = p.index(h, v);
            cells.push_back(
                {test::closed_form_cell_mean(source, p, h, v), p.candela[at], f.solid_angle[at]});
            total += cells.back()[0] * cells.back()[2];
        }
    std::sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a[0] > b[0]; });
    double flux = 0, square = 0;
    for (const auto& [truth, estimate, omega] : cells) {
        if (flux >= 0.99 * total) break;
        flux += truth * omega;
        square += truth * omega * (estimate / truth - 1) * (estimate / truth - 1);
    }
    return std::sqrt(square / flux);
}

TEST(FarFieldSmoothing, BeatsBinningKeepsTheFluxAndGivesOneValueAtEachPole) {
    // A Lambertian disk tilted 30 degrees (no symmetry about the polar axis), 20 000 rays, a fixed
    // seed. tests/bench/farfield_accuracy measures the same at 10^4 to 10^7 rays: there the
    // kernel estimate's error is 0.10-0.30 of binning's; here it must be under half.
    const auto disk = make_source("disk", {{"tilt", "30"}});
    const uint64_t n = 20000;
    FarFieldOptions none, automatic;
    none.quantity = automatic.quantity = FarFieldQuantity::radiometric;
    none.smoothing = FarFieldSmoothing::none;
    automatic.smoothing = FarFieldSmoothing::automatic;
    const FarField binned = far_field(*synthetic_reader(*disk, n, 5), none);
    const FarField smoothed = far_field(*synthetic_reader(*disk, n, 5), automatic);
    const double binned_error = flux_weighted_error(*disk, binned),
                 smoothed_error = flux_weighted_error(*disk, smoothed);
    std::printf(
        "[ figures  ] tilted disk, %llu rays: flux-weighted RMS error, binning %.4f, kernel "
        "density %.4f\n",
        (unsigned long long)n, binned_error, smoothed_error);
    EXPECT_LT(smoothed_error, 0.5 * binned_error);

    for (const FarField* f : {&binned, &smoothed}) {
        const Photometry& p = f->photometry;
        const size_t nv = p.vertical_deg.size();
        double sum = 0;
        for (size_t h = 0; h + 1 < p.horizontal_deg.size(); ++h)
            for (size_t v = 0; v < nv; ++v)
                sum += p.candela[p.index(h, v)] * f->solid_angle[p.index(h, v)];
        const double rays_total =
            1.0;  // the disk's default flux, W: equal rays of 1/n each (float)
        EXPECT_NEAR(sum, n * double(float(rays_total / double(n))), 1e-9 * sum);
        for (size_t h = 1; h < p.horizontal_deg.size(); ++h) {
            EXPECT_EQ(p.candela[p.index(h, 0)], p.candela[p.index(0, 0)]);
            EXPECT_EQ(p.candela[p.index(h, nv - 1)], p.candela[p.index(0, nv - 1)]);
        }
    }
    EXPECT_EQ(smoothed.photometry.keywords.at("_SMOOTHING").rfind("kernel density", 0), 0u);
    EXPECT_EQ(binned.photometry.keywords.at("_SMOOTHING").rfind("none", 0), 0u);
}

TEST(FarFieldDigits, ValuesKeepTheDigitsTheirErrorsSupport) {
    FarField f;
    f.photometry.vertical_deg = {0, 90, 180};
    f.photometry.horizontal_deg = {0, 180, 360};
    f.photometry.candela = {18.38155, 123.456, 0.0123456, 7.0, 5.55, 0};
    f.variance = {0.135 * 0.135, 12.3 * 12.3, 0.00021 * 0.00021, 0, 0.05 * 0.05, 0};
    f.solid_angle.assign(6, 1.0);
    round_to_uncertainty(f);
    const std::vector<double> expected = {18.38, 123, 0.01235, 7.0, 5.55, 0};
    for (size_t k = 0; k < expected.size(); ++k)
        EXPECT_EQ(f.photometry.candela[k], expected[k]) << k;
    EXPECT_EQ(format_double(f.photometry.candela[2]), "0.01235");  // no binary tail in the file
    EXPECT_DOUBLE_EQ(written_flux(f),
                     18.38 + 123 + 0.01235 + 7.0 + 5.55);  // the C 0 and 180 planes
}

// Coarser levels merge 2 x 2 bins, so every level's bins must tile the sphere: 2 x 2^3 = 16
// degrees does not divide 180.
TEST(FarFieldSmoothing, HistogramLevelsMustDivideTheSphere) {
    EXPECT_NO_THROW(DirectionHistogram(DirectionResolution{2.5, 3, 4, 16, 4, false}));
    EXPECT_THROW(DirectionHistogram(DirectionResolution{2, 4, 4, 16, 4, false}),
                 std::invalid_argument);
    EXPECT_THROW(DirectionHistogram(DirectionResolution{7, 1, 14, 28, 4, false}),
                 std::invalid_argument);
}

// The rays a source emits on average: each 0.25 degree bin of the histogram gets its expected
// flux (the closed form integrated on 3 x 3 points) as rays of total / n each, at its centre.
DirectionHistogram expected_rays(const analytic::Source& source, double n) {
    DirectionHistogram h;
    const double step = 0.25 * kDeg, ray = source.total_flux() / n;
    for (int row = 0; row < 720; ++row)
        for (int column = 0; column < 1440; ++column) {
            double flux = 0;
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) {
                    const double g = (row + (a + 0.5) / 3) * step,
                                 c = (column + (b + 0.5) / 3) * step;
                    const Vec3 v{std::sin(g) * std::cos(c), std::sin(g) * std::sin(c), std::cos(g)};
                    flux += source.intensity(v) * std::sin(g) * step * step / 9;
                }
            const double g = (row + 0.5) * step, c = (column + 0.5) * step;
            const double x = std::sin(g) * std::cos(c), y = std::sin(g) * std::sin(c),
                         z = std::cos(g);
            for (; flux >= ray; flux -= ray) h.add(x, y, z, ray);
            if (flux > 0) h.add(x, y, z, flux);
        }
    h.prepare();
    return h;
}

Vec3 direction_deg(double gamma, double c) {
    const double g = gamma * kDeg, a = c * kDeg;
    return {std::sin(g) * std::cos(a), std::sin(g) * std::sin(a), std::cos(g)};
}

// A flat Lambertian emitter's intensity falls linearly to zero at its horizon: every kernel
// reaching across is biased there, the edge fit is exact (to the binning, 0.25 degrees).
TEST(FarFieldSmoothing, EdgeFitIsExactAtTheHorizonOfAFlatEmitter) {
    const auto disk = make_source("disk", {});
    const DirectionHistogram h = expected_rays(*disk, 1e7);
    for (double gamma : {30.0, 75.0, 80.0, 85.0})
        for (double sigma : {4.0, 8.0}) {
            const Vec3 u = direction_deg(gamma, 7);
            const double truth = disk->intensity(u);
            const double edge = h.edge_fit(u.x, u.y, u.z, sigma).intensity / truth - 1;
            EXPECT_NEAR(edge, 0, 1e-3) << gamma << " deg, sigma " << sigma;
            if (gamma == 80 && sigma == 8) {
                std::printf(
                    "[ figures  ] disk at 80 deg, sigma 8 deg: edge fit %+.4f%%, kernel %+.2f%%\n",
                    100 * edge, 100 * (h.at(u.x, u.y, u.z, sigma).intensity / truth - 1));
                EXPECT_GT(std::abs(h.at(u.x, u.y, u.z, sigma).intensity / truth - 1), 0.01);
                EXPECT_GT(std::abs(h.local_fit(u.x, u.y, u.z, sigma).intensity / truth - 1), 0.01);
            }
        }
}

// The rule offers edge fits only where the rays spread as at an edge: on a disk's flanks they are
// chosen, on a cos^20 lobe (which a Gaussian-weighted fit flattens) never.
TEST(FarFieldSmoothing, EdgeFitsAreChosenAtEdgesNotOnLobes) {
    const auto disk = make_source("disk", {});
    const auto lobe = make_source("lobe", {{"n", "20"}});
    const DirectionHistogram flat = expected_rays(*disk, 1e6), peaked = expected_rays(*lobe, 1e6);
    for (double gamma = 60; gamma <= 85; gamma += 5) {
        const Vec3 u = direction_deg(gamma, 7);
        EXPECT_EQ(flat.adaptive(u.x, u.y, u.z).kind, DirectionHistogram::Kind::edge) << gamma;
    }
    for (double gamma = 0; gamma <= 40; gamma += 2.5) {
        const Vec3 u = direction_deg(gamma, 7);
        EXPECT_NE(peaked.adaptive(u.x, u.y, u.z).kind, DirectionHistogram::Kind::edge) << gamma;
    }
}

TEST(FarFieldSmoothing, TheOptionIsAutoNoneOrABandwidth) {
    FarFieldOptions o;
    parse_smoothing("3.5", o);
    EXPECT_EQ(o.smoothing, FarFieldSmoothing::fixed);
    EXPECT_EQ(o.smoothing_deg, 3.5);
    parse_smoothing("none", o);
    EXPECT_EQ(o.smoothing, FarFieldSmoothing::none);
    parse_smoothing("auto", o);
    EXPECT_EQ(o.smoothing, FarFieldSmoothing::automatic);
    for (const char* bad : {"fast", "0", "90", "3deg", ""})
        EXPECT_EQ(error_of([&] { parse_smoothing(bad, o); }),
                  std::string("far field: smoothing '") + bad +
                      "': expected auto, none or a bandwidth in degrees from 0.5 to 45");
}

TEST(FarField, RaysWithoutTheQuantityAreAClearError) {
    RayHeader h;
    h.has_radiant = true;  // and no spectrum: no luminous flux
    Ray r;
    r.direction = {0, 0, 1};
    r.radiant = 1;
    EXPECT_EQ(error_of([&] { far_field(*test::memory_reader(h, {r})); }),
              "memory.rays: the rays carry neither luminous flux nor radiant flux with a spectrum, "
              "so their luminous "
              "intensity is unknown; ask for a radiometric far field instead");
    RayHeader l;
    l.has_luminous = true;
    Ray lr = r;
    lr.luminous = 1;
    EXPECT_EQ(error_of([&] {
                  far_field(*test::memory_reader(l, {lr}),
                            grid_options(5, 2.5, PolarAxis::plus_z, FarFieldQuantity::radiometric));
              }),
              "memory.rays: the rays carry neither radiant flux nor luminous flux with a spectrum, "
              "so their radiant "
              "intensity is unknown; ask for a photometric far field instead");
    RayHeader w = h;
    w.spectral = SpectralKind::per_ray_wavelength;
    Ray known = r, unknown = r;
    known.wavelength = 550;
    EXPECT_EQ(error_of([&] {
                  far_field(*test::memory_reader(w, {known, unknown}));
              }),
              "memory.rays: ray 2: its luminous flux is unknown (no flux column for it and an "
              "unknown wavelength)");
}

// ---------------------------------------------------------------------------------------------
// Acceptance (a): the far field of a Lambertian disk against I = I0 cos(gamma).

// The exact fraction of a cos law's flux in every cell (k = h * vertical + v):
// p = dC/(2 pi) (sin^2 b - sin^2 a), gamma clipped to [a, b] within 0..90 deg.
std::vector<double> cosine_law_fractions(const Photometry& p) {
    const size_t nc = p.horizontal_deg.size() - 1, nv = p.vertical_deg.size();
    const double dc = (p.horizontal_deg[1] - p.horizontal_deg[0]) * kDeg,
                 dg = p.vertical_deg[1] - p.vertical_deg[0];
    std::vector<double> fraction(nc * nv);
    for (size_t h = 0; h < nc; ++h)
        for (size_t v = 0; v < nv; ++v) {
            const double a = std::clamp(p.vertical_deg[v] - dg / 2, 0.0, 90.0) * kDeg;
            const double b = std::clamp(p.vertical_deg[v] + dg / 2, 0.0, 90.0) * kDeg;
            fraction[h * nv + v] =
                dc / (2 * kPi) * (std::sin(b) * std::sin(b) - std::sin(a) * std::sin(a));
        }
    test::pool_caps(fraction, nc, nv);
    return fraction;
}

// Cell fluxes as the photometry states them: candela x solid angle.
std::vector<double> stated_cell_flux(const Photometry& p, const FarField& f) {
    std::vector<double> flux(p.candela.size());
    for (size_t k = 0; k < flux.size(); ++k) flux[k] = p.candela[k] * f.solid_angle[k];
    return flux;
}

TEST(FarFieldAcceptance, LambertianDiskIesFollowsTheCosineLaw) {
    test::ScratchDir dir;
    const auto disk = make_source("disk", {{"radius", "1"}, {"flux", "1"}, {"wavelength", "555"}});
    const uint64_t n = 1000000;
    const std::string rays = dir.file("disk.tm25ray"), ies = dir.file("disk.ies");
    {
        auto out = create_rays(rays, RayFormat::tm25, synth_header(*disk, n, 20240601));
        synthesize(*disk, n, 20240601, *out);
    }
    auto reader = open_rays(rays);
    const FarField f = far_field(*reader);
    write_photometry(ies, f.photometry, PhotometryFormat::ies);
    const Photometry back = read_photometry(ies);
    ASSERT_EQ(back.candela.size(), f.photometry.candela.size());
    for (size_t k = 0; k < back.candela.size(); ++k)
        ASSERT_EQ(back.candela[k], f.photometry.candela[k]) << "cell " << k;

    // Conservation: sum(I x solid angle) is the rays' luminous total, which is the disk's
    // 683.002 V(555) lm to the one float rounding of the equal ray flux.
    double sum = 0;
    for (size_t h = 0; h + 1 < back.horizontal_deg.size(); ++h)
        for (size_t v = 0; v < back.vertical_deg.size(); ++v)
            sum += back.candela[back.index(h, v)] * f.solid_angle[back.index(h, v)];
    EXPECT_NEAR(sum, reader->totals().luminous, 1e-9 * sum);
    EXPECT_NEAR(sum, disk->luminous_flux(), 1.2e-7 * sum);

    // Per cell: measured intensity against the exact bin average of I0 cos(gamma), as counts of
    // equal-flux rays against Multinomial(n, p) (see test::check_counts for the bounds).
    const double ray_flux =
        float(float(1.0 / n) * (kMaxLuminousEfficacy * photopic_efficiency(555)));
    size_t fractional = 0;
    const auto counts = test::cell_counts(f, stated_cell_flux(back, f), ray_flux, fractional);
    EXPECT_EQ(fractional, 0u);
    const test::CountCheck c = test::check_counts(cosine_law_fractions(back), counts, double(n));
    EXPECT_EQ(c.bins, 72u * 36u + 1u);  // gamma 2.5 .. 90 in every C plane, and the cap at 0
    EXPECT_EQ(c.outside, 0u) << "light where a cos law has none";
    EXPECT_EQ(c.beyond_bound, 0u) << "worst |count - expected| / bound = " << c.worst_ratio;
    EXPECT_LT(c.chi_square, c.critical) << "dof " << c.dof;
    std::printf(
        "[ figures  ] cos law, %zu cells: worst deviation / 99.9%% bound = %.3f, chi-square %.3f, "
        "dof %zu, "
        "critical %.1f\n",
        c.bins, c.worst_ratio, c.chi_square, c.dof, c.critical);
}

TEST(FarFieldAcceptance, TheCosineLawCheckRejectsACosineSquaredLobe) {
    // The same check on a cos^2 lobe of the same flux must fail: the test has power.
    const auto lobe = make_source("lobe", {{"n", "2"}, {"flux", "1"}});
    const uint64_t n = 1000000;
    const FarField f = far_field(*synthetic_reader(*lobe, n, 20240601));
    const double ray_flux =
        float(float(1.0 / n) * (kMaxLuminousEfficacy * photopic_efficiency(555)));
    size_t fractional = 0;
    const auto counts = test::cell_counts(f, f.flux, ray_flux, fractional);
    const test::CountCheck c =
        test::check_counts(cosine_law_fractions(f.photometry), counts, double(n));
    EXPECT_GT(c.beyond_bound, 100u);
    EXPECT_GT(c.chi_square, 10 * c.critical);
}

}  // namespace
}  // namespace rayset
