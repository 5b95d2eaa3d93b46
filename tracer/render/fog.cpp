#include "tracer/render/fog.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/scene_language/noise.h"

namespace rayset::tracer {
namespace {

[[noreturn]] void refuse(const std::string& feature, const SourceLocation& where) {
    throw Error(fmt::format("not supported: {} at {}", feature, where.str()));
}

// The integral of 1 / (1 + k^2) over the height h, k = (h - offset) / altitude, from h0 to h1
// with the density 1 below offset.
double ground_column(double h0, double h1, double offset, double altitude) {
    if (h0 > h1) std::swap(h0, h1);
    double sum = 0;
    if (h0 < offset) sum += std::min(h1, offset) - h0;
    if (h1 > offset) {
        const double k0 = (std::max(h0, offset) - offset) / altitude;
        const double k1 = (h1 - offset) / altitude;
        sum += altitude * (std::atan(k1) - std::atan(k0));
    }
    return sum;
}

}  // namespace

FogMedium::FogMedium(const SceneDescription& scene, double to_internal)
    : to_internal_(to_internal) {
    const auto& fogs = scene.atmosphere.fogs;
    if (fogs.empty()) return;
    if (fogs.size() > 1) refuse("more than one fog", fogs[1].location);
    const auto& fog = fogs.front();
    if (fog.distance <= 0) return;  // POV-Ray draws no fog of no distance
    present_ = true;
    ground_ = fog.fog_type == 2;
    distance_ = fog.distance;
    offset_ = fog.fog_offset;
    altitude_ = fog.fog_alt;
    if (ground_ && !(altitude_ > 0)) refuse("ground fog without a positive fog_alt", fog.location);
    up_ = normalized(fog.up);
    const ColourDecoding decoding(scene.global);
    colour_ = decoding(fog.colour.rgb());
    const double filter = fog.colour.filter;
    tint_ = Rgb{1 - filter, 1 - filter, 1 - filter} + filter * colour_;
    transmit_ = fog.colour.transmit;
    turbulent_ = !is_zero(fog.turbulence);
    turbulence_ = fog.turbulence;
    turb_depth_ = fog.turb_depth;
    octaves_ = fog.octaves, omega_ = fog.omega, lambda_ = fog.lambda;
    noise_generator_ = scene.global.noise_generator;
    world_to_fog_ = fog.transform.inverse();
}

double FogMedium::turbulence_factor(Vec3 origin, Vec3 direction, double length) const {
    const Vec3 p = world_to_fog_.point(origin + (turb_depth_ * length) * direction);
    const Vec3 q{p.x * turbulence_.x, p.y * turbulence_.y, p.z * turbulence_.z};
    // POV-Ray's sum has the mean of noise.h's and twice its spread.
    const double sum = scalar_turbulence(q, octaves_, omega_, lambda_, noise_generator_);
    double mean = 0, weight = 1;
    for (int i = 0; i < std::clamp(octaves_, 1, 10); ++i, weight *= omega_) mean += 0.5 * weight;
    const double x = std::max(0.0, 2 * sum - mean);
    return 1 - std::exp(-length / distance_) * std::min(1.0, turb_depth_ * x);
}

double FogMedium::optical_depth(Vec3 origin, Vec3 direction, double length) const {
    const double factor = turbulent_ && std::isfinite(length)
                              ? turbulence_factor(origin, direction, length)
                              : 1.0;
    return factor * untroubled_depth(origin, direction, length);
}

double FogMedium::untroubled_depth(Vec3 origin, Vec3 direction, double length) const {
    if (!ground_) return length / distance_;
    const double h0 = dot(origin, up_);
    const double rise = dot(direction, up_);
    // A level ray stays at one density; a rising one toward the sky meets a finite column.
    if (std::fabs(rise) < 1e-9 || (std::isinf(length) && rise < 0)) {
        const double k = std::max(0.0, h0 - offset_) / altitude_;
        return length / (1 + k * k) / distance_;
    }
    const double h1 = std::isinf(length) ? length : h0 + rise * length;
    return ground_column(h0, h1, offset_, altitude_) / std::fabs(rise) / distance_;
}

void FogMedium::along(Vec3 origin, Vec3 direction, double length, Rgb& through, Rgb& added) const {
    const double transmittance =
        std::max(std::exp(-optical_depth(origin, direction, length)), transmit_);
    through = transmittance * tint_;
    added = (to_internal_ * (1 - transmittance)) * colour_;
}

}  // namespace rayset::tracer
