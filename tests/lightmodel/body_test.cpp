// The source body: density lattice and its boundary cells, the per-cell sphere fit, the Embree
// sphere body, and the whole chain on a Lambertian disk against its true silhouette.
#include <gtest/gtest.h>

#include "converters/analytic/analytic_sources.h"
#include "core/random.h"
#include "lightmodel/density_lattice.h"
#include "lightmodel/sphere_body.h"
#include "lightmodel/sphere_fit.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace rayset::lightmodel {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

Vec3 random_in_box(Pcg32& rng, Vec3 lower, Vec3 upper) {
    return {lower.x + rng.uniform() * (upper.x - lower.x),
            lower.y + rng.uniform() * (upper.y - lower.y),
            lower.z + rng.uniform() * (upper.z - lower.z)};
}

LatticeFrame frame_over(Vec3 lower, Vec3 upper, int resolution) {
    Box box;
    box.extend(lower);
    box.extend(upper);
    return LatticeFrame(box, resolution);
}

// ---------------------------------------------------------------------------------------------
// Density lattice

TEST(BodyDensityLattice, AdaptedResolutionIsMonotoneAndClamped) {
    int previous = 0;
    for (double rays = 1; rays < 1e10; rays *= 1.37) {
        const int n = adapted_resolution(uint64_t(rays));
        EXPECT_GE(n, previous);
        EXPECT_GE(n, 8);
        EXPECT_LE(n, 128);
        previous = n;
    }
    EXPECT_EQ(adapted_resolution(0), 8);
    EXPECT_EQ(adapted_resolution(64 * 100 * 100), 100);  // sqrt(R / 64) exactly
    EXPECT_EQ(adapted_resolution(1000000), 125);
    EXPECT_EQ(adapted_resolution(10000000), 128);
    EXPECT_EQ(adapted_resolution(10000000, 32), 32);
    EXPECT_EQ(adapted_resolution(100, 4), 4);  // a cap below 8 wins
}

TEST(BodyDensityLattice, CountsWeightsAndGridTransform) {
    const LatticeFrame frame = frame_over({-1, -2, -3}, {3, 2, 1}, 16);  // cells of 0.25 mm
    DensityLattice lattice(frame);
    Pcg32 rng(7);
    std::vector<Vec3> points(20000);
    for (Vec3& p : points) p = random_in_box(rng, {-1, -2, -3}, {3, 2, 1});
    lattice.add(points);
    std::vector<double> expected(size_t(frame.cell_count()), 0);
    for (const Vec3& p : points) expected[size_t(frame.linear(frame.cell_of(p)))] += 1;
    uint64_t occupied = 0;
    for (int z = 0; z < frame.dims()[2]; ++z)
        for (int y = 0; y < frame.dims()[1]; ++y)
            for (int x = 0; x < frame.dims()[0]; ++x) {
                const Coord c{x, y, z};
                EXPECT_EQ(lattice.count(c), expected[size_t(frame.linear(c))]);
                occupied += expected[size_t(frame.linear(c))] > 0;
            }
    EXPECT_EQ(lattice.occupied_cell_count(), occupied);
    EXPECT_EQ(lattice.total(), 20000.0);

    // The grid's transform takes a world point to the voxel of its cell.
    const auto grid = lattice.grid();
    EXPECT_EQ(grid->getName(), "density");
    for (int i = 0; i < 100; ++i) {
        const Vec3 p = points[size_t(i)];
        const openvdb::Coord ijk =
            grid->transform().worldToIndexCellCentered(openvdb::Vec3d(p.x, p.y, p.z));
        const Coord c = frame.cell_of(p);
        EXPECT_EQ(ijk, openvdb::Coord(c[0], c[1], c[2]));
        EXPECT_EQ(grid->tree().getValue(ijk), float(expected[size_t(frame.linear(c))]));
    }
    // Read back from the grid: the same counts.
    DensityLattice reread(frame, *grid);
    EXPECT_EQ(reread.occupied_cell_count(), occupied);
    EXPECT_EQ(reread.total(), 20000.0);

    // Weights replace counts; weightless points leave cells empty.
    DensityLattice weighted(frame);
    const std::vector<Vec3> two{{0.1, 0.1, 0.1}, {0.2, 0.2, 0.2}};
    const float weights[2] = {0.5f, 0.0f};
    weighted.add(two.data(), 2, weights);
    EXPECT_EQ(weighted.count(frame.cell_of(two[0])), 0.5);
    EXPECT_EQ(weighted.occupied_cell_count(), 1u);
}

