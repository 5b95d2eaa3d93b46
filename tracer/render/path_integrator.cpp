// Path tracing with next-event estimation and MIS (see path_integrator.h), one code path for
// RGB and spectral transport.
#include "tracer/render/path_integrator.h"

#include <limits>
#include <type_traits>

#include "core/error.h"
#include "tracer/render/medium_light.h"
#include "tracer/render/receiver_irradiance.h"
#include "tracer/render/renderer.h"

namespace rayset::tracer {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Fade and media are rendered in RGB; media that scatter or emit light with shadow rays through
// clear surfaces (medium_light.h), which suits lights without a body only, and are not mixed
// with fog, which is drawn over whole segments.
void check_interiors_renderable(const RenderScene& scene, const RenderSettings& settings,
                                const LightSet& lights) {
    const Interiors& interiors = scene.interiors();
    if (!interiors.any()) return;
    if (spectral_transport(scene, settings))
        throw Error("not supported: interior fade or media under spectral transport");
    if (!interiors.participating()) return;
    if (lights.has_bodies())
        throw Error(
            "not supported: media that scatter or emit, with area lights or ray-file sources "
            "(point and spot lights only)");
    if (scene.fog().present()) throw Error("not supported: media together with fog");
}

}  // namespace

template <class Q>
PathIntegratorOf<Q>::PathIntegratorOf(const RenderScene& scene, const LightSet& lights)
    : scene_(scene), lights_(lights) {
    if constexpr (std::is_same_v<Q, SampledSpectrum>)
        wavelength_density_ = lights.wavelength_density();
}

template <class Q>
LightComponentsOf<Rgb> PathIntegratorOf<Q>::radiance(Vec3 origin, Vec3 direction, Sampler& sampler,
                                                     uint64_t& rays) const {
    const Wavelengths wavelengths = sample_wavelengths<Q>(wavelength_density_, sampler.rng());
    PathState state;
    state.origin = origin;
    state.direction = direction;
    return to_rgb(trace(state, wavelengths, sampler, rays), wavelengths);
}

template <class Q>
LightComponentsOf<Rgb> PathIntegratorOf<Q>::irradiance(Vec3 point, Vec3 normal, Sampler& sampler,
                                                       uint64_t& rays) const {
    return white_lambertian_irradiance<Q>(
        normal, wavelength_density_, sampler,
        [&](const BsdfOf<Q>& bsdf, const Wavelengths& wavelengths) {
            LightComponentsOf<Q> light;
            light.of[kPrimary] =
                direct_light(scene_, lights_, bsdf, point, normal, wavelengths, sampler, rays);
            return light;
        },
        [&](const BsdfSampleOf<Q>& s, const Wavelengths& wavelengths) {
            PathState state;
            state.origin = scene_.offset(point, normal, s.wi);
            state.direction = s.wi;
            state.kind = RayKind::indirect;
            state.beta = s.weight;
            state.bsdf_pdf = s.pdf;
            state.depth = 1;
            state.segment_layer = kPrimary;  // the receiver is the first smooth scattering
            return trace(state, wavelengths, sampler, rays);
        });
}

// Flattened: everything the bounce loop calls (ray queries, hit resolution, light sampling,
// the BSDF) is inlined into it. Left as calls across files, they pass their Vec3 arguments
// through memory and cost about a tenth of the renderer's time per ray (raytrace --bench).
template <class Q>
[[gnu::flatten]] LightComponentsOf<Q> PathIntegratorOf<Q>::trace(PathState& s,
                                                                 const Wavelengths& wavelengths,
                                                                 Sampler& sampler,
                                                                 uint64_t& rays) const {
    const LightSet& lights = lights_;
    Pcg32& rng = sampler.rng();
    const Interiors& interiors = scene_.interiors();
    LightComponentsOf<Q> sum;
    Q& unlayered = sum.of[kUnlayered];
    SurfaceHit hit;
    BsdfSampleOf<Q> sample;
    std::optional<Material> scratch;
    for (;; ++s.depth) {
        // The vertex's light and BSDF samples, drawn before its ray is cast: they do not
        // depend on what the ray hits, and their hashing (sampler.h) overlaps the query.
        const LightUniforms light_u = lights.draw(sampler);
        const double u_lobe = sampler.get_1d();
        double u1, u2;
        sampler.get_2d(u1, u2);
        ++rays;
        const bool found = scene_.intersect(s.origin, s.direction, 0, kInfinity, s.kind, hit);
        int medium = -1;
        if constexpr (std::is_same_v<Q, Rgb>) {  // spectral transport refuses media
            if (interiors.any()) {
                medium = interiors.segment_medium(s.medium, s.direction, found, hit);
                if (medium >= 0 &&
                    cross_medium(s, medium, found ? hit.t : kInfinity, rng, rays, sum)) {
                    if (s.depth + 1 >= kMaxPathVertices || !goes_on(s, rng)) break;
                    continue;
                }
            }
        }
        add_segment_light(s, found, hit, wavelengths, rays, sum);
        if (!found) {
            const Sky& sky = scene_.sky();
            unlayered += s.beta * emitted(sky.radiance(s.direction), sky.spectrum(), wavelengths);
            break;
        }
        const Material& material = scene_.material(hit, scratch);
        if (!is_black(material.emission))
            unlayered +=
                s.beta * emitted(material.emission, material.emission_spectrum, wavelengths);
        const Vec3 wo = -s.direction;
        const BsdfOf<Q> bsdf(material, hit.normal, hit.shading_normal, wo, wavelengths);
        const bool light_sampled = bsdf.has_smooth_lobes();
        ShadowRayOf<Q> shadow;
        if (light_sampled)
            shadow = sample_direct_light(scene_, lights, bsdf, hit.point, bsdf.facing_normal(),
                                         wavelengths, light_u);

        // The BSDF sample before the shadow ray (it does not depend on it; direct_light.h).
        const bool sampled = bsdf.sample(u_lobe, u1, u2, sample);
        if (light_sampled)
            sum.of[layer_of_light_at_vertex(s.segment_layer)] +=
                s.beta *
                light_through_interiors(scene_, shadow, s.direction, medium, hit, rng, rays);
        if (s.depth + 1 >= kMaxPathVertices || !sampled || is_black(sample.weight)) break;
        s.segment_layer = layer_after_scattering(s.segment_layer, sample.delta);
        if (interiors.any()) s.medium = interiors.medium_after(medium, s.direction, hit, sample.wi);
        s.beta *= sample.weight;
        s.bsdf_pdf = sample.delta ? -1 : sample.pdf;
        s.origin = scene_.offset(hit.point, hit.normal, sample.wi);
        s.direction = sample.wi;
        s.kind = RayKind::indirect;
        if (!goes_on(s, rng)) break;
    }
    return sum;
}

