// The RGB triple every part of the project carries: linear-sRGB radiometric channels
// (radiance, flux, throughput, reflectance); the photometric convention that gives them a
// luminous value is lightmodel/srgb.h's.
#pragma once

#include <algorithm>
#include <cmath>

namespace rayset {

struct Rgb {
    double red = 0, green = 0, blue = 0;
};

inline Rgb operator+(Rgb a, Rgb b) { return {a.red + b.red, a.green + b.green, a.blue + b.blue}; }
inline Rgb operator-(Rgb a, Rgb b) { return {a.red - b.red, a.green - b.green, a.blue - b.blue}; }
inline Rgb operator*(Rgb a, Rgb b) { return {a.red * b.red, a.green * b.green, a.blue * b.blue}; }
inline Rgb operator*(double s, Rgb a) { return {s * a.red, s * a.green, s * a.blue}; }
inline Rgb& operator+=(Rgb& a, Rgb b) { return a = a + b; }
inline Rgb& operator*=(Rgb& a, Rgb b) { return a = a * b; }
inline double max_component(Rgb a) { return std::max({a.red, a.green, a.blue}); }
inline double average(Rgb a) { return (a.red + a.green + a.blue) / 3; }
inline bool is_black(Rgb a) { return a.red <= 0 && a.green <= 0 && a.blue <= 0; }

// The sRGB transfer curve decoded: an encoded channel value to its linear value.
inline double srgb_to_linear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace rayset
