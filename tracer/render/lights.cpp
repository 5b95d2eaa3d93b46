// POV-Ray lights as physical emitters (see lights.h and README.md).
#include "tracer/render/lights.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
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
double effective_solid_angle(const PointEmitter& light) {
    if (!light.spot) return 4 * kPi;
    const int n = 20000;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double mu = double(i) / n;
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        sum +=
            w * light.spot_factor(mu * light.axis + std::sqrt(1 - mu * mu) * Frame(light.axis).s);
    }
    return 2 * kPi * sum / (3.0 * n);
}

}  // namespace

double PointEmitter::spot_factor(Vec3 direction) const {
    if (!spot) return 1;
    const double c = dot(direction, axis);
    if (c <= 0) return 0;
    double factor = std::pow(c, tightness);
    if (cos_radius > 0 && c < cos_radius) factor *= cubic_spline(cos_falloff, cos_radius, c);
    return factor;
}

bool RectEmitter::crossed(Vec3 origin, Vec3 direction, double t_max, double& t,
                          double& cos_light) const {
    const double denom = dot(direction, normal);
    if (denom == 0 || (!two_sided && denom > 0)) return false;
    t = dot(centre - origin, normal) / denom;
    if (!(t > 0 && t < t_max)) return false;
    const Vec3 q = origin + t * direction - centre;
    if (std::abs(dot(q, dual1)) > 0.5 || std::abs(dot(q, dual2)) > 0.5) return false;
    cos_light = std::abs(denom);
    return true;
}

LightSet::LightSet(const std::vector<LightSource>& lights, const SceneUnits& units) {
    std::vector<double> point_powers, rect_powers;
    for (const LightSource& source : lights) {
        const std::string where = source.location.str();
        if (source.shadowless)
            throw Error(
                fmt::format("not supported: shadowless light_source (not physical) at {}", where));
        if (source.area_light && (source.circular || source.orient))
            throw Error(fmt::format(
                "not supported: circular/orient area_light (only rectangles) at {}", where));
        Rgb intensity = source.colour;
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
        PointEmitter point;
        point.position = source.position;
        point.intensity = intensity;
        point.intensity_spectrum = IlluminantSpectrum(intensity);
        point.spot = source.spotlight;
        if (point.spot) {
            const Vec3 axis = source.point_at - source.position;
            if (length(axis) == 0)
                throw Error(fmt::format("spotlight point_at equals its location at {}", where));
            point.axis = normalized(axis);
            point.cos_radius = std::cos(source.radius * kRadiansPerDegree);
            point.cos_falloff = std::cos(source.falloff * kRadiansPerDegree);
            point.tightness = source.tightness;
        }
        const double solid_angle = effective_solid_angle(point);
        if (!source.area_light) {
            points_.push_back(point);
            point_powers.push_back(average(intensity) * solid_angle);
            continue;
        }
        // The n1 x n2 POV-Ray lights share the colour, so together they emit
        // P = intensity * solid_angle; the rectangle emits the same power, Lambertian.
        RectEmitter rect;
        rect.centre = source.position;
        rect.edge1 = source.axis1;
        rect.edge2 = source.axis2;
        const Vec3 n = cross(rect.edge1, rect.edge2);
        rect.area = length(n);
        if (rect.area == 0) throw Error(fmt::format("area_light axes span no area at {}", where));
        rect.normal = (1 / rect.area) * n;
        // q = a edge1 + b edge2 gives a = dot(q, cross(edge2, n)) / |n|^2, b likewise.
        rect.dual1 = (1 / (rect.area * rect.area)) * cross(rect.edge2, n);
        rect.dual2 = (1 / (rect.area * rect.area)) * cross(n, rect.edge1);
        rect.two_sided = !point.spot;
        if (point.spot && dot(rect.normal, point.axis) < 0) rect.normal = -rect.normal;
        const double projected = (rect.two_sided ? 2 : 1) * kPi * rect.area;  // W per unit radiance
        rect.radiance = (solid_angle / projected) * intensity;
        rect.radiance_spectrum = IlluminantSpectrum(rect.radiance);
        rects_.push_back(rect);
        rect_powers.push_back(average(intensity) * solid_angle);
    }
    rects_low_ = {1e300, 1e300, 1e300}, rects_high_ = {-1e300, -1e300, -1e300};
    for (const RectEmitter& r : rects_)
        for (double a : {-0.5, 0.5})
            for (double b : {-0.5, 0.5}) {
                const Vec3 c = r.centre + a * r.edge1 + b * r.edge2;
                rects_low_ = {std::min(rects_low_.x, c.x), std::min(rects_low_.y, c.y),
                              std::min(rects_low_.z, c.z)};
                rects_high_ = {std::max(rects_high_.x, c.x), std::max(rects_high_.y, c.y),
                               std::max(rects_high_.z, c.z)};
            }
    // Widened once here: the box test runs for every ray the path tracer casts.
    for (int k = 0; k < 3; ++k) {
        double& lo = k == 0 ? rects_low_.x : k == 1 ? rects_low_.y : rects_low_.z;
        double& hi = k == 0 ? rects_high_.x : k == 1 ? rects_high_.y : rects_high_.z;
        const double margin = 1e-9 * (std::abs(lo) + std::abs(hi) + (hi - lo)) + 1e-300;
        lo -= margin, hi += margin;
    }
    for (double p : point_powers) cdf_.push_back(total_power_ += p);
    for (double p : rect_powers) cdf_.push_back(total_power_ += p);
    for (size_t i = 0; i < cdf_.size(); ++i)
        probability_.push_back(total_power_ > 0 ? (cdf_[i] - (i ? cdf_[i - 1] : 0)) / total_power_
                                                : 0);
}

