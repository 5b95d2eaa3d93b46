// The colour of emitted light for a renderer whose channels are linear sRGB (ITU-R BT.709
// primaries, D65 white) and whose photometric convention is luminous = 683 lm/W x Y, with
// Y = 0.2126 R + 0.7152 G + 0.0722 B (srgb.h). A source's light is carried as
// that triple: its luminance Y is exact (from the model's luminous flux, which the build took
// from the tabulated CIE V(lambda)), its chromaticity comes from the binned spectrum through
// the CIE 1931 2-degree colour-matching functions in the analytic multi-lobe fit of Wyman,
// Sloan and Shirley ("Simple Analytic Approximations to the CIE XYZ Color Matching
// Functions", JCGT 2(2), 2013; within about 1% of the tables). Spectral colours lie outside
// the sRGB gamut: they are desaturated toward D65 at constant Y until no channel is negative,
// so the photometry stays right and only the saturation is lost.
#pragma once

#include "lightmodel/model.h"
#include "lightmodel/srgb.h"

namespace rayset::lightmodel {

// CIE 1931 x-bar, y-bar, z-bar at one wavelength (the analytic fit).
Xyz colour_matching(double wavelength_nm);
// Their mean over one spectral bin (1 nm steps).
Xyz bin_colour_matching(const SpectralBins& bins, int bin);

// Linear-sRGB triple of one unit of flux whose chromaticity is that of `xyz` (any scale; grey
// when it is zero) and whose luminous value is `efficacy` lm per unit: luminance(result) =
// efficacy / kRgbLumensPerWatt.
Rgb colour_per_flux(const Xyz& xyz, double efficacy);

// Per-unit-flux colour of each flux cell of a model: chromaticity of its spectrum, luminance
// from its luminous flux. Cells without a known spectrum are grey; without a known luminous
// flux they keep the renderer's convention (a watt is 683 lm, a lumen is a lumen).
std::vector<Rgb> cell_colours(const LightModel& model);

}  // namespace rayset::lightmodel
