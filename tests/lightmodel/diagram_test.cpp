// Tests of the equal-area octahedral direction map (used by the model's tests to lay out
// equal-area bins) and of the goniometric diagram on its (cos theta, phi) grid: the map's
// accuracy, area preservation and edge folding; the diagram's cells, normalisation, exact
// reproduction of Lambertian emission, continuity, exact sampling (pdf consistency and
// chi-square goodness of fit), storage, and its far-field accuracy on analytic sources.
#include "converters/analytic/analytic_sources.h"
#include "core/random.h"
#include "lightmodel/diagram_estimate.h"
#include "lightmodel/direction_map.h"
#include "lightmodel/goniometric_diagram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rayset::lightmodel {
namespace {

double distance(Vec3 a, Vec3 b) { return length(a - b); }

Vec3 uniform_direction(Pcg32& rng) {
    const double z = 1 - 2 * rng.uniform(), phi = 2 * kPi * rng.uniform();
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

Vec3 to_vec3(const Vec3f& v) { return {v.x, v.y, v.z}; }

// ---------------------------------------------------------------------------------------------
// Direction map

TEST(DirectionMap, RoundTripOfRandomDirections) {
    // Every step is a few correctly rounded operations plus atan2/cos/sin (<= 1 ulp) and the
    // map stretches lengths by less than 4 (measured below in the edge test), so a direction
    // comes back within a few 1e-16; 1e-14 leaves room without hiding a wrong branch (those
    // give errors of order 1).
    Pcg32 rng(11);
    double worst = 0;
    for (int k = 0; k < 1000000; ++k) {
        const Vec3 w = uniform_direction(rng);
        const Vec2 p = direction_to_square(w);
        ASSERT_TRUE(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1);
        worst = std::max(worst, distance(square_to_direction(p), w));
    }
    EXPECT_LT(worst, 1e-14);
}

TEST(DirectionMap, RoundTripNearPolesEdgesAndEquator) {
    std::vector<Vec3> directions = {{0, 0, 1},       {0, 0, -1},       {1, 0, 0},
                                    {-1, 0, 0},      {0, 1, 0},        {0, -1, 0},
                                    {-0.0, -0.0, 1}, {-0.0, -0.0, -1}, {1, -0.0, -0.0}};
    for (int k = 1; k <= 16; ++k) {
        const double gap = std::pow(10.0, -k);  // 1 - |z|
        for (double sign : {1.0, -1.0})
            for (int q = 0; q < 16; ++q) {
                const double z = sign * (1 - gap);
                const double s = std::sqrt(gap * (2 - gap));  // sin(theta) without cancellation
                const double phi = q * kPi / 8 + 0.1 * (q % 3);
                directions.push_back({s * std::cos(phi), s * std::sin(phi), z});
            }
    }
    for (int q = 0; q < 64; ++q) {  // equator, and the planes x = 0 and y = 0 (the folded edges)
        const double a = q * 2 * kPi / 64;
        directions.push_back({std::cos(a), std::sin(a), 0});
        directions.push_back({0, std::cos(a), std::sin(a)});
        directions.push_back({std::cos(a), 0, std::sin(a)});
    }
    for (const Vec3& w : directions) {
        const Vec3 back = square_to_direction(direction_to_square(w));
        EXPECT_LT(distance(back, w), 1e-14) << w.x << " " << w.y << " " << w.z;
        EXPECT_NEAR(length(back), 1.0, 1e-15);
    }
    const Vec2 south = direction_to_square({0, 0, -1});
    EXPECT_EQ(south.x, 1.0);
    EXPECT_EQ(south.y, 1.0);
    const Vec2 north = direction_to_square({0, 0, 1});
    EXPECT_EQ(north.x, 0.5);
    EXPECT_EQ(north.y, 0.5);
}

TEST(DirectionMap, RoundTripOfSquarePoints) {
    // Inside the square the map is one-to-one, so points come back too.
    Pcg32 rng(12);
    double worst = 0;
    for (int k = 0; k < 200000; ++k) {
        const Vec2 p{rng.uniform(), rng.uniform()};
        const Vec2 q = direction_to_square(square_to_direction(p));
        worst = std::max(worst, std::max(std::abs(p.x - q.x), std::abs(p.y - q.y)));
    }
    EXPECT_LT(worst, 1e-13);
}

TEST(DirectionMap, PreservesArea) {
    // Uniform points of the square must land in a spherical cap of half-angle alpha with
    // probability equal to its solid angle / 4 pi = (1 - cos alpha) / 2. With N = 1e6 the count
    // fraction is binomial; a 5 sigma bound fails a correct map with probability 5.7e-7 per cap
    // (seed fixed, so the outcome is in fact deterministic). Caps straddle the poles, the
    // equator and the folded edges of the lower hemisphere.
    struct Cap {
        Vec3 axis;
        double half_angle_deg;
    };
    const std::vector<Cap> caps = {{{0, 0, 1}, 30},     {{0, 0, -1}, 60}, {{1, 0, 0}, 45},
                                   {{1, 1, -1}, 20},    {{1, 0, -1}, 50}, {{-0.3, 0.2, -1}, 10},
                                   {{0.2, -1, 0.1}, 80}};
    const int samples = 1000000;
    std::vector<Vec3> directions;
    directions.reserve(samples);
    Pcg32 rng(13);
    for (int k = 0; k < samples; ++k)
        directions.push_back(square_to_direction({rng.uniform(), rng.uniform()}));
    for (const Cap& cap : caps) {
        const Vec3 axis = normalized(cap.axis);
        const double cos_alpha = std::cos(cap.half_angle_deg * kPi / 180);
        int inside = 0;
        for (const Vec3& w : directions) inside += dot(w, axis) >= cos_alpha;
        const double expected = (1 - cos_alpha) / 2;
        const double sigma = std::sqrt(expected * (1 - expected) / samples);
        EXPECT_NEAR(double(inside) / samples, expected, 5 * sigma)
            << "cap around " << axis.x << " " << axis.y << " " << axis.z << ", "
            << cap.half_angle_deg << " deg";
    }
}

TEST(DirectionMap, ContinuousAcrossFoldedEdges) {
    // Stepping out of the square by e and folding back must land next to the edge point, on the
    // sphere as in the square: within L e, L the map's Lipschitz constant (square [0,1]^2 to
    // chord length). L is the largest singular value of the map's Jacobian, reached at the edge
    // midpoints (the equator points +-x, +-y, where the fold meets the equator): there the
    // Jacobian's Gram matrix is [[16, 16], [16, 16 + pi^2]] (its determinant is (4 pi)^2, the
    // equal-area property), so L = 6.138. e = 1e-6 and 1e-3 are checked; 6.2 leaves the
    // second-order terms of the larger step.
    const double gram_mean = 16 + kPi * kPi / 2, gram_half_difference = kPi * kPi / 2;
    const double lipschitz =
        std::sqrt(gram_mean + std::sqrt(gram_half_difference * gram_half_difference + 256));
    ASSERT_NEAR(lipschitz, 6.138, 1e-3);
    Pcg32 rng(14);
    for (double e : {1e-6, 1e-3}) {
        double worst_ratio = 0;
        for (int k = 0; k < 20000; ++k) {
            const double t = rng.uniform();
            const Vec2 edge_points[4] = {{t, 0}, {t, 1}, {0, t}, {1, t}};
            const Vec2 outward[4] = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}};
            const Vec2 mirrors[4] = {{1 - t, 0}, {1 - t, 1}, {0, 1 - t}, {1, 1 - t}};
            for (int s = 0; s < 4; ++s) {
                const Vec2 p = edge_points[s];
                const Vec3 on_edge = square_to_direction(p);
                // The two edge points the fold identifies are one direction.
                ASSERT_LT(distance(on_edge, square_to_direction(mirrors[s])), 1e-15);
                const Vec2 outside{p.x + e * outward[s].x, p.y + e * outward[s].y};
                const Vec2 folded = wrap_square(outside);
                ASSERT_TRUE(folded.x >= 0 && folded.x <= 1 && folded.y >= 0 && folded.y <= 1);
                const Vec2 inside{p.x - e * outward[s].x, p.y - e * outward[s].y};
                worst_ratio =
                    std::max({worst_ratio, distance(square_to_direction(folded), on_edge) / e,
                              distance(square_to_direction(inside), on_edge) / e});
            }
        }
        EXPECT_LT(worst_ratio, 6.2) << "e = " << e;
        std::printf("[fold] e = %g: worst step ratio %.3f (Lipschitz bound %.3f)\n", e, worst_ratio,
                    lipschitz);
        EXPECT_GT(worst_ratio, 0.5) << "e = " << e;  // the step did move the direction
    }
    // The corners all meet at -z, and a diagonal step out of a corner folds into the opposite one.
    for (const Vec2 corner : {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}, Vec2{1, 1}})
        EXPECT_LT(distance(square_to_direction(corner), {0, 0, -1}), 1e-15);
    const Vec2 folded = wrap_square({-1e-4, -1e-4});
    EXPECT_NEAR(folded.x, 1 - 1e-4, 1e-15);
    EXPECT_NEAR(folded.y, 1 - 1e-4, 1e-15);
}

