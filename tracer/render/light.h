// The light interface: every light the renderer knows (POV-Ray's point, spot and area lights,
// and the scene's ray-file sources) behind one set of queries, so that both integrators choose,
// sample, weigh and emit from all of them alike. After pbrt-v4's Light: a tagged union of the
// light kinds dispatched without virtual calls, queries templated on what paths carry (Rgb, or
// SampledSpectrum at a path's wavelengths) and taking canonical random numbers.
//
// Queries of one light, in the scene frame and the renderer's units (units.h):
//   sample_Li   a direction toward the light from a reference point, the radiance arriving
//               along it (intensity / d^2 for a point) and its solid-angle density;
//   crossed     where a ray meets the light's body (area lights, ray-source bodies): lights are
//               not geometry, a ray collects every body it crosses before the first surface;
//               crossed_before, for a photon's line seen from its first hit, the quick answer
//               a ray source's balls around the photon's origin give;
//   arriving    the radiance such a ray brings, the density sample_Li has for it and, when
//               asked, pdf_Le's;
//   sample_Le   a photon: origin, direction and flux; pdf_Le the density it has for a given
//               ray, per steradian and per unit area across the ray (the light's projected
//               area, so that no cosine at the light enters), for weighing bidirectional
//               strategies against each other.
// Densities include the probability `chosen` with which the light was picked, passed in.
// Emitting surfaces and the background are not lights: paths collect them where they meet them.
#pragma once

#include <optional>
#include <variant>
#include <vector>

#include "core/random.h"
#include "tracer/render/povray_lights.h"
#include "tracer/render/ray_box.h"
#include "tracer/render/ray_sources.h"
#include "tracer/render/sampler.h"
#include "tracer/render/spectrum.h"
#include "tracer/render/units.h"

namespace rayset::tracer {

class RenderScene;

class Light {
public:
    template <class Kind>
    explicit Light(Kind kind) : kind_(std::move(kind)) {}

    // What lights are chosen by: W (a ray source's luminous flux / 683).
    double power() const {
        return std::visit([](const auto& l) { return l.power(); }, kind_);
    }
    // A ray source that is its stored rays (no body, no light sampling): its photons count
    // from their first hit.
    bool photons_only() const {
        return std::visit([](const auto& l) { return l.photons_only(); }, kind_);
    }
    // Extends [low, high] by the body of an area light (rectangle, ellipse or sphere); false
    // for the other kinds, which have none or track their own.
    bool extend_by_area_body(Vec3& low, Vec3& high) const {
        if (const auto* rect = std::get_if<RectLight>(&kind_)) {
            rect->extend_bounds(low, high);
            return true;
        }
        if (const auto* sphere = std::get_if<SphereLight>(&kind_)) {
            sphere->extend_bounds(low, high);
            return true;
        }
        return false;
    }
    bool is_ray_source() const { return std::holds_alternative<PlacedRaySource>(kind_); }
    PlacedRaySource* ray_source() { return std::get_if<PlacedRaySource>(&kind_); }

    // A light sample written into `out` (reset to its defaults, then the fields the light's
    // kind sets), or false when the light sends nothing toward `ref`. In place rather than
    // returned: a returned record is copied whole through memory right after being built
    // field by field, and the wide loads of the copy stall on the narrow stores.
    template <class Q>
    bool sample_Li(Vec3 ref, const LightUniforms& u, double chosen,
                   const WavelengthsFor<Q>& wavelengths, LightLiSampleOf<Q>& out) const {
        out = LightLiSampleOf<Q>{};
        return std::visit(
            [&](const auto& l) {
                return l.template sample_Li<Q>(ref, u, chosen, wavelengths, out);
            },
            kind_);
    }
    // Whether a photon's line, seen from `origin` along `direction` (toward the photon's
    // origin, t_max away), surely meets the light's body before the photon's origin (a ray
    // source's quick test with the balls around the photon's voxel); false says nothing.
    template <class Q>
    bool crossed_before(Vec3 origin, Vec3 direction, double t_max,
                        const LightPhotonOf<Q>& photon) const {
        const auto* source = std::get_if<PlacedRaySource>(&kind_);
        return source && source->crossed_before(origin, direction, t_max, photon.source_voxel);
    }
    bool crossed(Vec3 origin, Vec3 direction, double t_max, double& t) const {
        return std::visit([&](const auto& l) { return l.crossed(origin, direction, t_max, t); },
                          kind_);
    }
    // What a ray from `origin` along `wi` that crossed the body at distance t brings, with
    // pdf_Le when `with_pdf_Le`.
    template <class Q>
    LightArrivalOf<Q> arriving(Vec3 origin, Vec3 wi, double t, double chosen, bool with_pdf_Le,
                               const WavelengthsFor<Q>& wavelengths) const {
        return std::visit(
            [&](const auto& l) -> LightArrivalOf<Q> {
                if constexpr (std::is_same_v<std::decay_t<decltype(l)>, PlacedRaySource>) {
                    return l.template arriving<Q>(origin, wi, chosen, with_pdf_Le, wavelengths);
                } else {
                    return {l.template radiance<Q>(origin, wi, wavelengths),
                            l.pdf_Li(origin, wi, t, chosen),
                            with_pdf_Le ? l.pdf_Le(origin, wi, t, chosen) : 0};
                }
            },
            kind_);
    }
    template <class Q>
    LightPhotonOf<Q> sample_Le(const double u[7], double u_wavelength) const {
        return std::visit([&](const auto& l) { return l.template sample_Le<Q>(u, u_wavelength); },
                          kind_);
    }
    // The density with which sample_Le emits the light that arrives at `origin` along `wi`
    // (unit, toward the light) from distance t: where the ray crossed the body, or a point
    // light's distance. Per steradian, times per unit area across the ray for a body.
    double pdf_Le(Vec3 origin, Vec3 wi, double t, double chosen) const {
        return std::visit([&](const auto& l) { return l.pdf_Le(origin, wi, t, chosen); }, kind_);
    }
    // A point or spot light: photons leave one point, which no ray can meet.
    bool delta_position() const { return std::holds_alternative<PointLight>(kind_); }
    // The emitted light's spectral shape (any scale; zero when unknown), where paths that
    // carry it are worth sampling.
    lightmodel::BinnedSpectrum spectrum() const {
        return std::visit([](const auto& l) { return l.spectrum(); }, kind_);
    }

private:
    std::variant<PointLight, RectLight, SphereLight, PlacedRaySource> kind_;
};

// Every light of a scene, chosen in proportion to power for light sampling and for photons.
class LightSet {
public:
    LightSet() = default;
    explicit LightSet(std::vector<Light> lights);
    // The scene's POV-Ray lights, then its ray sources (each model built from its ray file or
    // read from a .vdb; with `naive_sources`, the stored rays themselves).
    LightSet(const SceneDescription& scene, const SceneUnits& units, bool naive_sources);
    // The lights of a scene ready to render: as above, and each ray source whose body's
    // surroundings hold no surface and no medium ends its shadow rays at its body's box.
    LightSet(const RenderScene& scene, bool naive_sources);

