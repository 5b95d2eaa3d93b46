// box_convergence: how fast the integrators converge on a scene lit by ray files (the paper's
// box, examples/led_box.pov, lit by the 39-chip cluster, by default): camera paths and photons
// per second, the memory of the photon grid and visible points, and the time to reach 2%
// relative RMSE of the image's illumination against a converged reference.
//
// The reference is a render of the first integrator named (default: the scene's) with
// REFERENCE_PASSES passes (default 1024); renders of 1, 2, 4 ... passes with each integrator
// named are compared with it by
//   relative RMSE = sqrt(mean over pixels (Y - Y_ref)^2) / mean(Y_ref)
// with Y the luminance of the illumination: primary + secondary light when both render has
// layers, else the whole image (then sources seen directly count too).
// The reference's own noise adds (passes / REFERENCE_PASSES) of a render's squared error; it
// is divided out, and both figures are printed.
// An integrator named INTEGRATOR:N stops its series at N passes (default REFERENCE_PASSES / 4).
// Usage: box_convergence SCENE INCLUDE_DIR [WIDTH HEIGHT REFERENCE_PASSES [INTEGRATOR...]]
//   e.g. box_convergence examples/led_box.pov out/example 160 120 1024
//        box_convergence grey_box.pov . 160 160 1024 path bidirectional
// (scripts/example.sh makes out/example/cluster.tm25ray.)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"

using namespace rayset::tracer;

namespace {

// Luminance of the light on surfaces: primary + secondary. The chips seen directly (or in the
// mirror) are left out: a few pixels 1e4 times brighter than the walls, whose sub-pixel
// coverage noise would be the whole figure.
double illumination(const RenderResult& r, int x, int y, bool layers) {
    if (!layers) return luminance_weight(r.film.mean(x, y));
    return luminance_weight(r.layers[1].film.mean(x, y)) +
           luminance_weight(r.layers[2].film.mean(x, y));
}

double relative_rmse(const RenderResult& a, const RenderResult& reference) {
    const bool layers = !a.layers.empty() && !reference.layers.empty();
    double squares = 0, sum = 0;
    for (int y = 0; y < a.film.ny(); ++y)
        for (int x = 0; x < a.film.nx(); ++x) {
            const double r = illumination(reference, x, y, layers);
            squares += std::pow(illumination(a, x, y, layers) - r, 2);
            sum += r;
        }
    const double n = double(a.film.nx()) * a.film.ny();
    return std::sqrt(squares / n) / (sum / n);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr,
                     "usage: box_convergence SCENE INCLUDE_DIR [WIDTH HEIGHT REFERENCE_PASSES "
                     "[INTEGRATOR...]]\n");
        return 2;
    }
    ParseOptions options;
    options.include_paths = {argv[2]};
    const SceneDescription description = parse_scene_file(argv[1], options);
    std::vector<std::string> integrators;
    std::vector<int> last_passes;
    for (int i = 6; i < argc; ++i) {
        const std::string named = argv[i];
        const size_t colon = named.find(':');
        integrators.push_back(named.substr(0, colon));
        last_passes.push_back(colon == std::string::npos ? 0
                                                         : std::atoi(named.c_str() + colon + 1));
    }
    if (integrators.empty())
        integrators.push_back(description.global.integrator), last_passes.push_back(0);
    auto scene_with = [&](const std::string& integrator) {
        SceneDescription d = description;
        d.global.integrator = integrator;
        return std::make_unique<RenderScene>(d);
    };
    RenderSettings settings;
    settings.width = argc > 4 ? std::atoi(argv[3]) : 160;
    settings.height = argc > 4 ? std::atoi(argv[4]) : 120;
    const int reference_passes = argc > 5 ? std::atoi(argv[5]) : 1024;
    settings.seed = 1;
    settings.passes = reference_passes;
    const RenderResult reference = render(*scene_with(integrators.front()), settings);
    const double pixels = double(settings.width) * settings.height;
    std::printf(
        "%s at %d x %d; reference (%s) %d passes (%d samples per pixel each) in %.1f s: %.3g "
        "camera paths/s, %.3g photons/s, %.3g rays/s; "
        "photon grid %.1f MiB, visible points %.1f MiB (largest pass)\n",
        argv[1], settings.width, settings.height, integrators.front().c_str(), reference.passes,
        reference.samples_per_pass, reference.seconds,
        pixels * reference.passes * reference.samples_per_pass / reference.seconds,
        reference.photons / reference.seconds, reference.rays / reference.seconds,
        reference.photon_bytes / 1048576.0, reference.visible_point_bytes / 1048576.0);
    for (size_t k = 0; k < integrators.size(); ++k) {
        const std::string& integrator = integrators[k];
        const int last = last_passes[k] > 0 ? last_passes[k] : reference_passes / 4;
        const std::unique_ptr<RenderScene> scene = scene_with(integrator);
        std::printf("%s\n%8s %10s %12s %14s\n", integrator.c_str(), "passes", "seconds",
                    "rel. RMSE", "without ref noise");
        settings.seed = 2;  // independent of the reference
        bool reached = false;
        for (int passes = 1; passes <= last; passes *= 2) {
            settings.passes = passes;
            const RenderResult r = render(*scene, settings);
            const double raw = relative_rmse(r, reference);
            const double corrected = raw / std::sqrt(1 + double(passes) / reference_passes);
            std::printf("%8d %10.2f %12.4f %14.4f\n", passes, r.seconds, raw, corrected);
            std::fflush(stdout);
            if (!reached && corrected <= 0.02) {
                std::printf("2%% relative RMSE reached after %d passes, %.1f s\n", passes,
                            r.seconds);
                reached = true;
            }
        }
    }
    return 0;
}
