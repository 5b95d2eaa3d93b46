// The scene's lights behind one interface, chosen in proportion to power (see light.h).
#include "tracer/render/light.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "tracer/render/ray_box.h"
#include "tracer/render/render_scene.h"
#include "tracer/render/sampling.h"

namespace rayset::tracer {

lightmodel::BinnedSpectrum ordinary_light_density() {
    const lightmodel::BinnedSpectrum d65 = lightmodel::d65_spectrum();
    std::array<double, lightmodel::kSpectrumBins> light{};
    for (int k = 0; k < lightmodel::kSpectrumBins; ++k) light[size_t(k)] = d65.value(k);
    return film_wavelength_density(light);
}

LightSet::LightSet(std::vector<Light> lights) : lights_(std::move(lights)) {
    // The box around area lights, widened once here: the box test runs for every ray a path
    // casts.
    area_low_ = {1e300, 1e300, 1e300}, area_high_ = {-1e300, -1e300, -1e300};
    for (size_t i = 0; i < lights_.size(); ++i) {
        cdf_.push_back(total_power_ += lights_[i].power());
        if (lights_[i].extend_by_area_body(area_low_, area_high_)) area_bodies_.push_back(i);
        if (lights_[i].is_ray_source()) {
            has_ray_sources_ = true;
            if (!lights_[i].photons_only()) ray_source_bodies_.push_back(i);
        }
    }
    widen_box(area_low_, area_high_);
    for (size_t i = 0; i < cdf_.size(); ++i)
        probability_.push_back(total_power_ > 0 ? (cdf_[i] - (i ? cdf_[i - 1] : 0)) / total_power_
                                                : 0);
}

LightSet::LightSet(const SceneDescription& scene, const SceneUnits& units, bool naive_sources) {
    PovrayLights povray = read_povray_lights(scene.lights, units, ColourDecoding(scene.global));
    std::vector<Light> lights;
    for (PointLight& l : povray.points) lights.emplace_back(std::move(l));
    for (RectLight& l : povray.rects) lights.emplace_back(std::move(l));
    for (SphereLight& l : povray.spheres) lights.emplace_back(std::move(l));
    for (PlacedRaySource& s : read_ray_sources(scene, naive_sources))
        lights.emplace_back(std::move(s));
    *this = LightSet(std::move(lights));
}

LightSet::LightSet(const RenderScene& scene, bool naive_sources)
    : LightSet(scene.description(), scene.units(), naive_sources) {
    for (Light& light : lights_) {
        PlacedRaySource* source = light.ray_source();
        if (!source || source->photons_only()) continue;
        const Bounds3& box = source->body_box();
        // Twice the distance the scene keeps a ray's ends from surfaces, at the box's corners.
        const double margin =
            2 * std::max(scene.offset_distance(box.lo), scene.offset_distance(box.hi));
        if (scene.clear_within(box.grown(2 * margin))) source->end_shadow_rays_at_box(margin);
    }
}

size_t LightSet::choose(double& u) const {
    const double x = u * total_power_;
    size_t i = 0;
    if (cdf_.size() <= 16) {
        // The index upper_bound finds, counted without branches: for a handful of lights this
        // is faster than a binary search whose branches the processor cannot predict.
        for (double c : cdf_) i += c <= x;
    } else {
        i = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), x) - cdf_.begin());
    }
    i = std::min(i, cdf_.size() - 1);
    const double low = i ? cdf_[i - 1] : 0;
    u = std::min(std::nextafter(1.0, 0.0), (x - low) / std::max(1e-300, cdf_[i] - low));
    return i;
}

LightUniforms LightSet::draw(Sampler& sampler) const {
    LightUniforms u;
    if (has_ray_sources_) {
        sampler.get_2d(u.select, u.u[0]);
        sampler.get_2d(u.u[1], u.u[2]);
        u.u[3] = sampler.get_1d();
    } else {
        u.select = sampler.get_1d();
        sampler.get_2d(u.u[0], u.u[1]);
    }
    return u;
}

template <class Q>
bool LightSet::sample_Li(Vec3 ref, const LightUniforms& u, const WavelengthsFor<Q>& wavelengths,
                         LightLiSampleOf<Q>& out) const {
    if (!(total_power_ > 0)) return false;
    LightUniforms chosen = u;
    const size_t i = choose(chosen.select);
    if (!lights_[i].sample_Li<Q>(ref, chosen, probability_[i], wavelengths, out)) return false;
    out.light = int(i);
    return true;
}

template <class Q>
Q LightSet::crossed_radiance(Vec3 origin, Vec3 direction, double t_max, double bsdf_pdf,
                             const WavelengthsFor<Q>& wavelengths) const {
    Q sum{};
    for_each_crossed(origin, direction, t_max, [&](size_t i, double t) {
        const LightArrivalOf<Q> light =
            lights_[i].arriving<Q>(origin, direction, t, probability_[i], false, wavelengths);
        const double weight = bsdf_pdf >= 0 ? power_heuristic(bsdf_pdf, light.pdf_Li) : 1;
        sum += weight * light.radiance;
    });
    return sum;
}

template <class Q>
LightPhotonOf<Q> LightSet::sample_Le(double u[7], double u_wavelength, uint64_t emitted) const {
    if (!(total_power_ > 0)) return {};
    const size_t i = choose(u[0]);
    LightPhotonOf<Q> photon = lights_[i].sample_Le<Q>(u, u_wavelength);
    photon.flux = (1 / (probability_[i] * double(emitted))) * photon.flux;
    photon.counts_first_hit = lights_[i].photons_only();
    photon.light = int(i);
    return photon;
}

lightmodel::BinnedSpectrum LightSet::wavelength_density() const {
    if (!has_ray_sources_) return ordinary_light_density();
    std::array<double, lightmodel::kSpectrumBins> light{};
    for (size_t j = 0; j < lights_.size(); ++j) {
        const lightmodel::BinnedSpectrum s = lights_[j].spectrum();
        if (s.is_zero()) continue;
        for (int k = 0; k < lightmodel::kSpectrumBins; ++k)
            light[size_t(k)] += probability_[j] * s.value(k) / s.integral();
    }
    return film_wavelength_density(light);
}

#define RAYSET_LIGHT_SET_QUERIES(Q)                                                                \
    template bool LightSet::sample_Li<Q>(Vec3, const LightUniforms&, const WavelengthsFor<Q>&,     \
                                         LightLiSampleOf<Q>&) const;                               \
    template Q LightSet::crossed_radiance<Q>(Vec3, Vec3, double, double, const WavelengthsFor<Q>&) \
        const;                                                                                     \
    template LightPhotonOf<Q> LightSet::sample_Le<Q>(double[7], double, uint64_t) const;
RAYSET_LIGHT_SET_QUERIES(Rgb)
RAYSET_LIGHT_SET_QUERIES(SampledSpectrum)
#undef RAYSET_LIGHT_SET_QUERIES

}  // namespace rayset::tracer
