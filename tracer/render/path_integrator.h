// The reference integrator: unidirectional path tracing with next-event estimation to every
// light (light.h: POV-Ray lights and ray-file sources), multiple importance sampling (power
// heuristic) between light sampling and BSDF sampling for lights with a body, and Russian
// roulette. Emitting surfaces and the background are collected where paths meet them.
// Radiance and irradiance in renderer units (units.h), split into the light components of
// integrator.h as the bidirectional integrator splits them, so that both agree on every
// layer's mean: a light's body met through specular (delta) bounces only is direct
// visibility; met on the segment right after the path's first smooth scattering, primary; met
// after any scattering beyond, secondary. A light sample at a vertex that specular bounces
// alone led to is primary (a vertex with a smooth lobe, whichever lobe the path then takes, or
// a scattering in a medium), secondary beyond.
//
// Q: what paths carry, Rgb or SampledSpectrum (spectral transport, spectrum.h). Spectral paths
// draw their own hero wavelength in proportion to the lights' spectra times (x-bar + y-bar +
// z-bar), the film's weights (D65 for POV-Ray lights), and see POV-Ray lights, emitting
// surfaces and the background as illuminant spectra (rgb_upsampling.h: IlluminantSpectrum).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/random.h"
#include "tracer/render/direct_light.h"
#include "tracer/render/integrator.h"
#include "tracer/render/light.h"
#include "tracer/render/render_scene.h"

namespace rayset::tracer {

template <class Q>
class PathIntegratorOf {
public:
    using Wavelengths = WavelengthsFor<Q>;

    // `lights`: the lights it samples and meets (kept by reference).
    PathIntegratorOf(const RenderScene& scene, const LightSet& lights);

    // Radiance arriving along a camera ray (origin, unit direction), linear sRGB whatever the
    // transport; `rays` counts every ray cast. Light and BSDF samples take pairs of `sampler`,
    // everything else its stream.
    LightComponentsOf<Rgb> radiance(Vec3 origin, Vec3 direction, Sampler& sampler,
                                    uint64_t& rays) const;
    // Irradiance at `point` on a virtual receiver of unit `normal` (not part of the scene),
    // from the half-space the normal points into: pi times the radiance a white Lambertian
    // surface there would reflect, estimated with the same path tracer. The receiver point is
    // the first smooth scattering.
    LightComponentsOf<Rgb> irradiance(Vec3 point, Vec3 normal, Sampler& sampler,
                                      uint64_t& rays) const;

    // Bounces before Russian roulette starts. Earlier is cheaper per path but noisier: in a
    // closed room of albedo 0.6 (tests/bench/grey_box.sh), starting at 3 kills two paths in
    // three at their third vertex and needs 1.5 times the time of starting at 5 for the same
    // error.
    static constexpr int kRouletteDepth = 5;

private:
    struct PathState {
        Vec3 origin, direction;
        RayKind kind = RayKind::camera;
        Q beta = constant_value<Q>(1);
        double bsdf_pdf = -1;  // pdf of the sampled direction; < 0: no light sampling competes
        int depth = 0;
        // The component a light's body met on the coming segment belongs to.
        LightComponent segment_layer = kDirectVisibility;
        int medium = -1;  // the object whose interior the path is in, if known (interior_media.h)
    };
    // Follows the path from `state` (advanced in place: a by-value copy of this struct cost
    // more than some of the arithmetic per bounce).
    LightComponentsOf<Q> trace(PathState& state, const Wavelengths& wavelengths, Sampler& sampler,
                               uint64_t& rays) const;
    // Along the segment the path just cast (to `hit`, if `found`): fog's light and dimming
    // (RGB transport), and the light of the bodies it crosses, into `sum`.
    void add_segment_light(PathState& state, bool found, const SurfaceHit& hit,
                           const Wavelengths& wavelengths, uint64_t& rays,
                           LightComponentsOf<Q>& sum) const;
    // Across a segment of `length` in the medium of object `medium` (RGB transport): adds its
    // emission to `sum`, draws a free flight and scales the throughput by it. If the medium
    // scatters the path there, adds the light sampled at that point, turns the path by the
    // phase function and returns true.
    bool cross_medium(PathState& state, int medium, double length, Pcg32& rng, uint64_t& rays,
                      LightComponentsOf<Rgb>& sum) const;
    // Russian roulette from kRouletteDepth on: whether the path goes on.
    static bool goes_on(PathState& s, Pcg32& rng) {
        return s.depth + 1 < kRouletteDepth || survives_roulette(s.beta, rng);
    }
    const RenderScene& scene_;
    const LightSet& lights_;
    lightmodel::BinnedSpectrum wavelength_density_;  // spectral only
};
using PathIntegrator = PathIntegratorOf<Rgb>;

// The path tracer as the renderer's integrator over every light of the scene: one radiance
// sample per camera ray, one irradiance sample per receiver sample, split into the light
// layers; RGB or spectral transport. Throws rayset::Error for the naive ray set (no body, no light
// sampling: only photons can carry its light).
std::unique_ptr<Integrator> make_path_integrator(const RenderScene& scene,
                                                 const RenderSettings& settings,
                                                 const RenderResult& start);

}  // namespace rayset::tracer