// Occupied cells = a box of a x b x c cells: its boundary cells are the box's surface cells,
// a b c - (a-2)(b-2)(c-2); against the lattice's own faces too (cells outside count as empty).
TEST(BodyDensityLattice, BoundaryCellsOfASolidBoxAreItsSurfaceCells) {
    const LatticeFrame frame = frame_over({0, 0, 0}, {10, 8, 6}, 10);  // 10 x 8 x 6 cells of 1 mm
    ASSERT_EQ(frame.dims(), (std::array<int32_t, 3>{10, 8, 6}));
    Pcg32 rng(11);
    auto fill = [&](Coord lo, Coord hi) {  // inclusive cell range, 3 random points a cell
        std::vector<Vec3> points;
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x)
                    for (int k = 0; k < 3; ++k)
                        points.push_back(random_in_box(rng, {x + 0.01, y + 0.01, z + 0.01},
                                                       {x + 0.99, y + 0.99, z + 0.99}));
        return points;
    };
    DensityLattice inner(frame);
    inner.add(fill({2, 1, 1}, {7, 6, 4}));  // 6 x 6 x 4
    EXPECT_EQ(inner.occupied_cell_count(), 144u);
    const auto cells = inner.boundary_cells();
    EXPECT_EQ(cells.size(), size_t(144 - 4 * 4 * 2));
    for (const Coord& c : cells) {
        const bool on_surface =
            c[0] == 2 || c[0] == 7 || c[1] == 1 || c[1] == 6 || c[2] == 1 || c[2] == 4;
        EXPECT_TRUE(on_surface) << c[0] << " " << c[1] << " " << c[2];
    }
    EXPECT_TRUE(std::is_sorted(cells.begin(), cells.end(), [&](const Coord& a, const Coord& b) {
        return frame.linear(a) < frame.linear(b);
    }));

    DensityLattice whole(frame);
    whole.add(fill({0, 0, 0}, {9, 7, 5}));
    EXPECT_EQ(whole.boundary_cells().size(), size_t(480 - 8 * 6 * 4));
}

TEST(BodyDensityLattice, EveryCellOfAFlatLayerIsABoundaryCell) {
    const LatticeFrame frame = frame_over({0, 0, 0}, {10, 8, 6}, 10);
    Pcg32 rng(5);
    std::vector<Vec3> points;
    for (int i = 0; i < 5000; ++i)
        points.push_back(random_in_box(rng, {1.001, 2.001, 3.5}, {8.999, 5.999, 3.5}));
    DensityLattice lattice(frame);
    lattice.add(points);
    EXPECT_EQ(lattice.occupied_cell_count(), 8u * 4u);
    EXPECT_EQ(lattice.boundary_cells().size(), 8u * 4u);
}

