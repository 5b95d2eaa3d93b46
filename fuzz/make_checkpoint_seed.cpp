// Writes the checkpoint of two passes of the render of checkpoint_render.h, the seed of
// fuzz_checkpoint (scripts/fuzz.sh runs it), and reads it back, so that a seed the reader refuses
// fails here.
// Usage: fuzz_checkpoint_seed OUT
#include "core/error.h"
#include "fuzz/checkpoint_render.h"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: fuzz_checkpoint_seed OUT\n");
        return 2;
    }
    using namespace rayset;
    tracer::RenderResult state = fuzz::blank_checkpoint_render();
    for (int pass = 0; pass < 2; ++pass) {
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) state.film.add(x, y, {0.5 * x, 0.25 * y, 0.125});
        state.film.finish_pass();
        state.receivers[0].irradiance.add(1, 1, {2, 2, 2});
        state.receivers[0].irradiance.finish_pass();
        for (tracer::RenderLayer& layer : state.layers) {
            layer.film.finish_pass();
            layer.receivers[0].irradiance.finish_pass();
        }
    }
    state.passes = 2, state.seconds = 1.5, state.rays = 1234, state.photons = 2000;
    state.photon_radius = 0.25, state.photon_bytes = 4096, state.visible_point_bytes = 512;
    try {
        tracer::write_checkpoint(argv[1], fuzz::checkpoint_identity(), state);
        tracer::read_checkpoint(argv[1], fuzz::checkpoint_identity(),
                                fuzz::blank_checkpoint_render());
    } catch (const Error& e) {
        std::fprintf(stderr, "fuzz_checkpoint_seed: %s\n", e.what());
        return 1;
    }
    return 0;
}
