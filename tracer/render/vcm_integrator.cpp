// Vertex connection and merging over the renderer's passes (see vcm_integrator.h).
//
// Notation of the technical report: a subpath vertex carries three partial weights, vcm, vc
// and vm, from which the weight of any strategy that uses the vertex follows with a few
// densities evaluated there. eta = pi r^2 N (N light subpaths a pass) relates merging to
// connecting.
#include "tracer/render/vcm_integrator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "tracer/render/direct_light.h"
#include "tracer/render/gather_radius.h"
#include "tracer/render/light.h"
#include "tracer/render/material.h"
#include "tracer/render/photon_grid.h"
#include "tracer/render/renderer.h"

namespace rayset::tracer {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr uint64_t kLightBlock = 1024;
constexpr uint64_t kLightSeedSalt = 0xBB67AE8584CAA73BULL;  // light streams apart from camera's
// Camera vertices before Russian roulette starts. A vertex here costs a light sample and
// connections, several times a path tracer's vertex, so roulette starts earlier than there:
// in examples/led_box.pov at 3 rather than 5 a pass takes 0.7 of the time at the same error.
constexpr int kCameraRouletteDepth = 3;

// The partial weights of a subpath vertex.
struct PartialWeights {
    double vcm = 0, vc = 0, vm = 0;
};

// A light subpath's vertex at a surface with a smooth lobe.
struct LightVertex {
    Vec3 position, normal, shading_normal;  // normal: geometric, as SurfaceHit's
    Vec3 facing;                            // the normal on the side the light arrived at
    Vec3 wi;                                // unit, toward the vertex before (the light's side)
    int object = -1, part = -1;
    Rgb beta;  // the subpath's weight: W that arrive here
    PartialWeights weights;
    int segments = 0;  // from the light: 1 for a light's first hit
};

// The state of a subpath between its vertices.
struct Walk {
    Vec3 origin, direction;
    Rgb beta{1, 1, 1};
    PartialWeights weights;
    int vertices = 0;
};

// The weights after scattering at a vertex into a direction of density `pdf` (0: a delta lobe),
// leaving at `cos_out` to the geometric normal; `reverse` the density of sampling the way
// back. `merging`: whether a subpath can end at this vertex by merging (eta, else nothing).
// Returns the part of the new vc that merging here adds.
double scatter_weights(PartialWeights& w, double pdf, double reverse, double cos_out, double eta,
                       bool merging) {
    if (!(pdf > 0)) {
        w.vcm = 0;
        w.vc *= cos_out;
        w.vm *= cos_out;
        return 0;
    }
    const double here = merging ? cos_out / pdf * eta : 0;
    const double vc = cos_out / pdf * (w.vc * reverse + w.vcm) + here;
    const double vm = cos_out / pdf * (w.vm * reverse + w.vcm / eta + (merging ? 1 : 0));
    w = {1 / pdf, vc, vm};
    return here;
}

// The weights on arriving at a vertex after a segment of length t, at cos_in to its normal.
void arrive_weights(PartialWeights& w, double t, double cos_in) {
    w.vcm *= t * t / cos_in;
    w.vc /= cos_in;
    w.vm /= cos_in;
}

class VcmPasses : public Integrator {
public:
    VcmPasses(const RenderScene& scene, const RenderSettings& settings, const RenderResult& start);

    int samples_per_pass() const override { return samples_; }
    void begin_pass(int pass, const SamplePoints& points, std::atomic<uint64_t>& rays) override;
    void camera_sample(const CameraRay& ray, const SampleSink& sink, Sampler& sampler,
                       uint64_t& rays) const override;
    void receiver_sample(Vec3 point, Vec3 normal, const SampleSink& sink, Sampler& sampler,
                         uint64_t& rays) const override;
    void pass_completed(RenderResult& result) override;

private:
    // A camera path's vertex, and where its light goes.
    struct CameraVertex {
        Vec3 point, normal, wo;
        bool surface;  // a scene surface (light subpaths end there), not a receiver point
    };
    struct CameraWalk : Walk {
        RayKind kind = RayKind::camera;
        LightComponent segment_layer = kDirectVisibility;
        // No smooth scene surface met yet: the next one is where this path may merge.
        bool merge_ahead = true;
        // The part of weights.vc that merging at the vertex just left adds. A light met on the
        // segment from there leaves it out: that merge would take a light subpath's first
        // vertex, which never merges.
        double merged_vc = 0;
    };