// One lattice per thread merged afterwards gives the serial counts; reports the speed of both.
TEST(BodyDensityLattice, ParallelBuildByMergingThreadLatticesMatchesSerial) {
    const size_t n = 4000000;
    std::vector<Vec3> points(n);
    Pcg32 rng(3);
    for (Vec3& p : points) {
        const double r = std::sqrt(rng.uniform()), phi = 2 * kPi * rng.uniform();
        p = {r * std::cos(phi), r * std::sin(phi), 0};
    }
    const LatticeFrame frame = frame_over({-1, -1, 0}, {1, 1, 0}, 128);
    auto start = Clock::now();
    DensityLattice serial(frame);
    serial.add(points);
    const double serial_s = seconds_since(start);

    start = Clock::now();
    tbb::enumerable_thread_specific<DensityLattice> locals([&] { return DensityLattice(frame); });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 65536),
                      [&](const tbb::blocked_range<size_t>& r) {
                          locals.local().add(points.data() + r.begin(), r.size());
                      });
    DensityLattice merged(frame);
    for (DensityLattice& local : locals) merged.merge(local);
    const double parallel_s = seconds_since(start);

    start = Clock::now();
    const auto boundary = serial.boundary_cells();
    const double boundary_s = seconds_since(start);
    std::printf(
        "[ density ] %zu points: serial add %.1f ns/point, %zu thread lattices + merge %.1f "
        "ns/point; "
        "%llu occupied cells, boundary cells in %.1f ms\n",
        n, 1e9 * serial_s / n, locals.size(), 1e9 * parallel_s / n,
        (unsigned long long)serial.occupied_cell_count(), 1e3 * boundary_s);
    EXPECT_EQ(merged.total(), double(n));
    EXPECT_EQ(merged.occupied_cell_count(), serial.occupied_cell_count());
    for (const Coord& c : boundary) EXPECT_EQ(merged.count(c), serial.count(c));
}

// ---------------------------------------------------------------------------------------------
// Sphere fit

double coverage(const std::vector<Sphere>& spheres, const std::vector<Vec3>& samples) {
    size_t covered = 0;
    for (const Vec3& p : samples)
        for (const Sphere& s : spheres) {
            const double dx = p.x - s.x, dy = p.y - s.y, dz = p.z - s.z;
            if (dx * dx + dy * dy + dz * dz <= double(s.r) * s.r) {
                ++covered;
                break;
            }
        }
    return double(covered) / double(samples.size());
}

TEST(BodySphereFit, SpheresCoverTheirSamples) {
    Pcg32 rng(21);
    const double h = 0.016;
    const Vec3 lower{0.3, -0.2, 0.05};
    double worst = 1;
    size_t cells = 0;
    double seconds = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int k = 1 + trial % 16;
        const size_t n = 1 + size_t(rng.below(64));
        std::vector<Vec3> samples(n);
        // Alternate volume clouds and tilted surface patches.
        const Vec3 tilt{rng.uniform() - 0.5, rng.uniform() - 0.5, 1};
        for (Vec3& p : samples) {
            p = random_in_box(rng, lower, lower + Vec3{h, h, h});
            if (trial % 2)
                p.z =
                    lower.z + 0.5 * h + 0.3 * (tilt.x * (p.x - lower.x) + tilt.y * (p.y - lower.y));
        }
        const auto start = Clock::now();
        const auto spheres = fit_cell_spheres(lower, h, samples, k);
        seconds += seconds_since(start);
        ++cells;
        ASSERT_FALSE(spheres.empty());
        EXPECT_LE(spheres.size(), size_t(k));
        worst = std::min(worst, coverage(spheres, samples));
    }
    std::printf(
        "[ fit ] worst coverage of a cell's samples %.4f; %.0f us per cell (1..64 samples, K "
        "1..16)\n",
        worst, 1e6 * seconds / double(cells));
    EXPECT_GE(worst, 0.99);
}

// A flat layer of origins gives a layer of spheres much thinner than the cell.
TEST(BodySphereFit, AFlatLayerGivesAThinLayerOfSpheres) {
    Pcg32 rng(8);
    const double h = 0.016, z0 = 0.37 * h;
    double thickest = 0, seconds = 0, worst = 1;
    const int trials = 200;
    for (int trial = 0; trial < trials; ++trial) {
        std::vector<Vec3> samples(64);
        for (Vec3& p : samples) p = {rng.uniform() * h, rng.uniform() * h, z0};
        const auto start = Clock::now();
        const auto spheres = fit_cell_spheres({0, 0, 0}, h, samples, 16);
        seconds += seconds_since(start);
        double thickness = 0;
        for (const Sphere& s : spheres) thickness = std::max(thickness, std::abs(s.z - z0) + s.r);
        thickest = std::max(thickest, thickness);
        worst = std::min(worst, coverage(spheres, samples));
        EXPECT_EQ(spheres.size(), 16u);
    }
    std::printf(
        "[ fit ] flat layer, 64 samples, K = 16: thickness at most %.3f h, coverage %.4f, %.0f us "
        "per cell\n",
        thickest / h, worst, 1e6 * seconds / trials);
    EXPECT_LT(thickest, h / 3);
    EXPECT_GE(worst, 0.99);
}

