// Progressive passes of the bidirectional integrator: camera pass over TBB tiles, photon pass,
// density estimation at the pass's visible points, then the layers' films.
//
// Progressive photon mapping in the probabilistic form of Knaus & Zwicker 2011 ("Progressive
// photon mapping: a probabilistic approach", ACM TOG 30(3)): every pass has fresh visible
// points and photons, all gathers of pass i use one radius r_i, and the image is the average
// of the passes. r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) with alpha = 2/3 (the rule and value of
// Hachisuka, Ogaki & Jensen 2008, "Progressive photon mapping"), so both the variance and the
// bias of the average vanish as passes grow.
#include "tracer/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/progress.h"
#include "tracer/render/bidirectional_integrator.h"
#include "tracer/render/camera.h"
#include "tracer/render/path_integrator.h"

namespace rayset::tracer {

namespace {

constexpr double kAlpha = 2.0 / 3.0;
constexpr uint64_t kPhotonBlock = 4096;
constexpr uint64_t kMinimumPhotons = 65536;
constexpr uint64_t kPhotonSeedSalt = 0x6A09E667F3BCC909ULL;  // photon streams apart from camera streams

// Lights, emitting surfaces and the background are the path tracer's (in the transport Q of the
// pass); skip it when there are none.
bool has_ordinary_light(const RenderScene& scene) {
    if (!scene.lights().empty() || !is_black(scene.background())) return true;
    for (size_t i = 0; i < scene.description().objects.size(); ++i)
        if (!is_black(scene.material(int(i)).emission)) return true;
    return false;
}

// Per camera sample of one pass, renderer units.
struct PassValues {
    std::vector<Rgb> direct, primary, secondary, ordinary;
    explicit PassValues(size_t n) : direct(n), primary(n), secondary(n), ordinary(n) {}
};

template <class Point>
double default_radius(const std::vector<std::vector<Point>>& points, const std::vector<ReceiverMap>& receivers) {
    // The extent of the middle 90% of the points along each axis: a floor plane seen to its
    // horizon must not make the radius (and so every gather) as wide as the floor.
    std::vector<double> coordinates[3];
    auto add = [&](Vec3 p) {
        coordinates[0].push_back(p.x), coordinates[1].push_back(p.y), coordinates[2].push_back(p.z);
    };
    for (const auto& tile : points)
        for (const Point& vp : tile) add(vp.point);
    for (const ReceiverMap& map : receivers)
        for (int j = 0; j < map.receiver.ny; ++j)
            for (int i = 0; i < map.receiver.nx; ++i) add(map.cell_centre(i, j));
    if (coordinates[0].empty()) return 1;
    double squares = 0;
    for (std::vector<double>& c : coordinates) {
        auto at = [&](double fraction) {
            const auto k = c.begin() + std::ptrdiff_t(fraction * double(c.size() - 1));
            std::nth_element(c.begin(), k, c.end());
            return *k;
        };
        const double low = at(0.05), high = at(0.95);
        squares += (high - low) * (high - low);
    }
    const double diagonal = std::sqrt(squares);
    return diagonal > 0 ? diagonal / 100 : 1;
}

// Camera samples per pixel and receiver cell in one pass: as many as make the pass's camera
// paths about as many as its photons, at least one.
int camera_samples_per_pass(uint64_t photons_per_pass, size_t camera_points) {
    return int(std::max<uint64_t>(1, photons_per_pass / std::max<uint64_t>(1, camera_points)));
}

// The radius after `passes_done` passes, the last of them gathered with `radius`.
double shrunk_radius(double radius, int passes_done) { return radius * std::sqrt((passes_done + kAlpha) / (passes_done + 1)); }

// The passes, with paths carrying Q (Rgb, or SampledSpectrum for spectral transport).
template <class Q>
RenderResult render_passes(const RenderScene& scene, const RaySourceSet& sources, const RenderSettings& settings,
                           RenderResult start, const RenderControl& control) {
    using Integrator = BidirectionalIntegratorOf<Q>;
    RenderResult result = starting_state(scene, settings, std::move(start));
    const PassBudget budget(settings, result.seconds);
    const int w = settings.width, h = settings.height;
    const PerspectiveCamera camera(scene.description().camera, w, h);
    const Integrator integrator(scene, sources);
    const PathIntegratorOf<Q> path(scene);
    const bool ordinary = has_ordinary_light(scene);
    const double to_si = scene.units().per_square_metre();

    const size_t pixels = settings.render_image ? size_t(w) * h : 0;
    std::vector<size_t> receiver_first;  // first cell of each receiver in the pass arrays
    size_t cells = 0;
    for (const ReceiverMap& map : result.receivers) receiver_first.push_back(cells), cells += size_t(map.receiver.nx) * map.receiver.ny;
    const uint64_t photons_per_pass =
        settings.photons_per_pass > 0 ? uint64_t(settings.photons_per_pass) : std::max<uint64_t>(kMinimumPhotons, pixels + cells);
    // Camera work balanced against photon work: a small image or a receiver-only render takes
    // several samples per pixel and cell in each pass rather than leave the photon pass (and its
    // fixed cost) to dominate; the primary light and antialiasing converge that much faster.
    const int samples = camera_samples_per_pass(photons_per_pass, pixels + cells);
    const double sample_weight = 1.0 / samples;
    result.samples_per_pass = samples;
    // A continued render goes on from the radius its last pass used.
    double radius = result.passes > 0 ? shrunk_radius(result.photon_radius, result.passes) : settings.photon_radius;

    const int tile = settings.tile_size, tiles_x = (w + tile - 1) / tile, tiles_y = (h + tile - 1) / tile;
    const int tiles = settings.render_image ? tiles_x * tiles_y : 0;
    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    ProgressBar progress("rendering", settings.progress);

    while (!stop_requested(control) && budget.allows_another(result.passes)) {
        const uint64_t seed = pass_seed(settings.seed, result.passes);
        std::atomic<uint64_t> rays{0};
        PassValues image(pixels), cell(cells);
        std::vector<std::vector<typename Integrator::Point>> visible(static_cast<size_t>(tiles));
        arena.execute([&] {
            // Camera pass.
            tbb::parallel_for(tbb::blocked_range<int>(0, tiles), [&](const tbb::blocked_range<int>& range) {
                uint64_t counted = 0;
                for (int t = range.begin(); t != range.end() && !stop_requested(control); ++t) {
                    const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
                    for (int y = y0; y < std::min(h, y0 + tile); ++y)
                        for (int x = x0; x < std::min(w, x0 + tile); ++x) {
                            const uint32_t p = uint32_t(y) * w + x;
                            Pcg32 rng(seed, p);
                            for (int k = 0; k < samples; ++k) {
                                const double px = x + rng.uniform_float(), py = y + rng.uniform_float();
                                const CameraRay ray = camera.ray(px, py);
                                const size_t first_point = visible[t].size();
                                const CameraSample s = integrator.camera_path(ray.origin, ray.direction, p, rng, counted, visible[t]);
                                for (size_t v = first_point; v < visible[t].size(); ++v) visible[t][v].beta = sample_weight * visible[t][v].beta;
                                image.direct[p] += sample_weight * s.direct_visibility;
                                image.primary[p] += sample_weight * s.primary;
                                if (ordinary) image.ordinary[p] += sample_weight * path.radiance(ray.origin, ray.direction, rng, counted);
                            }
                        }
                }
                rays += counted;
            });
            const uint64_t stream = uint64_t(w) * h;
            for (size_t r = 0; r < result.receivers.size(); ++r) {
                const ReceiverMap& map = result.receivers[r];
                const int nx = map.receiver.nx, ny = map.receiver.ny;
                const Vec3 normal = map.front_normal();
                tbb::parallel_for(tbb::blocked_range<int>(0, nx * ny), [&](const tbb::blocked_range<int>& range) {
                    if (stop_requested(control)) return;
                    uint64_t counted = 0;
                    for (int k = range.begin(); k != range.end(); ++k) {
                        const size_t c = receiver_first[r] + size_t(k);
                        Pcg32 rng(seed, stream + c);
                        const Vec3 point = map.cell_centre(k % nx, k / nx);
                        for (int n = 0; n < samples; ++n) {
                            cell.primary[c] += sample_weight * integrator.receiver_primary(point, normal, rng, counted);
                            if (ordinary) cell.ordinary[c] += sample_weight * path.irradiance(point, normal, rng, counted);
                        }
                    }
                    rays += counted;
                });
            }
            if (sources.empty() || (tiles == 0 && cells == 0) || stop_requested(control)) return;

            // Photon pass, in fixed blocks so that the photons' order does not depend on threads.
            if (!(radius > 0)) radius = default_radius(visible, result.receivers);
            const uint64_t photon_seed = pass_seed(settings.seed ^ kPhotonSeedSalt, result.passes);
            const size_t blocks = size_t((photons_per_pass + kPhotonBlock - 1) / kPhotonBlock);
            std::vector<std::vector<typename Integrator::Photon>> traced(blocks);
            tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
                if (stop_requested(control)) return;
                uint64_t counted = 0;
                const uint64_t first = b * kPhotonBlock, count = std::min(kPhotonBlock, photons_per_pass - first);
                traced[b] = integrator.trace_photons(first, count, photons_per_pass, photon_seed, counted);
                rays += counted;
            });
            if (stop_requested(control)) return;
            std::vector<typename Integrator::Photon> photons;
            for (auto& block : traced) photons.insert(photons.end(), block.begin(), block.end());
            const typename Integrator::Grid grid(std::move(photons), radius);
            size_t visible_points = 0;
            for (const auto& tile_points : visible) visible_points += tile_points.size();
            result.photon_bytes = std::max(result.photon_bytes, grid.memory_bytes());
            result.visible_point_bytes = std::max(result.visible_point_bytes, visible_points * sizeof(typename Integrator::Point));

            // Density estimation at the visible points and receiver cells.
            tbb::parallel_for(0, tiles, [&](int t) {
                for (const auto& vp : visible[size_t(t)]) {
                    Rgb direct, scattered;
                    integrator.gather(vp, grid, direct, scattered);
                    image.primary[vp.pixel] += direct;
                    image.secondary[vp.pixel] += scattered;
                }
            });
            for (size_t r = 0; r < result.receivers.size(); ++r) {
                const ReceiverMap& map = result.receivers[r];
                const int nx = map.receiver.nx;
                const Vec3 normal = map.front_normal();
                tbb::parallel_for(0, nx * map.receiver.ny, [&](int k) {
                    const size_t c = receiver_first[r] + size_t(k);
                    Rgb direct, scattered;
                    integrator.gather_irradiance(map.cell_centre(k % nx, k / nx), normal, grid, direct, scattered);
                    cell.primary[c] += direct;
                    cell.secondary[c] += scattered;
                });
            }
        });
        if (stop_requested(control)) break;  // the pass may be incomplete: abandoned
        result.photons += sources.empty() ? 0 : photons_per_pass;
        result.photon_radius = radius;

