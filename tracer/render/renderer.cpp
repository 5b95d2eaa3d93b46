// Progressive passes over tiles and receiver cells (see renderer.h).
#include "tracer/render/renderer.h"

#include <atomic>
#include <chrono>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/error.h"
#include "core/progress.h"
#include "core/random.h"
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

// One pass's samples, written by index (pixel, then receiver cell) and added to the grids only
// once the pass is complete, so that an abandoned pass leaves no trace.
void render_pass_image(const PassContext& c, std::vector<Rgb>& image, uint64_t seed, std::atomic<uint64_t>& rays,
                       const RenderControl& control) {
    const int tile = c.settings.tile_size, w = c.settings.width, h = c.settings.height;
    const int tiles_x = (w + tile - 1) / tile, tiles_y = (h + tile - 1) / tile;
    tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y), [&](const tbb::blocked_range<int>& range) {
        uint64_t counted = 0;
        for (int t = range.begin(); t != range.end() && !stop_requested(control); ++t) {
            const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
            for (int y = y0; y < std::min(h, y0 + tile); ++y)
                for (int x = x0; x < std::min(w, x0 + tile); ++x) {
                    Pcg32 rng(seed, uint64_t(y) * w + x);
                    const double px = x + rng.uniform_float(), py = y + rng.uniform_float();
                    const CameraRay ray = c.camera.ray(px, py);
                    image[size_t(y) * w + x] = c.to_si * c.integrator.radiance(ray.origin, ray.direction, rng, counted);
                }
        }
        rays += counted;
    });
}

void render_pass_receivers(const PassContext& c, const std::vector<ReceiverMap>& maps, std::vector<Rgb>& cells,
                           uint64_t seed, std::atomic<uint64_t>& rays, const RenderControl& control) {
    uint64_t stream = uint64_t(c.settings.width) * c.settings.height;
    size_t first = 0;
    for (const ReceiverMap& map : maps) {
        const int nx = map.irradiance.nx(), ny = map.irradiance.ny();
        const Vec3 normal = map.front_normal();
        tbb::parallel_for(tbb::blocked_range<int>(0, nx * ny), [&](const tbb::blocked_range<int>& range) {
            if (stop_requested(control)) return;
            uint64_t counted = 0;
            for (int k = range.begin(); k != range.end(); ++k) {
                Pcg32 rng(seed, stream + uint64_t(k));
                const Rgb e = c.integrator.irradiance(map.cell_centre(k % nx, k / nx), normal, rng, counted);
                cells[first + size_t(k)] = c.to_si * e;
            }
            rays += counted;
        });
        stream += uint64_t(nx) * ny;
        first += size_t(nx) * ny;
    }
}

bool same_layout(const SampleGrid& a, const SampleGrid& b) { return a.nx() == b.nx() && a.ny() == b.ny(); }

bool same_layout(const std::vector<ReceiverMap>& a, const std::vector<ReceiverMap>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].receiver.name != b[i].receiver.name || !same_layout(a[i].irradiance, b[i].irradiance)) return false;
    return true;
}

}  // namespace

RenderResult blank_render(const SceneDescription& scene, const RenderSettings& settings) {
    auto blank_maps = [&] {
        std::vector<ReceiverMap> maps;
        for (const IlluminanceReceiver& r : scene.receivers) maps.emplace_back(r);
        return maps;
    };
    const auto blank_film = [&] { return settings.render_image ? Film(settings.width, settings.height) : Film(1, 1); };
    RenderResult result;
    result.film = blank_film();
    result.receivers = blank_maps();
    if (scene.global.integrator == "bidirectional")
        for (const char* name : {"direct_visibility", "primary", "secondary"})
            result.layers.push_back({name, blank_film(), blank_maps()});
    return result;
}

