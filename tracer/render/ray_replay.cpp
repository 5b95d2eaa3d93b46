// The benchmark's bare Embree rate: recorded rays replayed through rtcIntersect1 and
// rtcOccluded1 with nothing else around them (no shading, sampling or film).
#include <atomic>
#include <chrono>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "tracer/render/scene_geometry.h"

namespace rayset::tracer {

double RenderScene::bare_embree_rays_per_second(const std::vector<RecordedRay>& rays, int threads,
                                                int repeats) const {
    if (rays.empty()) return 0;
    std::atomic<unsigned> hits{0};  // keeps the queries from being optimised away
    tbb::task_arena arena(threads);
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < repeats; ++r)
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096),
                              [&](const tbb::blocked_range<size_t>& range) {
                                  unsigned local = 0;
                                  TraceContext context;
                                  rtcInitIntersectContext(&context.embree);
                                  for (size_t i = range.begin(); i != range.end(); ++i) {
                                      const RecordedRay& q = rays[i];
                                      context.skip = q.skip;
                                      RTCRayHit rh;
                                      rh.ray.org_x = q.origin[0], rh.ray.org_y = q.origin[1],
                                      rh.ray.org_z = q.origin[2];
                                      rh.ray.dir_x = q.direction[0], rh.ray.dir_y = q.direction[1],
                                      rh.ray.dir_z = q.direction[2];
                                      rh.ray.tnear = q.t_near, rh.ray.tfar = q.t_far;
                                      rh.ray.time = 0, rh.ray.mask = ~0u, rh.ray.id = 0,
                                      rh.ray.flags = 0;
                                      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                                      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                                      if (q.shadow) {
                                          rtcOccluded1(scene_, &context.embree, &rh.ray);
                                          local += rh.ray.tfar < 0;
                                      } else {
                                          rtcIntersect1(scene_, &context.embree, &rh);
                                          local += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                                      }
                                  }
                                  hits += local;
                              });
        });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    volatile unsigned sink = hits.load();
    (void)sink;
    return double(rays.size()) * repeats / seconds;
}

}  // namespace rayset::tracer