TEST(DirectionMap, WrappedCellsCoverTheSameDirections) {
    // A cell outside the grid and the cell wrap_cell names must hold the same directions: the
    // centre of the outside cell, folded by wrap_square, is the centre of the named cell.
    // Every cell of the ring one cell outside the grid, corners included: the neighbours a
    // node or a cell lookup needs.
    for (int n : {1, 4, 5, 16}) {
        for (int i = -1; i <= n; ++i)
            for (int j = -1; j <= n; ++j) {
                const CellIndex c = wrap_cell({i, j}, n);
                ASSERT_TRUE(c.i >= 0 && c.i < n && c.j >= 0 && c.j < n) << i << " " << j;
                const Vec2 centre = wrap_square({(i + 0.5) / n, (j + 0.5) / n});
                EXPECT_NEAR(centre.x, (c.i + 0.5) / n, 1e-12) << n << ": " << i << " " << j;
                EXPECT_NEAR(centre.y, (c.j + 0.5) / n, 1e-12) << n << ": " << i << " " << j;
            }
    }
}

// ---------------------------------------------------------------------------------------------
// Goniometric diagram

// Direction of the point (u = cos theta, phi) of the diagram's grid.
Vec3 direction_at(double u, double phi) {
    const double s = std::sqrt(std::max(0.0, (1 - u) * (1 + u)));
    return {s * std::cos(phi), s * std::sin(phi), u};
}