    // The light subpaths of `pass`: their vertices into vertices_, path after path (where each
    // path's begin is kept in path_first_).
    void trace_light_paths(int pass, std::atomic<uint64_t>& rays);
    void trace_light_path(uint64_t index, uint64_t seed, std::vector<LightVertex>& out,
                          uint64_t& rays) const;
    // The first segment of a light subpath, from its light to the first surface: the weight
    // and partial weights on arrival; false when it brings nothing.
    bool emit(Pcg32& rng, Walk& walk, SurfaceHit& hit, uint64_t& rays) const;

    // Follows a camera path from the walk's ray on, adding its light to `sum`. Light and BSDF
    // samples take pairs of `sampler`, everything else its stream.
    void trace_camera(CameraWalk& walk, Sampler& sampler, uint64_t& rays,
                      LightComponentsOf<Rgb>& sum) const;
    // At a camera vertex: its light (with a smooth lobe) and the next direction; false when
    // the path ends.
    bool scatter(const CameraVertex& x, const Bsdf& bsdf, CameraWalk& walk, Sampler& sampler,
                 uint64_t& rays, LightComponentsOf<Rgb>& sum) const;
    // One of the pass's light subpaths, drawn by `rng`, its vertices asked of the cache (they
    // lie anywhere in the pass's vertices); empty when the pass has none.
    struct Subpath {
        const LightVertex *first, *last;
    };
    Subpath draw_subpath(Pcg32& rng) const;
    Rgb light_sample(const CameraVertex& x, const Bsdf& bsdf, const CameraWalk& walk,
                     const LightUniforms& u, uint64_t& rays) const;
    // `merges`: whether x is where the path may merge (scatter()).
    Rgb connection(const CameraVertex& x, const Bsdf& bsdf, const CameraWalk& walk, bool merges,
                   const LightVertex& y, uint64_t& rays) const;
    // The light of the light vertices within the radius of x that are not their subpath's
    // first (the grid holds no other).
    Rgb merge(const CameraVertex& x, const Bsdf& bsdf, const CameraWalk& walk) const;
    // The density of sampling x.wo at a camera vertex x (`bsdf` its BSDF) for a path that
    // arrives from `wi`: the way back to the camera side. Evaluated only where it has a weight.
    double reverse_pdf(const Bsdf& bsdf, double weight, Vec3 wi) const;

