// The emitter interface the tracer uses for every light source built from rays: the paper's
// complex model (ComplexSource) and the naive ray set of its Figure 1 (NaiveRaySource).
// Modelled on pbrt-v4's Light (Phi, L, SampleLi/PDF_Li, SampleLe/PDF_Le) with small sample
// records. Lengths mm; radiance in the selected quantity per (mm^2 sr).
#pragma once

#include "lightmodel/colour.h"
#include "lightmodel/emission_volume.h"
#include "lightmodel/lattice.h"

#include <optional>

namespace rayset::lightmodel {

// A camera or BSDF ray that met the source body.
struct EmitterHit {
    double t = 0;
    Vec3 point, normal;
};

// Whether a light sample says where along wi the ray enters the body: what a shadow ray ends
// at. A caller that knows nothing lies between the body's box and the body (no surface, no
// medium) may end its shadow rays at the box instead, and spare the source the search for the
// body's nearest entry: then the sample only checks that the ray meets the body.
enum class BodyEntry { wanted, not_wanted };

// Light sampling from a shaded point: a direction toward the source, and Li / pdf, an unbiased
// estimate of the light arriving from it over its solid-angle density: the sample's weight. pdf
// is the density multiple importance sampling weighs the sample by, pdf_Li's for wi: the density
// wi was drawn with, or (the complex model, far from its source) a stand-in for it that MIS
// weights see alike from both strategies. Li is then the radiance arriving from wi only where
// pdf is that exact density.
struct LiSample {
    Vec3 wi;              // unit, from the shaded point toward the source
    double distance = 0;  // to the body's entry along wi (BodyEntry::wanted), else 0
    double Li = 0;        // in the selected quantity
    double pdf = 0;       // sr^-1
    Rgb Li_colour;        // the same as a colour (colour.h), whatever the selection
};

// A ray that met the body, seen from its origin: the radiance it brings and the densities the
// other strategies have for it, each 0 unless asked for.
struct EmitterLine {
    Rgb L_colour;       // as L_colour (not written when the radiance goes to a SpectralQuery)
    double pdf_Li = 0;  // as pdf_Li
    double pdf_Le = 0;  // as pdf_Le_line
};

// Photon emission: where and in which direction a photon leaves, and the flux it carries
// (already divided by the densities it was drawn with).
struct LeSample {
    Vec3 origin, direction;
    double flux = 0;           // of the photon, in the selected quantity
    double pdf_position = 0;   // mm^-3 (volume) or probability of the ray (naive)
    double pdf_direction = 0;  // sr^-1 (0: the direction is fixed, a delta)
    int32_t cell = -1;         // flux cell (spectrum) of the origin; -1 naive
    int64_t voxel = -1;        // occupied voxel of the origin (LightModel::voxels); -1 naive
    Rgb flux_colour;           // the photon's whole flux as a colour (colour.h)
    // Its spectrum (emission_spectrum.h): the photon's flux at wavelength l is
    // luminance(flux_colour) x spectrum(l); or, for a ray of one known wavelength (naive),
    // that wavelength (spectrum null), the flux there being luminance(flux_colour) / V(l).
    const BinnedSpectrum* spectrum = nullptr;
    double wavelength_nm = 0;
};

class Emitter {
public:
    virtual ~Emitter() = default;
    virtual double phi(const SpectralSelect& select = {}) const = 0;
    virtual Box bounds() const = 0;
    // The source's whole flux as a colour (colour.h): what an RGB renderer emits.
    virtual Rgb phi_colour() const = 0;

    // The body a camera ray sees; an emitter without one (the naive ray set) returns false.
    virtual bool intersect(Vec3 origin, Vec3 dir, double tmax, EmitterHit& hit) const = 0;
    // Radiance arriving at `origin` from direction `dir` whose ray met the body at `hit`.
    virtual double L(Vec3 origin, Vec3 dir, const EmitterHit& hit,
                     const SpectralSelect& select = {}) const = 0;
    // The same radiance as a colour (colour.h).
    virtual Rgb L_colour(Vec3 origin, Vec3 dir, const EmitterHit& hit) const = 0;
    // The same radiance at the query's wavelengths (emission_spectrum.h), added to its values.
    virtual void L_spectral(Vec3 origin, Vec3 dir, const EmitterHit& hit,
                            SpectralQuery& query) const = 0;
    // The whole light's spectrum, each part weighted by its luminance weight: where a camera
    // path's wavelengths are worth sampling. Zero for an emitter a camera cannot see.
    virtual BinnedSpectrum phi_spectrum() const = 0;

    // Light sampling; nothing when the emitter cannot be sampled from `ref` (naive, or ref
    // inside the source).
    // With `spectral`, the radiance at its wavelengths is added to its values too.
    virtual std::optional<LiSample> sample_Li(Vec3 ref, double u_cell, double u_voxel, Vec3 u_point,
                                              const SpectralSelect& select = {},
                                              SpectralQuery* spectral = nullptr,
                                              BodyEntry entry = BodyEntry::wanted) const = 0;
    // The density sample_Li's samples along `wi` from `ref` are weighed by for MIS with BSDF
    // sampling (LiSample::pdf).
    virtual double pdf_Li(Vec3 ref, Vec3 wi) const = 0;

    // L_colour (or L_spectral, into `spectral` when given), pdf_Li and, with `with_pdf_Le`,
    // pdf_Le_line of one ray that met the body, at once: what weighs a camera path's hit on
    // the body, or a photon's first segment, against the other strategies.
    virtual EmitterLine line(Vec3 origin, Vec3 dir, bool with_pdf_Le,
                             SpectralQuery* spectral) const {
        EmitterLine out;
        if (spectral)
            L_spectral(origin, dir, {}, *spectral);
        else
            out.L_colour = L_colour(origin, dir, {});
        out.pdf_Li = pdf_Li(origin, dir);
        if (with_pdf_Le) out.pdf_Le = pdf_Le_line(origin, dir);
        return out;
    }

    // Whether the line origin + t dir (dir unit) enters the body at some t in [0, t_max] by one
    // of the few balls around occupied voxel `voxel` (a photon's, or a light sample's): true
    // means it does; false says nothing (intersect() knows).
    virtual bool enters_body_near(int64_t /*voxel*/, Vec3 /*origin*/, Vec3 /*dir*/,
                                  double /*t_max*/) const {
        return false;
    }

    // Photon emission from seven uniform numbers in [0, 1).
    virtual LeSample sample_Le(const double u[7], const SpectralSelect& select = {}) const = 0;
    virtual void pdf_Le(Vec3 origin, Vec3 direction, double& pdf_position,
                        double& pdf_direction) const = 0;
    // Density of sample_Le's rays along the line through `origin` with light leaving toward
    // -dir (dir unit), per mm^2 across the line and per sr: what a bidirectional integrator
    // weighs a path that met the body with. 0 for an emitter without a body.
    virtual double pdf_Le_line(Vec3 origin, Vec3 dir) const = 0;
};

}  // namespace rayset::lightmodel