template <class Q>
void PathIntegratorOf<Q>::add_segment_light(PathState& s, bool found, const SurfaceHit& hit,
                                            const Wavelengths& wavelengths, uint64_t& rays,
                                            LightComponentsOf<Q>& sum) const {
    if constexpr (std::is_same_v<Q, Rgb>) {  // spectral transport refuses fog
        if (scene_.fog().present()) {
            Rgb through, added;
            scene_.fog().along(s.origin, s.direction, found ? hit.t : kInfinity, through, added);
            sum.of[kUnlayered] += s.beta * added;
            s.beta *= through;
        }
    }
    if (lights_.has_bodies()) {
        // Lights are not geometry: a ray collects one if it crosses its body before the first
        // surface that casts shadows, which is exactly what light sampling tests.
        const double t_block = scene_.light_horizon(s.origin, s.direction, found, hit, rays);
        sum.of[s.segment_layer] += s.beta * lights_.template crossed_radiance<Q>(
                                                s.origin, s.direction, t_block + scene_.epsilon(),
                                                s.bsdf_pdf, wavelengths);
    }
}

template <class Q>
bool PathIntegratorOf<Q>::cross_medium(PathState& s, int medium, double length, Pcg32& rng,
                                       uint64_t& rays, LightComponentsOf<Rgb>& sum) const {
    if constexpr (std::is_same_v<Q, Rgb>) {
        const InteriorMedium& m = scene_.interiors().medium(medium);
        const FreeFlight flight = m.fly(s.origin, s.direction, length, rng);
        sum.of[kUnlayered] += s.beta * flight.emitted;
        s.beta *= flight.weight;
        if (!flight.scattered) return false;
        const Vec3 point = s.origin + flight.t * s.direction;
        sum.of[layer_of_light_at_vertex(s.segment_layer)] +=
            s.beta * medium_direct_light(scene_, lights_, medium, point, s.direction, rng, rays);
        s.segment_layer = layer_after_scattering(s.segment_layer, false);
        const double u_choice = rng.uniform_float(), u1 = rng.uniform_float(),
                     u2 = rng.uniform_float();
        const Vec3 wi = m.sample_phase(s.direction, u_choice, u1, u2);
        const double cos_theta = dot(wi, s.direction);
        const double pdf = m.phase_pdf(cos_theta);
        s.beta *= (pdf > 0 ? 1 / pdf : 0) * m.scattered(point, cos_theta);
        s.origin = point;
        s.direction = wi;
        s.bsdf_pdf = pdf;
        s.medium = medium;
        s.kind = RayKind::indirect;
        return true;
    } else {
        return false;
    }
}

template class PathIntegratorOf<Rgb>;
template class PathIntegratorOf<SampledSpectrum>;

namespace {

template <class Q>
class PathTracing : public Integrator {
public:
    PathTracing(const RenderScene& scene, LightSet lights)
        : lights_(std::move(lights)), path_(scene, lights_) {}
    void camera_sample(const CameraRay& ray, const SampleSink& sink, Sampler& sampler,
                       uint64_t& rays) const override {
        add_components(sink, path_.radiance(ray.origin, ray.direction, sampler, rays));
    }
    void receiver_sample(Vec3 point, Vec3 normal, const SampleSink& sink, Sampler& sampler,
                         uint64_t& rays) const override {
        add_components(sink, path_.irradiance(point, normal, sampler, rays));
    }

private:
    static void add_components(const SampleSink& sink, const LightComponentsOf<Rgb>& light) {
        for (int c = 0; c < kLightComponents; ++c) sink.add(c, light.of[size_t(c)]);
    }
    LightSet lights_;
    PathIntegratorOf<Q> path_;
};

}  // namespace

std::unique_ptr<Integrator> make_path_integrator(const RenderScene& scene,
                                                 const RenderSettings& settings,
                                                 const RenderResult&) {
    if (settings.naive_sources && !scene.description().ray_sources.empty())
        throw Error(
            "the naive ray set (--naive-sources) has no body and cannot be light sampled: only "
            "photons carry its light; render it with integrator \"bidirectional\"");
    if (scene.fog().present() && !scene.description().ray_sources.empty())
        throw Error("not supported: fog with ray-file sources (their bodies are not dimmed)");
    LightSet lights(scene, false);
    check_interiors_renderable(scene, settings, lights);
    if (spectral_transport(scene, settings))
        return std::make_unique<PathTracing<SampledSpectrum>>(scene, std::move(lights));
    return std::make_unique<PathTracing<Rgb>>(scene, std::move(lights));
}

}  // namespace rayset::tracer
