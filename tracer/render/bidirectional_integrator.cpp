// Camera pass, photon pass and density estimation of the bidirectional integrator
// (see bidirectional_integrator.h).
#include "tracer/render/bidirectional_integrator.h"

#include <cmath>
#include <limits>

namespace rayset::tracer {

namespace {

using analytic::dot;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Photons count at a point only if they landed on a surface facing nearly the same way, so
// that light on a neighbouring wall near a corner is not spread onto this one.
constexpr double kSameSurfaceCos = 0.9;

const Material& white_lambertian() {
    static const Material white = [] {
        Material m;
        m.diffuse = {1, 1, 1};
        return m;
    }();
    return white;
}

}  // namespace

Rgb BidirectionalIntegrator::sample_sources(const Bsdf& bsdf, Vec3 point, Vec3 normal, Pcg32& rng,
                                            uint64_t& rays) const {
    if (sources_.empty()) return {};
    double u_cell = rng.uniform();
    const size_t j = sources_.choose(u_cell);
    const double u_voxel = rng.uniform();
    const Vec3 u_point{rng.uniform(), rng.uniform(), rng.uniform()};
    const auto ls = sources_[j].sample_Li(point, u_cell, u_voxel, u_point);
    if (!ls) return {};
    const Rgb f = bsdf.eval(ls->wi);
    if (is_black(f) || is_black(ls->Li)) return {};
    ++rays;
    if (scene_.occluded(scene_.offset(point, normal, ls->wi), ls->wi, 0, ls->distance - scene_.epsilon())) return {};
    const double pdf_light = sources_.probability(j) * ls->pdf;
    const double weight = power_heuristic(pdf_light, bsdf.pdf(ls->wi));
    return (weight / pdf_light) * ls->Li * f;
}

Rgb BidirectionalIntegrator::bodies_crossed(Vec3 origin, Vec3 direction, double bsdf_pdf, Vec3 ref,
                                            uint64_t& rays) const {
    SurfaceHit hit;
    ++rays;
    const double t_block = scene_.intersect(origin, direction, 0, kInfinity, RayKind::indirect, hit) ? hit.t : kInfinity;
    Rgb sum;
    for (size_t j = 0; j < sources_.size(); ++j) {
        double t = 0;
        if (!sources_[j].intersect(origin, direction, t_block, t)) continue;
        const double pdf_light = sources_.probability(j) * sources_[j].pdf_Li(ref, direction);
        sum += power_heuristic(bsdf_pdf, pdf_light) * sources_[j].radiance(origin, direction);
    }
    return sum;
}

CameraSample BidirectionalIntegrator::camera_path(Vec3 origin, Vec3 direction, uint32_t pixel, Pcg32& rng,
                                                  uint64_t& rays, std::vector<VisiblePoint>& visible) const {
    CameraSample out;
    Rgb beta{1, 1, 1};
    RayKind kind = RayKind::camera;
    for (int depth = 0; depth < kMaxDepth; ++depth) {
        SurfaceHit hit;
        ++rays;
        const bool found = scene_.intersect(origin, direction, 0, kInfinity, kind, hit);
        const double t_block = found ? hit.t : kInfinity;
        for (size_t j = 0; j < sources_.size(); ++j) {
            double t = 0;
            if (sources_[j].intersect(origin, direction, t_block, t))
                out.direct_visibility += beta * sources_[j].radiance(origin, direction);
        }
        if (!found) break;
        const Material& material = scene_.material(hit.object);
        const Vec3 wo = -direction;
        const Bsdf bsdf(material, hit.normal, hit.shading_normal, wo);
        if (bsdf.has_smooth_lobes()) {
            out.primary += beta * sample_sources(bsdf, hit.point, bsdf.facing_normal(), rng, rays);
            visible.push_back({hit.point, hit.normal, hit.shading_normal, wo, hit.object, beta, pixel});
        }
        BsdfSample s;
        const double u_lobe = rng.uniform_float(), u1 = rng.uniform_float(), u2 = rng.uniform_float();
        if (!bsdf.sample(u_lobe, u1, u2, s) || is_black(s.weight)) break;
        const Vec3 next_origin = scene_.offset(hit.point, hit.normal, s.wi);
        if (!s.delta) {
            // The smooth lobe ends the camera path: what lies beyond is the photons' part.
            out.primary += beta * s.weight * bodies_crossed(next_origin, s.wi, s.pdf, hit.point, rays);
            break;
        }
        beta *= s.weight;
        origin = next_origin;
        direction = s.wi;
        kind = RayKind::indirect;
        if (depth + 1 >= kRouletteDepth) {
            const double survive = std::min(0.95, max_component(beta));
            if (rng.uniform_float() >= survive) break;
            beta = (1 / survive) * beta;
        }
    }
    return out;
}

Rgb BidirectionalIntegrator::receiver_primary(Vec3 point, Vec3 normal, Pcg32& rng, uint64_t& rays) const {
    const Bsdf bsdf(white_lambertian(), normal, normal, normal);
    Rgb reflected = sample_sources(bsdf, point, normal, rng, rays);
    BsdfSample s;
    const double u_lobe = rng.uniform_float(), u1 = rng.uniform_float(), u2 = rng.uniform_float();
    if (bsdf.sample(u_lobe, u1, u2, s) && !is_black(s.weight))
        reflected += s.weight * bodies_crossed(scene_.offset(point, normal, s.wi), s.wi, s.pdf, point, rays);
    return kPi * reflected;
}

std::vector<Photon> BidirectionalIntegrator::trace_photons(uint64_t first, uint64_t count, uint64_t emitted,
                                                           uint64_t seed, uint64_t& rays) const {
    std::vector<Photon> photons;
    if (sources_.empty()) return photons;
    const bool keep_direct = sources_.naive();
    for (uint64_t i = first; i < first + count; ++i) {
        Pcg32 rng(seed, i);
        double u[7];
        for (double& v : u) v = rng.uniform();
        const size_t j = sources_.choose(u[0]);
        const SourcePhoton emission = sources_[j].sample_Le(u);
        Rgb power = (1 / (sources_.probability(j) * double(emitted))) * emission.flux;
        Vec3 origin = emission.origin, direction = emission.direction;
        bool scattered = false;
        for (int depth = 0; depth < kMaxDepth; ++depth) {
            SurfaceHit hit;
            ++rays;
            if (!scene_.intersect(origin, direction, 0, kInfinity, RayKind::indirect, hit)) break;
            const Bsdf bsdf(scene_.material(hit.object), hit.normal, hit.shading_normal, -direction);
            if (bsdf.has_smooth_lobes() && (scattered || keep_direct))
                photons.push_back({hit.point, -direction, bsdf.facing_normal(), power, !scattered});
            BsdfSample s;
            const double u_lobe = rng.uniform_float(), u1 = rng.uniform_float(), u2 = rng.uniform_float();
            if (!bsdf.sample(u_lobe, u1, u2, s) || is_black(s.weight)) break;
            const Rgb next = power * s.weight;
            // Roulette keeps the surviving photons' power near the emitted one.
            const double survive = std::min(1.0, max_component(next) / max_component(power));
            if (!(survive > 0) || rng.uniform_float() >= survive) break;
            power = (1 / survive) * next;
            origin = scene_.offset(hit.point, hit.normal, s.wi);
            direction = s.wi;
            scattered = true;
        }
    }
    return photons;
}

void BidirectionalIntegrator::gather(const VisiblePoint& vp, const PhotonGrid& grid, Rgb& direct, Rgb& scattered) const {
    const Bsdf bsdf(scene_.material(vp.object), vp.normal, vp.shading_normal, vp.wo);
    const Vec3 n = bsdf.facing_normal();
    Rgb sum_direct, sum_scattered;
    grid.for_each_near(vp.point, [&](const Photon& p) {
        if (dot(p.normal, n) < kSameSurfaceCos) return;
        const double cos_i = std::fabs(dot(p.wi, vp.shading_normal));
        if (!(cos_i > 0)) return;
        // Bsdf::eval gives f |cos|; the photon's power already holds the projected area.
        const Rgb contribution = (1 / cos_i) * bsdf.eval(p.wi) * p.power;
        (p.direct ? sum_direct : sum_scattered) += contribution;
    });
    const double area = kPi * grid.radius() * grid.radius();
    direct = (1 / area) * (vp.beta * sum_direct);
    scattered = (1 / area) * (vp.beta * sum_scattered);
}

void BidirectionalIntegrator::gather_irradiance(Vec3 point, Vec3 normal, const PhotonGrid& grid, Rgb& direct,
                                                Rgb& scattered) const {
    Rgb sum_direct, sum_scattered;
    grid.for_each_near(point, [&](const Photon& p) {
        if (dot(p.normal, normal) < kSameSurfaceCos || dot(p.wi, normal) <= 0) return;
        (p.direct ? sum_direct : sum_scattered) += p.power;
    });
    const double area = kPi * grid.radius() * grid.radius();
    direct = (1 / area) * sum_direct;
    scattered = (1 / area) * sum_scattered;
}

}  // namespace rayset::tracer
