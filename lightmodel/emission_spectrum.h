// Emitted light as a spectrum, for a renderer that transports wavelengths
// (tracer/render/spectrum.h). A spectrum here is a shape: piecewise constant over 10 nm bins
// spanning 360-830 nm (the renderer's wavelength range, that of the tabulated CIE V(lambda)),
// normalised so that the integral of V(lambda) s(lambda) is 1. Multiplied by a luminance weight Y
// in the renderer's convention (683 lm/W x Y, colour.h), it gives the spectral quantity whose
// luminous value is exactly that of the RGB colour the same light has: a cell's spectrum is its
// binned spectrum (model.h, 10 nm from 380 nm); a cell without one takes the shape of CIE
// illuminant D65, the white point of linear sRGB, so grey light stays grey.
#pragma once

#include <array>

#include "lightmodel/model.h"

namespace rayset::lightmodel {

inline constexpr double kSpectrumFirstNm = 360, kSpectrumLastNm = 830;
inline constexpr double kSpectrumBinNm = 10;
inline constexpr int kSpectrumBins = 47;

// Mean of V(lambda) (photopic_efficiency, converters/colour/spectrum.h) over spectrum bin k (exact
// for its linear interpolation).
double photopic_bin_mean(int bin);
// CIE illuminant D65 (CIE 15, 10 nm table), relative, 100 at 560 nm; linear between entries.
double illuminant_d65(double wavelength_nm);

// A non-negative piecewise-constant function on the bins, with its normalised distribution for
// sampling wavelengths.
class BinnedSpectrum {
public:
    BinnedSpectrum() { value_.fill(0), cdf_.fill(0); }
    explicit BinnedSpectrum(const std::array<double, kSpectrumBins>& value);

    double operator()(double wavelength_nm) const;
    double value(int bin) const { return value_[size_t(bin)]; }
    double integral() const { return integral_; }  // of the value over nm
    bool is_zero() const { return !(integral_ > 0); }
    // A wavelength with density proportional to the value (call only when !is_zero()).
    double sample(double u) const;
    double pdf(double wavelength_nm) const;  // nm^-1
    // The same shape scaled so that the integral of V(lambda) times it is 1 (zero stays zero).
    BinnedSpectrum luminance_normalised() const;

    static int bin_of(double wavelength_nm);  // -1 outside the range

private:
    std::array<double, kSpectrumBins> value_;
    std::array<double, kSpectrumBins> cdf_;  // running integral at the end of each bin
    double integral_ = 0;
};

// The luminance-normalised shape of a binned spectrum of fractions (model.h: `fractions[b]`
// of the light in model bin b); D65 when the fractions are all zero (unknown wavelengths).
BinnedSpectrum emission_spectrum(const float* fractions, const SpectralBins& bins);
BinnedSpectrum d65_spectrum();  // luminance-normalised

// Each flux cell's luminance-normalised spectrum.
std::vector<BinnedSpectrum> cell_spectra(const LightModel& model);

// Wavelengths a spectral query asks about and the values it receives (of the emitter's
// quantity per nm, luminance-normalised as above times the light's luminance weight).
struct SpectralQuery {
    double nm[4] = {};
    double value[4] = {};
};

}  // namespace rayset::lightmodel
