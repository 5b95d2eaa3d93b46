// The paper's bidirectional integrator (its eqs. 1-5) over every light of the scene (light.h:
// ray sources and POV-Ray lights alike):
//   camera pass  - camera rays through specular chains (mirror, glass); a ray that meets a
//                  light's body adds its radiance (direct visibility, eq. 2); at the first
//                  vertex with a smooth lobe the primary light is estimated by light sampling
//                  (eq. 3) and BSDF sampling (eq. 4) with the power heuristic, and a visible
//                  point is kept for the photon pass;
//   photon pass  - photons from every light (sample_Le), Russian roulette; a photon is
//                  stored only after at least one scattering (eq. 5: secondary light), so
//                  the direct light the camera pass computed is not counted twice.
// The naive ray set has no body and cannot be light sampled: its photons are stored from
// the first hit as well and make its primary light.
// Radiance and irradiance in renderer units (units.h); light bodies are not geometry: light
// passes through them, and a ray adds every body it meets before the first surface.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/random.h"
#include "tracer/render/direct_light.h"
#include "tracer/render/integrator.h"
#include "tracer/render/light.h"
#include "tracer/render/photon_grid.h"
#include "tracer/render/render_scene.h"

namespace rayset::tracer {

// A surface point where a camera path met its first smooth lobe, with the path throughput
// (and, when spectral, the path's wavelengths).
template <class Q>
struct VisiblePointOf : PhotonWavelengths<Q> {
    Vec3 point, normal, shading_normal, wo;
    int object = -1, part = -1;  // as SurfaceHit's
    Q beta;
    uint32_t pixel = 0;
};
using VisiblePoint = VisiblePointOf<Rgb>;

// A camera sample's light, linear sRGB whatever the transport (spectrum.h's film conversion).
struct CameraSample {
    Rgb direct_visibility, primary;
};

// Q: what paths carry, Rgb (the default) or SampledSpectrum (spectral transport, spectrum.h).
// Spectral camera paths draw their hero wavelength from the lights' spectrum times the colour
// matching functions (camera paths carry only that light); photons from their own light's
// spectrum.
template <class Q>
class BidirectionalIntegratorOf {
public:
    using Wavelengths = WavelengthsFor<Q>;
    using Point = VisiblePointOf<Q>;
    using Photon = PhotonOf<Q>;
    using Grid = PhotonGridOf<Photon>;

    // `lights` kept by reference.
    BidirectionalIntegratorOf(const RenderScene& scene, const LightSet& lights);

    // Camera pass of one camera ray; visible points are appended to `visible` with `pixel`.
    // Light and BSDF samples take pairs of `sampler`, everything else its stream.
    CameraSample camera_path(Vec3 origin, Vec3 direction, uint32_t pixel, Sampler& sampler,
                             uint64_t& rays, std::vector<Point>& visible) const;
    // Primary irradiance of the lights at a virtual receiver point (pi x the radiance a white
    // Lambertian surface there would reflect), from the side `normal` points into.
    Rgb receiver_primary(Vec3 point, Vec3 normal, Sampler& sampler, uint64_t& rays) const;

    // Photons [first, first + count) of a pass of `emitted` photons; each photon i draws from
    // stream i of `seed`, so the result does not depend on how the range is split.
    std::vector<Photon> trace_photons(uint64_t first, uint64_t count, uint64_t emitted,
                                      uint64_t seed, uint64_t& rays) const;

    // Radiance the photons near a visible point reflect toward its wo (density estimation over
    // a disk of the grid's radius), split into photons that came straight from a light and
    // those that scattered before.
    // Spectral: each photon's light is reflected at its own wavelengths and made RGB there; the
    // camera-side throughput (through mirrors, glass) is made RGB by the camera path's own
    // wavelengths (throughput_to_rgb) and applied to that: exact for grey specular chains.
    void gather(const Point& vp, const Grid& grid, Rgb& direct, Rgb& scattered) const;
    // Irradiance at a receiver point from photons that landed on a surface there facing the
    // same way, split the same way.
    void gather_irradiance(Vec3 point, Vec3 normal, const Grid& grid, Rgb& direct,
                           Rgb& scattered) const;

    static constexpr int kRouletteDepth = 3;

private:
    // Radiance of every body a BSDF-sampled ray meets before the first surface, each weighted
    // against light sampling of its light.
    Q bodies_crossed(Vec3 origin, Vec3 direction, double bsdf_pdf, const Wavelengths& wavelengths,
                     uint64_t& rays) const;
    // Scales `beta` by the transmittance of the interior (fade, absorbing media;
    // interior_media.h) a segment from `origin` along `direction` that started in medium
    // `start` and ended at `hit` (if `found`) lay in; returns that medium.
    // The light sample of a visible point at `hit`, reached along `direction` through
    // `medium`, its shadow ray dimmed by the medium it starts in.
    Q primary_light(const BsdfOf<Q>& bsdf, const SurfaceHit& hit, int medium, Vec3 direction,
                    const Wavelengths& wavelengths, Sampler& sampler, uint64_t& rays) const;
    int attenuate_inside(Q& beta, int start, Vec3 origin, Vec3 direction, bool found,
                         const SurfaceHit& hit, Pcg32& rng) const;

    const RenderScene& scene_;
    const LightSet& lights_;
    lightmodel::BinnedSpectrum camera_wavelength_density_;  // spectral only
};
using BidirectionalIntegrator = BidirectionalIntegratorOf<Rgb>;

// The bidirectional integrator as the renderer's integrator (bidirectional_passes.cpp): its
// camera pass, then a photon pass and density estimation at the pass's visible points, the
// gather radius shrinking from pass to pass; emitting surfaces and the background (not lights:
// found only where paths meet them) by the path tracer alongside. RGB or spectral transport.
std::unique_ptr<Integrator> make_bidirectional_integrator(const RenderScene& scene,
                                                          const RenderSettings& settings,
                                                          const RenderResult& start);

}  // namespace rayset::tracer
