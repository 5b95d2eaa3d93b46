// Irradiance at a virtual receiver (an illuminance_receiver's cell centre, not part of the
// scene), the one estimate behind both integrators' receivers: pi times the radiance a white
// Lambertian surface at the point would reflect, from one light sample and one BSDF (cosine)
// sample weighted against each other by MIS. The integrators differ only in the lights the two
// strategies see (the path tracer's LightSet and paths, the ray sources' bodies), so those
// come in as callables.
#pragma once

#include "core/random.h"
#include "tracer/render/integrator.h"
#include "tracer/render/material.h"
#include "tracer/render/spectrum.h"

namespace rayset::tracer {

// Q: what the estimate carries (Rgb or SampledSpectrum), with wavelengths drawn from
// `wavelength_density` (spectral only). The callables return Q, or both LightComponentsOf<Q>
// (integrator.h) for an estimate split into components (returned as linear sRGB the same way):
//   sample_light(bsdf, wavelengths)      the light sample: f |cos| Li / pdf x its MIS weight;
//   follow_bsdf_sample(s, wavelengths)   what the ray along the BSDF sample s brings, times
//                                        s.weight, each light it meets weighted against
//                                        light sampling.
// Random numbers: the wavelength (the stream), sample_light's, then the lobe (one value) and
// direction (a pair), then follow_bsdf_sample's.
template <class Q, class SampleLight, class FollowBsdfSample>
auto white_lambertian_irradiance(Vec3 normal, const lightmodel::BinnedSpectrum& wavelength_density,
                                 Sampler& sampler, SampleLight&& sample_light,
                                 FollowBsdfSample&& follow_bsdf_sample) {
    const WavelengthsFor<Q> wavelengths = sample_wavelengths<Q>(wavelength_density, sampler.rng());
    const BsdfOf<Q> bsdf(white_lambertian(), normal, normal, normal, wavelengths);
    auto reflected = sample_light(bsdf, wavelengths);
    BsdfSampleOf<Q> s;
    const double u_lobe = sampler.get_1d();
    double u1, u2;
    sampler.get_2d(u1, u2);
    if (bsdf.sample(u_lobe, u1, u2, s) && !is_black(s.weight))
        reflected += follow_bsdf_sample(s, wavelengths);
    return kPi * to_rgb(reflected, wavelengths);
}

}  // namespace rayset::tracer
