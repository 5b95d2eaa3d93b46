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

#include "lightmodel/emitter.h"
#include "tracer/render/rgb.h"
#include "tracer/render/spectrum.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

template <class Q>
struct SourceLiSampleOf {
    Vec3 wi;              // unit, toward the source, scene frame
    double distance = 0;  // to the body along wi (shadow ray length), scene units
    Q Li;                 // renderer radiance units (per nm when spectral)
    double pdf = 0;       // sr^-1, not including the choice of the source
};
using SourceLiSample = SourceLiSampleOf<Rgb>;

template <class Q>
struct SourcePhotonOf {
    Vec3 origin, direction;  // scene frame, direction unit
    Q flux;                  // W per channel (per nm when spectral), of this photon
    WavelengthsFor<Q> wavelengths;
};
using SourcePhoton = SourcePhotonOf<Rgb>;

// One ray source placed in the scene.
class PlacedRaySource {
public:
    // `to_world`: model mm -> scene coordinates (source_to_world after the mm -> unit scale).
    // Throws rayset::Error when the transform does not keep angles (non-uniform scale or
    // shear): radiance and solid angles would no longer map one to one.
    PlacedRaySource(std::shared_ptr<const lightmodel::Emitter> emitter, const Matrix4& to_world);

    const lightmodel::Emitter& emitter() const { return *emitter_; }
    // Luminous flux / 683 (W at 555 nm): what the sources are chosen by.
    double power() const { return power_; }
    double units_per_mm() const { return k_; }

    // The body along a scene ray (unit direction) before t_max; t in scene units.
    bool intersect(Vec3 origin, Vec3 direction, double t_max, double& t) const;
    // Radiance arriving at `origin` from the body along `direction` (call after intersect),
    // as RGB or at a path's wavelengths.
    Rgb radiance(Vec3 origin, Vec3 direction, NoWavelengths = {}) const;
    SampledSpectrum radiance(Vec3 origin, Vec3 direction,
                             const SampledWavelengths& wavelengths) const;
    std::optional<SourceLiSample> sample_Li(Vec3 ref, double u_cell, double u_voxel, Vec3 u_point,
                                            NoWavelengths = {}) const;
    std::optional<SourceLiSampleOf<SampledSpectrum>> sample_Li(
        Vec3 ref, double u_cell, double u_voxel, Vec3 u_point,
        const SampledWavelengths& wavelengths) const;
    double pdf_Li(Vec3 ref, Vec3 wi) const;
    // A photon; spectral photons draw their wavelengths from the emitted light's spectrum by
    // `u_wavelength` (hero sampling, spectrum.h), or carry a ray's single wavelength.
    SourcePhoton sample_Le(const double u[7]) const;
    SourcePhotonOf<SampledSpectrum> sample_Le(const double u[7], double u_wavelength) const;
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
    double radiance_scale_ = 1;  // per mm^2 -> per unit^2
};

// Every ray source of a scene, with the choice probabilities of light sampling and photon
// emission (both in proportion to power).
class RaySourceSet {
public:
    RaySourceSet() = default;
    // Builds or reads each source's model; `naive`: the stored rays themselves instead.
    RaySourceSet(const SceneDescription& scene, bool naive);
    void add(PlacedRaySource source);

    bool empty() const { return sources_.empty(); }
    bool naive() const { return naive_; }
    size_t size() const { return sources_.size(); }
    const PlacedRaySource& operator[](size_t i) const { return sources_[i]; }
    double probability(size_t i) const { return probability_[i]; }
    double total_power() const { return total_power_; }
    // Source chosen by u in [0, 1); `u` is rescaled to [0, 1) for reuse.
    size_t choose(double& u) const;

private:
    std::vector<PlacedRaySource> sources_;
    std::vector<double> probability_, cdf_;
    double total_power_ = 0;
    bool naive_ = false;
};

}  // namespace rayset::tracer
