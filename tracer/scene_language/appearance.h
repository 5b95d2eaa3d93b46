// The appearance of surfaces and volumes as POV-Ray describes it: pigments, normals, finishes,
// textures, interiors and media, with POV-Ray's defaults. Plain data for the renderer; the
// grammar that fills it is grammar_appearance.cpp.
#pragma once

#include <memory>
#include <vector>

#include "tracer/scene_language/transform.h"
#include "tracer/scene_language/values.h"

namespace rayset::tracer {

struct Rgb {
    double red = 0, green = 0, blue = 0;
};

// POV-Ray's five-component colour: filter and transmit are the fractions of light passing
// through, filtered by the colour or not.
struct Colour {
    double red = 0, green = 0, blue = 0, filter = 0, transmit = 0;
    Rgb rgb() const { return {red, green, blue}; }
};

struct Pigment {
    Colour colour;  // POV-Ray's default pigment is black
};

// POV-Ray 3.7 finish keywords with POV-Ray's defaults.
struct Finish {
    Rgb ambient{0.1, 0.1, 0.1};
    Rgb emission{0, 0, 0};
    double diffuse = 0.6;
    double brilliance = 1.0;
    double specular = 0;
    double roughness = 0.05;
    double phong = 0;
    double phong_size = 40;
    double metallic = 0;
    Rgb reflection_min{0, 0, 0};  // `reflection X` sets both; `reflection { min, max }` each
    Rgb reflection_max{0, 0, 0};
    bool reflection_fresnel = false;
    double reflection_falloff = 1;
    bool conserve_energy = false;
};

struct Texture {
    Pigment pigment;
    Finish finish;
};

struct Interior {
    double ior = 1.0;
};

// What an object's own modifiers say about its appearance (texture, pigment, normal, finish,
// interior, material ...), and, once the tree is flattened, what it ends up with: its own, else
// the nearest enclosing union's (inherit_appearance).
struct ObjectAppearance {
    TextureRef texture;    // null: none (POV-Ray renders such an object black)
    InteriorRef interior;  // null: none
};

// POV-Ray's `material { texture interior }`.
struct TextureAndInterior {
    TextureRef texture;
    InteriorRef interior;
};

}  // namespace rayset::tracer
