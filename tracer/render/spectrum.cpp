// Sampled wavelengths and the film's spectral -> RGB conversion (see spectrum.h).
#include "tracer/render/spectrum.h"

#include "converters/colour/spectrum.h"
#include "lightmodel/colour.h"

namespace rayset::tracer {

namespace {

constexpr double kRange = kLambdaMax - kLambdaMin;

}  // namespace

SampledWavelengths SampledWavelengths::sample(const lightmodel::BinnedSpectrum& density, double u) {
    SampledWavelengths w;
    const double hero = density.sample(u);
    for (int i = 0; i < kWavelengths; ++i) {
        double nm = hero + i * kRange / kWavelengths;
        if (nm >= kLambdaMax) nm -= kRange;
        w.nm[i] = float(nm);
        w.pdf[i] = float(density.pdf(w.nm[i]));
    }
    return w;
}

SampledWavelengths SampledWavelengths::single(double nm) {
    SampledWavelengths w;
    std::fill(w.nm, w.nm + kWavelengths, float(nm));
    w.pdf[0] = 1;
    return w;
}

lightmodel::BinnedSpectrum film_wavelength_density(
    const std::array<double, lightmodel::kSpectrumBins>& light) {
    std::array<double, lightmodel::kSpectrumBins> density{};
    bool any = false;
    for (int k = 0; k < lightmodel::kSpectrumBins; ++k) {
        double film = 0;  // mean of x + y + z over the bin
        for (int i = 0; i < 10; ++i) {
            const CieXyz c =
                cie_xyz(kLambdaMin + (k + (i + 0.5) / 10) * lightmodel::kSpectrumBinNm);
            film += (c.x + c.y + c.z) / 10;
        }
        density[size_t(k)] = light[size_t(k)] * film;
        any = any || density[size_t(k)] > 0;
    }
    if (!any) density.fill(1);
    return lightmodel::BinnedSpectrum(density);
}

CieXyz cie_xyz(double nm) {
    const lightmodel::Xyz c = lightmodel::colour_matching(nm);
    const bool inside = nm >= kLambdaMin && nm <= kLambdaMax;
    return {inside ? std::max(0.0, c.x) : 0, photopic_efficiency(nm),
            inside ? std::max(0.0, c.z) : 0};
}

Rgb xyz_to_rgb(const CieXyz& c) { return lightmodel::to_linear_srgb(c); }

CieXyz rgb_to_xyz(const Rgb& c) { return lightmodel::to_xyz({c.red, c.green, c.blue}); }

Rgb to_rgb(const SampledSpectrum& value, const SampledWavelengths& w) {
    const double pdf_sum = w.pdf_sum();
    if (!(pdf_sum > 0)) return {};
    CieXyz sum;
    for (int i = 0; i < kWavelengths; ++i) {
        if (value.v[i] == 0) continue;
        const CieXyz c = cie_xyz(w.nm[i]);
        sum.x += c.x * value.v[i], sum.y += c.y * value.v[i], sum.z += c.z * value.v[i];
    }
    return xyz_to_rgb({sum.x / pdf_sum, sum.y / pdf_sum, sum.z / pdf_sum});
}

Rgb throughput_to_rgb(const SampledSpectrum& value, const SampledWavelengths& w) {
    CieXyz light, lit;
    for (int i = 0; i < kWavelengths; ++i) {
        if (!(w.pdf[i] > 0)) continue;
        const double d65 = lightmodel::illuminant_d65(w.nm[i]);
        const CieXyz c = cie_xyz(w.nm[i]);
        light.x += c.x * d65, light.y += c.y * d65, light.z += c.z * d65;
        lit.x += c.x * d65 * value.v[i], lit.y += c.y * d65 * value.v[i],
            lit.z += c.z * d65 * value.v[i];
    }
    // White (1, 1, 1) in XYZ, scaled coordinate by coordinate by the throughput's ratios.
    const CieXyz white = rgb_to_xyz({1, 1, 1});
    auto ratio = [](double a, double b) { return b > 0 ? a / b : 0; };
    return xyz_to_rgb({white.x * ratio(lit.x, light.x), white.y * ratio(lit.y, light.y),
                       white.z * ratio(lit.z, light.z)});
}

}  // namespace rayset::tracer
