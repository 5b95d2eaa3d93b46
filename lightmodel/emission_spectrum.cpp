// Emitted light as a spectrum (see emission_spectrum.h).
#include "lightmodel/emission_spectrum.h"

#include <algorithm>
#include <cmath>

#include "converters/colour/cie_tables.h"

namespace rayset::lightmodel {

namespace {

// CIE 15 standard illuminant D65 at 10 nm from 360 to 830 nm.
constexpr double kD65[48] = {
    46.6383, 52.0891, 49.9755, 54.6482, 82.7549, 91.486,  93.4318, 86.6823, 104.865, 117.008,
    117.812, 114.861, 115.923, 108.811, 109.354, 107.802, 104.79,  107.689, 104.405, 104.046,
    100.0,   96.3342, 95.788,  88.6856, 90.0062, 89.5991, 87.6987, 83.2886, 83.6992, 80.0268,
    80.2146, 82.2778, 78.2842, 69.7213, 71.6091, 74.349,  61.604,  69.8856, 75.087,  63.5927,
    46.4182, 66.8054, 63.3828, 64.304,  59.4519, 51.959,  57.4406, 60.3125};

double bin_start(int k) { return kSpectrumFirstNm + k * kSpectrumBinNm; }

}  // namespace

double photopic_bin_mean(int bin) {
    // Trapezoids over the 1 nm entries: the mean of the linear interpolation.
    const int first = int(bin_start(bin)) - kCiePhotopicFirst, steps = int(kSpectrumBinNm);
    double sum = 0.5 * (kCiePhotopic[first] + kCiePhotopic[first + steps]);
    for (int i = 1; i < steps; ++i) sum += kCiePhotopic[first + i];
    return sum / steps;
}

double illuminant_d65(double nm) {
    if (!(nm >= kSpectrumFirstNm && nm <= kSpectrumLastNm)) return 0;
    const double x = (nm - kSpectrumFirstNm) / 10;
    const int i = std::min(int(x), 46);
    const double t = x - i;
    return (1 - t) * kD65[i] + t * kD65[i + 1];
}

BinnedSpectrum::BinnedSpectrum(const std::array<double, kSpectrumBins>& value) : value_(value) {
    double running = 0;
    for (int k = 0; k < kSpectrumBins; ++k) {
        value_[size_t(k)] = std::max(0.0, value_[size_t(k)]);
        cdf_[size_t(k)] = running += value_[size_t(k)] * kSpectrumBinNm;
    }
    integral_ = running;
}

int BinnedSpectrum::bin_of(double nm) {
    if (!(nm >= kSpectrumFirstNm && nm < kSpectrumLastNm))
        return nm == kSpectrumLastNm ? kSpectrumBins - 1 : -1;
    return std::min(kSpectrumBins - 1, int((nm - kSpectrumFirstNm) / kSpectrumBinNm));
}

double BinnedSpectrum::operator()(double nm) const {
    const int k = bin_of(nm);
    return k < 0 ? 0 : value_[size_t(k)];
}

double BinnedSpectrum::pdf(double nm) const { return is_zero() ? 0 : (*this)(nm) / integral_; }

double BinnedSpectrum::sample(double u) const {
    const double target = u * integral_;
    int k = int(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin());
    while (k < kSpectrumBins - 1 && !(value_[size_t(k)] > 0)) ++k;  // never land in an empty bin
    k = std::min(k, kSpectrumBins - 1);
    const double before = k ? cdf_[size_t(k - 1)] : 0;
    const double t =
        value_[size_t(k)] > 0 ? (target - before) / (value_[size_t(k)] * kSpectrumBinNm) : 0.5;
    return bin_start(k) + std::clamp(t, 0.0, 1.0 - 1e-9) * kSpectrumBinNm;
}

BinnedSpectrum BinnedSpectrum::luminance_normalised() const {
    double luminance = 0;
    for (int k = 0; k < kSpectrumBins; ++k)
        luminance += value_[size_t(k)] * photopic_bin_mean(k) * kSpectrumBinNm;
    std::array<double, kSpectrumBins> v = value_;
    for (double& x : v) x = luminance > 0 ? x / luminance : 0;
    return BinnedSpectrum(v);
}

BinnedSpectrum d65_spectrum() {
    static const BinnedSpectrum d65 = [] {
        std::array<double, kSpectrumBins> v{};
        for (int k = 0; k < kSpectrumBins; ++k)
            v[size_t(k)] = 0.5 * (kD65[k] + kD65[k + 1]);  // bin mean
        return BinnedSpectrum(v).luminance_normalised();
    }();
    return d65;
}

BinnedSpectrum emission_spectrum(const float* fractions, const SpectralBins& bins) {
    std::array<double, kSpectrumBins> v{};
    double total = 0;
    for (int b = 0; fractions && b < bins.count; ++b) {
        const double f = fractions[b];
        if (!(f > 0)) continue;
        total += f;
        // Spread the model bin's fraction evenly over its width, onto the bins it overlaps.
        const double a = bins.first_nm + b * bins.width_nm, z = a + bins.width_nm;
        for (int k = 0; k < kSpectrumBins; ++k) {
            const double overlap =
                std::min(z, bin_start(k) + kSpectrumBinNm) - std::max(a, bin_start(k));
            if (overlap > 0) v[size_t(k)] += f / bins.width_nm * overlap / kSpectrumBinNm;
        }
    }
    if (!(total > 0)) return d65_spectrum();
    const BinnedSpectrum shape = BinnedSpectrum(v).luminance_normalised();
    return shape.is_zero() ? d65_spectrum() : shape;  // light V cannot see: the renderer's grey
}

std::vector<BinnedSpectrum> cell_spectra(const LightModel& model) {
    std::vector<BinnedSpectrum> spectra;
    spectra.reserve(model.flux_cells.size());
    for (size_t c = 0; c < model.flux_cells.size(); ++c)
        spectra.push_back(emission_spectrum(
            model.spectra.empty() ? nullptr : &model.spectra[c * size_t(model.bins.count)],
            model.bins));
    return spectra;
}

}  // namespace rayset::lightmodel
