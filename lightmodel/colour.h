// The colour of emitted light for a renderer whose channels are linear sRGB (ITU-R BT.709
// primaries, D65 white) and whose photometric convention is luminous = 683 lm/W x Y, with
// Y = 0.2126 R + 0.7152 G + 0.0722 B (tracer/render/rgb.h). A source's light is carried as
// that triple: its luminance Y is exact (from the model's luminous flux, which the build took
// from the tabulated CIE V(lambda)), its chromaticity comes from the binned spectrum through
// the CIE 1931 2-degree colour-matching functions in the analytic multi-lobe fit of Wyman,
// Sloan and Shirley ("Simple Analytic Approximations to the CIE XYZ Color Matching
// Functions", JCGT 2(2), 2013; within about 1% of the tables). Spectral colours lie outside
// the sRGB gamut: they are desaturated toward D65 at constant Y until no channel is negative,
// so the photometry stays right and only the saturation is lost.
#pragma once

#include "lightmodel/model.h"

namespace rayset::lightmodel {

// The efficacy that makes a grey triple (1, 1, 1) of 1 W carry 683 lm.
inline constexpr double kRgbLumensPerWatt = 683.0;

struct LinearRgb {
    double r = 0, g = 0, b = 0;
    LinearRgb& operator+=(const LinearRgb& o) { r += o.r, g += o.g, b += o.b; return *this; }
};
inline LinearRgb operator*(double s, const LinearRgb& c) { return {s * c.r, s * c.g, s * c.b}; }
inline double luminance(const LinearRgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

struct Xyz { double x = 0, y = 0, z = 0; };

// CIE 1931 x-bar, y-bar, z-bar at one wavelength (the analytic fit).
Xyz colour_matching(double wavelength_nm);
// Their mean over one spectral bin (1 nm steps).
Xyz bin_colour_matching(const SpectralBins& bins, int bin);

// Linear-sRGB triple of one unit of flux whose chromaticity is that of `xyz` (any scale; grey
// when it is zero) and whose luminous value is `efficacy` lm per unit: luminance(result) =
// efficacy / kRgbLumensPerWatt.
LinearRgb colour_per_flux(const Xyz& xyz, double efficacy);

// Per-unit-flux colour of each flux cell of a model: chromaticity of its spectrum, luminance
// from its luminous flux. Cells without a known spectrum are grey; without a known luminous
// flux they keep the renderer's convention (a watt is 683 lm, a lumen is a lumen).
std::vector<LinearRgb> cell_colours(const LightModel& model);

}  // namespace rayset::lightmodel