// Holes: a flat source covering 3 x 3 cells, 64 samples and K = 16 in each; the fraction of
// the middle cell's surface inside some sphere (of any of the nine cells) on a 100 x 100 grid.
TEST(BodySphereFit, AFlatLayerOfSpheresLeavesAlmostNoHoles) {
    Pcg32 rng(12);
    const double h = 0.016, z0 = 0.37 * h;
    double covered = 0;
    const int blocks = 20;
    for (int block = 0; block < blocks; ++block) {
        std::vector<Sphere> spheres;
        for (int cx = -1; cx <= 1; ++cx)
            for (int cy = -1; cy <= 1; ++cy) {
                std::vector<Vec3> samples(64);
                for (Vec3& p : samples)
                    p = {(cx + rng.uniform()) * h, (cy + rng.uniform()) * h, z0};
                const auto cell = fit_cell_spheres({cx * h, cy * h, 0}, h, samples, 16);
                spheres.insert(spheres.end(), cell.begin(), cell.end());
            }
        std::vector<Vec3> grid;
        for (int i = 0; i < 100; ++i)
            for (int j = 0; j < 100; ++j)
                grid.push_back({(i + 0.5) / 100 * h, (j + 0.5) / 100 * h, z0});
        covered += coverage(spheres, grid) / blocks;
    }
    std::printf("[ fit ] flat layer: %.4f of the surface inside the spheres\n", covered);
    EXPECT_GE(covered, 0.98);
}

// Four samples at A and one at B, K = 1, no footprint: the spread 4 (c/s)^8 + ((L - c)/s)^8
// along AB (c = distance from A, L = |AB|) is least at c = L w / (1 + w), w = 4^(-1/7), which
// Ceres must find from the centroid start c = L / 5; the radius is then L - c. (The smallest
// enclosing ball, radius L / 2, is what the spread approaches for larger m.)
TEST(BodySphereFit, CeresFindsTheMinimumOfTheStatedSpread) {
    const Vec3 a{0.2, 0.5, 0.45}, b{0.8, 0.5, 0.55};
    const std::vector<Vec3> samples{a, a, a, a, b};
    const double big_l = length(b - a), w = std::pow(4.0, -1.0 / 7), c = big_l * w / (1 + w);
    const Vec3 expected = a + (c / big_l) * (b - a);
    SphereFitOptions options;
    options.footprint = 0;
    // Converged tightly: the minimiser itself.
    options.function_tolerance = 1e-10;
    options.max_iterations = 50;
    auto spheres = fit_cell_spheres({0, 0, 0}, 1, samples, 1, options);
    ASSERT_EQ(spheres.size(), 1u);
    Vec3 centre{spheres[0].x, spheres[0].y, spheres[0].z};
    std::printf(
        "[ fit ] spread minimum, converged: centre off by %.2e L, radius %.5f (expected %.5f)\n",
        length(centre - expected) / big_l, spheres[0].r, big_l - c);
    EXPECT_LT(length(centre - expected), 1e-4 * big_l);
    EXPECT_NEAR(spheres[0].r, big_l - c, 1e-4 * big_l);
    EXPECT_EQ(coverage(spheres, samples), 1.0);
    // With the default, faster tolerance (relative cost change 1e-3) the radius stays within
    // 1% of the minimiser's.
    options.function_tolerance = SphereFitOptions().function_tolerance;
    options.max_iterations = SphereFitOptions().max_iterations;
    spheres = fit_cell_spheres({0, 0, 0}, 1, samples, 1, options);
    centre = {spheres[0].x, spheres[0].y, spheres[0].z};
    std::printf("[ fit ] spread minimum, default tolerance: centre off by %.2e L, radius %.5f\n",
                length(centre - expected) / big_l, spheres[0].r);
    EXPECT_NEAR(spheres[0].r, big_l - c, 0.01 * (big_l - c));
}

