// Light through participating media (interior_media.h), as the path integrator samples it:
// shadow rays that cross media and the surfaces that let light straight through, and
// next-event estimation at a point where a medium scatters. RGB transport.
//
// A surface lets a shadow ray through when its index of refraction is 1 (POV-Ray's clear
// containers of media: `pigment { rgbt 1 } hollow`): its transmission lobe is then a delta in
// the ray's own direction, so light arrives straight through it, scaled by that lobe's weight.
// Any other surface blocks the ray. This is exact only while no light has a body (a ray
// through such a surface would otherwise meet an area light both ways, with no MIS between
// them), which is why the path integrator refuses media with area lights and ray sources.
#pragma once

#include <cstdint>
#include <type_traits>

#include "core/random.h"
#include "tracer/render/direct_light.h"
#include "tracer/render/interior_media.h"
#include "tracer/render/light.h"
#include "tracer/render/render_scene.h"

namespace rayset::tracer {

// The fraction of light from `t_far` along (origin, unit direction) that reaches `origin`,
// which lies in `medium` (an object index, -1: none known); `rays` counts the rays cast.
inline Rgb shadow_transmittance(const RenderScene& scene, Vec3 origin, Vec3 direction, double t_far,
                                int medium, Pcg32& rng, uint64_t& rays) {
    constexpr int kMaxCrossings = 64;
    const Interiors& interiors = scene.interiors();
    Rgb through{1, 1, 1};
    std::optional<Material> scratch;
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        SurfaceHit hit;
        ++rays;
        const bool found = scene.intersect(origin, direction, 0, t_far, RayKind::shadow, hit);
        const int m = interiors.segment_medium(medium, direction, found, hit);
        if (m >= 0)
            through *=
                interiors.medium(m).transmittance(origin, direction, found ? hit.t : t_far, rng);
        if (!found) return through;
        const Material& material = scene.material(hit, scratch);
        if (material.ior != 1) return {};
        through *= material.transmission;
        if (is_black(through)) return {};
        medium = interiors.medium_after(m, direction, hit, direction);
        const Vec3 next = scene.offset(hit.point, hit.normal, direction);
        t_far -= dot(next - origin, direction);
        origin = next;
    }
    return {};
}

// A surface's light sample (direct_light.h) seen through the media on its way; the shadow ray
// starts in `medium`.
inline Rgb through_media(const RenderScene& scene, const ShadowRayOf<Rgb>& ray, int medium,
                         Pcg32& rng, uint64_t& rays) {
    const ShadowRayOf<Rgb> shadow = whole_ray(scene, ray);
    if (!shadow.cast) return {};
    if (shadow.shadowless) return shadow.contribution;
    return shadow.contribution * shadow_transmittance(scene, shadow.origin, shadow.direction,
                                                      shadow.t_far, medium, rng, rays);
}

// A surface's light sample whose shadow ray stops at every surface (direct_light.h), dimmed
// by the medium it starts in (Interiors::medium_after's): what fade and media that only absorb
// do to it, in both integrators.
inline Rgb dimmed_unless_occluded(const RenderScene& scene, const ShadowRayOf<Rgb>& ray, int medium,
                                  Pcg32& rng, uint64_t& rays) {
    const ShadowRayOf<Rgb> shadow = whole_ray(scene, ray);
    const Rgb c = unless_occluded(scene, shadow, rays);
    medium = scene.interiors().segment_medium(medium, shadow.direction, false, {});
    if (medium < 0 || shadow.shadowless || is_black(c)) return c;
    return c * scene.interiors().medium(medium).transmittance(shadow.origin, shadow.direction,
                                                              shadow.t_far, rng);
}

// A surface's light sample arriving at `hit`, which the path reached along `direction` in the
// medium of object `medium`: nothing if occluded, dimmed by fade and media on the way (RGB
// transport; spectral transport refuses fade and media). What both integrators add at a vertex.
template <class Q>
Q light_through_interiors(const RenderScene& scene, const ShadowRayOf<Q>& shadow, Vec3 direction,
                          int medium, const SurfaceHit& hit, Pcg32& rng, uint64_t& rays) {
    if constexpr (std::is_same_v<Q, Rgb>) {
        const Interiors& interiors = scene.interiors();
        if (interiors.any()) {
            const int shadow_medium =
                interiors.medium_after(medium, direction, hit, shadow.direction);
            return interiors.participating()
                       ? through_media(scene, shadow, shadow_medium, rng, rays)
                       : dimmed_unless_occluded(scene, shadow, shadow_medium, rng, rays);
        }
    }
    return unless_occluded(scene, shadow, rays);
}

// Light scattered toward -`direction` at `point`, inside the medium of object `medium`, from
// one light sample: sigma_s p Li / pdf, seen through the media on the way (lights have no
// body here, so no MIS). Lights with POV-Ray's media_interaction off bring nothing, as POV-Ray
// renders them (not physical; RenderScene notes it).
inline Rgb medium_direct_light(const RenderScene& scene, const LightSet& lights, int medium,
                               Vec3 point, Vec3 direction, Pcg32& rng, uint64_t& rays) {
    if (lights.empty()) return {};
    LightLiSampleOf<Rgb> light;
    if (!lights.sample_Li<Rgb>(point, lights.draw(rng), {}, light) || !(light.pdf > 0) ||
        !light.media_interaction)
        return {};
    const Rgb f = scene.interiors().medium(medium).scattered(point, dot(light.wi, direction));
    if (is_black(f) || is_black(light.Li)) return {};
    const Rgb contribution = (1 / light.pdf) * (f * light.Li);
    if (light.shadowless) return contribution;
    const double distance =
        light.body_entry_deferred
            ? to_body_entry(lights[size_t(light.light)], point, light.wi, light.distance, 0)
            : light.distance;
    return contribution * shadow_transmittance(scene, point, light.wi, distance, medium, rng, rays);
}

}  // namespace rayset::tracer