// A diagram with structure everywhere: a cos^4 lobe toward +z, a broad background in part of the
// lower hemisphere, and empty regions (x < -0.5 below the horizon).
GoniometricDiagram structured_diagram(int bands, int sectors) {
    GoniometricDiagram diagram(bands, sectors);
    const auto lobe = analytic::CosineLobe::with_flux(4, 1);
    Pcg32 rng(21);
    for (int k = 0; k < 100000; ++k)
        diagram.accumulate(to_vec3(lobe.sample_ray(rng).direction), 1.0);
    for (int k = 0; k < 30000; ++k) {
        const Vec3 w = uniform_direction(rng);
        if (w.z < 0 && w.x < -0.5) continue;
        diagram.accumulate(w, 0.5 + rng.uniform());
    }
    diagram.finalize();
    return diagram;
}

// Integral of the diagram's pdf over the sphere by the midpoint rule in (u, phi), where
// dOmega = du dphi, on an m_u x m_phi grid. The density is bilinear on patches bounded by
// multiples of half a band and half a sector, so when 2 bands divides m_u and 2 sectors divides
// m_phi the rule is exact: only rounding remains. Summed row by row to keep that small.
double integral_in_u_phi(const GoniometricDiagram& diagram, int m_u, int m_phi) {
    double sum = 0;
    for (int a = 0; a < m_u; ++a) {
        const double u = -1 + (a + 0.5) * 2 / m_u;
        double row = 0;
        for (int b = 0; b < m_phi; ++b)
            row += diagram.pdf(direction_at(u, (b + 0.5) * 2 * kPi / m_phi));
        sum += row;
    }
    return sum * 4 * kPi / (double(m_u) * m_phi);
}

// Integral of the diagram's pdf over the sphere by the midpoint rule on an m x m grid of the
// equal-area octahedral square: a second quadrature that knows nothing of the diagram's grid.
double integral_on_square(const GoniometricDiagram& diagram, int m) {
    double sum = 0;
    for (int j = 0; j < m; ++j) {
        double row = 0;
        for (int i = 0; i < m; ++i)
            row += diagram.pdf(square_to_direction({(i + 0.5) / m, (j + 0.5) / m}));
        sum += row;
    }
    return sum * kSquareToSolidAngle / (double(m) * m);
}

// Probabilities of the bins of an m x m grid of the octahedral square (equal solid angle,
// layout unrelated to the diagram's), by a 24 x 24 midpoint rule per bin.
std::vector<double> square_bin_probabilities(const GoniometricDiagram& diagram, int m) {
    const int sub = 24, fine = m * sub;
    std::vector<double> probability(size_t(m) * m, 0.0);
    for (int j = 0; j < fine; ++j)
        for (int i = 0; i < fine; ++i) {
            const Vec3 w = square_to_direction({(i + 0.5) / fine, (j + 0.5) / fine});
            probability[size_t(j / sub) * m + i / sub] +=
                diagram.pdf(w) * kSquareToSolidAngle / (double(fine) * fine);
        }
    return probability;
}

int square_bin_of(Vec3 w, int m) {
    const Vec2 p = direction_to_square(w);
    return std::min(m - 1, int(p.y * m)) * m + std::min(m - 1, int(p.x * m));
}

// Upper quantile of the chi-square distribution with `dof` degrees of freedom at upper-tail
// probability alpha, by the Wilson-Hilferty approximation (chi2/dof)^(1/3) ~ normal with mean
// 1 - 2/(9 dof) and variance 2/(9 dof); `z` is the standard normal quantile at 1 - alpha.
// Its relative error is below 1e-3 for dof of a few hundred.
double chi_square_quantile(int dof, double z) {
    const double v = 2.0 / (9.0 * dof);
    return dof * std::pow(1 - v + z * std::sqrt(v), 3);
}

// The diagram infinitely many rays would give for a density f(u) that depends on u only: each
// cell gets its exact probability, F(u1) - F(u0) over the number of sectors, F the
// antiderivative of 2 pi f, accumulated at the cell's centre.
template <class Antiderivative>
GoniometricDiagram noiseless_diagram(int bands, int sectors, Antiderivative F) {
    GoniometricDiagram diagram(bands, sectors);
    for (int k = 0; k < bands; ++k) {
        const double u0 = -1 + 2.0 * k / bands, u1 = -1 + 2.0 * (k + 1) / bands;
        for (int j = 0; j < sectors; ++j)
            diagram.accumulate(direction_at(0.5 * (u0 + u1), (j + 0.5) * 2 * kPi / sectors),
                               (F(u1) - F(u0)) / sectors);
    }
    diagram.finalize();
    return diagram;
}

