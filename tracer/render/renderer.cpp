// The progressive pass driver over an integrator (see renderer.h, integrator.h).
#include "tracer/render/renderer.h"

#include <atomic>
#include <chrono>
#include <limits>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/error.h"
#include "core/progress.h"
#include "core/random.h"
#include "tracer/render/camera.h"
#include "tracer/render/integrator.h"
#include "tracer/render/processes.h"

namespace rayset::tracer {

uint64_t pass_seed(uint64_t seed, int pass) {
    // Neighbouring (seed, pass) pairs give unrelated seeds.
    return splitmix64_finalise(seed + 0x9E3779B97F4A7C15ULL * (uint64_t(pass) + 1));
}

namespace {

// The one progressive pass loop: an integrator's samples at every sample point, pass after
// pass, each pass added to the films only once complete, so that an abandoned pass leaves
// no trace.
class PassDriver {
public:
    PassDriver(const RenderScene& scene, const RenderSettings& settings, Integrator& integrator,
               const std::vector<ReceiverMap>& receivers, StopFlag stop)
        : integrator_(integrator),
          camera_(scene.description().camera, settings.width, settings.height),
          points_(settings, receivers),
          samples_(integrator.samples_per_pass()),
          weight_(1.0 / samples_),
          to_si_(scene.units().per_square_metre()),
          seed_(settings.seed),
          stop_(stop) {}

    // Pass `pass` within `arena`: its values, or nothing when it was stopped. `between` runs
    // after the samples and before the integrator's end of the pass, stopped or not.
    template <class Between>
    std::optional<PassValues> render_pass(tbb::task_arena& arena, int pass, int components,
                                          std::atomic<uint64_t>& rays, Between&& between) {
        PassValues values(components, points_.size());
        const uint64_t seed = pass_seed(seed_, pass);
        arena.execute([&] {
            integrator_.begin_pass(pass, points_, rays);
            camera_samples(values, seed, pass, rays);
            receiver_samples(values, seed, pass, rays);
        });
        between();
        if (!stopped(stop_))
            arena.execute([&] { integrator_.end_pass(pass, points_, values, rays, stop_); });
        if (stopped(stop_)) return std::nullopt;  // the pass may be incomplete: abandoned
        return values;
    }

    // The pass's values into the film, the receivers and the layers, in SI units.
    void add(const PassValues& values, RenderResult& result) const {
        for (size_t p = 0; p < points_.pixels(); ++p) {
            const int x = int(p % size_t(points_.width)), y = int(p / size_t(points_.width));
            add_point(
                values, p, result.film,
                [&](size_t l) -> SampleGrid& { return result.layers[l].film; }, x, y);
        }
        for (size_t r = 0; r < result.receivers.size(); ++r) {
            const int nx = result.receivers[r].irradiance.nx(),
                      ny = result.receivers[r].irradiance.ny();
            const size_t first = points_.pixels() + points_.receiver_first[r];
            for (int k = 0; k < nx * ny; ++k)
                add_point(
                    values, first + size_t(k), result.receivers[r].irradiance,
                    [&](size_t l) -> SampleGrid& {
                        return result.layers[l].receivers[r].irradiance;
                    },
                    k % nx, k / nx);
        }
        if (points_.pixels() > 0) {
            result.film.finish_pass();
            for (RenderLayer& layer : result.layers) layer.film.finish_pass();
        }
        for (ReceiverMap& map : result.receivers) map.irradiance.finish_pass();
        for (RenderLayer& layer : result.layers)
            for (ReceiverMap& map : layer.receivers) map.irradiance.finish_pass();
    }

private:
    template <class LayerGrid>
    void add_point(const PassValues& values, size_t i, SampleGrid& total, LayerGrid&& layer, int x,
                   int y) const {
        for (size_t l = 0; l + 1 < values.components.size(); ++l)
            layer(l).add(x, y, to_si_ * values.components[l][i]);
        total.add(x, y, to_si_ * values.total(i));
    }

    // Sample k of pass p is sample p * samples_ + k of its pixel's sequence (sampler.h); the
    // pass's seed starts each pixel's stream for what the sequence does not cover.
    void camera_samples(PassValues& values, uint64_t seed, int pass,
                        std::atomic<uint64_t>& rays) const {
        const int w = points_.width, h = points_.height, tile = points_.tile_size,
                  tiles_x = points_.tiles_x();
        tbb::parallel_for(
            tbb::blocked_range<int>(0, points_.tiles()), [&](const tbb::blocked_range<int>& range) {
                uint64_t counted = 0;
                for (int t = range.begin(); t != range.end() && !stopped(stop_); ++t) {
                    const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
                    for (int y = y0; y < std::min(h, y0 + tile); ++y)
                        for (int x = x0; x < std::min(w, x0 + tile); ++x) {
                            const size_t p = size_t(y) * w + x;
                            Pcg32 rng(seed, p);
                            const SampleSink sink{values, p, t, weight_};
                            for (int k = 0; k < samples_; ++k) {
                                Sampler sampler(rng, seed_, p, sample_index(pass, k));
                                double px, py;
                                sampler.get_2d(px, py);
                                const CameraRay ray = camera_.ray(x + px, y + py);
                                if (ray.exists)
                                    integrator_.camera_sample(ray, sink, sampler, counted);
                            }
                        }
                }
                rays += counted;
            });
    }

