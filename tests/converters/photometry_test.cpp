// Photometry::intensity and total_flux against analytic distributions, and the symmetry
// unfolding against values chosen at mirror-image planes.
#include "converters/photometry/photometry.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace rayset {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi / 180;

std::vector<double> steps(double from, double to, double step) {
    std::vector<double> a;
    int n = int(std::lround((to - from) / step));
    for (int i = 0; i <= n; ++i) a.push_back(from + i * step);
    return a;
}

Photometry grid(PhotometricType type, std::vector<double> h, std::vector<double> v,
                const std::function<double(double, double)>& f) {
    Photometry p;
    p.type = type;
    p.horizontal_deg = std::move(h);
    p.vertical_deg = std::move(v);
    for (double a : p.horizontal_deg)
        for (double b : p.vertical_deg) p.candela.push_back(f(a, b));
    return p;
}

TEST(PhotometryFlux, IsotropicSourceGivesFourPiTimesIntensityOnAnyGridAndSymmetry) {
    // The band weights of every vertical grid sum to cos 0 - cos 180 = 2 and the plane weights
    // to 2 pi, so a constant is integrated exactly whatever the spacing.
    const double I = 7.25, expected = 4 * pi * I;
    auto constant = [&](double, double) { return I; };
    std::vector<double> uneven_v = {0, 1, 3, 7.5, 20, 45, 46, 90, 91, 135, 170, 179.5, 180};
    EXPECT_NEAR(grid(PhotometricType::C, {0}, steps(0, 180, 0.5), constant).total_flux(), expected,
                1e-9 * expected);
    EXPECT_NEAR(grid(PhotometricType::C, steps(0, 90, 7.5), uneven_v, constant).total_flux(),
                expected, 1e-9 * expected);
    EXPECT_NEAR(
        grid(PhotometricType::C, {0, 5, 15, 25, 40, 90, 180}, uneven_v, constant).total_flux(),
        expected, 1e-9 * expected);
    EXPECT_NEAR(grid(PhotometricType::C, steps(90, 270, 10), uneven_v, constant).total_flux(),
                expected, 1e-9 * expected);
    EXPECT_NEAR(grid(PhotometricType::C, steps(0, 360, 15), uneven_v, constant).total_flux(),
                expected, 1e-9 * expected);
    EXPECT_NEAR(grid(PhotometricType::C, steps(0, 345, 15), uneven_v, constant).total_flux(),
                expected, 1e-9 * expected);
}

TEST(PhotometryFlux, LowerHemisphereOnlyGivesTwoPiTimesIntensity) {
    const double I = 3;
    auto p = grid(PhotometricType::C, {0}, steps(0, 90, 5), [&](double, double) { return I; });
    EXPECT_NEAR(p.total_flux(), 2 * pi * I, 1e-12 * I);
    EXPECT_EQ(p.intensity(0, 90), I);
    EXPECT_EQ(p.intensity(0, 90.5), 0.0);  // not measured above the horizon: nothing there
    EXPECT_EQ(p.intensity(33, 120), 0.0);
    auto upper =
        grid(PhotometricType::C, {0}, steps(90, 180, 5), [&](double, double) { return I; });
    EXPECT_EQ(upper.intensity(0, 60), 0.0);
    EXPECT_EQ(upper.intensity(0, 150), I);
    EXPECT_NEAR(upper.total_flux(), 2 * pi * I, 1e-12 * I);
}

// Cosine lobe I0 cos(gamma) on the lower hemisphere, uniform gamma step d: an inner band
// [g - d/2, g + d/2] weighs 2 sin g sin(d/2), so the quadrature sums to (closed form of the sum)
//   Q(d) = 2 pi (1 - cos(d/2)) + pi cos d / cos(d/2) = pi (1 - d^2/8 + O(d^4)),
// against the exact flux pi I0.
double cosine_lobe_quadrature(double d) {
    return 2 * pi * (1 - std::cos(d / 2)) + pi * std::cos(d) / std::cos(d / 2);
}