    bool empty() const { return lights_.empty(); }
    size_t size() const { return lights_.size(); }
    const Light& operator[](size_t i) const { return lights_[i]; }
    double probability(size_t i) const { return probability_[i]; }
    double total_power() const { return total_power_; }
    bool has_bodies() const { return !area_bodies_.empty() || !ray_source_bodies_.empty(); }
    bool has_ray_sources() const { return has_ray_sources_; }

    // The canonical numbers of one light sample. Without ray sources: the choice of a light
    // alone, then a pair for a point of its area. With them: the choice (whose remainder picks
    // a ray source's flux cell) paired with its voxel, then a pair for two coordinates of the
    // point in the voxel, then the third alone.
    LightUniforms draw(Sampler& sampler) const;
    LightUniforms draw(Pcg32& rng) const {
        Sampler random(rng);
        return draw(random);
    }
    // A light chosen by u.select, then a sample of it into `out` (Light::sample_Li); the pdf
    // includes the choice.
    template <class Q>
    bool sample_Li(Vec3 ref, const LightUniforms& u, const WavelengthsFor<Q>& wavelengths,
                   LightLiSampleOf<Q>& out) const;
    // Radiance of every body a ray (origin, unit direction) crosses before t_max, each weighted
    // by the power heuristic against light sampling from `origin`; pass bsdf_pdf < 0 for rays no
    // light sampling could have made (camera rays, delta bounces): weight 1.
    template <class Q>
    Q crossed_radiance(Vec3 origin, Vec3 direction, double t_max, double bsdf_pdf,
                       const WavelengthsFor<Q>& wavelengths) const;
    // Calls f(light index, t) for every light body the ray (origin, unit direction) crosses
    // before t_max, at distance t.
    template <class F>
    void for_each_crossed(Vec3 origin, Vec3 direction, double t_max, F&& f) const {
        double t = 0;
        if (!area_bodies_.empty() &&
            ray_crosses_box(origin, direction, t_max, area_low_, area_high_))
            for (size_t i : area_bodies_)
                if (lights_[i].crossed(origin, direction, t_max, t)) f(i, t);
        for (size_t i : ray_source_bodies_)
            if (lights_[i].crossed(origin, direction, t_max, t)) f(i, t);
    }
    // A photon of a pass of `emitted`: a light chosen by u[0] (rescaled for the light's own
    // use), its flux divided by the choice and by `emitted`; zero flux when no light shines.
    template <class Q>
    LightPhotonOf<Q> sample_Le(double u[7], double u_wavelength, uint64_t emitted) const;

    // Where the wavelengths of paths that carry these lights' light are worth drawing:
    // the lights' spectra mixed by power times the film's weights (D65 x the film's weights
    // when only POV-Ray lights, whose spectra are D65 times a smooth factor, shine).
    lightmodel::BinnedSpectrum wavelength_density() const;

private:
    size_t choose(double& u) const;  // rescales u to [0, 1) for reuse

    std::vector<Light> lights_;
    std::vector<double> cdf_;  // running sum of the lights' power
    std::vector<double> probability_;
    // Lights a ray can cross: area lights (with a box around them all, widened a little: most
    // rays miss it at once) and ray sources with a body.
    std::vector<size_t> area_bodies_, ray_source_bodies_;
    Vec3 area_low_, area_high_;
    double total_power_ = 0;
    bool has_ray_sources_ = false;
};

// D65 x the film's weights: where the light of POV-Ray lights, emitting surfaces and the
// background (D65 times a smooth factor, grey ones exactly D65) is worth sampling.
lightmodel::BinnedSpectrum ordinary_light_density();

}  // namespace rayset::tracer
