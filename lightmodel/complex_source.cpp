#include "lightmodel/complex_source.h"

#include <limits>

namespace rayset::lightmodel {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}

ComplexSource::ComplexSource(std::shared_ptr<const LightModel> model)
    : model_(std::move(model)),
      volume_(*model_),
      body_(model_->spheres),
      voxel_balls_(*model_),
      bounds_(model_->bounds()),
      diagram_flux_(model_->diagrams.size(), 0) {
    for (const FluxCell& c : model_->flux_cells) diagram_flux_[size_t(c.intensity_cell)] += c.flux;
    // The sphere around the occupied voxels, which hold every point sample_point() draws
    // (widened by a little more than rounding, so that a point at a corner stays in its cone).
    Box voxels;
    const LatticeFrame& frame = model_->density_frame;
    const double h = frame.cell_size();
    for (const Coord& v : model_->voxels) {
        voxels.extend(frame.cell_lower(v));
        voxels.extend(frame.cell_lower(v) + Vec3{h, h, h});
    }
    if (!voxels.empty()) {
        reach_.centre = 0.5 * (voxels.lower + voxels.upper);
        reach_.radius = (0.5 + 1e-9) * length(voxels.upper - voxels.lower);
    }
}

bool ComplexSource::intersect(Vec3 origin, Vec3 dir, double tmax, EmitterHit& hit) const {
    BodyHit body_hit;
    if (!body_.intersect(origin, dir, tmax, body_hit)) return false;
    hit.t = body_hit.t;
    hit.point = body_hit.point;
    hit.normal = body_hit.normal;
    return true;
}

// The radiance of the whole line through the emitting volume, not only beyond the hit: the
// body marks where the source is seen, the volume says how bright. sample_Li uses the same
// line integral, so both strategies estimate the same integral (MIS stays unbiased).
double ComplexSource::L(Vec3 origin, Vec3 dir, const EmitterHit&,
                        const SpectralSelect& select) const {
    return volume_.radiance_toward(origin, dir, 0, kInfinity, select);
}

Rgb ComplexSource::L_colour(Vec3 origin, Vec3 dir, const EmitterHit&) const {
    Rgb colour;
    volume_.radiance_toward(origin, dir, 0, kInfinity, {}, {&colour});
    return colour;
}

void ComplexSource::L_spectral(Vec3 origin, Vec3 dir, const EmitterHit&,
                               SpectralQuery& query) const {
    volume_.radiance_toward(origin, dir, 0, kInfinity, {}, {nullptr, &query});
}

std::optional<LiSample> ComplexSource::sample_Li(Vec3 ref, double u_cell, double u_voxel,
                                                 Vec3 u_point, const SpectralSelect& select,
                                                 SpectralQuery* spectral, BodyEntry entry) const {
    const VolumeSample point = volume_.sample_point(u_cell, u_voxel, u_point);
    const Vec3 to_point = point.point - ref;
    const double distance = length(to_point);
    if (distance == 0) return std::nullopt;
    LiSample s;
    s.wi = (1 / distance) * to_point;
    // Light counts only where a camera would see the body: the same condition BSDF sampling
    // has (its ray must hit the body), so both estimate the same integrand.
    if (entry == BodyEntry::wanted) {
        BodyHit hit;
        if (!body_.intersect(ref, s.wi, kInfinity, hit)) return std::nullopt;
        s.distance = hit.t;
    } else if (!meets_body(ref, s.wi, point.voxel)) {
        return std::nullopt;
    }
    if (far_from(ref)) {
        s.pdf = cone_density(ref, s.wi);
        if (!(s.pdf > 0)) return std::nullopt;
        s.Li = volume_.point_estimate(point.flux_cell, s.wi, distance, s.pdf, select, &s.Li_colour,
                                      spectral);
        return s;
    }
    s.Li =
        volume_.radiance_toward(ref, s.wi, 0, kInfinity, select, {&s.Li_colour, spectral, &s.pdf});
    if (!(s.pdf > 0)) return std::nullopt;
    return s;
}

