// raytrace --bench: the renderer's rays per second (everything: sampling, shading, film) against
// bare Embree queries on the very rays the renderer cast, on 1 and 2 threads.
#include <algorithm>

#include <fmt/format.h>

#include "tracer/render/renderer.h"

namespace rayset::tracer {

void run_raytrace_benchmark(RenderScene& scene, const RenderSettings& base) {
    RenderSettings settings = base;
    settings.progress = false;
    settings.time_limit = 0;
    if (settings.passes <= 0) settings.passes = 8;

    // The rays of one pass, recorded on one thread.
    std::vector<RecordedRay> rays;
    RenderSettings one_pass = settings;
    one_pass.passes = 1;
    one_pass.threads = 1;
    scene.record_rays(&rays);
    render(scene, one_pass);
    scene.record_rays(nullptr);
    size_t shadow = 0;
    for (const RecordedRay& r : rays) shadow += r.shadow;

    fmt::print(
        "scene: {} objects; image {} x {}, {} passes; one pass casts {} rays ({} occlusion)\n",
        scene.description().objects.size(), settings.width, settings.height, settings.passes,
        rays.size(), shadow);
    // Best of 5 alternating rounds: on a shared machine other work only ever slows a round down.
    double renderer_one = 0, bare_one = 0;
    for (int threads : {1, 2}) {
        settings.threads = threads;
        double renderer = 0, bare = 0;
        for (int round = 0; round < 5; ++round) {
            const RenderResult result = render(scene, settings);
            renderer = std::max(renderer, result.rays / result.seconds);
            bare =
                std::max(bare, scene.bare_embree_rays_per_second(rays, threads, settings.passes));
        }
        if (threads == 1) renderer_one = renderer, bare_one = bare;
        fmt::print(
            "threads {}: renderer {:.4g} rays/s, bare rtcIntersect1/rtcOccluded1 {:.4g} rays/s, "
            "ratio {:.2f}",
            threads, renderer, bare, renderer / bare);
        if (threads == 2)
            fmt::print("; scaling 1->2 threads: renderer x{:.2f}, bare x{:.2f}",
                       renderer / renderer_one, bare / bare_one);
        fmt::print("\n");
    }
}

}  // namespace rayset::tracer
