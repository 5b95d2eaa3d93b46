// least_path_tracer: how close to bare Embree a path tracer can come on a scene, as a yardstick
// for `raytrace --bench`. It does the least a path tracer must: a camera ray per pixel and pass,
// at each hit a grey Lambertian (no material lookup), one light sample of the scene's lights
// (LightSet, as the renderer chooses and samples them) with its shadow ray, a cosine-weighted
// bounce, roulette after three bounces, the sum into a float film; no MIS, no layers, no
// receivers, no fog or media. The queries and their hit resolution are the renderer's
// (RenderScene), so the bare replay of its rays is measured exactly as --bench measures the
// renderer's. Its image is not the scene's (grey everywhere, emitting surfaces dark): what it
// measures is the cost of a path, and the mean pixel it prints only keeps the work from being
// optimised away.
// Usage: least_path_tracer SCENE.pov [WIDTH HEIGHT PASSES]   (defaults 320 240 8; one thread)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "core/random.h"
#include "tracer/render/camera.h"
#include "tracer/render/light.h"
#include "tracer/render/render_scene.h"
#include "tracer/render/rgb.h"
#include "tracer/render/sampling.h"
#include "tracer/scene_language/scene_language.h"

namespace {

using namespace rayset;
using namespace rayset::tracer;

constexpr double kAlbedo = 0.5;

// One pass over every pixel; returns the rays cast.
uint64_t render_pass(const RenderScene& scene, const LightSet& lights, const SceneCamera& camera,
                     Pcg32& rng, std::vector<float>& film) {
    const double infinity = std::numeric_limits<double>::infinity();
    uint64_t rays = 0;
    for (int y = 0; y < camera.height(); ++y)
        for (int x = 0; x < camera.width(); ++x) {
            const CameraRay ray = camera.ray(x + rng.uniform_float(), y + rng.uniform_float());
            Vec3 origin = ray.origin, direction = ray.direction;
            RayKind kind = RayKind::camera;
            double beta = 1, radiance = 0;
            SurfaceHit hit;
            for (int depth = 0; depth < 8; ++depth) {
                ++rays;
                if (!scene.intersect(origin, direction, 0, infinity, kind, hit)) break;
                const Vec3 normal = dot(hit.normal, direction) < 0 ? hit.normal : -hit.normal;
                LightLiSampleOf<Rgb> light;
                const bool sampled = lights.sample_Li<Rgb>(hit.point, lights.draw(rng), {}, light);
                const double cos_light = sampled ? dot(normal, light.wi) : 0;
                if (cos_light > 0) {
                    ++rays;
                    const Vec3 start = scene.offset(hit.point, normal, light.wi);
                    if (!scene.occluded(start, light.wi, 0, light.distance - scene.epsilon()))
                        radiance += beta * kAlbedo / kPi * cos_light * luminance_weight(light.Li) /
                                    light.pdf;
                }
                const Vec3 wi = Frame(normal).to_world(
                    cosine_hemisphere(rng.uniform_float(), rng.uniform_float()));
                beta *= kAlbedo;
                if (depth >= 3) {
                    if (rng.uniform_float() >= kAlbedo) break;
                    beta /= kAlbedo;
                }
                origin = scene.offset(hit.point, normal, wi);
                direction = wi;
                kind = RayKind::indirect;
            }
            film[size_t(y) * size_t(camera.width()) + size_t(x)] += float(radiance);
        }
    return rays;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 && argc != 5) {
        std::fprintf(stderr, "usage: least_path_tracer SCENE.pov [WIDTH HEIGHT PASSES]\n");
        return 2;
    }
    const int width = argc == 5 ? std::atoi(argv[2]) : 320;
    const int height = argc == 5 ? std::atoi(argv[3]) : 240;
    const int passes = argc == 5 ? std::atoi(argv[4]) : 8;
    RenderScene scene(parse_scene_file(argv[1]));
    const LightSet lights(scene, false);
    const SceneCamera camera(scene.description().camera, width, height);
    std::vector<float> film(size_t(width) * size_t(height));
    Pcg32 rng(1);

    std::vector<RecordedRay> recorded;
    scene.record_rays(&recorded);
    render_pass(scene, lights, camera, rng, film);
    scene.record_rays(nullptr);

    // Best of 5 alternating rounds, as raytrace --bench takes them.
    double tracer = 0, bare = 0;
    for (int round = 0; round < 5; ++round) {
        const auto start = std::chrono::steady_clock::now();
        uint64_t rays = 0;
        for (int pass = 0; pass < passes; ++pass)
            rays += render_pass(scene, lights, camera, rng, film);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        tracer = std::max(tracer, rays / seconds);
        bare = std::max(bare, scene.bare_embree_rays_per_second(recorded, 1, passes));
    }
    double sum = 0;
    for (float v : film) sum += v;
    std::printf("one pass casts %zu rays; mean pixel %.4g\n", recorded.size(),
                sum / double(film.size()));
    std::printf(
        "1 thread: least path tracer %.4g rays/s, bare rtcIntersect1/rtcOccluded1 %.4g "
        "rays/s, ratio %.2f\n",
        tracer, bare, tracer / bare);
}
