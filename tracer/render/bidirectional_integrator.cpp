// Camera pass, photon pass and density estimation of the bidirectional integrator
// (see bidirectional_integrator.h), one code path for RGB and spectral transport.
#include "tracer/render/bidirectional_integrator.h"

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

#include "tracer/render/gather_radius.h"
#include "tracer/render/medium_light.h"
#include "tracer/render/receiver_irradiance.h"

namespace rayset::tracer {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The photon's light reflected toward a camera path, made RGB at the photon's wavelengths.
Rgb reflected(const Bsdf& bsdf, const Material&, const Photon& p, double cos_i) {
    return (1 / cos_i) * bsdf.eval(p.wi) * p.power;
}
Rgb reflected(const Bsdf& bsdf, const Material& material, const PhotonOf<SampledSpectrum>& p,
              double cos_i) {
    double diffuse_factor, glossy_factor;
    bsdf.smooth_factors(p.wi, diffuse_factor, glossy_factor);
    if (!(diffuse_factor > 0)) return {};
    SampledSpectrum f;
    for (int i = 0; i < kWavelengths; ++i) {
        const double nm = p.wavelengths.nm[i];
        f.v[i] = diffuse_factor * material.spectra.diffuse(nm) +
                 (glossy_factor > 0 ? glossy_factor * material.spectra.glossy(nm) : 0);
    }
    return to_rgb((1 / cos_i) * f * p.power, p.wavelengths);
}

Rgb photon_rgb(const Photon& p) { return p.power; }
Rgb photon_rgb(const PhotonOf<SampledSpectrum>& p) { return to_rgb(p.power, p.wavelengths); }

WavelengthsFor<Rgb> wavelengths_of(const PhotonWavelengths<Rgb>&) { return {}; }
const SampledWavelengths& wavelengths_of(const PhotonWavelengths<SampledSpectrum>& p) {
    return p.wavelengths;
}

}  // namespace

// Camera wavelengths: camera paths carry only the lights' light (photons bring the rest), so
// they are drawn from the lights' spectra (light.h: wavelength_density).
template <class Q>
BidirectionalIntegratorOf<Q>::BidirectionalIntegratorOf(const RenderScene& scene,
                                                        const LightSet& lights)
    : scene_(scene), lights_(lights) {
    if constexpr (std::is_same_v<Q, SampledSpectrum>)
        camera_wavelength_density_ = lights.wavelength_density();
}

template <class Q>
Q BidirectionalIntegratorOf<Q>::bodies_crossed(Vec3 origin, Vec3 direction, double bsdf_pdf,
                                               const Wavelengths& wavelengths,
                                               uint64_t& rays) const {
    if (!lights_.has_bodies()) return {};
    SurfaceHit hit;
    ++rays;
    const bool found = scene_.intersect(origin, direction, 0, kInfinity, RayKind::indirect, hit);
    return lights_.crossed_radiance<Q>(origin, direction,
                                       scene_.light_horizon(origin, direction, found, hit, rays),
                                       bsdf_pdf, wavelengths);
}

template <class Q>
int BidirectionalIntegratorOf<Q>::attenuate_inside(Q& beta, int start, Vec3 origin, Vec3 direction,
                                                   bool found, const SurfaceHit& hit,
                                                   Pcg32& rng) const {
    const Interiors& interiors = scene_.interiors();
    if (!interiors.any()) return -1;
    const int medium = interiors.segment_medium(start, direction, found, hit);
    if constexpr (std::is_same_v<Q, Rgb>)  // spectral transport refuses fade
        if (medium >= 0)
            beta *= interiors.medium(medium).transmittance(origin, direction,
                                                           found ? hit.t : kInfinity, rng);
    return medium;
}

template <class Q>
Q BidirectionalIntegratorOf<Q>::primary_light(const BsdfOf<Q>& bsdf, const SurfaceHit& hit,
                                              int medium, Vec3 direction,
                                              const Wavelengths& wavelengths, Sampler& sampler,
                                              uint64_t& rays) const {
    const ShadowRayOf<Q> shadow = sample_direct_light(
        scene_, lights_, bsdf, hit.point, bsdf.facing_normal(), wavelengths, lights_.draw(sampler));
    // No medium here scatters (make_bidirectional_integrator refuses them): fade and absorption.
    return light_through_interiors(scene_, shadow, direction, medium, hit, sampler.rng(), rays);
}

