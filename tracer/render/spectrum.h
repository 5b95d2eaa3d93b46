// Spectral transport (global_settings { spectral on } or raytrace --spectral): what the
// bidirectional integrator carries instead of an RGB triple. Hero-wavelength sampling (Wilkie,
// Nawaz, Droske, Weidlich and Hanika 2014, "Hero wavelength spectral sampling", CGF 33(4)):
// a path draws one wavelength from a density p over 360-830 nm and carries three more, the
// hero rotated by a quarter, a half and three quarters of the range. Its value at the four is
// a SampledSpectrum; the one-sample balance heuristic over the four rotations gives every
// wavelength the same estimator, value / sum of p over the four, which is what the film's
// conversion below divides by.
//
// Film: spectral value -> CIE XYZ with the CIE 1931 x-bar and z-bar of the analytic fit
// (lightmodel/colour.h) and the tabulated V(lambda) for Y (the table the models' luminous
// flux comes from), then -> linear sRGB by the inverse of the sRGB matrix whose Y row is the
// renderer's luminance weights (rgb.h): luminance stays exact, in the units of the RGB mode.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "core/random.h"
#include "lightmodel/emission_spectrum.h"
#include "tracer/render/rgb.h"

namespace rayset::tracer {

inline constexpr int kWavelengths = 4;
inline constexpr double kLambdaMin = lightmodel::kSpectrumFirstNm,
                        kLambdaMax = lightmodel::kSpectrumLastNm;

// Values at a path's four wavelengths.
struct SampledSpectrum {
    double v[kWavelengths] = {};
    SampledSpectrum() = default;
    explicit SampledSpectrum(double c) { std::fill(v, v + kWavelengths, c); }
    double operator[](int i) const { return v[i]; }
    double& operator[](int i) { return v[i]; }
};
inline SampledSpectrum operator+(SampledSpectrum a, const SampledSpectrum& b) {
    for (int i = 0; i < kWavelengths; ++i) a.v[i] += b.v[i];
    return a;
}
inline SampledSpectrum operator-(SampledSpectrum a, const SampledSpectrum& b) {
    for (int i = 0; i < kWavelengths; ++i) a.v[i] -= b.v[i];
    return a;
}
inline SampledSpectrum operator*(SampledSpectrum a, const SampledSpectrum& b) {
    for (int i = 0; i < kWavelengths; ++i) a.v[i] *= b.v[i];
    return a;
}
inline SampledSpectrum operator*(double s, SampledSpectrum a) {
    for (double& x : a.v) x *= s;
    return a;
}
inline SampledSpectrum& operator+=(SampledSpectrum& a, const SampledSpectrum& b) {
    return a = a + b;
}
inline SampledSpectrum& operator*=(SampledSpectrum& a, const SampledSpectrum& b) {
    return a = a * b;
}
inline double max_component(const SampledSpectrum& a) {
    return *std::max_element(a.v, a.v + kWavelengths);
}
inline bool is_black(const SampledSpectrum& a) {
    return std::all_of(a.v, a.v + kWavelengths, [](double x) { return x <= 0; });
}

template <class Q>
Q constant_value(double c);
template <>
inline Rgb constant_value<Rgb>(double c) {
    return {c, c, c};
}
template <>
inline SampledSpectrum constant_value<SampledSpectrum>(double c) {
    return SampledSpectrum(c);
}

// The four wavelengths of a path (floats: photons store them) and the hero density at each.
// A ray of one known wavelength (a delta, the naive ray set) has it first with density 1 and
// zero density elsewhere; its spectrum is zero at the other three.
struct SampledWavelengths {
    float nm[kWavelengths] = {};
    float pdf[kWavelengths] = {};

    // Hero drawn from `density` (a wavelength distribution over 360-830 nm) by u.
    static SampledWavelengths sample(const lightmodel::BinnedSpectrum& density, double u);
    static SampledWavelengths single(double nm);
    double pdf_sum() const { return double(pdf[0]) + pdf[1] + pdf[2] + pdf[3]; }
};

// A hero-wavelength density for paths carrying light of spectral shape `light` (per
// lightmodel bin, any scale): light x (x-bar + y-bar + z-bar), the film's weights; uniform
// where that is zero everywhere.
lightmodel::BinnedSpectrum film_wavelength_density(
    const std::array<double, lightmodel::kSpectrumBins>& light);

// RGB transport carries no wavelengths; overloads on this type keep one code path for both.
struct NoWavelengths {};

template <class Q>
struct WavelengthsOf;
template <>
struct WavelengthsOf<Rgb> {
    using type = NoWavelengths;
};
template <>
struct WavelengthsOf<SampledSpectrum> {
    using type = SampledWavelengths;
};
template <class Q>
using WavelengthsFor = typename WavelengthsOf<Q>::type;

// A path's wavelengths, hero drawn from `density`; RGB transport draws nothing.
template <class Q>
WavelengthsFor<Q> sample_wavelengths(const lightmodel::BinnedSpectrum& density, Pcg32& rng) {
    if constexpr (std::is_same_v<Q, SampledSpectrum>)
        return SampledWavelengths::sample(density, rng.uniform());
    else
        return {};
}

// A radiometric quantity (radiance, irradiance, flux) at a path's wavelengths -> linear sRGB,
// the path's estimate of the spectral integrals (see the top of this file).
inline Rgb to_rgb(const Rgb& value, NoWavelengths) { return value; }
Rgb to_rgb(const SampledSpectrum& value, const SampledWavelengths& wavelengths);

// A throughput (a dimensionless factor such as a mirror's reflectance along a path) -> the
// linear-sRGB factor it applies to D65 white light: XYZ of throughput x D65 over XYZ of D65
// from the same four wavelengths, per coordinate (a ratio, so a constant throughput c gives
// exactly (c, c, c)). Used where a camera path's throughput meets light carried at other
// wavelengths (the photons of a density estimate).
inline Rgb throughput_to_rgb(const Rgb& value, NoWavelengths) { return value; }
Rgb throughput_to_rgb(const SampledSpectrum& value, const SampledWavelengths& wavelengths);

// CIE 1931 colour matching at one wavelength: x-bar, V(lambda), z-bar (see above).
using CieXyz = lightmodel::Xyz;
CieXyz cie_xyz(double nm);
// XYZ (Y in the renderer's luminance weight) -> linear sRGB, and back.
Rgb xyz_to_rgb(const CieXyz& xyz);
CieXyz rgb_to_xyz(const Rgb& rgb);

}  // namespace rayset::tracer