TEST(DiagramBuild, GridAndCells) {
    const GoniometricDiagram diagram(48, 16);
    EXPECT_EQ(diagram.bands(), 48);
    EXPECT_EQ(diagram.sectors(), 16);
    EXPECT_EQ(diagram.cell_count(), 768);
    EXPECT_DOUBLE_EQ(diagram.cell_solid_angle(), 4 * kPi / 768);
    EXPECT_EQ(GoniometricDiagram().bands(), GoniometricDiagram::kDefaultBands);
    EXPECT_EQ(GoniometricDiagram().sectors(), GoniometricDiagram::kDefaultSectors);
    Pcg32 rng(23);
    for (int k = 0; k < 10000; ++k) {
        const int band = int(rng.below(48)), sector = int(rng.below(16));
        const double u = -1 + (band + 0.05 + 0.9 * rng.uniform()) * 2 / 48;
        const double phi = (sector + 0.05 + 0.9 * rng.uniform()) * 2 * kPi / 16;
        EXPECT_EQ(diagram.cell_of(direction_at(u, phi)), band * 16 + sector);
    }
    EXPECT_EQ(diagram.cell_of({0, 0, -1}), 0);
    EXPECT_EQ(diagram.cell_of({0, 0, 1}), 47 * 16);
    // The horizon belongs to the band above it, and the smallest step below it to the band below.
    EXPECT_EQ(diagram.cell_of({1, 0, 0}), 24 * 16);
    EXPECT_EQ(diagram.cell_of({1, 0, -1e-300}), 23 * 16);
    EXPECT_EQ(diagram.cell_of({1, -1e-300, 0}), 24 * 16 + 15);  // phi just under 2 pi
    for (int bad : {0, 1, 3, 47, -2})
        EXPECT_THROW(GoniometricDiagram(bad, 16), std::invalid_argument);
    EXPECT_THROW(GoniometricDiagram(48, 0), std::invalid_argument);
}

TEST(DiagramBuild, WeightsLandInTheirCells) {
    GoniometricDiagram diagram;
    const Vec3 a = direction_at(0.3, 1.0), b = direction_at(-0.9, 5.0);
    diagram.accumulate(a, 1.0);
    diagram.accumulate(b, 3.0);
    diagram.accumulate(a, 0.25);
    EXPECT_DOUBLE_EQ(diagram.total_weight(), 4.25);
    EXPECT_DOUBLE_EQ(diagram.histogram()[diagram.cell_of(a)], 1.25);
    EXPECT_DOUBLE_EQ(diagram.histogram()[diagram.cell_of(b)], 3.0);
    EXPECT_THROW(diagram.accumulate(a, -1), std::invalid_argument);
    EXPECT_THROW(diagram.accumulate(a, std::nan("")), std::invalid_argument);
}

TEST(DiagramBuild, EmptyDiagramHasZeroPdfAndCannotBeSampled) {
    GoniometricDiagram diagram;
    EXPECT_THROW(diagram.pdf({0, 0, 1}), std::logic_error);  // not finalised yet
    diagram.finalize();
    EXPECT_TRUE(diagram.empty());
    EXPECT_EQ(diagram.pdf({0, 0, 1}), 0.0);
    EXPECT_EQ(diagram.bin_average(3), 0.0);
    EXPECT_THROW(diagram.sample({0.5, 0.5}), std::logic_error);
    diagram.accumulate({0, 0, 1}, 0.0);  // zero weight keeps it empty
    diagram.finalize();
    EXPECT_TRUE(diagram.empty());
}

TEST(DiagramBuild, MergeEqualsBuildingFromAllRays) {
    // Unit weights keep every sum an exact integer, so the comparison can be exact.
    GoniometricDiagram first, second, all;
    Pcg32 rng(24);
    for (int k = 0; k < 20000; ++k) {
        const Vec3 w = uniform_direction(rng);
        const Vec3 tilted = w.z < 0.3 ? Vec3{w.x, w.y, -w.z} : w;
        (k % 3 ? first : second).accumulate(tilted, 1.0);
        all.accumulate(tilted, 1.0);
    }
    first.merge(second);
    first.finalize();
    all.finalize();
    EXPECT_EQ(first.total_weight(), all.total_weight());
    EXPECT_EQ(first.histogram(), all.histogram());
    EXPECT_EQ(first.serialize(), all.serialize());
    EXPECT_THROW(first.merge(GoniometricDiagram(48, 8)), std::invalid_argument);
    EXPECT_THROW(first.merge(GoniometricDiagram(24, 16)), std::invalid_argument);
}

TEST(DiagramDensity, UniformCellsGiveTheUniformDensity) {
    // Every rule (interpolation, extrapolation to the poles and the horizon) keeps a constant.
    GoniometricDiagram diagram(8, 5);
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 5; ++j)
            diagram.accumulate(direction_at(-1 + (k + 0.5) / 4, (j + 0.5) * 2 * kPi / 5), 2.5);
    diagram.finalize();
    EXPECT_DOUBLE_EQ(diagram.total_weight(), 40 * 2.5);
    Pcg32 rng(22);
    for (int k = 0; k < 1000; ++k)
        EXPECT_NEAR(diagram.pdf(uniform_direction(rng)), 1 / (4 * kPi), 1e-15);
    for (const Vec3 w : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 0, 0}, Vec3{0, -1, 0}})
        EXPECT_NEAR(diagram.pdf(w), 1 / (4 * kPi), 1e-15);
}

