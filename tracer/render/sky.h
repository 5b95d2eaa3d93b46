// What rays that leave the scene see: the background colour, or POV-Ray's sky_sphere in front
// of it, as emitted radiance from every direction (an environment at infinite distance).
//
// The sky_sphere's pigments are evaluated at the ray's unit direction taken back through the
// sky's transform, as POV-Ray maps them onto a unit sphere about the origin; its layers are
// composed as POV-Ray composes layered pigments: each layer shows its colour times its opacity
// (1 - filter - transmit) and lets through filter x its colour + transmit of what lies below,
// the background at the bottom. Colours are radiance in W/(m^2 sr) per channel, as the
// background's are, decoded from the scene's assumed_gamma (colour_decoding.h); the sky's
// `emission` scales its layers.
#pragma once

#include <memory>
#include <vector>

#include "tracer/render/colour_decoding.h"
#include "tracer/render/rgb.h"
#include "tracer/render/rgb_upsampling.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

class Sky {
public:
    // Refuses (Error, "not supported: ...") a sky pigment whose colour is not known exactly in
    // every direction (noise, turbulence, images). `to_internal` converts W/(m^2 sr) to the
    // renderer's radiance unit (units.h).
    Sky(const SceneDescription& scene, double to_internal);

    // Radiance toward the scene from the unit direction `direction` points to.
    Rgb radiance(Vec3 direction) const;
    // The same in every direction: no sky_sphere, only the background colour.
    bool uniform() const { return !sky_; }
    bool black() const { return uniform() && is_black(background_); }
    // The uniform radiance as a spectrum (spectral transport refuses a sky_sphere).
    const IlluminantSpectrum& spectrum() const { return background_spectrum_; }

private:
    ColourDecoding decoding_;
    Rgb background_;
    IlluminantSpectrum background_spectrum_;
    std::shared_ptr<const SkySphere> sky_;
    Matrix4 world_to_sky_;
    double to_internal_ = 1;
};

}  // namespace rayset::tracer
