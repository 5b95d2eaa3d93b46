// The scene's `ray_source` entries as the renderer uses them: each ray file's light model
// (built in memory from the rays, or read from a .vdb model file) behind the emitter
// interface, placed in the scene by source_to_world, with every query answered in scene
// coordinates and renderer units. The paper's complex model by default; the naive ray set
// (its Figure 1) on request, for comparison.
//
// Units: the model lives in the ray file's mm. A point p of the model is placed at
// source_to_world(S p) with S the scaling from mm to the scene's length unit, so k, the
// scene units per model mm, is (1 / millimetres_per_unit) x the transform's own scale. Flux
// is the same in every frame; radiance per area scales by 1 / k^2: the model's
// flux/(mm^2 sr) becomes W/(unit^2 sr) (for a metre scene, x 1e6 = W/(m^2 sr)).
// Colour: light is carried as the model's linear-sRGB colour (lightmodel/colour.h), whose
// luminance is the model's luminous flux under the renderer's 683 lm/W convention (rgb.h) and
// whose chromaticity is that of each flux cell's spectrum. A source without spectra is grey;
// one that carries only luminous flux (lm) emits grey light of flux / 683 W. Spectral transport
// (spectrum.h) gets the same light at a path's wavelengths: each cell's luminance weight times
// its luminance-normalised spectrum (lightmodel/emission_spectrum.h), so luminance is the same.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/bounds.h"
#include "lightmodel/emitter.h"
#include "tracer/render/light_samples.h"
#include "tracer/render/rgb.h"
#include "tracer/render/spectrum.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

// One ray source placed in the scene, answering the queries of the light interface (light.h).
class PlacedRaySource {
public:
    // `to_world`: model mm -> scene coordinates (source_to_world after the mm -> unit scale).
    // Throws rayset::Error when the transform does not keep angles (non-uniform scale or
    // shear): radiance and solid angles would no longer map one to one.
    PlacedRaySource(std::shared_ptr<const lightmodel::Emitter> emitter, const Matrix4& to_world,
                    bool naive = false);

    const lightmodel::Emitter& emitter() const { return *emitter_; }
    // Luminous flux / 683 (W at 555 nm): what the sources are chosen by.
    double power() const { return power_; }
    double units_per_mm() const { return k_; }
    // The naive ray set: no body, no light sampling, only its rays as photons.
    bool photons_only() const { return naive_; }

    // u.select (the light's choice, rescaled) picks the flux cell, u.u[0] the voxel,
    // u.u[1..3] the point in it.
    template <class Q>
    bool sample_Li(Vec3 ref, const LightUniforms& u, double chosen,
                   const WavelengthsFor<Q>& wavelengths, LightLiSampleOf<Q>& out) const;
    // The body's box in scene coordinates (widened against rounding).
    const Bounds3& body_box() const { return body_box_; }
    // From now on, light samples from outside the body's box widened by `margin` end their
    // shadow rays where they enter that box, not where they meet the body, which spares the
    // source its search for the body's nearest entry. The caller has made sure that no surface
    // and no medium lies within twice `margin` of the body's box: a shadow ray then meets the
    // same surfaces either way.
    void end_shadow_rays_at_box(double margin);
    // The body along a scene ray (unit direction) before t_max; t in scene units.
    bool crossed(Vec3 origin, Vec3 direction, double t_max, double& t) const;
    // True when the ray (unit direction) surely meets the body before t_max: it enters, by
    // then, one of the balls around the model's occupied voxel `voxel` (a photon's
    // source_voxel). False says nothing.
    bool crossed_before(Vec3 origin, Vec3 direction, double t_max, int64_t voxel) const;
    // What arrives at `origin` from the body along `direction` (after crossed), with
    // pdf_Le when `with_pdf_Le`: one traversal of the model's emitting volume for all.
    template <class Q>
    LightArrivalOf<Q> arriving(Vec3 origin, Vec3 direction, double chosen, bool with_pdf_Le,
                               const WavelengthsFor<Q>& wavelengths) const;
    // A photon; spectral photons draw their wavelengths from the emitted light's spectrum by
    // `u_wavelength` (hero sampling, spectrum.h), or carry a ray's single wavelength.
    template <class Q>
    LightPhotonOf<Q> sample_Le(const double u[7], double u_wavelength) const;
    // Photons leave points of the emitting volume: the density of the line through `origin`
    // along `wi` (lightmodel's pdf_Le_line), whether or not the body shows it.
    double pdf_Le(Vec3 origin, Vec3 wi, double t, double chosen) const;
    // The whole light's spectrum weighted by luminance (zero when a camera cannot see it).
    lightmodel::BinnedSpectrum spectrum() const { return emitter_->phi_spectrum(); }

private:
    struct Local {
        Vec3 origin, direction;
        double scale;
    };  // scale: model mm per scene unit of t
    Local to_local(Vec3 origin, Vec3 direction) const;

    std::shared_ptr<const lightmodel::Emitter> emitter_;
    Matrix4 to_world_, to_local_;
    double k_ = 1;  // scene units per model mm
    double power_ = 0;
    // The model's line density (per mm^2 and sr) as the scene's pdf_Le of a light chosen with
    // probability `chosen`: per unit^2, as radiance.
    double scene_pdf_Le(double line_density, double chosen) const {
        return chosen * radiance_scale_ * line_density;
    }
    double radiance_scale_ = 1;  // per mm^2 -> per unit^2
    bool naive_ = false;
    // The body's box in the scene frame, widened: most rays miss it, and then the body.
    Bounds3 body_box_;
    // Where shadow rays end, when they end at a box (end_shadow_rays_at_box).
    bool shadow_rays_to_box_ = false;
    Bounds3 shadow_box_;
};

// The scene's ray sources, each model built from its ray file or read from a .vdb model file;
// `naive`: the stored rays themselves instead (ray files only).
std::vector<PlacedRaySource> read_ray_sources(const SceneDescription& scene, bool naive);

}  // namespace rayset::tracer
