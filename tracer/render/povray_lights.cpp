// POV-Ray lights as physical emitters (see povray_lights.h and README.md).
#include "tracer/render/povray_lights.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/render/light_samples.h"
#include "tracer/render/sampling.h"

namespace rayset::tracer {

namespace {

// POV-Ray's cubic_spline: 0 below `low`, 1 from `high`, smoothstep between.
double cubic_spline(double low, double high, double x) {
    if (x < low) return 0;
    if (x >= high) return 1;
    const double s = (x - low) / (high - low);
    return (3 - 2 * s) * s * s;
}

// Solid angle weighted by the spotlight factor: integral of spot_factor over the sphere
// (Simpson's rule in cos(theta); 4 pi for a plain point light).
double effective_solid_angle(const PointLight& light) {
    if (!light.spot) return 4 * kPi;
    const Vec3 axis = light.spot->axis;
    const int n = 20000;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double mu = double(i) / n;
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        sum += w * light.spot->factor(mu * axis + std::sqrt(1 - mu * mu) * Frame(axis).s);
    }
    return 2 * kPi * sum / (3.0 * n);
}

}  // namespace

double SpotProfile::factor(Vec3 direction) const {
    const double c = dot(direction, axis);
    if (c <= 0) return 0;
    double factor = std::pow(c, tightness);
    if (cos_radius > 0 && c < cos_radius) factor *= cubic_spline(cos_falloff, cos_radius, c);
    return factor;
}