    const RenderScene& scene_;
    LightSet lights_;
    uint64_t seed_;
    uint64_t light_paths_;
    int samples_;
    PassRadius radius_;  // unknown until the first pass measures it over the view
    // The pass under way.
    double eta_ = 1, merge_normalisation_ = 0;
    std::vector<uint32_t> path_first_;
    // The light vertices in path order (for connections) and by place (for merges), kept
    // from pass to pass with their storage.
    std::vector<LightVertex> vertices_;
    PhotonGridOf<LightVertex> grid_;
    size_t vertex_bytes_ = 0;
    std::vector<std::vector<LightVertex>> traced_;  // by block of paths, as traced
    std::vector<std::vector<uint32_t>> path_sizes_;
};

// Where camera paths first meet the scene, as the radius rule wants the points where merges
// happen: the hits of the pixel centres of an image of at most 256 x 256 over the same view,
// and the receivers' cells. The same in every process; their rays are not counted.
std::vector<Vec3> camera_hits(const RenderScene& scene, const SamplePoints& points) {
    std::vector<Vec3> out;
    if (points.pixels() > 0) {
        const int longest = std::max(points.width, points.height);
        const double scale = std::min(1.0, 256.0 / longest);
        const int w = std::max(1, int(points.width * scale)),
                  h = std::max(1, int(points.height * scale));
        for (const SurfaceHit& hit : centre_hits(scene, w, h))
            if (hit.object >= 0) out.push_back(hit.point);
    }
    append_receiver_cells(*points.receivers, out);
    return out;
}

VcmPasses::VcmPasses(const RenderScene& scene, const RenderSettings& settings,
                     const RenderResult& start)
    : scene_(scene),
      lights_(scene, false),
      seed_(settings.seed),
      radius_(settings.photon_radius, start.passes, start.photon_radius) {
    const LightPathBudget budget = light_path_budget(scene, settings);
    light_paths_ = budget.light_paths;
    samples_ = budget.camera_samples;
}

void VcmPasses::begin_pass(int pass, const SamplePoints& points, std::atomic<uint64_t>& rays) {
    if (!radius_.known()) radius_.set_first(default_radius(camera_hits(scene_, points)));
    const double r = radius_.at(pass);
    eta_ = kPi * r * r * double(light_paths_);
    merge_normalisation_ = 1 / eta_;
    trace_light_paths(pass, rays);
    // A subpath's first vertex never merges: light straight from a light is sampled or met,
    // without the blur of the radius (which darkens the last radius before every edge).
    grid_.assign(vertices_, r, [](const LightVertex& v) { return v.segments > 1; });
    vertex_bytes_ =
        std::max(vertex_bytes_, grid_.memory_bytes() + vertices_.size() * sizeof(LightVertex));
}

// In fixed blocks, so that the vertices' order does not depend on threads.
void VcmPasses::trace_light_paths(int pass, std::atomic<uint64_t>& rays) {
    const uint64_t seed = pass_seed(seed_ ^ kLightSeedSalt, pass);
    const size_t blocks = size_t((light_paths_ + kLightBlock - 1) / kLightBlock);
    traced_.resize(blocks);
    path_sizes_.resize(blocks);
    tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
        uint64_t counted = 0;
        traced_[b].clear();
        path_sizes_[b].clear();
        const uint64_t first = b * kLightBlock, last = std::min(light_paths_, first + kLightBlock);
        for (uint64_t i = first; i < last; ++i) {
            const size_t before = traced_[b].size();
            trace_light_path(i, seed, traced_[b], counted);
            path_sizes_[b].push_back(uint32_t(traced_[b].size() - before));
        }
        rays += counted;
    });
    vertices_.clear();
    path_first_.assign(1, 0);
    for (size_t b = 0; b < blocks; ++b) {
        vertices_.insert(vertices_.end(), traced_[b].begin(), traced_[b].end());
        for (uint32_t n : path_sizes_[b]) path_first_.push_back(path_first_.back() + n);
    }
}

bool VcmPasses::emit(Pcg32& rng, Walk& walk, SurfaceHit& hit, uint64_t& rays) const {
    double u[7];
    for (double& v : u) v = rng.uniform();
    const LightPhotonOf<Rgb> photon = lights_.sample_Le<Rgb>(u, 0, 1);
    if (photon.light < 0 || is_black(photon.flux)) return false;
    const Light& light = lights_[size_t(photon.light)];
    const double chosen = lights_.probability(size_t(photon.light));
    ++rays;
    if (!scene_.intersect(photon.origin, photon.direction, 0, kInfinity, RayKind::indirect, hit))
        return false;
    const Vec3 back = -photon.direction;
    const double cos_in = std::fabs(dot(hit.normal, photon.direction));
    if (!(cos_in > 0)) return false;
    if (light.is_ray_source() && !light.crossed_before(hit.point, back, hit.t, photon)) {
        // What a camera at the hit sees along the photon's line: nothing unless the line meets
        // the body before a shadow caster (beyond the photon's origin the scene may block it).
        // Met before the origin (nearly always, and quickly known), the photon's own segment
        // says there is none.
        double t_body = 0;
        if (!light.crossed(hit.point, back, kInfinity, t_body)) return false;
        if (t_body > hit.t) {
            ++rays;
            if (scene_.occluded(photon.origin, back, 0, t_body - hit.t)) return false;
        }
    }
    const LightArrivalOf<Rgb> seen = light.arriving<Rgb>(hit.point, back, hit.t, chosen, true, {});
    if (!(seen.pdf_Le > 0)) return false;
    walk.origin = photon.origin, walk.direction = photon.direction;
    walk.beta = light.is_ray_source() ? (1 / seen.pdf_Le) * seen.radiance : photon.flux;
    if (light.delta_position()) {
        walk.weights = {chosen * hit.t * hit.t / (seen.pdf_Le * cos_in), 0, 0};
    } else {
        const double vc = 1 / (seen.pdf_Le * cos_in);
        walk.weights = {seen.pdf_Li * vc, vc, vc / eta_};
    }
    walk.vertices = 1;
    return true;
}