TEST(BodySphereFit, SphereCountFollowsDensity) {
    EXPECT_EQ(spheres_for_count(1000, 1000), 16);
    EXPECT_EQ(spheres_for_count(5000, 1000), 16);
    EXPECT_EQ(spheres_for_count(500, 1000), 8);
    EXPECT_EQ(spheres_for_count(1, 1000), 1);
    EXPECT_EQ(spheres_for_count(500, 1000, 4), 2);
    int previous = 0;
    for (double c = 0; c < 2000; c += 7) {
        const int k = spheres_for_count(c, 1000);
        EXPECT_GE(k, previous);
        previous = k;
    }
    std::vector<double> counts;
    for (int i = 1; i <= 101; ++i) counts.push_back(i);
    std::reverse(counts.begin(), counts.end());
    EXPECT_EQ(reference_count(counts, 0.9), 91);
    EXPECT_EQ(reference_count(counts, 1.0), 101);
    EXPECT_EQ(reference_count(counts, 0.0), 1);
}

// ---------------------------------------------------------------------------------------------
// Sphere body

TEST(BodySphereBody, OneSphereAgainstTheRaySphereFormula) {
    const Vec3 c{1, 2, 3};
    const double r = 0.5;
    SphereBody body({{1, 2, 3, 0.5f}});
    EXPECT_NEAR(body.bounds().lower.x, 0.5, 1e-7);
    EXPECT_NEAR(body.bounds().upper.z, 3.5, 1e-7);
    Pcg32 rng(4);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        // Origins on a shell 2..6 mm from the centre, aimed at a point within 0.8 mm of it.
        const Vec3 u = normalized(random_in_box(rng, {-1, -1, -1}, {1, 1, 1}));
        const Vec3 origin = c + (2 + 4 * rng.uniform()) * u;
        const Vec3 target = c + 0.8 * random_in_box(rng, {-1, -1, -1}, {1, 1, 1});
        const Vec3 d = normalized(target - origin);
        // Analytic: |o + t d - c|^2 = r^2, the smaller root.
        const Vec3 oc = origin - c;
        const double b = dot(oc, d), disc = b * b - (dot(oc, oc) - r * r);
        BodyHit hit;
        const bool found = body.intersect(origin, d, 100, hit);
        if (std::abs(disc) < 1e-5) continue;  // grazing: float and double may disagree
        ASSERT_EQ(found, disc > 0);
        EXPECT_EQ(body.occluded(origin, d, 100), disc > 0);
        if (!found) continue;
        ++hits;
        const double t = -b - std::sqrt(disc);
        EXPECT_NEAR(hit.t, t, 1e-5);
        const Vec3 n = (1 / r) * (origin + t * d - c);
        EXPECT_NEAR(hit.normal.x, n.x, 1e-4);
        EXPECT_NEAR(hit.normal.y, n.y, 1e-4);
        EXPECT_NEAR(hit.normal.z, n.z, 1e-4);
        EXPECT_LE(dot(hit.normal, d), 0);
        EXPECT_EQ(hit.sphere, 0u);
        EXPECT_FALSE(body.occluded(origin, d, 0.99 * t));
        // From the hit point on into the ball the ray only leaves it: nothing more to enter.
        EXPECT_FALSE(body.intersect(hit.point + 1e-6 * d, d, 100, hit));
    }
    EXPECT_GT(hits, 500);
}

