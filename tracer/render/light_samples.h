// The small records of the light interface (light.h): the canonical numbers of a light sample,
// a light sample and a photon, for either transport (Q = Rgb or SampledSpectrum).
#pragma once

#include "tracer/render/spectrum.h"

namespace rayset::tracer {

// The canonical random numbers of one light sample, each in [0, 1): `select` picks the light and
// is handed to it rescaled to [0, 1) (a ray source reuses it for its flux cell); a light uses as
// many of `u` as it needs, in order (a rectangle or a sphere 2, a ray source 4, a point none).
struct LightUniforms {
    static constexpr int kCount = 4;
    double select = 0;
    double u[kCount] = {};
};

template <class Q>
struct LightLiSampleOf {
    Vec3 wi;                  // unit, from the reference point toward the light
    double distance = 0;      // to the light along wi (the shadow ray's length), scene units
    Q Li;                     // arriving radiance (a point light's intensity / d^2): divide by pdf
    double pdf = 0;           // solid-angle density including the choice of the light; that choice
                              // alone for a point light
    bool delta = false;       // a point light: no other strategy can find it, no MIS
    bool shadowless = false;  // POV-Ray's shadowless light: nothing blocks it, no shadow ray
    bool media_interaction = true;  // false: media do not scatter its light (POV-Ray's flag)
    int light = -1;                 // the light's index in its LightSet (set by the set)
    // `distance` reaches only the box around the light's body (a ray source whose box has
    // surfaces near it): the shadow ray goes on to the body's entry (Light::crossed), which
    // is worth finding only once the ray's first part is clear.
    bool body_entry_deferred = false;
};

// A ray that crossed a light's body, seen from its origin: the radiance it brings, the density
// light sampling has for its direction (solid angle, including the light's choice), and, when
// asked for, the density photon emission has for it (Light::pdf_Le), else 0.
template <class Q>
struct LightArrivalOf {
    Q radiance;
    double pdf_Li = 0, pdf_Le = 0;
};

template <class Q>
struct LightPhotonOf {
    Vec3 origin, direction;  // scene frame, direction unit
    Q flux;                  // W per channel (per nm when spectral), of this photon
    WavelengthsFor<Q> wavelengths;
    // Its light has no other estimate of its direct light (the naive ray set: no body, no
    // light sampling), so the photon counts from its first hit.
    bool counts_first_hit = false;
    int light = -1;  // the light's index in its LightSet (set by the set)
    // A ray source's occupied voxel the photon leaves from, whose balls answer most questions
    // about whether its line meets the body (-1: none).
    int64_t source_voxel = -1;
};

}  // namespace rayset::tracer