void VcmPasses::trace_light_path(uint64_t index, uint64_t seed, std::vector<LightVertex>& out,
                                 uint64_t& rays) const {
    if (lights_.empty()) return;
    Pcg32 rng(seed, index);
    Walk walk;
    SurfaceHit hit;
    if (!emit(rng, walk, hit, rays)) return;
    std::optional<Material> scratch;
    for (;;) {
        const Vec3 wi = -walk.direction;
        const Material& material = scene_.material(hit, scratch);
        const Bsdf bsdf(material, hit.normal, hit.shading_normal, wi);
        const bool smooth = bsdf.has_smooth_lobes();
        if (smooth) {
            LightVertex v;
            v.position = hit.point, v.normal = hit.normal, v.shading_normal = hit.shading_normal;
            v.facing = bsdf.facing_normal(), v.wi = wi;
            v.object = hit.object, v.part = hit.part;
            v.beta = walk.beta, v.weights = walk.weights, v.segments = walk.vertices;
            out.push_back(v);
        }
        BsdfSample s;
        const double u_lobe = rng.uniform_float(), u1 = rng.uniform_float(),
                     u2 = rng.uniform_float();
        if (walk.vertices >= kMaxPathVertices || !bsdf.sample(u_lobe, u1, u2, s) ||
            is_black(s.weight))
            return;
        const double reverse = s.delta ? 0 : bsdf.pdf_reversed(s.wi);
        // Never where the path merges: every strategy that uses this vertex has a smooth
        // scene surface nearer the sensor (connection() weighs the one exception).
        scatter_weights(walk.weights, s.delta ? 0 : s.pdf, reverse,
                        std::fabs(dot(hit.normal, s.wi)), eta_, false);
        // Roulette keeps the surviving subpaths' weight near the emitted one.
        const Rgb next = walk.beta * s.weight;
        const double survive = std::min(1.0, max_component(next) / max_component(walk.beta));
        if (!(survive > 0) || rng.uniform_float() >= survive) return;
        walk.beta = (1 / survive) * next;
        walk.origin = scene_.offset(hit.point, hit.normal, s.wi);
        walk.direction = s.wi;
        ++rays;
        if (!scene_.intersect(walk.origin, walk.direction, 0, kInfinity, RayKind::indirect, hit))
            return;
        const double cos_in = std::fabs(dot(hit.normal, walk.direction));
        if (!(cos_in > 0)) return;
        arrive_weights(walk.weights, hit.t, cos_in);
        ++walk.vertices;
    }
}

void VcmPasses::camera_sample(const CameraRay& ray, const SampleSink& sink, Sampler& sampler,
                              uint64_t& rays) const {
    CameraWalk walk;
    walk.origin = ray.origin, walk.direction = ray.direction;
    LightComponentsOf<Rgb> sum;
    trace_camera(walk, sampler, rays, sum);
    for (int c = 0; c < kLightComponents; ++c) sink.add(c, sum.of[size_t(c)]);
}