        auto accumulate = [&](const PassValues& v, size_t i, auto&& add) {
            add(0, to_si * v.direct[i]);
            add(1, to_si * v.primary[i]);
            add(2, to_si * v.secondary[i]);
            add(3, to_si * (v.direct[i] + v.primary[i] + v.secondary[i] + v.ordinary[i]));
        };
        for (size_t p = 0; p < pixels; ++p) {
            const int x = int(p % w), y = int(p / w);
            accumulate(image, p, [&](int layer, Rgb value) {
                (layer < 3 ? result.layers[size_t(layer)].film : result.film).add(x, y, value);
            });
        }
        for (size_t r = 0; r < result.receivers.size(); ++r) {
            const int nx = result.receivers[r].receiver.nx, ny = result.receivers[r].receiver.ny;
            for (int k = 0; k < nx * ny; ++k)
                accumulate(cell, receiver_first[r] + size_t(k), [&](int layer, Rgb value) {
                    (layer < 3 ? result.layers[size_t(layer)].receivers[r] : result.receivers[r]).irradiance.add(k % nx, k / nx, value);
                });
        }
        if (settings.render_image) {
            result.film.finish_pass();
            for (RenderLayer& layer : result.layers) layer.film.finish_pass();
        }
        for (ReceiverMap& map : result.receivers) map.irradiance.finish_pass();
        for (RenderLayer& layer : result.layers)
            for (ReceiverMap& map : layer.receivers) map.irradiance.finish_pass();
        ++result.passes;
        radius = shrunk_radius(radius, result.passes);
        result.rays += rays;
        result.seconds = budget.elapsed();
        if (control.after_pass) control.after_pass(result);
        progress.update(budget.fraction_done(result.passes));
    }
    progress.done();
    result.seconds = budget.elapsed();
    return result;
}

}  // namespace

RenderResult render_bidirectional(const RenderScene& scene, const RaySourceSet& sources, const RenderSettings& settings,
                                  RenderResult start, const RenderControl& control) {
    if (settings.spectral || scene.description().global.spectral)
        return render_passes<SampledSpectrum>(scene, sources, settings, std::move(start), control);
    return render_passes<Rgb>(scene, sources, settings, std::move(start), control);
}

}  // namespace rayset::tracer