TEST(BodySphereBody, ARayStartingInsideFindsTheNextSphereItEnters) {
    // Two overlapping balls A and B, then C apart; a ray from A's centre along +x.
    SphereBody body({{0, 0, 0, 1}, {1.5f, 0, 0, 1}, {5, 0, 0, 0.5f}});
    EXPECT_TRUE(body.inside({0, 0, 0}));
    EXPECT_FALSE(body.inside({3, 0, 0}));
    BodyHit hit;
    ASSERT_TRUE(body.intersect({0, 0, 0}, {1, 0, 0}, 100, hit));
    EXPECT_EQ(hit.sphere, 2u);
    EXPECT_NEAR(hit.t, 4.5, 1e-6);
    EXPECT_NEAR(hit.normal.x, -1, 1e-6);
    EXPECT_FALSE(body.intersect({0, 0, 0}, {1, 0, 0}, 4.4, hit));
    EXPECT_FALSE(body.occluded({0, 0, 0}, {1, 0, 0}, 4.4));
    EXPECT_TRUE(body.occluded({0, 0, 0}, {1, 0, 0}, 4.6));
    EXPECT_FALSE(body.intersect({0, 0, 0}, {-1, 0, 0}, 100, hit));
    // From outside, the first entry is A's front.
    ASSERT_TRUE(body.intersect({-3, 0, 0}, {1, 0, 0}, 100, hit));
    EXPECT_EQ(hit.sphere, 0u);
    EXPECT_NEAR(hit.t, 2, 1e-6);
    std::vector<uint32_t> crossed;
    body.crossed_spheres({-3, 0, 0}, {1, 0, 0}, 100, crossed);
    EXPECT_EQ(crossed, (std::vector<uint32_t>{0, 1, 2}));
    body.crossed_spheres({0, 0, 0}, {1, 0, 0}, 4.4, crossed);
    EXPECT_EQ(crossed, (std::vector<uint32_t>{0, 1}));
    body.crossed_spheres({0.6, 0, 0}, {1, 0, 0}, 0.1, crossed);  // a segment inside A and B
    EXPECT_EQ(crossed, (std::vector<uint32_t>{0, 1}));
}

struct RandomBody {
    std::vector<Sphere> spheres;
    explicit RandomBody(uint64_t seed, int count = 300) {
        Pcg32 rng(seed);
        for (int i = 0; i < count; ++i) {
            const Vec3 c = random_in_box(rng, {0, 0, 0}, {10, 10, 10});
            spheres.push_back(
                {float(c.x), float(c.y), float(c.z), float(0.1 + 0.9 * rng.uniform())});
        }
    }
};

// Brute force over every ball in double; balls within 1e-4 of tangent to the segment (relative
// to r^2) are left out of the comparison, where float traversal may decide either way.
TEST(BodySphereBody, CrossedSpheresAgreeWithBruteForce) {
    const RandomBody random(99);
    SphereBody body(random.spheres);
    Pcg32 rng(100);
    std::vector<uint32_t> crossed;
    size_t total = 0, borderline = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 o = random_in_box(rng, {-2, -2, -2}, {12, 12, 12});
        const Vec3 d = normalized(random_in_box(rng, {-1, -1, -1}, {1, 1, 1}));
        const double tmax =
            i % 4 == 0 ? std::numeric_limits<double>::infinity() : 15 * rng.uniform();
        body.crossed_spheres(o, d, tmax, crossed);
        EXPECT_TRUE(std::is_sorted(crossed.begin(), crossed.end()));
        EXPECT_TRUE(std::adjacent_find(crossed.begin(), crossed.end()) == crossed.end());
        for (uint32_t k = 0; k < random.spheres.size(); ++k) {
            const Sphere& s = random.spheres[k];
            const Vec3 c{s.x, s.y, s.z};
            const double t = std::clamp(dot(c - o, d), 0.0, tmax);
            const Vec3 e = o + t * d - c;
            const double r2 = double(s.r) * s.r, d2 = dot(e, e);
            if (std::abs(d2 - r2) < 1e-4 * r2) {
                ++borderline;
                continue;
            }
            const bool listed = std::binary_search(crossed.begin(), crossed.end(), k);
            EXPECT_EQ(listed, d2 < r2) << "ray " << i << " sphere " << k;
            total += d2 < r2;
        }
    }
    std::printf("[ body ] crossed_spheres: %zu crossings checked, %zu borderline pairs skipped\n",
                total, borderline);
    EXPECT_GT(total, 1000u);
}