// The receiver point as the camera path's first vertex: a white Lambertian surface, pi times
// whose reflected radiance is the irradiance.
void VcmPasses::receiver_sample(Vec3 point, Vec3 normal, const SampleSink& sink, Sampler& sampler,
                                uint64_t& rays) const {
    const CameraVertex x{point, normal, normal, false};
    const Bsdf bsdf(white_lambertian(), normal, normal, normal);
    CameraWalk walk;
    walk.beta = Rgb{kPi, kPi, kPi};
    walk.vertices = 1;
    LightComponentsOf<Rgb> sum;
    if (scatter(x, bsdf, walk, sampler, rays, sum)) trace_camera(walk, sampler, rays, sum);
    for (int c = 0; c < kLightComponents; ++c) sink.add(c, sum.of[size_t(c)]);
}

void VcmPasses::trace_camera(CameraWalk& walk, Sampler& sampler, uint64_t& rays,
                             LightComponentsOf<Rgb>& sum) const {
    SurfaceHit hit;
    std::optional<Material> scratch;
    for (;;) {
        ++rays;
        const bool found =
            scene_.intersect(walk.origin, walk.direction, 0, kInfinity, walk.kind, hit);
        if (lights_.has_bodies()) {
            // A body met on the segment, weighted against sampling it from the vertex before
            // and against light subpaths that leave it along the segment.
            const double t_block =
                scene_.light_horizon(walk.origin, walk.direction, found, hit, rays);
            lights_.for_each_crossed(
                walk.origin, walk.direction, t_block + scene_.epsilon(), [&](size_t i, double t) {
                    const Light& light = lights_[i];
                    const double chosen = lights_.probability(i);
                    const LightArrivalOf<Rgb> seen =
                        light.arriving<Rgb>(walk.origin, walk.direction, t, chosen, true, {});
                    const double others = seen.pdf_Li * walk.weights.vcm +
                                          seen.pdf_Le * (walk.weights.vc - walk.merged_vc);
                    sum.of[walk.segment_layer] += (1 / (1 + others)) * (walk.beta * seen.radiance);
                });
        }
        if (!found) {
            sum.of[kUnlayered] += walk.beta * scene_.sky().radiance(walk.direction);
            return;
        }
        const Material& material = scene_.material(hit, scratch);
        if (!is_black(material.emission)) sum.of[kUnlayered] += walk.beta * material.emission;
        const double cos_in = std::fabs(dot(hit.normal, walk.direction));
        if (!(cos_in > 0)) return;
        arrive_weights(walk.weights, hit.t, cos_in);
        ++walk.vertices;
        const CameraVertex x{hit.point, hit.normal, -walk.direction, true};
        const Bsdf bsdf(material, hit.normal, hit.shading_normal, x.wo);
        if (!scatter(x, bsdf, walk, sampler, rays, sum)) return;
    }
}

