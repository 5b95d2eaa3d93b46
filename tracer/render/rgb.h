// The photometric weights that turn the renderer's linear-sRGB radiometric triples (radiance,
// irradiance; core/colour.h) into luminous quantities.
#pragma once

#include "lightmodel/srgb.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

// The photometric convention of lightmodel/srgb.h: a radiometric triple R, G, B in W/... per
// channel has the luminous value 683 lm/W x (0.2126 R + 0.7152 G + 0.0722 B); this is what gives
// the channels photometric meaning (radiance -> cd/m^2, irradiance -> lx).
inline constexpr double kLumensPerWatt = lightmodel::kRgbLumensPerWatt;
inline double luminance_weight(Rgb a) { return lightmodel::luminance(a.red, a.green, a.blue); }
inline double photometric(Rgb a) { return kLumensPerWatt * luminance_weight(a); }

}  // namespace rayset::tracer