// The first entry into the union, by brute force: the smallest t0 > 0 of a ball whose entry
// point is strictly inside no other ball (every such point is an entry from outside).
TEST(BodySphereBody, IntersectFindsTheFirstEntryIntoTheUnion) {
    const RandomBody random(7);
    SphereBody body(random.spheres);
    Pcg32 rng(8);
    int checked = 0, from_inside = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 o = random_in_box(rng, {-2, -2, -2}, {12, 12, 12});
        const Vec3 d = normalized(random_in_box(rng, {-1, -1, -1}, {1, 1, 1}));
        double best = std::numeric_limits<double>::infinity(), margin = 1;
        int best_sphere = -1;
        bool origin_inside = false;
        for (size_t k = 0; k < random.spheres.size(); ++k) {
            const Sphere& s = random.spheres[k];
            const Vec3 c{s.x, s.y, s.z}, oc = o - c;
            origin_inside |= dot(oc, oc) < double(s.r) * s.r;
            const double b = dot(oc, d), disc = b * b - (dot(oc, oc) - double(s.r) * s.r);
            if (disc <= 0) continue;
            const double t0 = -b - std::sqrt(disc);
            if (t0 <= 0 || t0 >= best) continue;
            const Vec3 p = o + t0 * d;
            bool covered = false;
            for (size_t j = 0; j < random.spheres.size() && !covered; ++j) {
                if (j == k) continue;
                const Sphere& q = random.spheres[j];
                const Vec3 e = p - Vec3{q.x, q.y, q.z};
                const double r2 = double(q.r) * q.r;
                margin = std::min(margin, std::abs(dot(e, e) - r2) / r2);
                covered = dot(e, e) < r2;
            }
            if (!covered) best = t0, best_sphere = int(k);
        }
        if (margin < 1e-4) continue;  // an entry point on another ball's surface: either answer
        BodyHit hit;
        const bool found = body.intersect(o, d, 1e9, hit);
        ASSERT_EQ(found, best_sphere >= 0) << "ray " << i;
        EXPECT_EQ(body.inside(o), origin_inside);
        EXPECT_EQ(body.occluded(o, d, 1e9), found);
        if (!found) continue;
        EXPECT_EQ(hit.sphere, uint32_t(best_sphere));
        EXPECT_NEAR(hit.t, best, 1e-5);
        ++checked;
        from_inside += origin_inside;
    }
    std::printf("[ body ] intersect: %d hits checked, %d of them from inside the body\n", checked,
                from_inside);
    EXPECT_GT(checked, 1000);
    EXPECT_GT(from_inside, 100);
}

// ---------------------------------------------------------------------------------------------
// End to end: Lambertian disk -> density -> boundary cells -> samples -> spheres -> body.

struct Silhouette {
    double iou;
    size_t true_pixels;
};

// Orthographic rays along -w over a square of half-width 1.1 mm; truth: the ellipse
// (a / cos theta)^2 + b^2 <= 1 that the unit disk in z = 0 projects to.
Silhouette silhouette_iou(const SphereBody& body, double theta, double pixel) {
    const Vec3 w{std::sin(theta), 0, std::cos(theta)}, u{std::cos(theta), 0, -std::sin(theta)},
        v{0, 1, 0};
    const int n = int(std::ceil(2.2 / pixel));
    std::vector<uint8_t> both(size_t(n) * n), either(size_t(n) * n), truth(size_t(n) * n);
    tbb::parallel_for(0, n, [&](int row) {
        for (int col = 0; col < n; ++col) {
            const double a = -1.1 + (col + 0.5) * pixel, b = -1.1 + (row + 0.5) * pixel;
            const bool in_truth = (a / std::cos(theta)) * (a / std::cos(theta)) + b * b <= 1;
            BodyHit hit;
            const bool in_model = body.intersect(2.0 * w + a * u + b * v, -w, 10, hit);
            const size_t i = size_t(row) * n + col;
            both[i] = in_truth && in_model;
            either[i] = in_truth || in_model;
            truth[i] = in_truth;
        }
    });
    size_t intersection = 0, uni = 0, t = 0;
    for (size_t i = 0; i < both.size(); ++i)
        intersection += both[i], uni += either[i], t += truth[i];
    return {double(intersection) / double(uni), t};
}