bool VcmPasses::scatter(const CameraVertex& x, const Bsdf& bsdf, CameraWalk& walk, Sampler& sampler,
                        uint64_t& rays, LightComponentsOf<Rgb>& sum) const {
    Pcg32& rng = sampler.rng();
    const bool smooth = bsdf.has_smooth_lobes();
    const bool merges = smooth && x.surface && walk.merge_ahead;
    if (smooth && !lights_.empty()) {
        // The subpath is drawn first: the light sample's work hides the wait for its vertices.
        const Subpath subpath = draw_subpath(rng);
        // Light straight from a light (sampled), and light that scattered on the light subpath
        // (connected or merged).
        const Rgb straight = light_sample(x, bsdf, walk, lights_.draw(sampler), rays);
        Rgb scattered;
        for (const LightVertex* y = subpath.first; y < subpath.last; ++y)
            scattered += connection(x, bsdf, walk, merges, *y, rays);
        if (merges) scattered += merge(x, bsdf, walk);
        sum.of[layer_of_light_at_vertex(walk.segment_layer)] += walk.beta * straight;
        sum.of[kSecondary] += walk.beta * scattered;
    }
    BsdfSample s;
    const double u_lobe = sampler.get_1d();
    double u1, u2;
    sampler.get_2d(u1, u2);
    if (walk.vertices >= kMaxPathVertices || !bsdf.sample(u_lobe, u1, u2, s) || is_black(s.weight))
        return false;
    const double reverse = s.delta ? 0 : reverse_pdf(bsdf, walk.weights.vc + walk.weights.vm, s.wi);
    walk.merged_vc = scatter_weights(walk.weights, s.delta ? 0 : s.pdf, reverse,
                                     std::fabs(dot(x.normal, s.wi)), eta_, merges);
    walk.merge_ahead = walk.merge_ahead && !merges;
    walk.segment_layer = layer_after_scattering(walk.segment_layer, s.delta);
    walk.beta *= s.weight;
    walk.origin = scene_.offset(x.point, x.normal, s.wi);
    walk.direction = s.wi;
    walk.kind = RayKind::indirect;
    return walk.vertices + 1 < kCameraRouletteDepth || survives_roulette(walk.beta, rng);
}

VcmPasses::Subpath VcmPasses::draw_subpath(Pcg32& rng) const {
    if (path_first_.size() < 2) return {nullptr, nullptr};
    const uint32_t path = rng.below(uint32_t(path_first_.size() - 1));
    const Subpath s{vertices_.data() + path_first_[path], vertices_.data() + path_first_[path + 1]};
    const auto* end = reinterpret_cast<const char*>(s.last);
    for (auto p = reinterpret_cast<const char*>(s.first); p < end; p += 64) __builtin_prefetch(p);
    return s;
}

double VcmPasses::reverse_pdf(const Bsdf& bsdf, double weight, Vec3 wi) const {
    return weight > 0 ? bsdf.pdf_reversed(wi) : 0;
}

Rgb VcmPasses::light_sample(const CameraVertex& x, const Bsdf& bsdf, const CameraWalk& walk,
                            const LightUniforms& u, uint64_t& rays) const {
    LightLiSampleOf<Rgb> sample;
    if (!lights_.sample_Li<Rgb>(x.point, u, {}, sample)) return {};
    const Rgb f = bsdf.eval(sample.wi);
    if (is_black(f) || is_black(sample.Li)) return {};
    const double d = sample.distance;
    // The shadow ray before the weight: an occluded sample spares its light's pdf_Le (a ray
    // source's traversal of its emitting volume).
    if (blocked(scene_, shadow_ray_of(scene_, lights_, sample, x.point, bsdf.facing_normal()),
                rays))
        return {};
    const size_t light = size_t(sample.light);
    // The light sample's density per unit area across the ray at the light, times d^2 (a point
    // light's position is certain: its choice alone).
    const double direct = sample.delta ? sample.pdf * d * d : sample.pdf;
    const double bsdf_pdf = sample.delta ? 0 : bsdf.pdf(sample.wi);
    const double emission_pdf =
        lights_[light].pdf_Le(x.point, sample.wi, d, lights_.probability(light));
    const double cos_x = std::fabs(dot(x.normal, sample.wi));
    const double w_light = bsdf_pdf / sample.pdf;
    // Merging at x would take the light subpath's first vertex: no strategy.
    const double w_camera =
        emission_pdf * cos_x / direct *
        (walk.weights.vcm + walk.weights.vc * reverse_pdf(bsdf, walk.weights.vc, sample.wi));
    return (1 / ((1 + w_light + w_camera) * sample.pdf)) * (f * sample.Li);
}