TEST(DiagramDensity, LambertianIsReproducedWithoutBias) {
    // Exact cell probabilities of D = u / pi (u > 0): the density is linear in u, so the centres
    // carry it exactly, the bilinear patches and the one-sided extrapolations to the horizon and
    // the pole reproduce it, and nothing leaks below the horizon. Only rounding remains.
    for (int bands : {4, 24, 48}) {
        const GoniometricDiagram diagram =
            noiseless_diagram(bands, 16, [](double u) { return u > 0 ? u * u : 0.0; });
        Pcg32 rng(29);
        double worst = 0;
        for (int k = 0; k < 100000; ++k) {
            const Vec3 w = uniform_direction(rng);
            worst = std::max(worst, std::abs(diagram.pdf(w) - std::max(0.0, w.z) / kPi));
        }
        for (const Vec3 w : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 0, 0}, Vec3{0, 1, -1e-9}})
            worst = std::max(worst, std::abs(diagram.pdf(w) - std::max(0.0, w.z) / kPi));
        // Exact but for the single precision the nodes are kept in: 2^-24 relative of 1 / pi
        // for each node, at most three of it where the horizon row is extrapolated (1.5 x one
        // rounded node - 0.5 x another, rounded again). Any bias of the build would be larger.
        EXPECT_LT(worst, 3 * std::ldexp(1.0, -24) / kPi) << bands << " bands";
    }
}

TEST(DiagramDensity, IntegratesToOne) {
    const std::pair<int, int> grids[] = {{2, 1}, {4, 3}, {40, 16}, {24, 8}, {96, 32}};
    for (const auto& [bands, sectors] : grids) {
        const GoniometricDiagram diagram = structured_diagram(bands, sectors);
        ASSERT_FALSE(diagram.empty());
        // Exact quadrature (aligned with the patches): only rounding remains.
        EXPECT_NEAR(integral_in_u_phi(diagram, 2 * bands * 5, 2 * sectors * 7), 1.0, 1e-12)
            << bands << " x " << sectors;
        // Independent quadrature on the octahedral square: midpoint error on the patches' kinks
        // and on the horizon's jump over the dark sectors, O(1/m^2) and O(1/m); measured at
        // most 6e-5 at m = 1024 (halving with each doubling of m).
        EXPECT_NEAR(integral_on_square(diagram, 1024), 1.0, 2e-4) << bands << " x " << sectors;
    }
}

TEST(DiagramDensity, BinAverageIsTheCellMean) {
    const GoniometricDiagram diagram = structured_diagram(40, 16);
    double weighted_sum = 0;
    for (int cell = 0; cell < diagram.cell_count(); ++cell) {
        const int band = cell / 16, sector = cell % 16;
        double mean = 0;  // 8 x 8 midpoints in (u, phi) integrate the bilinear quarters exactly
        for (int b = 0; b < 8; ++b)
            for (int a = 0; a < 8; ++a)
                mean += diagram.pdf(direction_at(-1 + (band + (a + 0.5) / 8) * 2 / 40,
                                                 (sector + (b + 0.5) / 8) * 2 * kPi / 16)) /
                        64;
        EXPECT_NEAR(diagram.bin_average(cell), mean, 1e-12 * std::max(1.0, mean)) << cell;
        weighted_sum += diagram.bin_average(cell) * diagram.cell_solid_angle();
    }
    EXPECT_NEAR(weighted_sum, 1.0, 1e-12);
    EXPECT_THROW(diagram.bin_average(640), std::out_of_range);
}

TEST(DiagramDensity, ContinuousExceptWhereTheHorizonCutsTheLight) {
    const GoniometricDiagram diagram = structured_diagram(40, 16);
    Pcg32 rng(25);
    for (int k = 0; k < 2000; ++k) {
        // Across phi = 0 = 2 pi.
        const double u = 2 * rng.uniform() - 1;
        EXPECT_NEAR(diagram.pdf(direction_at(u, 1e-12)),
                    diagram.pdf(direction_at(u, 2 * kPi - 1e-12)), 1e-9);
        // At the poles, the same value from every azimuth.
        const double phi = 2 * kPi * rng.uniform();
        EXPECT_NEAR(diagram.pdf(direction_at(1 - 1e-13, phi)), diagram.pdf({0, 0, 1}), 1e-10);
        EXPECT_NEAR(diagram.pdf(direction_at(-1 + 1e-13, phi)), diagram.pdf({0, 0, -1}), 1e-10);
        // Across a row of centres and a column of centres.
        const double centre_u = -1 + (int(rng.below(40)) + 0.5) / 20,
                     centre_phi = (int(rng.below(16)) + 0.5) * kPi / 8;
        EXPECT_NEAR(diagram.pdf(direction_at(centre_u - 1e-12, phi)),
                    diagram.pdf(direction_at(centre_u + 1e-12, phi)), 1e-9);
        EXPECT_NEAR(diagram.pdf(direction_at(u, centre_phi - 1e-12)),
                    diagram.pdf(direction_at(u, centre_phi + 1e-12)), 1e-9);
    }
    // Where both sides of the horizon hold light (x > -0.5 here), it is an ordinary line.
    for (int k = 0; k < 16; ++k) {
        const double phi = (k - 2.5) * 2 * kPi / 48;  // -37.5 to +37.5 degrees
        EXPECT_NEAR(diagram.pdf(direction_at(1e-15, phi)), diagram.pdf(direction_at(-1e-15, phi)),
                    1e-9)
            << phi;
    }
    // Where the side below is dark (x < -0.5), the lobe's density stops at the horizon.
    double largest_jump = 0;
    for (int k = 0; k < 64; ++k) {
        const double phi = (k + 0.5) * 2 * kPi / 64;
        largest_jump = std::max(largest_jump, std::abs(diagram.pdf(direction_at(1e-15, phi)) -
                                                       diagram.pdf(direction_at(-1e-15, phi))));
    }
    EXPECT_GT(largest_jump, 1e-3);
}

