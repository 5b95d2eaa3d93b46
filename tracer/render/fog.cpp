#include "tracer/render/fog.h"

#include <cmath>

#include <fmt/format.h>

#include "core/error.h"

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
    if (!is_zero(fog.turbulence)) refuse("fog turbulence", fog.location);
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
}

double FogMedium::optical_depth(Vec3 origin, Vec3 direction, double length) const {
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
