// Linear sRGB (IEC 61966-2-1: ITU-R BT.709 primaries, D65 white) and the photometric convention
// every RGB value of the project follows: a radiometric triple R, G, B (W/... per channel) has
// the luminous value 683 lm/W x Y, with Y the middle row of the sRGB -> XYZ matrix
// (0.2126 R + 0.7152 G + 0.0722 B). The light model's colours (colour.h) and the renderer's
// channels (tracer/render/rgb.h, spectrum.h) both take these numbers from here.
#pragma once

#include "core/colour.h"

namespace rayset::lightmodel {

// The efficacy that makes a grey triple (1, 1, 1) of 1 W carry 683 lm.
inline constexpr double kRgbLumensPerWatt = 683.0;
// Linear sRGB -> CIE XYZ (the standard's four-digit matrix); row 1 is the luminance weights.
inline constexpr double kSrgbToXyz[3][3] = {
    {0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};

inline double luminance(double r, double g, double b) {
    return kSrgbToXyz[1][0] * r + kSrgbToXyz[1][1] * g + kSrgbToXyz[1][2] * b;
}
inline double luminance(const Rgb& c) { return luminance(c.red, c.green, c.blue); }

struct Xyz {
    double x = 0, y = 0, z = 0;
};

Xyz to_xyz(const Rgb& c);
// The exact inverse of kSrgbToXyz: to_linear_srgb(to_xyz(c)) == c up to rounding.
Rgb to_linear_srgb(const Xyz& c);

}  // namespace rayset::lightmodel