TEST(DiagramSampling, PdfOfSampleEqualsPdfOfDirection) {
    const std::pair<int, int> grids[] = {{2, 1}, {4, 3}, {40, 16}};
    for (const auto& [bands, sectors] : grids) {
        const GoniometricDiagram diagram = structured_diagram(bands, sectors);
        Pcg32 rng(26);
        for (int k = 0; k < 100000; ++k) {
            const DirectionSample s = diagram.sample({rng.uniform(), rng.uniform()});
            ASSERT_NEAR(length(s.direction), 1.0, 1e-14);
            ASSERT_GT(s.pdf, 0);
            ASSERT_NEAR(s.pdf, diagram.pdf(s.direction), 1e-9 * s.pdf) << bands << " x " << sectors;
        }
    }
}

TEST(DiagramSampling, ChiSquareAgainstPdf) {
    // 1e6 samples into the 400 bins of a 20 x 20 grid of the octahedral square (a layout
    // unrelated to the diagram's) against the pdf integrated over each bin. Bins expecting fewer
    // than 5 samples are pooled into one. The threshold is the chi-square quantile at
    // significance 1e-3 (Wilson-Hilferty approximation, z_{0.999} = 3.0902): a correct sampler
    // fails with probability 1e-3 (seed fixed, so the outcome is deterministic).
    const int m = 20, samples = 1000000;
    const GoniometricDiagram diagram = structured_diagram(40, 16);
    const std::vector<double> probability = square_bin_probabilities(diagram, m);
    std::vector<double> observed(probability.size(), 0.0);
    Pcg32 rng(27);
    for (int k = 0; k < samples; ++k)
        observed[square_bin_of(diagram.sample({rng.uniform(), rng.uniform()}).direction, m)] += 1;

    double chi2 = 0, pooled_expected = 0, pooled_observed = 0;
    int bins = 0;
    for (size_t b = 0; b < probability.size(); ++b) {
        const double expected = probability[b] * samples;
        if (expected == 0) {
            ASSERT_EQ(observed[b], 0) << "sample in a bin of zero probability " << b;
        } else if (expected < 5) {
            pooled_expected += expected;
            pooled_observed += observed[b];
        } else {
            chi2 += (observed[b] - expected) * (observed[b] - expected) / expected;
            ++bins;
        }
    }
    if (pooled_expected >= 5) {
        chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
                pooled_expected;
        ++bins;
    }
    const double threshold = chi_square_quantile(bins - 1, 3.0902);
    std::printf("[chi-square] %d bins, chi2 = %.1f, threshold (alpha 1e-3) = %.1f\n", bins, chi2,
                threshold);
    EXPECT_GT(bins, 300);
    EXPECT_LT(chi2, threshold);
}

TEST(DiagramStorage, SerialiseRoundTrip) {
    const GoniometricDiagram original = structured_diagram(40, 16);
    const std::vector<float> data = original.serialize();
    ASSERT_EQ(data.size(), 3u + 40u * 16u);
    const GoniometricDiagram loaded = GoniometricDiagram::deserialize(data);
    EXPECT_EQ(loaded.bands(), 40);
    EXPECT_EQ(loaded.sectors(), 16);
    EXPECT_FLOAT_EQ(float(loaded.total_weight()), float(original.total_weight()));
    EXPECT_FALSE(loaded.has_histogram());
    EXPECT_NEAR(integral_in_u_phi(loaded, 80 * 3, 32 * 3), 1.0, 1e-12);
    Pcg32 rng(28);
    for (int k = 0; k < 10000; ++k) {
        const Vec3 w = uniform_direction(rng);
        // float rounding of each centre (6e-8), carried through the extrapolations (x 2) and
        // the renormalisation
        EXPECT_NEAR(loaded.pdf(w), original.pdf(w), 3e-7 * original.pdf(w) + 1e-300);
        const DirectionSample s = loaded.sample({rng.uniform(), rng.uniform()});
        EXPECT_NEAR(s.pdf, loaded.pdf(s.direction), 1e-9 * s.pdf);
    }
    EXPECT_THROW(GoniometricDiagram::deserialize({}), std::invalid_argument);
    EXPECT_THROW(GoniometricDiagram::deserialize({48, 16, 1, 0.5f}), std::invalid_argument);
    EXPECT_THROW(GoniometricDiagram::deserialize({3, 1, 1, 0.5f, 0.5f, 0.5f}),
                 std::invalid_argument);  // odd bands
    EXPECT_THROW(GoniometricDiagram::deserialize({2, 1, 1, 0.5f, -0.5f}), std::invalid_argument);
    EXPECT_NO_THROW(GoniometricDiagram::deserialize({2, 1, 1, 0.5f, 0.5f}));
    GoniometricDiagram loaded_copy = loaded;
    EXPECT_THROW(loaded_copy.accumulate({0, 0, 1}, 1.0), std::logic_error);

    GoniometricDiagram empty(4, 2);
    empty.finalize();
    EXPECT_TRUE(GoniometricDiagram::deserialize(empty.serialize()).empty());
}