TEST(BodyEndToEnd, LambertianDiskSilhouetteMatchesTheTrueDisk) {
    const analytic::LambertianDisk disk(1.0, 1.0);
    const size_t rays = 1000000;
    Pcg32 rng(2024);
    std::vector<Vec3> origins(rays);
    Box box;
    for (Vec3& p : origins) {
        const Ray ray = disk.sample_ray(rng);
        p = {ray.origin.x, ray.origin.y, ray.origin.z};
        box.extend(p);
    }
    auto start = Clock::now();
    const LatticeFrame frame(box, adapted_resolution(rays));
    DensityLattice density(frame);
    density.add(origins);
    const auto boundary = density.boundary_cells();
    const double density_s = seconds_since(start);

    // Reservoir sample of at most 64 origins per boundary cell (a second pass, as the build's).
    start = Clock::now();
    const size_t kSamples = 64;
    std::unordered_map<int64_t, size_t> slot;
    for (size_t i = 0; i < boundary.size(); ++i) slot[frame.linear(boundary[i])] = i;
    std::vector<std::vector<Vec3>> samples(boundary.size());
    std::vector<uint64_t> seen(boundary.size(), 0);
    Pcg32 reservoir_rng(77);
    for (const Vec3& p : origins) {
        const auto it = slot.find(frame.linear(frame.cell_of(p)));
        if (it == slot.end()) continue;
        auto& s = samples[it->second];
        const uint64_t index = seen[it->second]++;
        if (s.size() < kSamples)
            s.push_back(p);
        else if (const uint64_t j = reservoir_rng.below(uint32_t(index + 1)); j < kSamples)
            s[j] = p;
    }
    const double sampling_s = seconds_since(start);

    start = Clock::now();
    std::vector<double> counts;
    for (const Coord& c : boundary) counts.push_back(density.count(c));
    const double reference = reference_count(counts);
    std::vector<std::vector<Sphere>> per_cell(boundary.size());
    tbb::parallel_for(size_t(0), boundary.size(), [&](size_t i) {
        per_cell[i] = fit_cell_spheres(frame.cell_lower(boundary[i]), frame.cell_size(), samples[i],
                                       spheres_for_count(counts[i], reference));
    });
    std::vector<Sphere> spheres;
    for (const auto& cell : per_cell) spheres.insert(spheres.end(), cell.begin(), cell.end());
    const double fit_s = seconds_since(start);

    start = Clock::now();
    SphereBody body(spheres);
    const double embree_s = seconds_since(start);

    const double pixel = 0.004;  // a quarter of a density cell (2 mm / 125 = 0.016 mm)
    start = Clock::now();
    const Silhouette face_on = silhouette_iou(body, 0, pixel);
    const Silhouette oblique = silhouette_iou(body, kPi / 3, pixel);
    const double render_s = seconds_since(start);
    std::printf(
        "[ disk ] %zu rays, resolution %d (%d x %d x %d cells), %zu occupied, %zu boundary cells, "
        "reference count %.0f, %zu spheres\n",
        rays, frame.resolution(), frame.dims()[0], frame.dims()[1], frame.dims()[2],
        size_t(density.occupied_cell_count()), boundary.size(), reference, spheres.size());
    std::printf(
        "[ disk ] density+boundary %.2f s, reservoir %.2f s, fit %.2f s (%.0f us per cell on %s), "
        "Embree %.3f s, 2 silhouettes %.2f s\n",
        density_s, sampling_s, fit_s, 1e6 * fit_s / double(boundary.size()), "2 threads", embree_s,
        render_s);
    std::printf(
        "[ disk ] silhouette IoU face-on %.4f (%zu true pixels), at 60 degrees %.4f (%zu true "
        "pixels)\n",
        face_on.iou, face_on.true_pixels, oblique.iou, oblique.true_pixels);
    EXPECT_GE(face_on.iou, 0.95);
    EXPECT_GE(oblique.iou, 0.95);
}

}  // namespace
}  // namespace rayset::lightmodel
