// RGB reflectances (POV-Ray pigments, finish weights) as smooth spectra for spectral transport
// (spectrum.h): the sigmoid-of-a-quadratic space of Jakob and Hanika 2019 ("A low-dimensional
// function space for efficient spectral upsampling", CGF 38(2)),
//     rho(lambda) = S(c0 t^2 + c1 t + c2),  S(x) = 1/2 + x / (2 sqrt(1 + x^2)),
// t = (lambda - 360 nm) / 470 nm, which stays in (0, 1) by construction and is smooth. The
// three coefficients are fitted once per distinct colour (at scene load, cached) by
// Levenberg-Marquardt on the linear-sRGB colour the spectrum reflects under D65 (the space's
// white), continued from the colour's grey so that saturated colours converge. Greys (and
// black) are exact constants: a grey world renders as in RGB.
#pragma once

#include "tracer/render/rgb.h"
#include "tracer/render/spectrum.h"

namespace rayset::tracer {

class ReflectanceSpectrum {
public:
    ReflectanceSpectrum() = default;  // black
    static ReflectanceSpectrum constant(double value);
    static ReflectanceSpectrum sigmoid(double c0, double c1, double c2);

    double operator()(double nm) const;
    bool is_constant() const { return constant_ >= 0; }
    const double* coefficients() const { return c_; }

private:
    double c_[3] = {0, 0, 0};
    double constant_ = 0;  // >= 0: this value everywhere; < 0: the sigmoid
};

// The fitted spectrum of an RGB reflectance (channels clamped to [0, 1]); thread-safe, cached.
ReflectanceSpectrum upsample_reflectance(Rgb colour);
// The linear-sRGB colour a reflectance spectrum has under D65 (what the fit matches): each
// channel is the integral of its sRGB matching function x D65 x rho, normalised so that
// rho = 1 gives exactly (1, 1, 1).
Rgb reflected_colour(const ReflectanceSpectrum& spectrum);

// An RGB emission (a POV-Ray light's colour, an emitting surface, the background) as a
// spectrum, pbrt-v4's RGBIlluminantSpectrum: m x rho(lambda) x D65(lambda), with m the largest
// channel, rho the fitted reflectance of colour / m and D65 the renderer's grey light (the
// luminance-normalised D65 of lightmodel::d65_spectrum, which ray sources of unknown
// wavelengths also emit). A grey (c, c, c) thus has exactly luminance c, as in RGB mode; a
// coloured one has its colour's luminance up to the fit (reflected_colour).
class IlluminantSpectrum {
public:
    IlluminantSpectrum() = default;           // black
    explicit IlluminantSpectrum(Rgb colour);  // negative channels read as 0

    double operator()(double nm) const;

private:
    ReflectanceSpectrum shape_;
    double scale_ = 0;
};

// An emission in the quantity a path carries: the RGB triple, or its spectrum at the path's
// wavelengths.
inline Rgb emitted(const Rgb& colour, const IlluminantSpectrum&, NoWavelengths) { return colour; }
SampledSpectrum emitted(const Rgb& colour, const IlluminantSpectrum& spectrum,
                        const SampledWavelengths& wavelengths);

}  // namespace rayset::tracer