TEST(PhotometryFlux, CosineLobeMatchesTheDerivedQuadratureAndPiWithinItsError) {
    const double I0 = 1000;
    auto lobe = [&](double, double g) { return g <= 90 ? I0 * std::cos(g * deg) : 0.0; };
    for (double step : {5.0, 2.5, 1.0}) {
        double d = step * deg;
        for (auto h : {std::vector<double>{0}, steps(0, 90, 15), steps(0, 360, 30)}) {
            double flux = grid(PhotometricType::C, h, steps(0, 180, step), lobe).total_flux();
            EXPECT_NEAR(flux, I0 * cosine_lobe_quadrature(d), 1e-12 * I0) << "step " << step;
            // The quadrature error is -pi I0 d^2/8 to leading order; the next term is O(d^4).
            EXPECT_NEAR(flux, pi * I0, pi * I0 * d * d / 8 * 1.01) << "step " << step;
            EXPECT_GT(std::fabs(flux - pi * I0), pi * I0 * d * d / 8 * 0.99) << "step " << step;
        }
    }
}

TEST(PhotometryFlux, TypeBCosineBeamGivesPi) {
    // Type B: latitude H toward the polar (lateral) axis, plane angle V around it. The cosine of
    // the angle from the beam axis is cos H cos V; its flux over the front hemisphere is pi I0.
    const double I0 = 500;
    auto beam = [&](double h, double v) { return I0 * std::cos(h * deg) * std::cos(v * deg); };
    for (double step : {5.0, 1.0}) {
        double d = step * deg;
        double full =
            grid(PhotometricType::B, steps(-90, 90, step), steps(-90, 90, step), beam).total_flux();
        double half =
            grid(PhotometricType::B, steps(0, 90, step), steps(-90, 90, step), beam).total_flux();
        EXPECT_NEAR(full, half, 1e-12 * full);  // 0..90 is mirrored to -90..90
        // Uniform step d: the latitude bands sum cos^2 H x 2 sin(d/2) to pi sin(d/2) / d and the
        // plane widths sum cos V x d to d cot(d/2), so the quadrature gives pi I0 cos(d/2), within
        // pi I0 d^2/8 of the exact pi I0.
        EXPECT_NEAR(full, pi * I0 * std::cos(d / 2), 1e-12 * I0) << "step " << step;
        EXPECT_NEAR(full, pi * I0, pi * I0 * d * d / 8) << "step " << step;
        double constant = grid(PhotometricType::B, steps(-90, 90, step), steps(-90, 90, step),
                               [](double, double) { return 2.0; })
                              .total_flux();
        EXPECT_NEAR(constant, 2 * pi * 2.0, 1e-12);  // the front hemisphere, exactly
    }
}

// A value for every (plane, gamma) that differs from plane to plane, so that a wrong mirror shows.
double marker(double h, double v) { return 100 + h + v / 1000; }

TEST(PhotometryIntensity, QuadrantSymmetryMirrorsInBothPlanes) {
    auto p = grid(PhotometricType::C, {0, 30, 60, 90}, {0, 45, 90, 135, 180}, marker);
    for (double v : {0.0, 45.0, 135.0}) {
        EXPECT_EQ(p.intensity(30, v), marker(30, v));
        EXPECT_EQ(p.intensity(150, v), marker(30, v));  // mirror in the 90-270 plane
        EXPECT_EQ(p.intensity(210, v), marker(30, v));
        EXPECT_EQ(p.intensity(330, v), marker(30, v));  // mirror in the 0-180 plane
        EXPECT_EQ(p.intensity(-30, v), marker(30, v));
        EXPECT_EQ(p.intensity(120, v), marker(60, v));
        EXPECT_EQ(p.intensity(270, v), marker(90, v));
        EXPECT_DOUBLE_EQ(p.intensity(165, v), 0.5 * (marker(0, v) + marker(30, v)));
    }
}