// ---------------------------------------------------------------------------------------------
// Far-field accuracy on analytic sources

// The directions of a 128 x 128 grid of the octahedral square (equal solid angles) that carry
// 99% of a source's flux: those where its normalised intensity D = I / Phi is at least the
// level at which the cumulative sum of D dOmega, from the largest D down, reaches 0.99. Ties
// at that level are all kept, so an isotropic source keeps every direction.
struct FluxRegion {
    std::vector<Vec3> directions;
    std::vector<double> truth;  // D, sr^-1
};
FluxRegion flux_region(const analytic::Source& source) {
    const int m = 128;
    std::vector<std::pair<double, Vec3>> all;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            const Vec3 w = square_to_direction({(i + 0.5) / m, (j + 0.5) / m});
            all.push_back({source.intensity(w) / source.total_flux(), w});
        }
    std::sort(all.begin(), all.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });
    double total = 0;
    for (const auto& a : all) total += a.first;
    double cumulative = 0, level = 0;
    for (const auto& a : all) {
        cumulative += a.first;
        level = a.first;
        if (cumulative >= 0.99 * total) break;
    }
    FluxRegion region;
    for (const auto& a : all)
        if (a.first >= level)
            region.directions.push_back(a.second), region.truth.push_back(a.first);
    return region;
}

double rms_relative_error(const GoniometricDiagram& diagram, const FluxRegion& region) {
    double sum = 0;
    for (size_t k = 0; k < region.directions.size(); ++k) {
        const double relative = diagram.pdf(region.directions[k]) / region.truth[k] - 1;
        sum += relative * relative;
    }
    return std::sqrt(sum / double(region.directions.size()));
}

struct FarFieldCase {
    const char* name;
    std::shared_ptr<analytic::Source> source;
    double (*antiderivative)(double u);  // of 2 pi D(u), for the noiseless diagram
    bool linear_in_u;                    // D linear in u on each side of the horizon
};

std::vector<FarFieldCase> far_field_cases() {
    return {
        {"lambertian disk",
         std::make_shared<analytic::LambertianDisk>(analytic::LambertianDisk::with_flux(1, 1)),
         [](double u) { return u > 0 ? u * u : 0.0; }, true},
        {"lambertian sphere",
         std::make_shared<analytic::LambertianSphere>(analytic::LambertianSphere::with_flux(1, 1)),
         [](double u) { return (u + 1) / 2; }, true},
        {"cos^4 lobe",
         std::make_shared<analytic::CosineLobe>(analytic::CosineLobe::with_flux(4, 1)),
         [](double u) { return u > 0 ? std::pow(u, 5) : 0.0; }, false},
        {"chip cluster",
         std::make_shared<analytic::ChipCluster>(
             analytic::ChipCluster::Layout{}, std::vector<double>{1.0}, std::vector<double>{555.0}),
         [](double u) { return u > 0 ? u * u : 0.0; }, true}};
}

TEST(DiagramFarField, AccuracyAtOneMillionRays) {
    // The acceptance: < 2% RMS relative error over the directions carrying 99% of the flux, for
    // a diagram of 1e6 rays, on the default grid. Four independent ray sets (fixed seeds) per
    // source, each asserted; the error is almost all statistical noise (the bias, from the
    // noiseless diagram, is 0 for the three sources linear in u and 0.86% for cos^4), so it
    // scatters from set to set. Over 10 sets per source measured while choosing the grid (these
    // 4 and 6 others), 40 x 12 gave disk 1.09-1.32%, sphere 1.33-1.51%, cos^4 1.30-1.93%,
    // cluster 1.05-1.41%. The cos^4 lobe is the tight one: its 99% region reaches u = 0.40,
    // where the density is 1/40 of its peak and each cell holds ~400 rays (5% Poisson noise,
    // 3.3% after the bilinear blend). Its RMS over the 10 sets has mean 1.58% and spread 0.19%,
    // so one set exceeds 2% with probability ~1-2% (normal tail at 2.2 sigma); the 4 sets here
    // all pass. The alternatives (the lead's 48 x 16, 40 x 16, 32 x 12) are printed only.
    const std::pair<int, int> grids[] = {
        {GoniometricDiagram::kDefaultBands, GoniometricDiagram::kDefaultSectors},
        {48, 16},
        {40, 16},
        {32, 12}};
    for (const FarFieldCase& c : far_field_cases()) {
        const FluxRegion region = flux_region(*c.source);
        for (uint64_t seed = 1000; seed < 1004; ++seed) {
            std::vector<GoniometricDiagram> diagrams;
            for (const auto& [bands, sectors] : grids) diagrams.emplace_back(bands, sectors);
            Pcg32 rng(seed, uint64_t(c.name[0]));
            for (int k = 0; k < 1000000; ++k) {
                const Vec3 w = normalized(to_vec3(c.source->sample_ray(rng).direction));
                for (auto& diagram : diagrams) diagram.accumulate(w, 1.0);
            }
            for (size_t g = 0; g < diagrams.size(); ++g) {
                diagrams[g].finalize();
                const auto [bands, sectors] = grids[g];
                const double error = rms_relative_error(diagrams[g], region);
                const double bias =
                    rms_relative_error(noiseless_diagram(bands, sectors, c.antiderivative), region);
                std::printf(
                    "[far field] %-17s seed %d, %2d x %2d: RMS relative error %.4f (bias %.4f) "
                    "over %zu "
                    "directions\n",
                    c.name, int(seed), bands, sectors, error, bias, region.directions.size());
                if (g == 0) {
                    EXPECT_LT(error, 0.02) << c.name << ", seed " << seed;
                    // The sources linear in u are reproduced exactly: only the rounding of the
                    // nodes to single precision remains.
                    if (c.linear_in_u) {
                        EXPECT_LT(bias, 1e-7) << c.name;
                    }
                }
            }
        }
    }
}

