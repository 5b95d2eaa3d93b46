// Progressive passes over tiles and receiver cells (see renderer.h).
#include "tracer/render/renderer.h"

#include <atomic>
#include <chrono>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "converters/progress.h"
#include "converters/random.h"
#include "tracer/render/camera.h"
#include "tracer/render/path_integrator.h"
#include "tracer/render/ray_sources.h"

namespace rayset::tracer {

uint64_t pass_seed(uint64_t seed, int pass) {
    // SplitMix64 finaliser: neighbouring (seed, pass) pairs give unrelated seeds.
    uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (uint64_t(pass) + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

namespace {

struct PassContext {
    const RenderScene& scene;
    const PathIntegrator& integrator;
    const PerspectiveCamera& camera;
    const RenderSettings& settings;
    double to_si;  // internal radiance/irradiance -> per square metre
};

void render_pass_image(const PassContext& c, Film& film, uint64_t seed, std::atomic<uint64_t>& rays) {
    const int tile = c.settings.tile_size, w = c.settings.width, h = c.settings.height;
    const int tiles_x = (w + tile - 1) / tile, tiles_y = (h + tile - 1) / tile;
    tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y), [&](const tbb::blocked_range<int>& range) {
        uint64_t counted = 0;
        for (int t = range.begin(); t != range.end(); ++t) {
            const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
            for (int y = y0; y < std::min(h, y0 + tile); ++y)
                for (int x = x0; x < std::min(w, x0 + tile); ++x) {
                    Pcg32 rng(seed, uint64_t(y) * w + x);
                    const double px = x + rng.uniform_float(), py = y + rng.uniform_float();
                    const CameraRay ray = c.camera.ray(px, py);
                    film.add(x, y, c.to_si * c.integrator.radiance(ray.origin, ray.direction, rng, counted));
                }
        }
        rays += counted;
    });
}

void render_pass_receivers(const PassContext& c, std::vector<ReceiverMap>& maps, uint64_t seed, std::atomic<uint64_t>& rays) {
    uint64_t stream = uint64_t(c.settings.width) * c.settings.height;
    for (ReceiverMap& map : maps) {
        const int nx = map.irradiance.nx(), ny = map.irradiance.ny();
        const Vec3 normal = map.front_normal();
        tbb::parallel_for(tbb::blocked_range<int>(0, nx * ny), [&](const tbb::blocked_range<int>& range) {
            uint64_t counted = 0;
            for (int k = range.begin(); k != range.end(); ++k) {
                Pcg32 rng(seed, stream + uint64_t(k));
                const Rgb e = c.integrator.irradiance(map.cell_centre(k % nx, k / nx), normal, rng, counted);
                map.irradiance.add(k % nx, k / nx, c.to_si * e);
            }
            rays += counted;
        });
        stream += uint64_t(nx) * ny;
    }
}

}  // namespace

PassBudget::PassBudget(const RenderSettings& settings)
    : time_limit_(settings.time_limit),
      passes_(settings.passes > 0       ? settings.passes
              : settings.time_limit > 0 ? std::numeric_limits<int>::max()
                                        : RenderSettings::kDefaultPasses),
      timed_only_(settings.passes == 0 && settings.time_limit > 0),
      start_(std::chrono::steady_clock::now()) {}

double PassBudget::elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool PassBudget::allows_another(int passes_done) const {
    return passes_done < passes_ && !(time_limit_ > 0 && elapsed() >= time_limit_);
}

double PassBudget::fraction_done(int passes_done) const {
    double fraction = timed_only_ ? 0 : double(passes_done) / passes_;
    if (time_limit_ > 0) fraction = std::max(fraction, elapsed() / time_limit_);
    return std::min(1.0, fraction);
}

RenderResult render(const RenderScene& scene, const RenderSettings& settings) {
    if (scene.description().global.integrator == "bidirectional")
        return render_bidirectional(scene, RaySourceSet(scene.description(), settings.naive_sources), settings);
    const PassBudget budget(settings);
    const PerspectiveCamera camera(scene.description().camera, settings.width, settings.height);
    const PathIntegrator integrator(scene);
    const PassContext context{scene, integrator, camera, settings, scene.units().per_square_metre()};

    RenderResult result;
    if (settings.render_image) result.film = Film(settings.width, settings.height);
    for (const IlluminanceReceiver& r : scene.description().receivers) result.receivers.emplace_back(r);

    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    ProgressBar progress("rendering", settings.progress);
    std::atomic<uint64_t> rays{0};
    while (budget.allows_another(result.passes)) {
        const uint64_t seed = pass_seed(settings.seed, result.passes);
        arena.execute([&] {
            if (settings.render_image) render_pass_image(context, result.film, seed, rays);
            render_pass_receivers(context, result.receivers, seed, rays);
        });
        if (settings.render_image) result.film.finish_pass();
        for (ReceiverMap& map : result.receivers) map.irradiance.finish_pass();
        ++result.passes;
        progress.update(budget.fraction_done(result.passes));
    }
    progress.done();
    result.seconds = budget.elapsed();
    result.rays = rays;
    return result;
}

std::vector<int> object_id_image(const RenderScene& scene, int width, int height) {
    const PerspectiveCamera camera(scene.description().camera, width, height);
    std::vector<int> ids(size_t(width) * height, -1);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const CameraRay ray = camera.ray(x + 0.5, y + 0.5);
            SurfaceHit hit;
            if (scene.intersect(ray.origin, ray.direction, 0, std::numeric_limits<double>::infinity(), RayKind::camera, hit))
                ids[size_t(y) * width + x] = hit.object;
        }
    return ids;
}

}  // namespace rayset::tracer