    void receiver_samples(PassValues& values, uint64_t seed, int pass,
                          std::atomic<uint64_t>& rays) const {
        for (size_t r = 0; r < points_.receivers->size(); ++r) {
            const ReceiverMap& map = (*points_.receivers)[r];
            const int nx = map.irradiance.nx(), ny = map.irradiance.ny();
            const Vec3 normal = map.front_normal();
            const size_t first = points_.receiver_first[r];
            tbb::parallel_for(
                tbb::blocked_range<int>(0, nx * ny), [&](const tbb::blocked_range<int>& range) {
                    if (stopped(stop_)) return;
                    uint64_t counted = 0;
                    for (int k = range.begin(); k != range.end(); ++k) {
                        const size_t c = first + size_t(k);
                        const uint64_t stream = points_.first_cell_stream + c;
                        Pcg32 rng(seed, stream);
                        const SampleSink sink{values, points_.pixels() + c, -1, weight_};
                        const Vec3 point = map.cell_centre(k % nx, k / nx);
                        for (int n = 0; n < samples_; ++n) {
                            Sampler sampler(rng, seed_, stream, sample_index(pass, n));
                            integrator_.receiver_sample(point, normal, sink, sampler, counted);
                        }
                    }
                    rays += counted;
                });
        }
    }

    uint32_t sample_index(int pass, int k) const { return uint32_t(pass) * samples_ + k; }

    Integrator& integrator_;
    const SceneCamera camera_;
    const SamplePoints points_;
    const int samples_;
    const double weight_, to_si_;
    const uint64_t seed_;
    const StopFlag stop_;
};

bool same_layout(const SampleGrid& a, const SampleGrid& b) {
    return a.nx() == b.nx() && a.ny() == b.ny();
}

bool same_layout(const std::vector<ReceiverMap>& a, const std::vector<ReceiverMap>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].receiver.name != b[i].receiver.name ||
            !same_layout(a[i].irradiance, b[i].irradiance))
            return false;
    return true;
}

}  // namespace