template <class Q>
CameraSample BidirectionalIntegratorOf<Q>::camera_path(Vec3 origin, Vec3 direction, uint32_t pixel,
                                                       Sampler& sampler, uint64_t& rays,
                                                       std::vector<Point>& visible) const {
    Pcg32& rng = sampler.rng();
    const Wavelengths wavelengths = sample_wavelengths<Q>(camera_wavelength_density_, rng);
    Q direct_visibility{}, primary{};
    Q beta = constant_value<Q>(1);
    RayKind kind = RayKind::camera;
    int medium = -1;  // the object whose interior the path is in, if known (interior_media.h)
    for (int depth = 0; depth < kMaxPathVertices; ++depth) {
        SurfaceHit hit;
        ++rays;
        const bool found = scene_.intersect(origin, direction, 0, kInfinity, kind, hit);
        if (lights_.has_bodies())
            direct_visibility +=
                beta * lights_.crossed_radiance<Q>(
                           origin, direction,
                           scene_.light_horizon(origin, direction, found, hit, rays), -1,
                           wavelengths);
        medium = attenuate_inside(beta, medium, origin, direction, found, hit, rng);
        if (!found) break;
        std::optional<Material> scratch;
        const Material& material = scene_.material(hit, scratch);
        const Vec3 wo = -direction;
        const BsdfOf<Q> bsdf(material, hit.normal, hit.shading_normal, wo, wavelengths);
        if (bsdf.has_smooth_lobes()) {
            primary +=
                beta * primary_light(bsdf, hit, medium, direction, wavelengths, sampler, rays);
            Point vp;
            vp.point = hit.point, vp.normal = hit.normal, vp.shading_normal = hit.shading_normal,
            vp.wo = wo;
            vp.object = hit.object, vp.part = hit.part, vp.beta = beta, vp.pixel = pixel;
            if constexpr (std::is_same_v<Q, SampledSpectrum>) vp.wavelengths = wavelengths;
            visible.push_back(vp);
        }
        BsdfSampleOf<Q> s;
        const double u_lobe = sampler.get_1d();
        double u1, u2;
        sampler.get_2d(u1, u2);
        if (!bsdf.sample(u_lobe, u1, u2, s) || is_black(s.weight)) break;
        if (scene_.interiors().any())
            medium = scene_.interiors().medium_after(medium, direction, hit, s.wi);
        const Vec3 next_origin = scene_.offset(hit.point, hit.normal, s.wi);
        if (!s.delta) {
            // The smooth lobe ends the camera path: what lies beyond is the photons' part.
            primary +=
                beta * s.weight * bodies_crossed(next_origin, s.wi, s.pdf, wavelengths, rays);
            break;
        }
        beta *= s.weight;
        origin = next_origin;
        direction = s.wi;
        kind = RayKind::indirect;
        if (depth + 1 >= kRouletteDepth && !survives_roulette(beta, rng)) break;
    }
    return {to_rgb(direct_visibility, wavelengths), to_rgb(primary, wavelengths)};
}

template <class Q>
Rgb BidirectionalIntegratorOf<Q>::receiver_primary(Vec3 point, Vec3 normal, Sampler& sampler,
                                                   uint64_t& rays) const {
    return white_lambertian_irradiance<Q>(
        normal, camera_wavelength_density_, sampler,
        [&](const BsdfOf<Q>& bsdf, const Wavelengths& wavelengths) {
            return direct_light(scene_, lights_, bsdf, point, normal, wavelengths, sampler, rays);
        },
        [&](const BsdfSampleOf<Q>& s, const Wavelengths& wavelengths) {
            return s.weight * bodies_crossed(scene_.offset(point, normal, s.wi), s.wi, s.pdf,
                                             wavelengths, rays);
        });
}