// The factor is zero behind the light and, with a radius, outside the falloff cone.
double SpotProfile::sample_cone(double u1, double u2, Vec3& direction) const {
    const double cos_edge = std::max(0.0, cos_radius > 0 ? cos_falloff : 0.0);
    const double cos_theta = 1 - u1 * (1 - cos_edge), phi = 2 * kPi * u2;
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    const Vec3 local{sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
    direction = normalized(Frame(axis).to_world(local));
    return 2 * kPi * (1 - cos_edge);
}

double SpotProfile::cone_pdf(Vec3 direction) const {
    const double cos_edge = std::max(0.0, cos_radius > 0 ? cos_falloff : 0.0);
    return dot(direction, axis) > cos_edge ? 1 / (2 * kPi * (1 - cos_edge)) : 0;
}

double PointLight::pdf_Le(Vec3, Vec3 wi, double, double chosen) const {
    return chosen * (spot ? spot->cone_pdf(-wi) : 1 / (4 * kPi));
}

// A uniform point (1 / A) and side, a cosine-distributed direction (cos / pi): per unit area
// across the ray the cosines cancel.
double RectLight::pdf_Le(Vec3, Vec3 wi, double, double chosen) const {
    if (!two_sided && dot(wi, normal) >= 0) return 0;
    return chosen / ((two_sided ? 2 : 1) * area * kPi);
}

// Without a spot, a uniform point of the sphere (1 / (4 pi r^2)) and a cosine-distributed
// direction (cos / pi); with one, a direction of the cone and a uniform point of the disc of
// area pi r^2 across it.
double SphereLight::pdf_Le(Vec3, Vec3 wi, double, double chosen) const {
    if (!spot) return chosen / (4 * kPi * kPi * radius * radius);
    return chosen * spot->cone_pdf(-wi) / (kPi * radius * radius);
}

bool RectLight::crossed(Vec3 origin, Vec3 direction, double t_max, double& t) const {
    const double denom = dot(direction, normal);
    if (denom == 0 || (!two_sided && denom > 0)) return false;
    t = dot(centre - origin, normal) / denom;
    if (!(t > 0 && t < t_max)) return false;
    const Vec3 q = origin + t * direction - centre;
    const double a = dot(q, dual1), b = dot(q, dual2);
    return elliptical ? a * a + b * b <= 0.25 : std::abs(a) <= 0.5 && std::abs(b) <= 0.5;
}

Vec3 RectLight::point_at(double u0, double u1) const {
    if (!elliptical) return centre + (u0 - 0.5) * edge1 + (u1 - 0.5) * edge2;
    const double r = 0.5 * std::sqrt(u0), phi = 2 * kPi * u1;
    return centre + (r * std::cos(phi)) * edge1 + (r * std::sin(phi)) * edge2;
}

void RectLight::extend_bounds(Vec3& low, Vec3& high) const {
    for (double a : {-0.5, 0.5})
        for (double b : {-0.5, 0.5}) {
            const Vec3 c = centre + a * edge1 + b * edge2;
            low = {std::min(low.x, c.x), std::min(low.y, c.y), std::min(low.z, c.z)};
            high = {std::max(high.x, c.x), std::max(high.y, c.y), std::max(high.z, c.z)};
        }
}

bool SphereLight::crossed(Vec3 origin, Vec3 direction, double t_max, double& t) const {
    const Vec3 from_centre = origin - centre;
    const double b = dot(from_centre, direction);
    const double c = dot(from_centre, from_centre) - radius * radius;
    if (c <= 0) return false;  // inside: the sphere emits outward only
    const double discriminant = b * b - c;
    if (discriminant < 0 || b > 0) return false;
    t = c / (-b + std::sqrt(discriminant));  // the nearer root, without cancellation
    return t > 0 && t < t_max;
}

double SphereLight::cone_solid_angle(Vec3 ref) const {
    const Vec3 d = centre - ref;
    const double sin2 = std::min(1.0, radius * radius / dot(d, d));
    return 2 * kPi * sin2 / (1 + std::sqrt(1 - sin2));  // 2 pi (1 - cos), without cancellation
}

double SphereLight::pdf_Li(Vec3 ref, Vec3, double, double chosen) const {
    return chosen / cone_solid_angle(ref);
}

void SphereLight::extend_bounds(Vec3& low, Vec3& high) const {
    low = {std::min(low.x, centre.x - radius), std::min(low.y, centre.y - radius),
           std::min(low.z, centre.z - radius)};
    high = {std::max(high.x, centre.x + radius), std::max(high.y, centre.y + radius),
            std::max(high.z, centre.z + radius)};
}

double RectLight::pdf_Li(Vec3, Vec3 wi, double t, double chosen) const {
    return chosen * t * t / (area * std::abs(dot(wi, normal)));
}

template <class Q>
bool PointLight::sample_Li(Vec3 ref, const LightUniforms&, double chosen,
                           const WavelengthsFor<Q>& wavelengths, LightLiSampleOf<Q>& out) const {
    const Vec3 d = position - ref;
    out.distance = length(d);
    if (out.distance == 0) return false;
    out.wi = (1 / out.distance) * d;
    const double factor = spot_factor(-out.wi) / (out.distance * out.distance);
    out.Li = factor * emitted(intensity, intensity_spectrum, wavelengths);
    out.pdf = chosen;
    out.delta = true;
    out.shadowless = shadowless;
    out.media_interaction = media_interaction;
    return true;
}

template <class Q>
bool RectLight::sample_Li(Vec3 ref, const LightUniforms& u, double chosen,
                          const WavelengthsFor<Q>& wavelengths, LightLiSampleOf<Q>& out) const {
    const Vec3 d = point_at(u.u[0], u.u[1]) - ref;
    out.distance = length(d);
    if (out.distance == 0) return false;
    out.wi = (1 / out.distance) * d;
    double cos_light = -dot(out.wi, normal);
    if (two_sided) cos_light = std::abs(cos_light);
    if (cos_light <= 0) return false;
    out.Li = emitted(radiance_rgb, radiance_spectrum, wavelengths);
    out.pdf = chosen * out.distance * out.distance / (area * cos_light);
    return true;
}

namespace {

// A photon's flux `watts` (per channel) of light with the spectrum `spectrum`, at wavelengths
// drawn from D65 (the shape of every POV-Ray light's spectrum up to a smooth factor).
template <class Q>
void set_photon_flux(LightPhotonOf<Q>& photon, const Rgb& watts, const IlluminantSpectrum& spectrum,
                     double u_wavelength) {
    if constexpr (std::is_same_v<Q, SampledSpectrum>) {
        static const lightmodel::BinnedSpectrum d65 = lightmodel::d65_spectrum();
        photon.wavelengths = SampledWavelengths::sample(d65, u_wavelength);
        photon.flux = emitted(watts, spectrum, photon.wavelengths);
    } else {
        photon.flux = watts;
    }
}

}  // namespace

template <class Q>
LightPhotonOf<Q> PointLight::sample_Le(const double u[7], double u_wavelength) const {
    LightPhotonOf<Q> photon;
    photon.origin = position;
    double solid_angle = 4 * kPi;
    if (spot)
        solid_angle = spot->sample_cone(u[1], u[2], photon.direction);
    else
        photon.direction = uniform_sphere(u[1], u[2]);
    set_photon_flux(photon, (spot_factor(photon.direction) * solid_angle) * intensity,
                    intensity_spectrum, u_wavelength);
    return photon;
}

template <class Q>
LightPhotonOf<Q> RectLight::sample_Le(const double u[7], double u_wavelength) const {
    LightPhotonOf<Q> photon;
    photon.origin = point_at(u[1], u[2]);
    const bool back = two_sided && u[0] < 0.5;
    const Vec3 side = back ? -normal : normal;
    photon.direction = normalized(Frame(side).to_world(cosine_hemisphere(u[3], u[4])));
    // L cos dA dw over (cos / pi) / A, times the two sides' choice.
    const double sides = two_sided ? 2 : 1;
    set_photon_flux(photon, (sides * kPi * area) * radiance_rgb, radiance_spectrum, u_wavelength);
    return photon;
}

template <class Q>
bool SphereLight::sample_Li(Vec3 ref, const LightUniforms& u, double chosen,
                            const WavelengthsFor<Q>& wavelengths, LightLiSampleOf<Q>& out) const {
    const Vec3 d = centre - ref;
    const double distance = length(d);
    if (!(distance > radius)) return false;
    const double sin2_max = radius * radius / (distance * distance);
    const double one_minus_cos_max = sin2_max / (1 + std::sqrt(1 - sin2_max));
    const double cos_theta = 1 - u.u[0] * one_minus_cos_max;
    const double sin2_theta = std::max(0.0, (1 - cos_theta) * (1 + cos_theta));
    const double sin_theta = std::sqrt(sin2_theta), phi = 2 * kPi * u.u[1];
    out.wi = normalized(
        Frame((1 / distance) * d)
            .to_world({sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta}));
    // The nearer crossing along wi; at the cone's edge the ray grazes the sphere.
    const double half_chord =
        std::sqrt(std::max(0.0, radius * radius - distance * distance * sin2_theta));
    out.distance = distance * cos_theta - half_chord;
    out.Li = radiance<Q>(ref, out.wi, wavelengths);
    out.pdf = chosen / (2 * kPi * one_minus_cos_max);
    return true;
}

template <class Q>
LightPhotonOf<Q> SphereLight::sample_Le(const double u[7], double u_wavelength) const {
    LightPhotonOf<Q> photon;
    if (!spot) {
        const Vec3 n = uniform_sphere(u[1], u[2]);
        photon.origin = centre + radius * n;
        photon.direction = normalized(Frame(n).to_world(cosine_hemisphere(u[3], u[4])));
        // L cos dA dw over (cos / pi) / A.
        set_photon_flux(photon, (kPi * 4 * kPi * radius * radius) * radiance_rgb, radiance_spectrum,
                        u_wavelength);
        return photon;
    }
    // Seen along w the sphere is a disc of area pi r^2: a point uniform on it, moved along w
    // onto the sphere; flux L(w) pi r^2 over the direction's density.
    const double solid_angle = spot->sample_cone(u[1], u[2], photon.direction);
    const Frame frame(photon.direction);
    const double rho = radius * std::sqrt(u[3]), phi = 2 * kPi * u[4];
    const double along = std::sqrt(std::max(0.0, radius * radius - rho * rho));
    photon.origin = centre + frame.to_world({rho * std::cos(phi), rho * std::sin(phi), along});
    const double weight = spot->factor(photon.direction) * kPi * radius * radius * solid_angle;
    set_photon_flux(photon, weight * radiance_rgb, radiance_spectrum, u_wavelength);
    return photon;
}

lightmodel::BinnedSpectrum PointLight::spectrum() const { return lightmodel::d65_spectrum(); }
lightmodel::BinnedSpectrum RectLight::spectrum() const { return lightmodel::d65_spectrum(); }
lightmodel::BinnedSpectrum SphereLight::spectrum() const { return lightmodel::d65_spectrum(); }

namespace {

PointLight point_light_of(const LightSource& source, Rgb colour, const SceneUnits& units,
                          const std::string& where) {
    Rgb intensity = colour;
    // POV-Ray's fade 2 / (1 + (d/d0)^2) tends to 2 d0^2 / d^2: read as inverse-square with the
    // same far-field value. Other fade powers have no physical reading.
    if (source.fade_distance > 0 && source.fade_power > 0) {
        if (source.fade_power != 2)
            throw Error(fmt::format(
                "not supported: fade_power {} (only 2, read as the inverse-square law) at {}",
                source.fade_power, where));
        const double d0 = source.fade_distance * units.metres_per_unit;
        intensity = (2 * d0 * d0) * intensity;
    }
    PointLight point;
    point.position = source.position;
    point.intensity = intensity;
    point.intensity_spectrum = IlluminantSpectrum(intensity);
    if (source.spotlight) {
        const Vec3 axis = source.point_at - source.position;
        if (length(axis) == 0)
            throw Error(fmt::format("spotlight point_at equals its location at {}", where));
        SpotProfile& spot = point.spot.emplace();
        spot.axis = normalized(axis);
        spot.cos_radius = std::cos(source.radius * kRadiansPerDegree);
        spot.cos_falloff = std::cos(source.falloff * kRadiansPerDegree);
        spot.tightness = source.tightness;
    }
    return point;
}

// The n1 x n2 POV-Ray lights of an area light share the colour, so together they emit the
// power of `point`; the rectangle (or ellipse) emits the same power, Lambertian.
RectLight rect_light_of(const LightSource& source, const PointLight& point, double solid_angle,
                        const std::string& where) {
    RectLight rect;
    rect.centre = source.position;
    rect.edge1 = source.axis1;
    rect.edge2 = source.axis2;
    rect.elliptical = source.circular;
    const Vec3 n = cross(rect.edge1, rect.edge2);
    const double parallelogram = length(n);
    if (parallelogram == 0) throw Error(fmt::format("area_light axes span no area at {}", where));
    rect.area = rect.elliptical ? kPi / 4 * parallelogram : parallelogram;
    rect.normal = (1 / parallelogram) * n;
    // q = a edge1 + b edge2 gives a = dot(q, cross(edge2, n)) / |n|^2, b likewise.
    rect.dual1 = (1 / (parallelogram * parallelogram)) * cross(rect.edge2, n);
    rect.dual2 = (1 / (parallelogram * parallelogram)) * cross(n, rect.edge1);
    rect.two_sided = !point.spot;
    if (point.spot && dot(rect.normal, point.spot->axis) < 0) rect.normal = -rect.normal;
    const double projected = (rect.two_sided ? 2 : 1) * kPi * rect.area;  // W per unit radiance
    rect.emitted_power = point.emitted_power;
    rect.radiance_rgb = (solid_angle / projected) * point.intensity;
    rect.radiance_spectrum = IlluminantSpectrum(rect.radiance_rgb);
    return rect;
}

// An oriented area light (POV-Ray makes it circular, both axes as long as the first): a sphere
// of that diameter emitting the power of `point`, in its directions.
SphereLight sphere_light_of(const LightSource& source, const PointLight& point,
                            const std::string& where) {
    SphereLight sphere;
    sphere.centre = source.position;
    sphere.radius = 0.5 * length(source.axis1);
    if (sphere.radius == 0) throw Error(fmt::format("area_light axis of length 0 at {}", where));
    // The far field of radiance L0 s(w) from a disc of area pi r^2 is the point light's
    // intensity I s(w): L0 = I / (pi r^2), Lambertian (s = 1) or spot alike.
    sphere.spot = point.spot;
    sphere.emitted_power = point.emitted_power;
    sphere.radiance_rgb = (1 / (kPi * sphere.radius * sphere.radius)) * point.intensity;
    sphere.radiance_spectrum = IlluminantSpectrum(sphere.radiance_rgb);
    return sphere;
}

}  // namespace

PovrayLights read_povray_lights(const std::vector<LightSource>& lights, const SceneUnits& units,
                                const ColourDecoding& decoding) {
    PovrayLights out;
    for (const LightSource& source : lights) {
        const std::string where = source.location.str();
        if (source.shadowless && source.area_light)
            throw Error(fmt::format("not supported: shadowless area_light at {}", where));
        PointLight point = point_light_of(source, decoding(source.colour), units, where);
        point.shadowless = source.shadowless;
        point.media_interaction = source.media_interaction;
        const double solid_angle = effective_solid_angle(point);
        point.emitted_power = average(point.intensity) * solid_angle;
        if (source.area_light && source.orient)
            out.spheres.push_back(sphere_light_of(source, point, where));
        else if (source.area_light)
            out.rects.push_back(rect_light_of(source, point, solid_angle, where));
        else
            out.points.push_back(point);
    }
    return out;
}

#define RAYSET_POVRAY_LIGHT_QUERIES(Q)                                                            \
    template bool PointLight::sample_Li<Q>(Vec3, const LightUniforms&, double,                    \
                                           const WavelengthsFor<Q>&, LightLiSampleOf<Q>&) const;  \
    template bool RectLight::sample_Li<Q>(Vec3, const LightUniforms&, double,                     \
                                          const WavelengthsFor<Q>&, LightLiSampleOf<Q>&) const;   \
    template bool SphereLight::sample_Li<Q>(Vec3, const LightUniforms&, double,                   \
                                            const WavelengthsFor<Q>&, LightLiSampleOf<Q>&) const; \
    template LightPhotonOf<Q> PointLight::sample_Le<Q>(const double[7], double) const;            \
    template LightPhotonOf<Q> RectLight::sample_Le<Q>(const double[7], double) const;             \
    template LightPhotonOf<Q> SphereLight::sample_Le<Q>(const double[7], double) const;
RAYSET_POVRAY_LIGHT_QUERIES(Rgb)
RAYSET_POVRAY_LIGHT_QUERIES(SampledSpectrum)
#undef RAYSET_POVRAY_LIGHT_QUERIES

}  // namespace rayset::tracer
