// The bidirectional integrator over the renderer's passes: the camera samples of a pass keep
// their visible points, then a photon pass and density estimation at those points, every pass
// with fresh visible points and photons and the radius of gather_radius.h.
#include "tracer/render/bidirectional_integrator.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "tracer/render/gather_radius.h"
#include "tracer/render/path_integrator.h"
#include "tracer/render/renderer.h"

namespace rayset::tracer {

namespace {

constexpr uint64_t kPhotonBlock = 4096;
constexpr uint64_t kPhotonSeedSalt =
    0x6A09E667F3BCC909ULL;  // photon streams apart from camera streams

// Emitting surfaces and the background are the path tracer's (in the transport Q of the pass);
// skip it when there are none.
bool has_ordinary_light(const RenderScene& scene) {
    if (!scene.sky().black()) return true;
    for (size_t i = 0; i < scene.description().objects.size(); ++i)
        if (scene.emits(int(i))) return true;
    return false;
}

// Where the pass's gathers happen: its visible points and the receiver cells.
template <class Point>
std::vector<Vec3> gather_points(const std::vector<std::vector<Point>>& points,
                                const std::vector<ReceiverMap>& receivers) {
    std::vector<Vec3> out;
    for (const auto& tile : points)
        for (const Point& vp : tile) out.push_back(vp.point);
    append_receiver_cells(receivers, out);
    return out;
}

template <class Q>
class BidirectionalPasses : public Integrator {
public:
    using Point = VisiblePointOf<Q>;
    using Photon = PhotonOf<Q>;
    using Grid = PhotonGridOf<Photon>;

    BidirectionalPasses(const RenderScene& scene, const RenderSettings& settings,
                        const RenderResult& start);
    int samples_per_pass() const override { return samples_; }
    void begin_pass(int, const SamplePoints& points, std::atomic<uint64_t>&) override {
        visible_.assign(size_t(points.tiles()), {});
        receivers_ = points.receivers;
    }
    void camera_sample(const CameraRay& ray, const SampleSink& sink, Sampler& sampler,
                       uint64_t& rays) const override;
    void receiver_sample(Vec3 point, Vec3 normal, const SampleSink& sink, Sampler& sampler,
                         uint64_t& rays) const override;
    void end_pass(int pass, const SamplePoints& points, PassValues& values,
                  std::atomic<uint64_t>& rays, StopFlag stop) override;
    void pass_completed(RenderResult& result) override;
    bool first_pass_sets_outcome() const override { return !lights_.empty() && !radius_.known(); }
    std::vector<double> first_pass_outcome() override {
        if (!radius_.known())
            radius_.set_first(default_radius(gather_points(visible_, *receivers_)));
        return {radius_.first()};
    }
    void set_first_pass_outcome(const std::vector<double>& outcome) override {
        radius_.set_first(outcome.at(0));
    }

private:
    std::vector<Photon> trace_photons(int pass, std::atomic<uint64_t>& rays, StopFlag stop) const;
    void gather(const SamplePoints& points, const Grid& grid, PassValues& values) const;