RenderResult blank_render(const SceneDescription& scene, const RenderSettings& settings) {
    auto blank_maps = [&] {
        std::vector<ReceiverMap> maps;
        for (const IlluminanceReceiver& r : scene.receivers) maps.emplace_back(r);
        return maps;
    };
    const auto blank_film = [&] {
        return settings.render_image ? Film(settings.width, settings.height) : Film(1, 1);
    };
    RenderResult result;
    result.film = blank_film();
    result.receivers = blank_maps();
    for (const std::string& name : integrator_layers(scene.global.integrator))
        result.layers.push_back({name, blank_film(), blank_maps()});
    return result;
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
    return seconds_before_ +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool PassBudget::allows_another(int passes_done) const {
    return passes_done < passes_ && !(time_limit_ > 0 && elapsed() >= time_limit_);
}

double PassBudget::fraction_done(int passes_done) const {
    double fraction = timed_only_ ? 0 : double(passes_done) / passes_;
    if (time_limit_ > 0) fraction = std::max(fraction, elapsed() / time_limit_);
    return std::min(1.0, fraction);
}

namespace {

// `start` if it continues a render (after checking it has the layout of blank_render),
// else the blank state.
RenderResult starting_state(const RenderScene& scene, const RenderSettings& settings,
                            RenderResult start) {
    RenderResult blank = blank_render(scene.description(), settings);
    if (start.passes == 0) return blank;
    bool fits = same_layout(start.film, blank.film) &&
                same_layout(start.receivers, blank.receivers) &&
                start.layers.size() == blank.layers.size();
    for (size_t i = 0; fits && i < blank.layers.size(); ++i)
        fits = start.layers[i].name == blank.layers[i].name &&
               same_layout(start.layers[i].film, blank.layers[i].film) &&
               same_layout(start.layers[i].receivers, blank.layers[i].receivers);
    if (!fits)
        throw Error(
            "the render to continue has another image size, receivers or layers than this scene "
            "and settings");
    return start;
}

// Every grid of a render, in one order on every process.
template <class Result, class F>
void for_each_grid(Result& result, F&& f) {
    f(result.film);
    for (auto& map : result.receivers) f(map.irradiance);
    for (auto& layer : result.layers) {
        f(layer.film);
        for (auto& map : layer.receivers) f(map.irradiance);
    }
}

// The render as a whole at the root: every process's passes summed (Processes::sum_at_root:
// the same bits for a given number of processes), rays too. Several processes only; the
// others get their own share back.
RenderResult combined(const Processes& processes, const RenderResult& local, RenderResult blank) {
    std::vector<double> numbers{double(local.rays)};  // exact below 2^53
    for_each_grid(local, [&](const SampleGrid& g) { g.append_accumulators(numbers); });
    processes.sum_at_root(numbers);
    if (!processes.is_root()) return local;
    RenderResult total = local;
    total.film = std::move(blank.film), total.receivers = std::move(blank.receivers);
    total.layers = std::move(blank.layers);
    const double* in = numbers.data();
    total.rays = uint64_t(*in++);
    for_each_grid(total, [&](SampleGrid& g) { g.add_accumulators(in); });
    return total;
}

// Every process starts from the root's passes, radius, photons and time; only the root holds
// the accumulators of a continued render.
void share_start(const Processes& processes, RenderResult& result) {
    std::vector<int64_t> counts{result.passes, int64_t(result.photons)};
    std::vector<double> figures{result.photon_radius, result.seconds};
    processes.broadcast(counts);
    processes.broadcast(figures);
    result.passes = int(counts[0]), result.photons = uint64_t(counts[1]);
    result.photon_radius = figures[0], result.seconds = figures[1];
}

// What the root decides before each round of passes: how many (0: the render ends; at most
// one per process) and whether after_pass wants the state after them.
struct Round {
    int passes = 0;
    bool report = false;
};

Round next_round(const Processes& processes, const PassBudget& budget, const Integrator& integrator,
                 const RenderResult& result, const RenderControl& control) {
    std::vector<int64_t> decision{0, 0};
    if (processes.is_root() && !stop_requested(control)) {
        int passes = 0;
        while (passes < processes.size() && budget.allows_another(result.passes + passes)) ++passes;
        const bool report = control.after_pass && (!control.wants_state || control.wants_state());
        decision = {passes, report ? 1 : 0};
    }
    processes.broadcast(decision);
    return {int(decision[0]), decision[1] != 0};
}

}  // namespace

RenderResult render(const RenderScene& scene, const RenderSettings& settings, RenderResult start,
                    const RenderControl& control) {
    const Processes& processes = Processes::world();
    RenderResult result =
        starting_state(scene, settings, processes.is_root() ? std::move(start) : RenderResult{});
    share_start(processes, result);
    const std::unique_ptr<Integrator> integrator = make_integrator(scene, settings, result);
    result.samples_per_pass = integrator->samples_per_pass();
    const PassBudget budget(settings, result.seconds);
    PassDriver driver(scene, settings, *integrator, result.receivers, control.stop);
    const int components = int(result.layers.size()) + 1;
    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    ProgressBar progress("rendering", settings.progress && processes.is_root());
    // Rounds of passes: process r renders pass (passes done) + r.
    for (Round round;
         (round = next_round(processes, budget, *integrator, result, control)).passes > 0;) {
        const bool renders = processes.rank() < round.passes;
        const bool sets_outcome = result.passes == 0 && integrator->first_pass_sets_outcome();
        std::atomic<uint64_t> rays{0};
        // Rank 0 renders the first pass: what the others take from it is handed on once its
        // samples are in, before their own passes end.
        const auto share_outcome = [&] {
            if (!sets_outcome) return;
            std::vector<double> outcome;
            if (processes.is_root()) outcome = integrator->first_pass_outcome();
            processes.broadcast(outcome);
            integrator->set_first_pass_outcome(outcome);
        };
        std::optional<PassValues> pass;
        if (renders)
            pass = driver.render_pass(arena, result.passes + processes.rank(), components, rays,
                                      share_outcome);
        else
            share_outcome();
        if (!processes.all(!renders || pass)) break;  // stopped somewhere: the round is dropped
        if (pass) driver.add(*pass, result);
        for (int p = 0; p < round.passes; ++p) ++result.passes, integrator->pass_completed(result);
        result.rays += rays;
        result.seconds = budget.elapsed();
        if (round.report && processes.size() == 1) control.after_pass(result);
        if (round.report && processes.size() > 1) {
            const RenderResult state =
                combined(processes, result, blank_render(scene.description(), settings));
            if (processes.is_root()) control.after_pass(state);
        }
        progress.update(budget.fraction_done(result.passes));
    }
    progress.done();
    result.seconds = budget.elapsed();
    if (processes.size() > 1)
        result = combined(processes, result, blank_render(scene.description(), settings));
    return result;
}

std::vector<SurfaceHit> centre_hits(const RenderScene& scene, int width, int height) {
    const SceneCamera camera(scene.description().camera, width, height);
    std::vector<SurfaceHit> hits(size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const CameraRay ray = camera.ray(x + 0.5, y + 0.5);
            SurfaceHit& hit = hits[size_t(y) * width + x];
            if (!ray.exists ||
                !scene.intersect(ray.origin, ray.direction, 0,
                                 std::numeric_limits<double>::infinity(), RayKind::camera, hit))
                hit.object = -1;
        }
    return hits;
}

std::vector<int> object_id_image(const RenderScene& scene, int width, int height) {
    std::vector<int> ids;
    for (const SurfaceHit& hit : centre_hits(scene, width, height)) ids.push_back(hit.object);
    return ids;
}

}  // namespace rayset::tracer