EmitterLine ComplexSource::line(Vec3 origin, Vec3 dir, bool with_pdf_Le,
                                SpectralQuery* spectral) const {
    EmitterLine out;
    const bool far = far_from(origin);
    LineAlso also;
    if (spectral)
        also.spectral = spectral;
    else
        also.colour = &out.L_colour;
    if (!far) also.pdf = &out.pdf_Li;
    if (with_pdf_Le) also.line_density = &out.pdf_Le;
    volume_.radiance_toward(origin, dir, 0, kInfinity, {}, also);
    if (far) out.pdf_Li = cone_density(origin, dir);
    return out;
}

bool ComplexSource::far_from(Vec3 ref) const {
    const Vec3 d = ref - reach_.centre;
    const double far = kFarRadii * reach_.radius;
    return reach_.radius > 0 && dot(d, d) > far * far;
}

// The uniform density over the cone of directions from `ref` that meet the sphere: 1 / (2 pi
// (1 - cos theta_max)) with sin theta_max = radius / distance, written without the cancellation
// of 1 - cos for a distant sphere.
double ComplexSource::cone_density(Vec3 ref, Vec3 wi) const {
    const Vec3 to_centre = reach_.centre - ref;
    const double d2 = dot(to_centre, to_centre), r2 = reach_.radius * reach_.radius;
    const double cos_max = std::sqrt(std::max(0.0, 1 - r2 / d2));
    if (dot(wi, to_centre) < cos_max * std::sqrt(d2)) return 0;
    return (1 + cos_max) / (2 * kPi * (r2 / d2));
}

// From outside the body's box, a ball listed for the sampled point's voxel that the ray enters
// is the body met; otherwise the body decides (from inside the box too).
bool ComplexSource::meets_body(Vec3 ref, Vec3 wi, uint32_t voxel) const {
    if (!bounds_.contains(ref) && voxel_balls_.ray_enters(voxel, ref, wi)) return true;
    return body_.occluded(ref, wi, kInfinity);
}

double ComplexSource::pdf_Li(Vec3 ref, Vec3 wi) const {
    return far_from(ref) ? cone_density(ref, wi) : volume_.pdf_direction(ref, wi);
}

LeSample ComplexSource::sample_Le(const double u[7], const SpectralSelect& select) const {
    const VolumeSample point = volume_.sample_point(u[0], u[1], {u[2], u[3], u[4]});
    const FluxCell& cell = model_->flux_cells[point.flux_cell];
    const GoniometricDiagram& diagram = model_->diagrams[size_t(cell.intensity_cell)];
    const DirectionSample dir = diagram.sample({u[5], u[6]});
    LeSample s;
    s.origin = point.point;
    s.direction = dir.direction;
    s.pdf_position = point.pdf_volume;
    s.pdf_direction = dir.pdf;
    s.cell = int32_t(point.flux_cell);
    s.voxel = point.voxel;
    // Emitted radiance per volume eps = Phi_c D / V_c over pdf (Phi_c / Phi / V_c) D = Phi,
    // scaled to the selected part of the cell's light.
    const double phi = volume_.total_flux();
    s.flux = phi * volume_.cell_flux(point.flux_cell, select) / cell.flux;
    s.flux_colour = phi * volume_.cell_colour(point.flux_cell);
    s.spectrum = &volume_.cell_spectrum(point.flux_cell);
    return s;
}

void ComplexSource::pdf_Le(Vec3 origin, Vec3 direction, double& pdf_position,
                           double& pdf_direction) const {
    pdf_position = volume_.pdf_point(origin);
    const int32_t c = volume_.cell_at(origin);
    pdf_direction =
        c < 0
            ? 0
            : model_->diagrams[size_t(model_->flux_cells[size_t(c)].intensity_cell)].pdf(direction);
}

double ComplexSource::intensity(Vec3 w, const SpectralSelect& select) const {
    double sum = 0;
    if (select.whole_flux()) {
        for (size_t k = 0; k < diagram_flux_.size(); ++k)
            sum += diagram_flux_[k] * model_->diagrams[k].pdf(w);
        return sum;
    }
    for (uint32_t c = 0; c < model_->flux_cells.size(); ++c)
        sum += volume_.cell_flux(c, select) *
               model_->diagrams[size_t(model_->flux_cells[c].intensity_cell)].pdf(w);
    return sum;
}

}  // namespace rayset::lightmodel
