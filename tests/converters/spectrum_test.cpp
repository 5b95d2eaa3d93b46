#include "converters/colour/spectrum.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rayset {
namespace {

constexpr double kKm = kMaxLuminousEfficacy;
// CIE 1924 tabulated values at 5 nm knots (CIE 018), an independent check of the transcription.
constexpr double kV450 = 0.038, kV500 = 0.323, kV510 = 0.503, kV600 = 0.631, kV650 = 0.107;
// The 1 nm table's value at 556 nm.
constexpr double kV556 = 0.9998567;

TEST(Photopic, PeaksAtOneAt555nm) {
    EXPECT_EQ(photopic_efficiency(555), 1.0);
    double max = 0, argmax = 0;
    for (int i = 0; i <= 4700; ++i) {
        double w = 360 + 0.1 * i;
        if (photopic_efficiency(w) > max) max = photopic_efficiency(w), argmax = w;
    }
    EXPECT_EQ(max, 1.0);
    EXPECT_NEAR(argmax, 555, 1e-9);
}

TEST(Photopic, MatchesCieFiveNanometreValuesAndInterpolatesLinearly) {
    EXPECT_DOUBLE_EQ(photopic_efficiency(450), kV450);
    EXPECT_DOUBLE_EQ(photopic_efficiency(500), kV500);
    EXPECT_DOUBLE_EQ(photopic_efficiency(510), kV510);
    EXPECT_DOUBLE_EQ(photopic_efficiency(600), kV600);
    EXPECT_DOUBLE_EQ(photopic_efficiency(650), kV650);
    EXPECT_DOUBLE_EQ(photopic_efficiency(555.25), 0.75 + 0.25 * kV556);
    EXPECT_EQ(photopic_efficiency(359.9), 0);
    EXPECT_EQ(photopic_efficiency(830.1), 0);
    EXPECT_TRUE(std::isnan(photopic_efficiency(std::nan(""))));
}

// The integral of the 1 nm CIE table is 106.856 nm (a figure quoted to the nm/1000, so it may
// differ from the table's own sum by up to one unit of that digit).
TEST(Photopic, IntegralIs106point856nm) {
    double trapezoid = 0;  // 0.1 nm steps include V's knots: exact for the piecewise-linear V
    for (int i = 0; i < 4700; ++i) {
        double a = 360 + 0.1 * i, b = 360 + 0.1 * (i + 1);
        trapezoid += 0.1 * (photopic_efficiency(a) + photopic_efficiency(b)) / 2;
    }
    EXPECT_NEAR(trapezoid, 106.856, 1e-3);
    // A flat spectrum over the table's range has efficacy Km x (integral of V) / 470 nm.
    SpectralTable flat{{360, 830}, {1, 1}};
    EXPECT_NEAR(luminous_efficacy(flat) * 470 / kKm, trapezoid, 1e-9);
}

TEST(LuminousEfficacy, IntegratesTheProductOfTwoLinearFunctionsExactly) {
    // Ramp from 0 to 1 over 555..556 nm, where V runs linearly from 1 to kV556:
    // integral of x (1 + (kV556 - 1) x) dx over [0, 1] is 1/2 + (kV556 - 1)/3, power 1/2.
    SpectralTable ramp{{555, 556}, {0, 1}};
    EXPECT_NEAR(luminous_efficacy(ramp), kKm * (1 + 2 * (kV556 - 1) / 3), 1e-9);
    // Scaling the weights changes nothing.
    SpectralTable ramp3{{555, 556}, {0, 3}};
    EXPECT_NEAR(luminous_efficacy(ramp3), luminous_efficacy(ramp), 1e-12);
    // A box 500..510 nm spanning ten 1 nm pieces: the mean of V over it, i.e. the trapezoid
    // sum of the knots, each of which photopic_efficiency returns.
    double sum = 0;
    for (int w = 500; w < 510; ++w)
        sum += (photopic_efficiency(w) + photopic_efficiency(w + 1)) / 2;
    SpectralTable box{{500, 505, 510}, {2, 2, 2}};
    EXPECT_NEAR(luminous_efficacy(box), kKm * sum / 10, 1e-9);
}

TEST(LuminousEfficacy, SinglePointIsASpectralLineAndDegenerateTablesAreUnknown) {
    EXPECT_DOUBLE_EQ(luminous_efficacy(SpectralTable{{500}, {7}}), kKm * kV500);
    EXPECT_TRUE(std::isnan(luminous_efficacy(SpectralTable{})));
    EXPECT_TRUE(std::isnan(luminous_efficacy(SpectralTable{{500, 510}, {0, 0}})));
    EXPECT_TRUE(std::isnan(luminous_efficacy(SpectralTable{{510, 500}, {1, 1}})));
    // Entirely outside V's range: efficacy 0, not unknown.
    EXPECT_EQ(luminous_efficacy(SpectralTable{{900, 1000}, {1, 1}}), 0);
}

Ray make_ray(float radiant, float luminous, float wavelength = kUnknown, int32_t spectrum = -1) {
    Ray r;
    r.direction = {0, 0, 1};
    r.radiant = radiant, r.luminous = luminous, r.wavelength = wavelength, r.spectrum = spectrum;
    return r;
}

TEST(PhotometricWeights, NoSpectrumLuminousColumnOnly) {
    RayHeader h;
    h.has_luminous = true;
    PhotometricWeights w(h);
    EXPECT_TRUE(w.luminous_known());
    EXPECT_FALSE(w.radiant_known());
    Ray r = make_ray(kUnknown, 2.5f);
    EXPECT_EQ(w.luminous(r), 2.5);
    EXPECT_TRUE(std::isnan(w.radiant(r)));
    EXPECT_TRUE(std::isnan(w.efficacy(r)));
}

TEST(PhotometricWeights, NoSpectrumRadiantOnlyLeavesLuminousUnknown) {
    RayHeader h;
    h.has_radiant = true;
    PhotometricWeights w(h);
    EXPECT_FALSE(w.luminous_known());
    EXPECT_TRUE(w.radiant_known());
    Ray r = make_ray(0.5f, kUnknown);
    EXPECT_EQ(w.radiant(r), 0.5);
    EXPECT_TRUE(std::isnan(w.luminous(r)));
}

TEST(PhotometricWeights, NoSpectrumBothColumnsAreTakenAsTheyAre) {
    RayHeader h;
    h.has_radiant = h.has_luminous = true;
    PhotometricWeights w(h);
    Ray r = make_ray(0.25f, 40.0f);
    EXPECT_EQ(w.radiant(r), 0.25);
    EXPECT_EQ(w.luminous(r), 40.0);
}

TEST(PhotometricWeights, SingleWavelength) {
    RayHeader h;
    h.has_radiant = true;
    h.spectral = SpectralKind::single_wavelength;
    h.single_wavelength = 600;
    PhotometricWeights w(h);
    EXPECT_TRUE(w.luminous_known());
    Ray r = make_ray(2.0f, kUnknown);
    EXPECT_DOUBLE_EQ(w.efficacy(r), kKm * kV600);
    EXPECT_DOUBLE_EQ(w.luminous(r), 2 * kKm * kV600);

    // Luminous column only: the radiant flux follows from the efficacy.
    RayHeader l = h;
    l.has_radiant = false, l.has_luminous = true;
    l.single_wavelength = 555;
    PhotometricWeights wl(l);
    EXPECT_TRUE(wl.radiant_known());
    // 1366.004 lm as a float is off by 3e-5 lm at most: 2.2e-8 relative.
    EXPECT_NEAR(wl.radiant(make_ray(kUnknown, 1366.004f)), 2.0, 1e-7);

    // Infrared: no light, and its power cannot be told from its (zero) luminous flux.
    l.single_wavelength = 900;
    PhotometricWeights ir(l);
    EXPECT_TRUE(std::isnan(ir.radiant(make_ray(kUnknown, 0))));
}

TEST(PhotometricWeights, PerRayWavelengthWithUnknownWavelengths) {
    RayHeader h;
    h.has_radiant = true;
    h.spectral = SpectralKind::per_ray_wavelength;
    PhotometricWeights w(h);
    EXPECT_DOUBLE_EQ(w.luminous(make_ray(1.0f, kUnknown, 555)), kKm);
    EXPECT_DOUBLE_EQ(w.luminous(make_ray(2.0f, kUnknown, 500)), 2 * kKm * kV500);
    EXPECT_TRUE(std::isnan(w.luminous(make_ray(1.0f, kUnknown, kUnknown))));
    EXPECT_TRUE(std::isnan(w.efficacy(make_ray(1.0f, kUnknown, kUnknown))));
}

TEST(PhotometricWeights, SharedTable) {
    RayHeader h;
    h.has_radiant = true;
    h.spectral = SpectralKind::shared_table;
    h.spectral_tables = {SpectralTable{{555, 556}, {1, 1}}};
    PhotometricWeights w(h);
    const double e = kKm * (1 + kV556) / 2;  // mean of linear V over the box
    EXPECT_NEAR(w.efficacy(make_ray(1, kUnknown)), e, 1e-9);
    EXPECT_NEAR(w.luminous(make_ray(3, kUnknown)), 3 * e, 1e-9);
}

TEST(PhotometricWeights, PerRayTable) {
    RayHeader h;
    h.has_radiant = true;
    h.spectral = SpectralKind::per_ray_table;
    h.spectral_tables = {SpectralTable{{500}, {1}}, SpectralTable{{650}, {1}}};
    PhotometricWeights w(h);
    EXPECT_DOUBLE_EQ(w.luminous(make_ray(1, kUnknown, kUnknown, 0)), kKm * kV500);
    EXPECT_DOUBLE_EQ(w.luminous(make_ray(4, kUnknown, kUnknown, 1)), 4 * kKm * kV650);
    EXPECT_TRUE(std::isnan(w.luminous(make_ray(1, kUnknown, kUnknown, 2))));
    EXPECT_TRUE(std::isnan(w.luminous(make_ray(1, kUnknown, kUnknown, -1))));
}

}  // namespace
}  // namespace rayset