TEST(PhotometryIntensity, BilateralSymmetriesMirrorInTheirPlane) {
    auto b0 = grid(PhotometricType::C, {0, 45, 90, 135, 180}, {0, 90, 180}, marker);
    EXPECT_EQ(b0.intensity(315, 90), marker(45, 90));
    EXPECT_EQ(b0.intensity(225, 0), marker(135, 0));
    EXPECT_DOUBLE_EQ(b0.intensity(337.5, 90), 0.5 * (marker(0, 90) + marker(45, 90)));
    // LM-63-1995 90..270: mirror in the 90-270 plane, C -> 180 - C.
    auto b90 = grid(PhotometricType::C, {90, 135, 180, 225, 270}, {0, 90, 180}, marker);
    EXPECT_EQ(b90.intensity(0, 90), marker(180, 90));
    EXPECT_EQ(b90.intensity(45, 90), marker(135, 90));
    EXPECT_EQ(b90.intensity(315, 90), marker(225, 90));
    EXPECT_EQ(b90.intensity(225, 90), marker(225, 90));
    EXPECT_DOUBLE_EQ(b90.intensity(22.5, 180), 0.5 * (marker(180, 180) + marker(135, 180)));
}

TEST(PhotometryIntensity, FullCircleWrapsFromTheLastPlaneToTheFirst) {
    auto p = grid(PhotometricType::C, {0, 90, 180, 270}, {0, 180}, marker);
    EXPECT_DOUBLE_EQ(p.intensity(315, 0), 0.5 * (marker(270, 0) + marker(0, 0)));
    EXPECT_EQ(p.intensity(-90, 0), marker(270, 0));
    EXPECT_EQ(p.intensity(450, 180), marker(90, 180));
    // Gamma beyond 180 continues over the zenith into the opposite plane.
    EXPECT_EQ(p.intensity(0, 190), p.intensity(180, 170));
    EXPECT_EQ(p.intensity(90, -45), p.intensity(270, 45));
}

TEST(PhotometryIntensity, AClosingC360PlaneIsC0Again) {
    // LM-63 requires the C360 plane to repeat C0; when it does not, C0's values are the ones used
    // (EULUMDAT cannot hold C360, so a table and its LDT form then agree).
    auto p = grid(PhotometricType::C, {0, 90, 180, 270, 360}, {0, 180}, marker);
    EXPECT_EQ(p.intensity(360, 0), marker(0, 0));
    EXPECT_DOUBLE_EQ(p.intensity(315, 0), 0.5 * (marker(270, 0) + marker(0, 0)));
    auto without = grid(PhotometricType::C, {0, 90, 180, 270}, {0, 180}, marker);
    EXPECT_EQ(p.total_flux(), without.total_flux());
}

TEST(PhotometryIntensity, BilinearBetweenGridAngles) {
    auto p = grid(PhotometricType::C, {0, 10, 20}, {0, 10, 20},
                  [](double h, double v) { return 1 + 2 * h + 3 * v + 0.5 * h * v; });
    // Bilinear interpolation reproduces a bilinear function exactly inside a cell.
    double h = 13.5, v = 4.25;
    EXPECT_NEAR(p.intensity(h, v), 1 + 2 * h + 3 * v + 0.5 * h * v, 1e-12);
}

TEST(PhotometryIntensity, TypeBLateralSymmetryAndRange) {
    auto p = grid(PhotometricType::B, {0, 30, 60, 90}, {-90, -45, 0, 45, 90}, marker);
    EXPECT_EQ(p.intensity(-30, 45), marker(30, 45));
    EXPECT_EQ(p.intensity(60, -45), marker(60, -45));
    // Back hemisphere (|V| > 90 with |H| <= 90) was not measured.
    EXPECT_EQ(p.intensity(0, 120), 0.0);
}

TEST(PhotometryFlux, MaxCandelaAndBadGrids) {
    auto p =
        grid(PhotometricType::C, {0}, {0, 90}, [](double, double v) { return v == 0 ? 12.5 : 3; });
    EXPECT_EQ(p.max_candela(), 12.5);
    p.candela.pop_back();
    try {
        p.total_flux();
        FAIL() << "no error for a candela count that does not match the angles";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("1 candela values for 2 x 1 angles"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace rayset