    LightSet lights_;
    LightSet no_lights_;  // the path tracer's alongside: emitting surfaces and background only
    BidirectionalIntegratorOf<Q> integrator_;
    PathIntegratorOf<Q> path_;
    bool ordinary_;
    uint64_t seed_;
    uint64_t photons_per_pass_;
    int samples_;
    PassRadius radius_;  // unknown until the first pass's visible points give it
    // The pass under way: visible points by tile (each tile's written by one thread), memory.
    mutable std::vector<std::vector<Point>> visible_;
    const std::vector<ReceiverMap>* receivers_ = nullptr;
    size_t photon_bytes_ = 0, visible_point_bytes_ = 0;
};

template <class Q>
BidirectionalPasses<Q>::BidirectionalPasses(const RenderScene& scene,
                                            const RenderSettings& settings,
                                            const RenderResult& start)
    : lights_(scene, settings.naive_sources),
      integrator_(scene, lights_),
      path_(scene, no_lights_),
      ordinary_(has_ordinary_light(scene)),
      seed_(settings.seed),
      radius_(settings.photon_radius, start.passes, start.photon_radius) {
    const LightPathBudget budget = light_path_budget(scene, settings);
    photons_per_pass_ = budget.light_paths;
    samples_ = budget.camera_samples;
}

template <class Q>
void BidirectionalPasses<Q>::camera_sample(const CameraRay& ray, const SampleSink& sink,
                                           Sampler& sampler, uint64_t& rays) const {
    std::vector<Point>& visible = visible_[size_t(sink.tile)];
    const size_t first_point = visible.size();
    const CameraSample s = integrator_.camera_path(ray.origin, ray.direction, uint32_t(sink.index),
                                                   sampler, rays, visible);
    for (size_t v = first_point; v < visible.size(); ++v)
        visible[v].beta = sink.weight * visible[v].beta;
    sink.add(kDirectVisibility, s.direct_visibility);
    sink.add(kPrimary, s.primary);
    if (ordinary_)
        sink.add(kUnlayered, path_.radiance(ray.origin, ray.direction, sampler, rays).total());
}

template <class Q>
void BidirectionalPasses<Q>::receiver_sample(Vec3 point, Vec3 normal, const SampleSink& sink,
                                             Sampler& sampler, uint64_t& rays) const {
    sink.add(kPrimary, integrator_.receiver_primary(point, normal, sampler, rays));
    if (ordinary_) sink.add(kUnlayered, path_.irradiance(point, normal, sampler, rays).total());
}

template <class Q>
void BidirectionalPasses<Q>::end_pass(int pass, const SamplePoints& points, PassValues& values,
                                      std::atomic<uint64_t>& rays, StopFlag stop) {
    if (lights_.empty() || points.size() == 0 || stopped(stop)) return;
    if (!radius_.known())
        radius_.set_first(default_radius(gather_points(visible_, *points.receivers)));
    std::vector<Photon> photons = trace_photons(pass, rays, stop);
    if (stopped(stop)) return;
    const Grid grid(photons, radius_.at(pass));
    size_t visible_points = 0;
    for (const auto& tile_points : visible_) visible_points += tile_points.size();
    photon_bytes_ = std::max(photon_bytes_, grid.memory_bytes());
    visible_point_bytes_ = std::max(visible_point_bytes_, visible_points * sizeof(Point));
    gather(points, grid, values);
}

// In fixed blocks, so that the photons' order does not depend on threads.
template <class Q>
std::vector<typename BidirectionalPasses<Q>::Photon> BidirectionalPasses<Q>::trace_photons(
    int pass, std::atomic<uint64_t>& rays, StopFlag stop) const {
    const uint64_t photon_seed = pass_seed(seed_ ^ kPhotonSeedSalt, pass);
    const size_t blocks = size_t((photons_per_pass_ + kPhotonBlock - 1) / kPhotonBlock);
    std::vector<std::vector<Photon>> traced(blocks);
    tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
        if (stopped(stop)) return;
        uint64_t counted = 0;
        const uint64_t first = b * kPhotonBlock,
                       count = std::min(kPhotonBlock, photons_per_pass_ - first);
        traced[b] =
            integrator_.trace_photons(first, count, photons_per_pass_, photon_seed, counted);
        rays += counted;
    });
    size_t total = 0;
    for (const auto& block : traced) total += block.size();
    std::vector<Photon> photons;
    photons.reserve(total);
    for (auto& block : traced) photons.insert(photons.end(), block.begin(), block.end());
    return photons;
}

// Density estimation at the visible points and receiver cells.
template <class Q>
void BidirectionalPasses<Q>::gather(const SamplePoints& points, const Grid& grid,
                                    PassValues& values) const {
    std::vector<Rgb>& primary = values.components[kPrimary];
    std::vector<Rgb>& secondary = values.components[kSecondary];
    tbb::parallel_for(size_t(0), visible_.size(), [&](size_t t) {
        for (const Point& vp : visible_[t]) {
            Rgb direct, scattered;
            integrator_.gather(vp, grid, direct, scattered);
            primary[vp.pixel] += direct;
            secondary[vp.pixel] += scattered;
        }
    });
    for (size_t r = 0; r < points.receivers->size(); ++r) {
        const ReceiverMap& map = (*points.receivers)[r];
        const int nx = map.receiver.nx;
        const Vec3 normal = map.front_normal();
        tbb::parallel_for(0, nx * map.receiver.ny, [&](int k) {
            const size_t c = points.pixels() + points.receiver_first[r] + size_t(k);
            Rgb direct, scattered;
            integrator_.gather_irradiance(map.cell_centre(k % nx, k / nx), normal, grid, direct,
                                          scattered);
            primary[c] += direct;
            secondary[c] += scattered;
        });
    }
}

template <class Q>
void BidirectionalPasses<Q>::pass_completed(RenderResult& result) {
    result.photons += lights_.empty() ? 0 : photons_per_pass_;
    result.photon_radius = radius_.at(result.passes - 1);
    result.photon_bytes = std::max(result.photon_bytes, photon_bytes_);
    result.visible_point_bytes = std::max(result.visible_point_bytes, visible_point_bytes_);
}

}  // namespace

std::unique_ptr<Integrator> make_bidirectional_integrator(const RenderScene& scene,
                                                          const RenderSettings& settings,
                                                          const RenderResult& start) {
    refuse_what_light_paths_do_not_carry(scene, "bidirectional");
    if (scene.interiors().participating())
        throw Error(
            "not supported: media that scatter or emit with integrator \"bidirectional\" (the "
            "path integrator renders them)");
    if (spectral_transport(scene, settings)) {
        if (scene.interiors().any())
            throw Error("not supported: interior fade or media under spectral transport");
        return std::make_unique<BidirectionalPasses<SampledSpectrum>>(scene, settings, start);
    }
    return std::make_unique<BidirectionalPasses<Rgb>>(scene, settings, start);
}

}  // namespace rayset::tracer
