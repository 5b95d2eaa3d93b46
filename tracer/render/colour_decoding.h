// The linear values of a scene's colours under its assumed_gamma.
//
// Under `assumed_gamma 1` POV-Ray 3.7 reads colour numbers as linear, and so does the renderer.
// A scene written for another gamma (older scenes: 2.2 on PCs, 1.8 on Macs) holds colours
// encoded with it, and POV-Ray computes its lighting on the encoded numbers, which no physical
// reading can reproduce. Such scenes are rendered as POV-Ray's guide to migrating old scenes
// ports them: every colour decoded first (raised to the power G, or the sRGB curve for
// `assumed_gamma srgb`, the sign kept), the light transport then physical. A surface lit by one
// light keeps POV-Ray's look (a product of colours decodes to the product of the decoded
// ones); shading, falloff and interreflection are physical.
//
// Decoded: pigments (after their patterns and maps are evaluated), light colours, background
// and sky. Kept as written: filter and transmit, and the finish's amounts (diffuse,
// reflection, emission, ...), which are fractions rather than colours.
#pragma once

#include <cmath>

#include "core/colour.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

class ColourDecoding {
public:
    explicit ColourDecoding(const GlobalSettings& global)
        : srgb_(global.assumed_gamma_srgb), gamma_(global.assumed_gamma) {}

    bool linear() const { return !srgb_ && gamma_ == 1; }
    double operator()(double c) const {
        if (linear()) return c;
        const double a = std::abs(c);
        return std::copysign(srgb_ ? srgb_to_linear(a) : std::pow(a, gamma_), c);
    }
    Rgb operator()(Rgb c) const { return {(*this)(c.red), (*this)(c.green), (*this)(c.blue)}; }
    // The colour channels decoded, filter and transmit kept.
    Colour operator()(Colour c) const {
        const Rgb rgb = (*this)(c.rgb());
        c.red = rgb.red, c.green = rgb.green, c.blue = rgb.blue;
        return c;
    }

private:
    bool srgb_;
    double gamma_;
};

}  // namespace rayset::tracer
