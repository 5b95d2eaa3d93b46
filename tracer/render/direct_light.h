// Next-event estimation at a surface point, as both integrators do it: one sample of the scene's
// lights (LightSet: choice by power, then the light's own sampling), weighted by the power
// heuristic against BSDF sampling for lights with a body, and the shadow ray that decides it.
//
// In two halves, so that a bounce loop can sample the BSDF in between and the two chains of
// square roots and divisions overlap instead of waiting on each other.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>

#include "core/random.h"
#include "tracer/render/light.h"
#include "tracer/render/material.h"
#include "tracer/render/render_scene.h"
#include "tracer/render/sampler.h"
#include "tracer/render/sampling.h"

namespace rayset::tracer {

// A light sample's shadow ray and what it brings, f |cos| Li / pdf times its MIS weight, if
// nothing blocks it.
template <class Q>
struct ShadowRayOf {
    bool cast = false;        // false: the sample brings nothing, no shadow ray
    bool shadowless = false;  // brings it whatever lies between (POV-Ray's shadowless light)
    Vec3 origin, direction;
    double t_far = 0;
    Q contribution{};
    // The light whose body's entry, beyond t_far, ends the ray (LightLiSampleOf's
    // body_entry_deferred); null when t_far is the whole ray.
    const Light* body_beyond = nullptr;
};

// Where a ray that reaches `t_far` (the box around `light`'s body) ends: at the body's entry
// less `epsilon`. A ray that grazes the body, met from the shaded point but not from the ray's
// origin, ends at t_far.
inline double to_body_entry(const Light& light, Vec3 origin, Vec3 direction, double t_far,
                            double epsilon) {
    double t = 0;
    if (light.crossed(origin, direction, std::numeric_limits<double>::infinity(), t))
        return std::max(t_far, t - epsilon);
    return t_far;
}

// The whole of a shadow ray whose end waits for its light's body: t_far at the body's entry.
template <class Q>
ShadowRayOf<Q> whole_ray(const RenderScene& scene, ShadowRayOf<Q> shadow) {
    if (!shadow.body_beyond) return shadow;
    shadow.t_far = to_body_entry(*shadow.body_beyond, shadow.origin, shadow.direction, shadow.t_far,
                                 scene.epsilon());
    shadow.body_beyond = nullptr;
    return shadow;
}

// The shadow ray of light sample `light` of `lights` taken at `point`, offset along `normal`;
// nothing of what it brings.
template <class Q>
ShadowRayOf<Q> shadow_ray_of(const RenderScene& scene, const LightSet& lights,
                             const LightLiSampleOf<Q>& light, Vec3 point, Vec3 normal) {
    ShadowRayOf<Q> shadow;
    shadow.origin = scene.offset(point, normal, light.wi);
    shadow.direction = light.wi;
    shadow.t_far = light.distance - scene.epsilon();
    if (light.body_entry_deferred) shadow.body_beyond = &lights[size_t(light.light)];
    return shadow;
}

// The light sample `u` (LightSet::draw) for the BSDF `bsdf` at `point` (offset along
// `normal`).
template <class Q>
ShadowRayOf<Q> sample_direct_light(const RenderScene& scene, const LightSet& lights,
                                   const BsdfOf<Q>& bsdf, Vec3 point, Vec3 normal,
                                   const WavelengthsFor<Q>& wavelengths, const LightUniforms& u) {
    ShadowRayOf<Q> shadow;
    if (lights.empty()) return shadow;
    LightLiSampleOf<Q> light;
    if (!lights.sample_Li<Q>(point, u, wavelengths, light)) return shadow;
    const Q f = bsdf.eval(light.wi);
    if (is_black(f) || is_black(light.Li)) return shadow;
    shadow = shadow_ray_of(scene, lights, light, point, normal);
    shadow.cast = true;
    shadow.shadowless = light.shadowless;
    const double weight = light.delta ? 1 : power_heuristic(light.pdf, bsdf.pdf(light.wi));
    shadow.contribution = (weight / light.pdf) * (f * light.Li);
    return shadow;
}

// Whether the scene blocks the ray of `shadow`: up to t_far, then (only where that part is
// clear) on to its light's body if that waits beyond; `rays` counts the rays cast.
template <class Q>
bool blocked(const RenderScene& scene, const ShadowRayOf<Q>& shadow, uint64_t& rays) {
    ++rays;
    if (scene.occluded(shadow.origin, shadow.direction, 0, shadow.t_far)) return true;
    if (!shadow.body_beyond) return false;
    const ShadowRayOf<Q> whole = whole_ray(scene, shadow);
    ++rays;
    return whole.t_far > shadow.t_far &&
           scene.occluded(shadow.origin, shadow.direction, shadow.t_far, whole.t_far);
}

// The contribution of `shadow` unless the scene blocks its ray.
template <class Q>
Q unless_occluded(const RenderScene& scene, const ShadowRayOf<Q>& shadow, uint64_t& rays) {
    if (!shadow.cast) return {};
    if (shadow.shadowless) return shadow.contribution;
    return blocked(scene, shadow, rays) ? Q{} : shadow.contribution;
}

// Both halves at once, the light sample drawn from `sampler`.
template <class Q>
Q direct_light(const RenderScene& scene, const LightSet& lights, const BsdfOf<Q>& bsdf, Vec3 point,
               Vec3 normal, const WavelengthsFor<Q>& wavelengths, Sampler& sampler,
               uint64_t& rays) {
    const LightUniforms u = lights.draw(sampler);
    return unless_occluded(
        scene, sample_direct_light(scene, lights, bsdf, point, normal, wavelengths, u), rays);
}

}  // namespace rayset::tracer
