// Physical materials made from POV-Ray textures (the mapping is in README.md beside this
// file) and the BSDF a path samples at a surface point: a Lambertian lobe, a normalised Phong
// lobe, a perfect mirror and a smooth dielectric, mixed with weights that never sum above one.
#pragma once

#include <memory>
#include <optional>

#include "tracer/render/colour_decoding.h"
#include "tracer/render/rgb.h"
#include "tracer/render/rgb_upsampling.h"
#include "tracer/render/sampling.h"
#include "tracer/render/spectrum.h"

namespace rayset::tracer {

struct Material {
    Rgb diffuse;  // Lambertian albedo
    Rgb glossy;   // albedo of the normalised Phong lobe about the mirror direction
    double glossy_exponent = 40;
    Rgb mirror_min, mirror_max;  // perfect mirror: weight at normal and at grazing incidence
    double mirror_falloff = 1;
    bool mirror_fresnel = false;
    // A metallic reflection (POV-Ray's `reflection { metallic M }`): the weights above tinted
    // by the pigment, taking over from them by M (1 - F(angle)), F rising from 0 at normal
    // incidence to 1 at grazing (BsdfOf::mirror_weight).
    Rgb mirror_min_metal, mirror_max_metal;
    double mirror_metallic = 0;
    Rgb transmission;  // smooth dielectric lobe (Fresnel reflection + refraction)
    double ior = 1;
    // Added to the shading normal, then normalised (a normal { } pattern's tilt; world space).
    Vec3 bump;
    Rgb emission;                          // emitted radiance, renderer units (both sides)
    IlluminantSpectrum emission_spectrum;  // the same for spectral transport
    // The reflectances above as spectra, for spectral transport (rgb_upsampling.h).
    struct Spectra {
        ReflectanceSpectrum diffuse, glossy, mirror_min, mirror_max, transmission;
        ReflectanceSpectrum mirror_min_metal, mirror_max_metal;
    } spectra;
};

// A material's reflectances in the quantity a path carries: the RGB triples, or the spectra
// at the path's wavelengths.
template <class Q>
struct LobeColours {
    Q diffuse, glossy, mirror_min, mirror_max, transmission;
    Q mirror_min_metal, mirror_max_metal;
};
LobeColours<Rgb> lobe_colours(const Material& m, NoWavelengths);
LobeColours<SampledSpectrum> lobe_colours(const Material& m, const SampledWavelengths& wavelengths);

// A white Lambertian surface (albedo 1 in every channel and at every wavelength): what an
// irradiance receiver stands for.
const Material& white_lambertian();

// An object's material at its surface points: one material for a texture the same everywhere;
// else the material made at the point (world coordinates, where the object's textures are
// placed) from its pigment patterns, normal patterns, layers and texture patterns. Patterns
// the scene language cannot evaluate (surface coordinates, function images, ...) are refused.
// The normal patterns of a texture's parts tilt its one shading normal together, each weighted
// by the share of its part, as the lobes are.
class ObjectMaterial {
public:
    // Refuses what the renderer does not render of the object's appearance (Error, "not
    // supported: ..."). `emission_scale` converts W/(m^2 sr) to the renderer's radiance unit
    // (units.h); `decoding` gives the pigment's linear colour (colour_decoding.h).
    ObjectMaterial(const ObjectInstance& object, double emission_scale,
                   const ColourDecoding& decoding);

    // The material at `point`, where the outward geometric normal is `normal`: the uniform
    // one, or one made in `scratch` (without the spectra of spectral transport, which refuses
    // materials that vary). `scratch` is constructed only then: a Material is 520 bytes,
    // and most objects' materials are uniform.
    const Material& at(Vec3 point, Vec3 normal, std::optional<Material>& scratch) const;
    bool patterned() const { return texture_ != nullptr; }
    // Whether some point may emit (a texture that varies: some part has finish emission).
    bool emits() const { return emits_; }

private:
    struct Maker;
    Maker maker(Vec3 normal) const;

