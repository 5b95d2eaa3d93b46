// POV-Ray light sources read physically (the unit conventions are in README.md beside this
// file): point and spot lights as point emitters of radiant intensity in W/sr, area lights as
// Lambertian rectangles. Lights are chosen for next-event estimation in proportion to power.
#pragma once

#include <vector>

#include "tracer/render/rgb.h"
#include "tracer/render/rgb_upsampling.h"
#include "tracer/render/units.h"

namespace rayset::tracer {

struct PointEmitter {
    Vec3 position;
    Rgb intensity;                          // W/sr along the axis (spot) or in every direction
    IlluminantSpectrum intensity_spectrum;  // the same for spectral transport
    bool spot = false;
    Vec3 axis;  // unit, toward point_at
    double cos_radius = 0, cos_falloff = 0, tightness = 0;
    // POV-Ray's spotlight factor (Attenuate_Light) for a unit direction leaving the light.
    double spot_factor(Vec3 direction) const;
};

struct RectEmitter {
    Vec3 centre, edge1, edge2;
    Vec3 normal;  // unit; the emitting side (both sides when two_sided)
    bool two_sided = false;
    double area = 0;
    Rgb radiance;                          // renderer units, W/(unit^2 sr)
    IlluminantSpectrum radiance_spectrum;  // the same for spectral transport
    Vec3 dual1, dual2;  // dot(q, dual_k) is q's coordinate along edge_k, for q in the plane
    // Distance along (origin, unit direction) to the rectangle in (0, t_max), if crossed from an
    // emitting side; `cos_light` receives |cos| at the light.
    bool crossed(Vec3 origin, Vec3 direction, double t_max, double& t, double& cos_light) const;
};

struct LightSample {
    Vec3 direction;  // unit, from the shaded point toward the light
    double distance = 0;
    Rgb radiance;        // arriving radiance (area) or intensity / d^2 (point): divide by pdf
    double pdf = 0;      // solid-angle pdf including the choice of the light; 1 for points
    bool delta = false;  // point emitter: no MIS
    // For spectral transport: the radiance is spectrum_factor x the light's spectrum.
    const IlluminantSpectrum* spectrum = nullptr;
    double spectrum_factor = 0;
};

// A light sample's radiance in the quantity a path carries.
inline Rgb arriving_radiance(const LightSample& s, NoWavelengths) { return s.radiance; }
SampledSpectrum arriving_radiance(const LightSample& s, const SampledWavelengths& wavelengths);

class LightSet {
public:
    LightSet() = default;
    LightSet(const std::vector<LightSource>& lights, const SceneUnits& units);

    bool empty() const { return points_.empty() && rects_.empty(); }
    const std::vector<PointEmitter>& points() const { return points_; }
    const std::vector<RectEmitter>& rects() const { return rects_; }
    double total_power() const { return total_power_; }  // W, average over channels

    // Picks a light (probability proportional to power) and a point on it as seen from p.
    bool sample(Vec3 p, double u_select, double u1, double u2, LightSample& out) const;
    // Radiance of area lights a ray crosses before t_max, each weighted by the power heuristic
    // against `bsdf_pdf` (pass bsdf_pdf < 0 for rays no light sampling could have made:
    // camera rays and delta bounces, weight 1).
    // Spectral transport passes the path's wavelengths.
    Rgb crossed_radiance(Vec3 origin, Vec3 direction, double t_max, double bsdf_pdf,
                         NoWavelengths = {}) const;
    SampledSpectrum crossed_radiance(Vec3 origin, Vec3 direction, double t_max, double bsdf_pdf,
                                     const SampledWavelengths& wavelengths) const;

private:
    template <class Q>
    Q crossed(Vec3 origin, Vec3 direction, double t_max, double bsdf_pdf,
              const WavelengthsFor<Q>& wavelengths) const;
    double selection_probability(size_t light_index) const { return probability_[light_index]; }
    size_t choose(double u_select) const;  // index into cdf_, proportional to power

    std::vector<PointEmitter> points_;
    std::vector<RectEmitter> rects_;
    std::vector<double> cdf_;          // over points_ then rects_
    std::vector<double> probability_;  // of choosing each light
    Vec3 rects_low_,
        rects_high_;  // box around every rectangle, widened a little: most rays miss it at once
    double total_power_ = 0;
};

}  // namespace rayset::tracer
