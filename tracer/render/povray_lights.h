// POV-Ray light sources read physically (the unit conventions are in README.md beside this
// file): point and spot lights as point emitters of radiant intensity in W/sr, area lights as
// Lambertian rectangles or ellipses (circular), oriented area lights as Lambertian spheres.
// Each kind answers the queries of the light interface (light.h).
#pragma once

#include <optional>
#include <vector>

#include "tracer/render/colour_decoding.h"
#include "tracer/render/light_samples.h"
#include "tracer/render/rgb.h"
#include "tracer/render/rgb_upsampling.h"
#include "tracer/render/units.h"

namespace rayset::tracer {

// POV-Ray's spotlight: the share of a light's axial intensity it sends along a direction.
struct SpotProfile {
    Vec3 axis;  // unit, toward point_at
    double cos_radius = 0, cos_falloff = 0, tightness = 0;

    // POV-Ray's spotlight factor (Attenuate_Light) for a unit direction leaving the light.
    double factor(Vec3 direction) const;
    // A direction uniform over the cone the factor is not zero in, for uniform u1, u2; returns
    // the cone's solid angle.
    double sample_cone(double u1, double u2, Vec3& direction) const;
    // The density sample_cone draws a unit direction with (sr^-1).
    double cone_pdf(Vec3 direction) const;
};

// A point or spot light: radiant intensity `intensity` W/sr along the axis (spot) or in every
// direction, inverse-square law.
struct PointLight {
    Vec3 position;
    Rgb intensity;
    IlluminantSpectrum intensity_spectrum;  // the same for spectral transport
    std::optional<SpotProfile> spot;
    bool shadowless = false;        // POV-Ray's shadowless light: its light passes through objects
    bool media_interaction = true;  // false: media do not scatter its light (POV-Ray's flag)
    double emitted_power = 0;       // W, average over channels

    double spot_factor(Vec3 direction) const { return spot ? spot->factor(direction) : 1; }

    double power() const { return emitted_power; }
    bool photons_only() const { return false; }
    template <class Q>
    bool sample_Li(Vec3 ref, const LightUniforms& u, double chosen,
                   const WavelengthsFor<Q>& wavelengths, LightLiSampleOf<Q>& out) const;
    bool crossed(Vec3, Vec3, double, double&) const { return false; }
    double pdf_Li(Vec3, Vec3, double, double) const { return 0; }
    template <class Q>
    Q radiance(Vec3, Vec3, const WavelengthsFor<Q>&) const {
        return {};
    }
    // Directions uniform over the cone the spot factor is not zero in (the sphere for a point).
    template <class Q>
    LightPhotonOf<Q> sample_Le(const double u[7], double u_wavelength) const;
    double pdf_Le(Vec3 origin, Vec3 wi, double t, double chosen) const;
    lightmodel::BinnedSpectrum spectrum() const;
};

// An area light: a Lambertian rectangle of radiance `radiance` (renderer units), one-sided
// toward `normal` or two-sided; or the ellipse inscribed in it (a circular area light).
struct RectLight {
    Vec3 centre, edge1, edge2;
    Vec3 normal;  // unit; the emitting side (both sides when two_sided)
    bool two_sided = false;
    bool elliptical = false;
    double area = 0;
    Rgb radiance_rgb;                      // W/(unit^2 sr)
    IlluminantSpectrum radiance_spectrum;  // the same for spectral transport
    Vec3 dual1, dual2;         // dot(q, dual_k) is q's coordinate along edge_k, for q in the plane
    double emitted_power = 0;  // W, average over channels

    double power() const { return emitted_power; }
    bool photons_only() const { return false; }
    template <class Q>
    bool sample_Li(Vec3 ref, const LightUniforms& u, double chosen,
                   const WavelengthsFor<Q>& wavelengths, LightLiSampleOf<Q>& out) const;
    // Distance along (origin, unit direction) to the rectangle in (0, t_max), if crossed from
    // an emitting side.
    bool crossed(Vec3 origin, Vec3 direction, double t_max, double& t) const;
    double pdf_Li(Vec3 ref, Vec3 wi, double t, double chosen) const;
    template <class Q>
    Q radiance(Vec3, Vec3, const WavelengthsFor<Q>& wavelengths) const {
        return emitted(radiance_rgb, radiance_spectrum, wavelengths);
    }
    // A uniform point, a cosine-distributed direction on an emitting side.
    template <class Q>
    LightPhotonOf<Q> sample_Le(const double u[7], double u_wavelength) const;
    double pdf_Le(Vec3 origin, Vec3 wi, double t, double chosen) const;
    lightmodel::BinnedSpectrum spectrum() const;
    void extend_bounds(Vec3& low, Vec3& high) const;  // by the body's box

private:
    Vec3 point_at(double u0, double u1) const;  // uniform on the body for uniform u0, u1
};

// An oriented area light: a sphere seen from every point as a disc facing it, as POV-Ray turns
// an oriented light's disc toward each point it lights. Its radiance along a direction w
// leaving it is `radiance` times the spot factor of w (1 without a spot): Lambertian, or a
// spotlight whose far field is the point spotlight's.
struct SphereLight {
    Vec3 centre;
    double radius = 0;
    Rgb radiance_rgb;                      // W/(unit^2 sr)
    IlluminantSpectrum radiance_spectrum;  // the same for spectral transport
    std::optional<SpotProfile> spot;
    double emitted_power = 0;  // W, average over channels

    double power() const { return emitted_power; }
    bool photons_only() const { return false; }
    // Uniform in the cone of directions the sphere fills seen from `ref` (outside it).
    template <class Q>
    bool sample_Li(Vec3 ref, const LightUniforms& u, double chosen,
                   const WavelengthsFor<Q>& wavelengths, LightLiSampleOf<Q>& out) const;
    // Distance along (origin, unit direction) to the sphere in (0, t_max), from outside it.
    bool crossed(Vec3 origin, Vec3 direction, double t_max, double& t) const;
    double pdf_Li(Vec3 ref, Vec3 wi, double t, double chosen) const;
    template <class Q>
    Q radiance(Vec3, Vec3 direction, const WavelengthsFor<Q>& wavelengths) const {
        const double factor = spot ? spot->factor(-direction) : 1;
        return factor * emitted(radiance_rgb, radiance_spectrum, wavelengths);
    }
    // A uniform point, a cosine-distributed direction about the outward normal there; with a
    // spot, a direction in the spot's cone and a point uniform over the disc facing it.
    template <class Q>
    LightPhotonOf<Q> sample_Le(const double u[7], double u_wavelength) const;
    double pdf_Le(Vec3 origin, Vec3 wi, double t, double chosen) const;
    lightmodel::BinnedSpectrum spectrum() const;
    void extend_bounds(Vec3& low, Vec3& high) const;  // by the body's box

private:
    double cone_solid_angle(Vec3 ref) const;  // of the directions toward it from `ref`
};

struct PovrayLights {
    std::vector<PointLight> points;
    std::vector<RectLight> rects;
    std::vector<SphereLight> spheres;
};
// The scene's light_source statements; throws rayset::Error, naming the statement, for what
// it does not render (shadowless area lights, fade powers other than 2).
// Shadowless point and spot lights light every point they face, as POV-Ray's do: not
// physical (RenderScene::notes says so).
PovrayLights read_povray_lights(const std::vector<LightSource>& lights, const SceneUnits& units,
                                const ColourDecoding& decoding);

}  // namespace rayset::tracer