TEST(DiagramFarField, BiasIsSecondOrderInTheBandWidth) {
    // The noiseless diagram's error on the cos^4 lobe (curved in u) falls as the band width
    // squared: the centres carry cell means (error f'' h^2 / 24) and the patches interpolate
    // linearly between them (error up to f'' h^2 / 8). A halving must divide it by > 3 (4 in
    // the limit; measured 4.4 from 20 to 40 bands and 6.3 from 40 to 80).
    const FarFieldCase lobe = far_field_cases()[2];
    const FluxRegion region = flux_region(*lobe.source);
    double previous = 0;
    for (int bands : {20, 40, 80}) {
        const double bias =
            rms_relative_error(noiseless_diagram(bands, 12, lobe.antiderivative), region);
        std::printf("[far field] cos^4 lobe noiseless, %2d x 12: RMS relative error %.5f\n", bands,
                    bias);
        if (previous > 0) {
            EXPECT_GT(previous / bias, 3.0) << bands << " bands";
        }
        previous = bias;
    }
}

// Smoothed diagrams of two cells, each Lambertian about its own normal (+z and +x), 2e5 rays
// each: every diagram integrates to 1, keeps its cell's flux as its weight, and follows
// cos(theta) / pi within 1.5% RMS up to 60 degrees from its normal (the noise of kernels 8 to 16
// degrees wide over 2e5 such rays is 0.6% to 1.2%, their bias at a Lambertian 0); the kernels
// spill light behind each emitter's plane, but none 30 degrees or more (two of the widest
// bandwidths).
TEST(DiagramEstimate, LambertianCellsAboutTheirOwnNormals) {
    DiagramEstimate estimate(2);
    Pcg32 rng(31);
    const Vec3 normals[2] = {{0, 0, 1}, {1, 0, 0}};
    for (int k = 0; k < 400000; ++k) {
        const int cell = k % 2;
        const double r = std::sqrt(rng.uniform()), phi = 2 * kPi * rng.uniform();
        const double a = r * std::cos(phi), b = r * std::sin(phi),
                     c = std::sqrt(std::max(0.0, 1 - r * r));
        const Vec3 w = cell == 0 ? Vec3{a, b, c} : Vec3{c, a, b};
        estimate.add(size_t(cell), w, 0.5);
    }
    const std::vector<GoniometricDiagram> diagrams = estimate.diagrams({1, 0});
    ASSERT_EQ(diagrams.size(), 2u);
    for (int k = 0; k < 2; ++k) {
        const GoniometricDiagram& d = diagrams[size_t(k)];
        const Vec3 n = normals[1 - k];
        EXPECT_NEAR(d.total_weight(), 100000, 1e-6);
        EXPECT_NEAR(integral_in_u_phi(d, 4 * d.bands(), 4 * d.sectors()), 1.0, 1e-9);
        double square = 0, behind = 0;
        int front = 0;
        for (int j = 0; j < 20000; ++j) {
            const Vec3 w = uniform_direction(rng);
            const double cosine = dot(w, n);
            if (cosine >= 0.5) square += std::pow(d.pdf(w) / (cosine / kPi) - 1, 2), ++front;
            if (cosine <= -0.5) behind = std::max(behind, d.pdf(w));
        }
        const double rms = std::sqrt(square / front);
        std::printf(
            "[ figures  ] smoothed Lambertian cell about %s: %d x %d grid, RMS error within 60 deg "
            "%.4f, largest density 30 deg or more behind %.2g\n",
            k == 0 ? "+x" : "+z", d.bands(), d.sectors(), rms, behind);
        EXPECT_LT(rms, 0.015);
        EXPECT_EQ(behind, 0);
    }
    EXPECT_THROW(GoniometricDiagram::from_densities(2, 1, 1, {0.5}), std::invalid_argument);
    EXPECT_THROW(GoniometricDiagram::from_densities(2, 1, 1, {0.5, -0.5}), std::invalid_argument);
}

}  // namespace
}  // namespace rayset::lightmodel
