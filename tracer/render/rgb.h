// Arithmetic on the RGB triples the renderer carries (radiance, throughput, albedo), and the
// photometric weights that turn a linear-sRGB radiometric triple into a luminous quantity.
#pragma once

#include <algorithm>

#include "lightmodel/srgb.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

inline Rgb operator+(Rgb a, Rgb b) { return {a.red + b.red, a.green + b.green, a.blue + b.blue}; }
inline Rgb operator-(Rgb a, Rgb b) { return {a.red - b.red, a.green - b.green, a.blue - b.blue}; }
inline Rgb operator*(Rgb a, Rgb b) { return {a.red * b.red, a.green * b.green, a.blue * b.blue}; }
inline Rgb operator*(double s, Rgb a) { return {s * a.red, s * a.green, s * a.blue}; }
inline Rgb& operator+=(Rgb& a, Rgb b) { return a = a + b; }
inline Rgb& operator*=(Rgb& a, Rgb b) { return a = a * b; }
inline double max_component(Rgb a) { return std::max({a.red, a.green, a.blue}); }
inline double average(Rgb a) { return (a.red + a.green + a.blue) / 3; }
inline bool is_black(Rgb a) { return a.red <= 0 && a.green <= 0 && a.blue <= 0; }

// The photometric convention of lightmodel/srgb.h: a radiometric triple R, G, B in W/... per
// channel has the luminous value 683 lm/W x (0.2126 R + 0.7152 G + 0.0722 B); this is what gives
// the channels photometric meaning (radiance -> cd/m^2, irradiance -> lx).
inline constexpr double kLumensPerWatt = lightmodel::kRgbLumensPerWatt;
inline double luminance_weight(Rgb a) { return lightmodel::luminance(a.red, a.green, a.blue); }
inline double photometric(Rgb a) { return kLumensPerWatt * luminance_weight(a); }

}  // namespace rayset::tracer
