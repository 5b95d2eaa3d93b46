// box_convergence: how fast the bidirectional renderer converges on the paper's box
// (examples/led_box.pov, lit by the 39-chip cluster): camera paths and photons per second,
// the memory of the photon grid and visible points, and the time to reach 2% relative RMSE
// of the image's illumination (primary + secondary light) against a converged reference.
//
// The reference is the same render with REFERENCE_PASSES passes (default 1024); renders of
// 1, 2, 4 ... passes are compared with it by
//   relative RMSE = sqrt(mean over pixels (Y - Y_ref)^2) / mean(Y_ref)
// with Y the luminance of primary + secondary light.
// The reference's own noise adds (passes / REFERENCE_PASSES) of a render's squared error; it
// is divided out, and both figures are printed.
// Usage: box_convergence SCENE INCLUDE_DIR [WIDTH HEIGHT REFERENCE_PASSES]
//   e.g. box_convergence examples/led_box.pov out/example 160 120 1024
// (scripts/example.sh makes out/example/cluster.tm25ray.)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"

using namespace rayset::tracer;

namespace {

// Luminance of the light on surfaces: primary + secondary. The chips seen directly (or in the
// mirror) are left out: a few pixels 1e4 times brighter than the walls, whose sub-pixel
// coverage noise would be the whole figure.
double illumination(const RenderResult& r, int x, int y) {
    return luminance_weight(r.layers[1].film.mean(x, y)) +
           luminance_weight(r.layers[2].film.mean(x, y));
}

double relative_rmse(const RenderResult& a, const RenderResult& reference) {
    double squares = 0, sum = 0;
    for (int y = 0; y < a.film.ny(); ++y)
        for (int x = 0; x < a.film.nx(); ++x) {
            const double r = illumination(reference, x, y);
            squares += std::pow(illumination(a, x, y) - r, 2);
            sum += r;
        }
    const double n = double(a.film.nx()) * a.film.ny();
    return std::sqrt(squares / n) / (sum / n);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr,
                     "usage: box_convergence SCENE INCLUDE_DIR [WIDTH HEIGHT REFERENCE_PASSES]\n");
        return 2;
    }
    ParseOptions options;
    options.include_paths = {argv[2]};
    const RenderScene scene(parse_scene_file(argv[1], options));
    RenderSettings settings;
    settings.width = argc > 4 ? std::atoi(argv[3]) : 160;
    settings.height = argc > 4 ? std::atoi(argv[4]) : 120;
    const int reference_passes = argc > 5 ? std::atoi(argv[5]) : 1024;
    settings.seed = 1;
    settings.passes = reference_passes;
    const RenderResult reference = render(scene, settings);
    const double pixels = double(settings.width) * settings.height;
    std::printf(
        "%s at %d x %d; reference %d passes (%d samples per pixel each) in %.1f s: %.3g camera "
        "paths/s, %.3g photons/s, %.3g rays/s; "
        "photon grid %.1f MiB, visible points %.1f MiB (largest pass)\n",
        argv[1], settings.width, settings.height, reference.passes, reference.samples_per_pass,
        reference.seconds,
        pixels * reference.passes * reference.samples_per_pass / reference.seconds,
        reference.photons / reference.seconds, reference.rays / reference.seconds,
        reference.photon_bytes / 1048576.0, reference.visible_point_bytes / 1048576.0);
    std::printf("%8s %10s %12s %14s\n", "passes", "seconds", "rel. RMSE", "without ref noise");
    settings.seed = 2;  // independent of the reference
    bool reached = false;
    for (int passes = 1; passes <= reference_passes / 4; passes *= 2) {
        settings.passes = passes;
        const RenderResult r = render(scene, settings);
        const double raw = relative_rmse(r, reference);
        const double corrected = raw / std::sqrt(1 + double(passes) / reference_passes);
        std::printf("%8d %10.2f %12.4f %14.4f\n", passes, r.seconds, raw, corrected);
        std::fflush(stdout);
        if (!reached && corrected <= 0.02) {
            std::printf("2%% relative RMSE reached after %d passes, %.1f s\n", passes, r.seconds);
            reached = true;
        }
    }
    return 0;
}
