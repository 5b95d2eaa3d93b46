// The progressive renderer: one pass driver over the scene's integrator (integrator.h). A pass
// takes the integrator's samples at every pixel and receiver cell, tiles spread over TBB
// threads; a pass or time budget, checkpoints after passes, a progress bar. Every pixel and
// cell draws from its own PCG32 stream (stream = sample point, seed mixed with the pass
// number), so an image depends on the seed and the number of passes only, not on threads or
// timing.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "tracer/film/film.h"
#include "tracer/render/integrator.h"
#include "tracer/render/render_scene.h"

namespace rayset::tracer {

struct RenderSettings {
    int width = 320, height = 240;  // POV-Ray's default size
    int passes = 0;                 // 0: until time_limit, or kDefaultPasses without one
    double time_limit = 0;          // seconds, checked between passes; 0: none
    uint64_t seed = 0;
    int threads = 0;           // 0: every core
    bool render_image = true;  // false: receivers only
    bool progress = false;     // progress bar on stderr (when it is a terminal)
    int tile_size = 16;
    static constexpr int kDefaultPasses = 16;
    // Bidirectional integrator (bidirectional_passes.cpp).
    int photons_per_pass =
        0;  // 0: the camera samples of a pass (pixels + receiver cells), at least 65536;
            // a pass takes photons / (pixels + cells) samples per pixel and cell, at least 1
    double photon_radius =
        0;  // gather radius of the first pass, scene units; 0: 1/100 of the
            // diagonal of the box of the middle 90% (per axis) of the first pass's visible points
    bool naive_sources = false;  // ray sources as their stored rays (the paper's Figure 1)
    bool spectral = false;  // spectral transport (spectrum.h); also global_settings { spectral on }
};

// One light component of a bidirectional render, as its own image and receiver maps.
struct RenderLayer {
    std::string name;  // direct_visibility, primary, secondary
    Film film{1, 1};
    std::vector<ReceiverMap> receivers;
};

struct RenderResult {
    Film film{1, 1};
    std::vector<ReceiverMap> receivers;
    int passes = 0;
    int samples_per_pass = 1;  // camera samples per pixel and receiver cell in each pass
    double seconds = 0;
    uint64_t rays = 0;  // every ray cast: camera, bounce, shadow
    // Bidirectional only: the components (the film and receivers above hold their sum plus
    // the ordinary lights), photons emitted, and the gather radius of the last pass.
    std::vector<RenderLayer> layers;
    uint64_t photons = 0;
    double photon_radius = 0;
    size_t photon_bytes = 0,
           visible_point_bytes = 0;  // the photon grid and visible points, largest pass
};

// What a render is told besides its settings, for checkpoints and interruption.
struct RenderControl {
    // Called after every completed pass with the state so far (passes, accumulators, rays,
    // photons, radius, seconds): what a checkpoint stores.
    std::function<void(const RenderResult&)> after_pass;
    // Whether after_pass would use the state after the passes under way (a checkpoint is due);
    // unset: always. Asked at the root before each round: with several processes the state
    // is only combined when wanted.
    std::function<bool()> wants_state;
    // Once true (a signal handler may set it), the pass under way is abandoned and render
    // returns the completed passes.
    const std::atomic<bool>* stop = nullptr;
};

// The state before the first pass: zeroed film (when settings.render_image), receiver maps
// and the integrator's layers.
RenderResult blank_render(const SceneDescription& scene, const RenderSettings& settings);

// Renders with the scene's integrator (make_integrator, integrator.h), on every process of
// Processes::world() (processes.h): each renders its share of the passes, the root returns
// their combination (the others their own share) and alone calls control.after_pass.
// `start`: a state to continue (from a checkpoint of the same scene and settings, or a render
// stopped earlier); with start.passes == 0 the render starts afresh. Pass budgets count
// start's passes and seconds: a continued render ends where an uninterrupted one would.
RenderResult render(const RenderScene& scene, const RenderSettings& settings,
                    RenderResult start = {}, const RenderControl& control = {});

// The budget of a render: `passes`, else passes until `time_limit`, else
// kDefaultPasses; checked between passes. The clock starts at construction, from
// `seconds_before` (the time a continued render has already spent).
class PassBudget {
public:
    explicit PassBudget(const RenderSettings& settings, double seconds_before = 0);
    double elapsed() const;  // seconds
    bool allows_another(int passes_done) const;
    double fraction_done(int passes_done) const;  // for the progress bar, 0..1

private:
    double time_limit_;
    int passes_;
    bool timed_only_;
    double seconds_before_;
    std::chrono::steady_clock::time_point start_;
};

inline bool stop_requested(const RenderControl& control) { return stopped(control.stop); }

// Seed of the random streams of one pass.
uint64_t pass_seed(uint64_t seed, int pass);

// The surface each pixel's centre ray sees (object -1: none), row by row from the top; the
// comparisons against POV-Ray's renders (silhouettes, patterns) use it.
std::vector<SurfaceHit> centre_hits(const RenderScene& scene, int width, int height);
// The index of the object each pixel's centre ray sees (-1: none).
std::vector<int> object_id_image(const RenderScene& scene, int width, int height);

}  // namespace rayset::tracer