    Material uniform_;
    std::shared_ptr<const Texture> texture_;  // set when the material varies
    bool emits_ = false;
    double ior_ = 1, emission_scale_ = 1;
    ColourDecoding decoding_;
};

template <class Q>
struct BsdfSampleOf {
    Vec3 wi;
    Q weight;        // f |cos| / pdf, lobe choice included
    double pdf = 0;  // solid-angle pdf of the non-delta lobes (0 for a delta lobe)
    bool delta = false;
};

// A material at one surface point seen from direction `wo` (unit, pointing away from it), in
// the quantity Q a path carries (Rgb, or SampledSpectrum at the path's wavelengths). Lobes are
// chosen from the RGB albedos in both cases, so both make the same sampling decisions.
template <class Q>
class BsdfOf {
public:
    // `normal`: the surface's geometric normal, outward for closed shapes (dielectrics use it
    // to tell entering from leaving). `shading_normal` may differ (interpolated mesh normals);
    // the material's bump tilts it.
    BsdfOf(const Material& material, Vec3 normal, Vec3 shading_normal, Vec3 wo,
           const WavelengthsFor<Q>& wavelengths = {});

    bool has_smooth_lobes() const { return odds_.diffuse + odds_.glossy > 0; }
    // f |cos(wi)| of the non-delta lobes, and their sampling pdf.
    Q eval(Vec3 wi) const;
    // The same as the two factors of f |cos(wi)| = diffuse_factor x diffuse albedo +
    // glossy_factor x glossy albedo, for light carried at other wavelengths (photons).
    void smooth_factors(Vec3 wi, double& diffuse_factor, double& glossy_factor) const;
    double pdf(Vec3 wi) const;
    // The density with which the BSDF of the same point made for `wi` samples the direction
    // this one was made for: the way back along a path, as bidirectional weights want it.
    // Computed here with the two directions exchanged and, for a mirror lobe, the lobe odds
    // of `wi`: no second BSDF to make.
    double pdf_reversed(Vec3 wi) const;
    bool sample(double u_lobe, double u1, double u2, BsdfSampleOf<Q>& out) const;
    // The normal on the side `wo` is on: where reflected rays leave from.
    Vec3 facing_normal() const { return n_; }
    // The shading normal on that side, tilted by the material's bump: what the lobes turn on.
    Vec3 shading_normal() const { return ns_; }

private:
    // The probabilities of picking each lobe for light leaving toward `wo`.
    struct LobeOdds {
        double diffuse = 0, glossy = 0, mirror = 0, dielectric = 0;
    };
    LobeOdds lobe_odds(Vec3 wo) const;
    // The smooth lobes' density of sampling `sampled` given the other direction `given`, with
    // the lobes picked by these odds.
    double smooth_pdf(Vec3 sampled, Vec3 given, const LobeOdds& odds) const;
    double mirror_fraction(Vec3 wo) const;  // of the way from mirror_min to mirror_max
    Rgb mirror_weight_rgb(Vec3 wo) const;   // what the lobe choice uses
    Q mirror_weight() const;
    template <class Colour>
    Colour mirror_weight_of(const Colour& min, const Colour& max, const Colour& min_metal,
                            const Colour& max_metal, Vec3 wo) const;

    const Material& m_;
    LobeColours<Q> c_;
    Vec3 wo_, n_, ns_;
    bool entering_;
    // The diffuse lobe's scale: 1, or more where the shading normal is tilted off the
    // geometric one, so that the lobe still reflects its whole albedo above the surface.
    double diffuse_scale_;
    double cos_o_;
    LobeOdds odds_;  // for wo_
};

using Bsdf = BsdfOf<Rgb>;
using BsdfSample = BsdfSampleOf<Rgb>;

// Unpolarised Fresnel reflectance of a smooth dielectric interface; eta = n_t / n_i,
// cos_i > 0 on the incident side.
double fresnel_dielectric(double cos_i, double eta);

}  // namespace rayset::tracer