template <class Q>
std::vector<typename BidirectionalIntegratorOf<Q>::Photon>
BidirectionalIntegratorOf<Q>::trace_photons(uint64_t first, uint64_t count, uint64_t emitted,
                                            uint64_t seed, uint64_t& rays) const {
    std::vector<Photon> photons;
    if (lights_.empty()) return photons;
    for (uint64_t i = first; i < first + count; ++i) {
        Pcg32 rng(seed, i);
        double u[7];
        for (double& v : u) v = rng.uniform();
        const double u_wavelength = std::is_same_v<Q, SampledSpectrum> ? rng.uniform() : 0;
        const LightPhotonOf<Q> emission = lights_.sample_Le<Q>(u, u_wavelength, emitted);
        Photon photon;
        if constexpr (std::is_same_v<Q, SampledSpectrum>) photon.wavelengths = emission.wavelengths;
        const Wavelengths& wavelengths = wavelengths_of(photon);
        const bool keep_direct = emission.counts_first_hit;
        Q power = emission.flux;
        Vec3 origin = emission.origin, direction = emission.direction;
        bool scattered = false;
        int medium = -1;
        for (int depth = 0; depth < kMaxPathVertices; ++depth) {
            SurfaceHit hit;
            ++rays;
            const bool found =
                scene_.intersect(origin, direction, 0, kInfinity, RayKind::indirect, hit);
            medium = attenuate_inside(power, medium, origin, direction, found, hit, rng);
            if (!found) break;
            std::optional<Material> scratch;
            const BsdfOf<Q> bsdf(scene_.material(hit, scratch), hit.normal, hit.shading_normal,
                                 -direction, wavelengths);
            if (bsdf.has_smooth_lobes() && (scattered || keep_direct)) {
                photon.position = hit.point, photon.wi = -direction,
                photon.normal = bsdf.facing_normal();
                photon.power = power, photon.direct = !scattered;
                photons.push_back(photon);
            }
            BsdfSampleOf<Q> s;
            const double u_lobe = rng.uniform_float(), u1 = rng.uniform_float(),
                         u2 = rng.uniform_float();
            if (!bsdf.sample(u_lobe, u1, u2, s) || is_black(s.weight)) break;
            if (scene_.interiors().any())
                medium = scene_.interiors().medium_after(medium, direction, hit, s.wi);
            const Q next = power * s.weight;
            // Roulette keeps the surviving photons' power near the emitted one.
            const double survive = std::min(1.0, max_component(next) / max_component(power));
            if (!(survive > 0) || rng.uniform_float() >= survive) break;
            power = (1 / survive) * next;
            origin = scene_.offset(hit.point, hit.normal, s.wi);
            direction = s.wi;
            scattered = true;
        }
    }
    return photons;
}

template <class Q>
void BidirectionalIntegratorOf<Q>::gather(const Point& vp, const Grid& grid, Rgb& direct,
                                          Rgb& scattered) const {
    std::optional<Material> scratch;
    const Material& material = scene_.material(vp.object, vp.part, vp.point, vp.normal, scratch);
    const Bsdf bsdf(material, vp.normal, vp.shading_normal, vp.wo);
    const Vec3 n = bsdf.facing_normal();
    Rgb sum_direct, sum_scattered;
    grid.for_each_near(vp.point, [&](const Photon& p) {
        if (dot(p.normal, n) < kSameSurfaceCos) return;
        const double cos_i = std::fabs(dot(p.wi, n));
        if (!(cos_i > 0)) return;
        // Bsdf::eval gives f |cos| about the shading normal; the photon's power already holds
        // the projected area on the surface itself, whose cosine is divided out.
        const Rgb contribution = reflected(bsdf, material, p, cos_i);
        (p.direct ? sum_direct : sum_scattered) += contribution;
    });
    const double area = kPi * grid.radius() * grid.radius();
    const Rgb beta = throughput_to_rgb(vp.beta, wavelengths_of(vp));
    direct = (1 / area) * (beta * sum_direct);
    scattered = (1 / area) * (beta * sum_scattered);
}

template <class Q>
void BidirectionalIntegratorOf<Q>::gather_irradiance(Vec3 point, Vec3 normal, const Grid& grid,
                                                     Rgb& direct, Rgb& scattered) const {
    Rgb sum_direct, sum_scattered;
    grid.for_each_near(point, [&](const Photon& p) {
        if (dot(p.normal, normal) < kSameSurfaceCos || dot(p.wi, normal) <= 0) return;
        (p.direct ? sum_direct : sum_scattered) += photon_rgb(p);
    });
    const double area = kPi * grid.radius() * grid.radius();
    direct = (1 / area) * sum_direct;
    scattered = (1 / area) * sum_scattered;
}

template class BidirectionalIntegratorOf<Rgb>;
template class BidirectionalIntegratorOf<SampledSpectrum>;

}  // namespace rayset::tracer