RenderResult starting_state(const RenderScene& scene, const RenderSettings& settings, RenderResult start) {
    RenderResult blank = blank_render(scene.description(), settings);
    if (start.passes == 0) return blank;
    bool fits = same_layout(start.film, blank.film) && same_layout(start.receivers, blank.receivers) &&
                start.layers.size() == blank.layers.size();
    for (size_t i = 0; fits && i < blank.layers.size(); ++i)
        fits = start.layers[i].name == blank.layers[i].name && same_layout(start.layers[i].film, blank.layers[i].film) &&
               same_layout(start.layers[i].receivers, blank.layers[i].receivers);
    if (!fits) throw Error("the render to continue has another image size, receivers or layers than this scene and settings");
    return start;
}

PassBudget::PassBudget(const RenderSettings& settings, double seconds_before)
    : time_limit_(settings.time_limit),
      passes_(settings.passes > 0       ? settings.passes
              : settings.time_limit > 0 ? std::numeric_limits<int>::max()
                                        : RenderSettings::kDefaultPasses),
      timed_only_(settings.passes == 0 && settings.time_limit > 0),
      seconds_before_(seconds_before),
      start_(std::chrono::steady_clock::now()) {}

double PassBudget::elapsed() const {
    return seconds_before_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool PassBudget::allows_another(int passes_done) const {
    return passes_done < passes_ && !(time_limit_ > 0 && elapsed() >= time_limit_);
}

double PassBudget::fraction_done(int passes_done) const {
    double fraction = timed_only_ ? 0 : double(passes_done) / passes_;
    if (time_limit_ > 0) fraction = std::max(fraction, elapsed() / time_limit_);
    return std::min(1.0, fraction);
}

RenderResult render(const RenderScene& scene, const RenderSettings& settings, RenderResult start,
                    const RenderControl& control) {
    if (scene.description().global.integrator == "bidirectional")
        return render_bidirectional(scene, RaySourceSet(scene.description(), settings.naive_sources), settings,
                                    std::move(start), control);
    RenderResult result = starting_state(scene, settings, std::move(start));
    const PassBudget budget(settings, result.seconds);
    const PerspectiveCamera camera(scene.description().camera, settings.width, settings.height);
    const PathIntegrator integrator(scene);
    const PassContext context{scene, integrator, camera, settings, scene.units().per_square_metre()};

    std::vector<Rgb> image(settings.render_image ? size_t(settings.width) * settings.height : 0);
    size_t cells = 0;
    for (const ReceiverMap& map : result.receivers) cells += size_t(map.irradiance.nx()) * map.irradiance.ny();
    std::vector<Rgb> cell_values(cells);

    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    ProgressBar progress("rendering", settings.progress);
    while (!stop_requested(control) && budget.allows_another(result.passes)) {
        const uint64_t seed = pass_seed(settings.seed, result.passes);
        std::atomic<uint64_t> rays{0};
        arena.execute([&] {
            if (settings.render_image) render_pass_image(context, image, seed, rays, control);
            render_pass_receivers(context, result.receivers, cell_values, seed, rays, control);
        });
        if (stop_requested(control)) break;  // the pass may be incomplete: abandoned
        if (settings.render_image) {
            for (size_t p = 0; p < image.size(); ++p) result.film.add(int(p % settings.width), int(p / settings.width), image[p]);
            result.film.finish_pass();
        }
        size_t first = 0;
        for (ReceiverMap& map : result.receivers) {
            const int nx = map.irradiance.nx(), ny = map.irradiance.ny();
            for (int k = 0; k < nx * ny; ++k) map.irradiance.add(k % nx, k / nx, cell_values[first + size_t(k)]);
            map.irradiance.finish_pass();
            first += size_t(nx) * ny;
        }
        ++result.passes;
        result.rays += rays;
        result.seconds = budget.elapsed();
        if (control.after_pass) control.after_pass(result);
        progress.update(budget.fraction_done(result.passes));
    }
    progress.done();
    result.seconds = budget.elapsed();
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
