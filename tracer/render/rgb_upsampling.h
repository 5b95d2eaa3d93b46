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

}  // namespace rayset::tracer
