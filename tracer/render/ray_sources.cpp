// Loading and placing ray sources (see ray_sources.h).
#include "tracer/render/ray_sources.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include <fmt/format.h>

#include "converters/colour/spectrum.h"
#include "converters/rays/ray_stream.h"
#include "core/error.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"
#include "lightmodel/naive_source.h"
#include "tracer/render/ray_box.h"

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
                                 const Matrix4& to_world, bool naive)
    : emitter_(std::move(emitter)),
      to_world_(to_world),
      to_local_(to_world.inverse()),
      naive_(naive) {
    k_ = conformal_scale(to_world);
    if (!(k_ > 0))
        throw Error(
            "ray_source: the transform must keep angles (rotations, translations and one uniform "
            "scale)");
    power_ = luminance_weight(emitter_->phi_colour());
    radiance_scale_ = 1 / (k_ * k_);
    const lightmodel::Box body = emitter_->bounds();
    for (int corner = 0; corner < 8; ++corner)
        body_box_.add(to_world_.point({corner & 1 ? body.upper.x : body.lower.x,
                                       corner & 2 ? body.upper.y : body.lower.y,
                                       corner & 4 ? body.upper.z : body.lower.z}));
    widen_box(body_box_.lo, body_box_.hi);
}

void PlacedRaySource::end_shadow_rays_at_box(double margin) {
    shadow_rays_to_box_ = true;
    shadow_box_ = body_box_.grown(margin);
}

PlacedRaySource::Local PlacedRaySource::to_local(Vec3 origin, Vec3 direction) const {
    // A unit scene direction becomes a direction of length 1/k in model mm.
    return {to_local_.point(origin), k_ * to_local_.vector(direction), 1 / k_};
}

bool PlacedRaySource::crossed(Vec3 origin, Vec3 direction, double t_max, double& t) const {
    if (!ray_crosses_box(origin, direction, t_max, body_box_.lo, body_box_.hi)) return false;
    const Local l = to_local(origin, direction);
    lightmodel::EmitterHit hit;
    if (!emitter_->intersect(l.origin, l.direction, t_max < kInfinity ? t_max * l.scale : kInfinity,
                             hit))
        return false;
    t = hit.t / l.scale;
    return true;
}

bool PlacedRaySource::crossed_before(Vec3 origin, Vec3 direction, double t_max,
                                     int64_t voxel) const {
    const Local l = to_local(origin, direction);
    return emitter_->enters_body_near(voxel, l.origin, l.direction, t_max * l.scale);
}

template <class Q>
LightArrivalOf<Q> PlacedRaySource::arriving(Vec3 origin, Vec3 direction, double chosen,
                                            bool with_pdf_Le,
                                            const WavelengthsFor<Q>& wavelengths) const {
    const Local l = to_local(origin, direction);
    LightArrivalOf<Q> out;
    lightmodel::EmitterLine line;
    if constexpr (std::is_same_v<Q, SampledSpectrum>) {
        lightmodel::SpectralQuery query = spectral_query(wavelengths);
        line = emitter_->line(l.origin, l.direction, with_pdf_Le, &query);
        out.radiance = radiance_scale_ * spectrum_of(query);
    } else {
        line = emitter_->line(l.origin, l.direction, with_pdf_Le, nullptr);
        out.radiance = radiance_scale_ * line.L_colour;
    }
    out.pdf_Li = chosen * line.pdf_Li;
    out.pdf_Le = scene_pdf_Le(line.pdf_Le, chosen);
    return out;
}

template <class Q>
bool PlacedRaySource::sample_Li(Vec3 ref, const LightUniforms& u, double chosen,
                                const WavelengthsFor<Q>& wavelengths,
                                LightLiSampleOf<Q>& out) const {
    const Vec3 u_point{u.u[1], u.u[2], u.u[3]};
    const bool to_box = shadow_rays_to_box_ && !box_holds(ref, shadow_box_.lo, shadow_box_.hi);
    // From outside the body's box, the shadow ray's part up to the box is tested first: most
    // samples that are blocked then never ask for the body's nearest entry.
    const bool box_first = !to_box && !box_holds(ref, body_box_.lo, body_box_.hi);
    const auto entry =
        to_box || box_first ? lightmodel::BodyEntry::not_wanted : lightmodel::BodyEntry::wanted;
    std::optional<lightmodel::LiSample> s;
    if constexpr (std::is_same_v<Q, SampledSpectrum>) {
        lightmodel::SpectralQuery query = spectral_query(wavelengths);
        s = emitter_->sample_Li(to_local_.point(ref), u.select, u.u[0], u_point, {}, &query, entry);
        out.Li = radiance_scale_ * spectrum_of(query);
    } else {
        s = emitter_->sample_Li(to_local_.point(ref), u.select, u.u[0], u_point, {}, nullptr,
                                entry);
        if (s) out.Li = radiance_scale_ * s->Li_colour;
    }
    if (!s) return false;
    out.wi = normalized(to_world_.vector(s->wi));
    out.distance = to_box      ? box_entry(ref, out.wi, shadow_box_.lo, shadow_box_.hi)
                   : box_first ? box_entry(ref, out.wi, body_box_.lo, body_box_.hi)
                               : s->distance * k_;
    out.body_entry_deferred = box_first;
    out.pdf = chosen * s->pdf;  // a conformal map keeps solid angles
    return true;
}

double PlacedRaySource::pdf_Le(Vec3 origin, Vec3 wi, double, double chosen) const {
    const Local l = to_local(origin, wi);
    return scene_pdf_Le(emitter_->pdf_Le_line(l.origin, l.direction), chosen);
}

template <class Q>
LightPhotonOf<Q> PlacedRaySource::sample_Le(const double u[7], double u_wavelength) const {
    const lightmodel::LeSample s = emitter_->sample_Le(u);
    LightPhotonOf<Q> out;
    out.origin = to_world_.point(s.origin);
    out.direction = normalized(to_world_.vector(s.direction));
    out.source_voxel = s.voxel;
    if constexpr (std::is_same_v<Q, SampledSpectrum>) {
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
    } else {
        out.flux = s.flux_colour;
    }
    return out;
}

#define RAYSET_RAY_SOURCE_QUERIES(Q)                                                              \
    template LightArrivalOf<Q> PlacedRaySource::arriving<Q>(Vec3, Vec3, double, bool,             \
                                                            const WavelengthsFor<Q>&) const;      \
    template bool PlacedRaySource::sample_Li<Q>(                                                  \
        Vec3, const LightUniforms&, double, const WavelengthsFor<Q>&, LightLiSampleOf<Q>&) const; \
    template LightPhotonOf<Q> PlacedRaySource::sample_Le<Q>(const double[7], double) const;
RAYSET_RAY_SOURCE_QUERIES(Rgb)
RAYSET_RAY_SOURCE_QUERIES(SampledSpectrum)
#undef RAYSET_RAY_SOURCE_QUERIES

std::vector<PlacedRaySource> read_ray_sources(const SceneDescription& scene, bool naive) {
    std::vector<PlacedRaySource> sources;
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
            sources.emplace_back(std::make_shared<lightmodel::NaiveRaySource>(r.path), to_world,
                                 true);
            continue;
        }
        auto model = std::make_shared<lightmodel::LightModel>(
            ends_with(r.path, ".vdb") ? lightmodel::read_model(r.path)
                                      : lightmodel::build_model(r.path, {}));
        sources.emplace_back(std::make_shared<lightmodel::ComplexSource>(std::move(model)),
                             to_world);
    }
    return sources;
}

}  // namespace rayset::tracer
