// Loading and placing ray sources (see ray_sources.h).
#include "tracer/render/ray_sources.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "converters/colour/spectrum.h"
#include "converters/rays/ray_stream.h"
#include "core/error.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"
#include "lightmodel/naive_source.h"

namespace rayset::tracer {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Uniform scale of a transform that keeps angles (rotation times a scale), or 0 if it does not.
double conformal_scale(const Matrix4& m) {
    const Vec3 a = m.vector({1, 0, 0}), b = m.vector({0, 1, 0}), c = m.vector({0, 0, 1});
    const double s = length(a), tolerance = 1e-6 * s;
    if (!(s > 0) || std::fabs(length(b) - s) > tolerance || std::fabs(length(c) - s) > tolerance)
        return 0;
    if (std::fabs(dot(a, b)) > tolerance * s || std::fabs(dot(a, c)) > tolerance * s ||
        std::fabs(dot(b, c)) > tolerance * s)
        return 0;
    return s;
}

static_assert(lightmodel::kRgbLumensPerWatt == kLumensPerWatt, "one photometric convention");

lightmodel::SpectralQuery spectral_query(const SampledWavelengths& wavelengths) {
    lightmodel::SpectralQuery query;
    for (int i = 0; i < kWavelengths; ++i) query.nm[i] = wavelengths.nm[i];
    return query;
}
SampledSpectrum spectrum_of(const lightmodel::SpectralQuery& query) {
    SampledSpectrum s;
    for (int i = 0; i < kWavelengths; ++i) s.v[i] = query.value[i];
    return s;
}

bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

PlacedRaySource::PlacedRaySource(std::shared_ptr<const lightmodel::Emitter> emitter,
                                 const Matrix4& to_world)
    : emitter_(std::move(emitter)), to_world_(to_world), to_local_(to_world.inverse()) {
    k_ = conformal_scale(to_world);
    if (!(k_ > 0))
        throw Error(
            "ray_source: the transform must keep angles (rotations, translations and one uniform "
            "scale)");
    power_ = luminance_weight(emitter_->phi_colour());
    radiance_scale_ = 1 / (k_ * k_);
}

PlacedRaySource::Local PlacedRaySource::to_local(Vec3 origin, Vec3 direction) const {
    // A unit scene direction becomes a direction of length 1/k in model mm.
    return {to_local_.point(origin), k_ * to_local_.vector(direction), 1 / k_};
}

bool PlacedRaySource::intersect(Vec3 origin, Vec3 direction, double t_max, double& t) const {
    const Local l = to_local(origin, direction);
    lightmodel::EmitterHit hit;
    if (!emitter_->intersect(l.origin, l.direction, t_max < kInfinity ? t_max * l.scale : kInfinity,
                             hit))
        return false;
    t = hit.t / l.scale;
    return true;
}

Rgb PlacedRaySource::radiance(Vec3 origin, Vec3 direction, NoWavelengths) const {
    const Local l = to_local(origin, direction);
    return radiance_scale_ * emitter_->L_colour(l.origin, l.direction, lightmodel::EmitterHit{});
}

SampledSpectrum PlacedRaySource::radiance(Vec3 origin, Vec3 direction,
                                          const SampledWavelengths& wavelengths) const {
    const Local l = to_local(origin, direction);
    lightmodel::SpectralQuery query = spectral_query(wavelengths);
    emitter_->L_spectral(l.origin, l.direction, lightmodel::EmitterHit{}, query);
    return radiance_scale_ * spectrum_of(query);
}

std::optional<SourceLiSampleOf<SampledSpectrum>> PlacedRaySource::sample_Li(
    Vec3 ref, double u_cell, double u_voxel, Vec3 u_point,
    const SampledWavelengths& wavelengths) const {
    lightmodel::SpectralQuery query = spectral_query(wavelengths);
    const auto s = emitter_->sample_Li(to_local_.point(ref), u_cell, u_voxel, u_point, {}, &query);
    if (!s) return std::nullopt;
    SourceLiSampleOf<SampledSpectrum> out;
    out.wi = normalized(to_world_.vector(s->wi));
    out.distance = s->distance * k_;
    out.Li = radiance_scale_ * spectrum_of(query);
    out.pdf = s->pdf;
    return out;
}

std::optional<SourceLiSample> PlacedRaySource::sample_Li(Vec3 ref, double u_cell, double u_voxel,
                                                         Vec3 u_point, NoWavelengths) const {
    const auto s = emitter_->sample_Li(to_local_.point(ref), u_cell, u_voxel, u_point);
    if (!s) return std::nullopt;
    SourceLiSample out;
    out.wi = normalized(to_world_.vector(s->wi));
    out.distance = s->distance * k_;
    out.Li = radiance_scale_ * s->Li_colour;
    out.pdf = s->pdf;  // a conformal map keeps solid angles
    return out;
}

double PlacedRaySource::pdf_Li(Vec3 ref, Vec3 wi) const {
    return emitter_->pdf_Li(to_local_.point(ref), k_ * to_local_.vector(wi));
}

SourcePhoton PlacedRaySource::sample_Le(const double u[7]) const {
    const lightmodel::LeSample s = emitter_->sample_Le(u);
    return {
        to_world_.point(s.origin), normalized(to_world_.vector(s.direction)), s.flux_colour, {}};
}

SourcePhotonOf<SampledSpectrum> PlacedRaySource::sample_Le(const double u[7],
                                                           double u_wavelength) const {
    const lightmodel::LeSample s = emitter_->sample_Le(u);
    SourcePhotonOf<SampledSpectrum> out;
    out.origin = to_world_.point(s.origin);
    out.direction = normalized(to_world_.vector(s.direction));
    const double luminance = lightmodel::luminance(s.flux_colour);
    if (s.spectrum && !s.spectrum->is_zero()) {
        out.wavelengths = SampledWavelengths::sample(*s.spectrum, u_wavelength);
        for (int i = 0; i < kWavelengths; ++i)
            out.flux.v[i] = luminance * (*s.spectrum)(out.wavelengths.nm[i]);
    } else if (!s.spectrum) {
        // One wavelength: its flux is what makes the photon's luminance (zero where V is).
        out.wavelengths = SampledWavelengths::single(s.wavelength_nm);
        const double v = photopic_efficiency(s.wavelength_nm);
        out.flux.v[0] = v > 0 ? luminance / v : 0;
    }
    return out;
}

RaySourceSet::RaySourceSet(const SceneDescription& scene, bool naive) : naive_(naive) {
    const double units_per_mm = 1 / scene.global.millimetres_per_unit;
    const Matrix4 mm_to_unit = scaling({units_per_mm, units_per_mm, units_per_mm});
    for (const RaySource& r : scene.ray_sources) {
        const Matrix4 to_world = r.source_to_world * mm_to_unit;
        if (naive) {
            if (ends_with(r.path, ".vdb"))
                throw Error(
                    fmt::format("{}: the naive model emits the stored rays; name the ray file, not "
                                "a .vdb model",
                                r.path));
            add(PlacedRaySource(std::make_shared<lightmodel::NaiveRaySource>(r.path), to_world));
            continue;
        }
        auto model = std::make_shared<lightmodel::LightModel>(
            ends_with(r.path, ".vdb") ? lightmodel::read_model(r.path)
                                      : lightmodel::build_model(r.path, {}));
        add(PlacedRaySource(std::make_shared<lightmodel::ComplexSource>(std::move(model)),
                            to_world));
    }
}

void RaySourceSet::add(PlacedRaySource source) {
    sources_.push_back(std::move(source));
    total_power_ = 0;
    for (const PlacedRaySource& s : sources_) total_power_ += s.power();
    probability_.clear(), cdf_.clear();
    double running = 0;
    for (const PlacedRaySource& s : sources_) {
        const double p = total_power_ > 0 ? s.power() / total_power_ : 1.0 / sources_.size();
        probability_.push_back(p);
        cdf_.push_back(running += p);
    }
    cdf_.back() = 1;
}

size_t RaySourceSet::choose(double& u) const {
    const size_t i = std::min(size_t(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin()),
                              cdf_.size() - 1);
    const double low = i ? cdf_[i - 1] : 0;
    u = std::min(std::nextafter(1.0, 0.0), (u - low) / std::max(1e-300, cdf_[i] - low));
    return i;
}

}  // namespace rayset::tracer