Rgb VcmPasses::connection(const CameraVertex& x, const Bsdf& bsdf, const CameraWalk& walk,
                          bool merges, const LightVertex& y, uint64_t& rays) const {
    const Vec3 d = y.position - x.point;
    const double distance2 = dot(d, d);
    if (!(distance2 > 0)) return {};
    const double distance = std::sqrt(distance2);
    const Vec3 w = (1 / distance) * d;
    const Rgb f_x = bsdf.eval(w);
    if (is_black(f_x)) return {};
    std::optional<Material> scratch;
    const Material& material = scene_.material(y.object, y.part, y.position, y.normal, scratch);
    const Bsdf bsdf_y(material, y.normal, y.shading_normal, y.wi);
    const Rgb f_y = bsdf_y.eval(-w);
    if (is_black(f_y)) return {};
    const double cos_x = std::fabs(dot(x.normal, w)), cos_y = std::fabs(dot(y.normal, w));
    // Each side's density of reaching the other's vertex, per unit area there.
    const double camera_to_y = bsdf.pdf(w) * cos_y / distance2;
    const double light_to_x = bsdf_y.pdf(-w) * cos_x / distance2;
    const double y_reverse = bsdf_y.pdf_reversed(-w);
    // y is where the path may merge only as the first scene surface after a receiver point (x
    // the receiver point itself, the one camera vertex that is no surface), and not as its
    // subpath's first vertex.
    const bool y_merges = !x.surface && y.segments > 1;
    const double w_light =
        camera_to_y * ((y_merges ? eta_ : 0) + y.weights.vcm + y.weights.vc * y_reverse);
    const double w_camera = light_to_x * ((merges ? eta_ : 0) + walk.weights.vcm +
                                          walk.weights.vc * reverse_pdf(bsdf, walk.weights.vc, w));
    const Vec3 origin = scene_.offset(x.point, bsdf.facing_normal(), w);
    const Vec3 target = scene_.offset(y.position, y.facing, -w);
    const Vec3 between = target - origin;
    const double length = std::sqrt(dot(between, between));
    ++rays;
    if (!(length > 0) || scene_.occluded(origin, (1 / length) * between, 0, length)) return {};
    return (1 / ((1 + w_light + w_camera) * distance2)) * (f_x * f_y * y.beta);
}

Rgb VcmPasses::merge(const CameraVertex& x, const Bsdf& bsdf, const CameraWalk& walk) const {
    const Vec3 n = bsdf.facing_normal();
    Rgb sum;
    grid_.for_each_near(x.point, [&](const LightVertex& y) {
        if (dot(y.facing, n) < kSameSurfaceCos) return;
        const double cos_i = std::fabs(dot(y.wi, n));
        if (!(cos_i > 0)) return;
        const Rgb f = bsdf.eval(y.wi);
        if (is_black(f)) return;
        const double w_light = y.weights.vcm / eta_ + y.weights.vm * bsdf.pdf(y.wi);
        const double w_camera =
            walk.weights.vcm / eta_ + walk.weights.vm * reverse_pdf(bsdf, walk.weights.vm, y.wi);
        // The vertex's weight holds the projected area on its own surface: its cosine out.
        sum += (merge_normalisation_ / ((1 + w_light + w_camera) * cos_i)) * (f * y.beta);
    });
    return sum;
}

void VcmPasses::pass_completed(RenderResult& result) {
    result.photons += lights_.empty() ? 0 : light_paths_;
    result.photon_radius = radius_.at(result.passes - 1);
    result.photon_bytes = std::max(result.photon_bytes, vertex_bytes_);
}

}  // namespace

std::unique_ptr<Integrator> make_vcm_integrator(const RenderScene& scene,
                                                const RenderSettings& settings,
                                                const RenderResult& start) {
    refuse_what_light_paths_do_not_carry(scene, "vcm");
    const std::string refuse =
        "not supported with integrator \"vcm\" (the path integrator renders it): ";
    if (spectral_transport(scene, settings)) throw Error(refuse + "spectral transport");
    if (scene.interiors().any()) throw Error(refuse + "interior fade or media");
    if (settings.naive_sources && !scene.description().ray_sources.empty())
        throw Error(refuse + "the naive ray set (--naive-sources)");
    return std::make_unique<VcmPasses>(scene, settings, start);
}

}  // namespace rayset::tracer