size_t LightSet::choose(double u_select) const {
    const double x = u_select * total_power_;
    size_t i = 0;
    if (cdf_.size() <= 16) {
        // The index upper_bound finds, counted without branches: for a handful of lights this
        // is faster than a binary search whose branches the processor cannot predict.
        for (double c : cdf_) i += c <= x;
    } else {
        i = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), x) - cdf_.begin());
    }
    return std::min(i, cdf_.size() - 1);
}

bool LightSet::sample(Vec3 p, double u_select, double u1, double u2, LightSample& out) const {
    if (total_power_ <= 0) return false;
    const size_t i = choose(u_select);
    const double chosen = selection_probability(i);
    if (i < points_.size()) {
        const PointEmitter& light = points_[i];
        const Vec3 d = light.position - p;
        out.distance = length(d);
        if (out.distance == 0) return false;
        out.direction = (1 / out.distance) * d;
        out.spectrum_factor = light.spot_factor(-out.direction) / (out.distance * out.distance);
        out.radiance = out.spectrum_factor * light.intensity;
        out.spectrum = &light.intensity_spectrum;
        out.pdf = chosen;
        out.delta = true;
        return true;
    }
    const RectEmitter& rect = rects_[i - points_.size()];
    const Vec3 q = rect.centre + (u1 - 0.5) * rect.edge1 + (u2 - 0.5) * rect.edge2;
    const Vec3 d = q - p;
    out.distance = length(d);
    if (out.distance == 0) return false;
    out.direction = (1 / out.distance) * d;
    double cos_light = -dot(out.direction, rect.normal);
    if (rect.two_sided) cos_light = std::abs(cos_light);
    if (cos_light <= 0) return false;
    out.radiance = rect.radiance;
    out.spectrum = &rect.radiance_spectrum;
    out.spectrum_factor = 1;
    out.pdf = chosen * out.distance * out.distance / (rect.area * cos_light);
    out.delta = false;
    return true;
}

namespace {

// Slab test of a ray against a box (already widened: the box of coplanar rectangles is flat).
bool crosses_box(Vec3 origin, Vec3 direction, double t_max, Vec3 low, Vec3 high) {
    double t0 = 0, t1 = t_max;
    const double o[3] = {origin.x, origin.y, origin.z},
                 d[3] = {direction.x, direction.y, direction.z};
    const double lo[3] = {low.x, low.y, low.z}, hi[3] = {high.x, high.y, high.z};
    // A ray outside a slab and heading away from it misses the box: decided by signs alone,
    // before any division. For a unit direction the slab test below says the same (both its
    // distances are negative), so this changes no outcome, only what those rays cost. A NaN
    // t_max makes the slab test reject nothing: then neither does this.
    bool away = false;
    for (int k = 0; k < 3; ++k) away |= (o[k] < lo[k] && d[k] < 0) | (o[k] > hi[k] && d[k] > 0);
    if (away && !std::isnan(t_max)) return false;
    for (int k = 0; k < 3; ++k) {
        const double inverse = 1 / d[k];
        double near = (lo[k] - o[k]) * inverse, far = (hi[k] - o[k]) * inverse;
        if (near > far) std::swap(near, far);
        if (std::isnan(near)) {  // parallel to the slab: inside it or not
            if (o[k] < lo[k] || o[k] > hi[k]) return false;
            continue;
        }
        t0 = std::max(t0, near), t1 = std::min(t1, far);
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace

template <class Q>
Q LightSet::crossed(Vec3 origin, Vec3 direction, double t_max, double bsdf_pdf,
                    const WavelengthsFor<Q>& wavelengths) const {
    Q sum{};
    if (rects_.empty() || !crosses_box(origin, direction, t_max, rects_low_, rects_high_))
        return sum;
    for (size_t k = 0; k < rects_.size(); ++k) {
        double t = 0, cos_light = 0;
        if (!rects_[k].crossed(origin, direction, t_max, t, cos_light)) continue;
        double weight = 1;
        if (bsdf_pdf >= 0) {
            const double light_pdf =
                selection_probability(points_.size() + k) * t * t / (rects_[k].area * cos_light);
            weight = power_heuristic(bsdf_pdf, light_pdf);
        }
        sum += weight * emitted(rects_[k].radiance, rects_[k].radiance_spectrum, wavelengths);
    }
    return sum;
}

Rgb LightSet::crossed_radiance(Vec3 origin, Vec3 direction, double t_max, double bsdf_pdf,
                               NoWavelengths w) const {
    return crossed<Rgb>(origin, direction, t_max, bsdf_pdf, w);
}

SampledSpectrum LightSet::crossed_radiance(Vec3 origin, Vec3 direction, double t_max,
                                           double bsdf_pdf,
                                           const SampledWavelengths& wavelengths) const {
    return crossed<SampledSpectrum>(origin, direction, t_max, bsdf_pdf, wavelengths);
}

SampledSpectrum arriving_radiance(const LightSample& s, const SampledWavelengths& wavelengths) {
    if (!s.spectrum) return {};
    return s.spectrum_factor * emitted(s.radiance, *s.spectrum, wavelengths);
}

}  // namespace rayset::tracer
