// Speed of the emitter interface of the complex model: sample_Li (light sampling from a point
// 3 source sizes away), sample_Le (photon emission) and a camera ray's intersect + L, on a
// model of the 39-chip cluster built from 1e6 synthetic rays at start-up.
// Usage: emitter_bench [--benchmark_filter=...]
#include "converters/analytic/synth.h"
#include "converters/rays/ray_stream.h"
#include "core/random.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

namespace {

using namespace rayset;
using namespace rayset::lightmodel;

const ComplexSource& cluster() {
    static std::unique_ptr<ComplexSource> source = [] {
        const std::string path =
            (std::filesystem::temp_directory_path() / "rayset_emitter_bench.tm25ray").string();
        auto truth = make_source("cluster", {});
        {
            auto out = create_rays(path, RayFormat::tm25, synth_header(*truth, 1000000, 1));
            synthesize(*truth, 1000000, 1, *out);
        }
        auto model = std::make_shared<LightModel>(build_model(path, {}));
        std::filesystem::remove(path);
        return std::make_unique<ComplexSource>(model);
    }();
    return *source;
}

void sample_Li(benchmark::State& state) {
    const ComplexSource& s = cluster();
    const Box b = s.bounds();
    const Vec3 ref =
        0.5 * (b.lower + b.upper) + Vec3{b.longest(), 0.5 * b.longest(), 3 * b.longest()};
    Pcg32 rng(1);
    for (auto _ : state) {
        auto li = s.sample_Li(ref, rng.uniform(), rng.uniform(),
                              {rng.uniform(), rng.uniform(), rng.uniform()});
        benchmark::DoNotOptimize(li);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(sample_Li);

void sample_Le(benchmark::State& state) {
    const ComplexSource& s = cluster();
    Pcg32 rng(2);
    for (auto _ : state) {
        double u[7];
        for (double& v : u) v = rng.uniform();
        auto le = s.sample_Le(u);
        benchmark::DoNotOptimize(le);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(sample_Le);

void camera_ray(benchmark::State& state) {
    const ComplexSource& s = cluster();
    const Box b = s.bounds();
    Pcg32 rng(3);
    for (auto _ : state) {
        const Vec3 target{b.lower.x + rng.uniform() * (b.upper.x - b.lower.x),
                          b.lower.y + rng.uniform() * (b.upper.y - b.lower.y), 0};
        const Vec3 eye{0, 0, 50};
        const Vec3 dir = normalized(target - eye);
        EmitterHit hit;
        double L = 0;
        if (s.intersect(eye, dir, 1e9, hit)) L = s.L(eye, dir, hit);
        benchmark::DoNotOptimize(L);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(camera_ray);

}  // namespace

BENCHMARK_MAIN();
