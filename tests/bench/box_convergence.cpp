// box_convergence: how fast the integrators converge on a scene lit by ray files (the paper's
// box, examples/led_box.pov, lit by the 39-chip cluster, by default): camera paths and photons
// per second, the memory of the photon grid and visible points, and the time to reach 2%
// relative RMSE of the image's illumination against a converged reference.
//
// The reference is a render of the first integrator named (default: the scene's) with
// REFERENCE_PASSES passes (default 1024), made as two halves of independent seeds; renders of
// 1, 2, 4 ... passes with each integrator named are compared with it by
//   relative RMSE = sqrt(mean over pixels (Y - Y_ref)^2) / mean(Y_ref)
// with Y the luminance of the illumination: primary + secondary light when both render has
// layers, else the whole image (then sources seen directly count too).
// The reference's own noise adds to a render's squared error what the halves' difference
// measures, mean (Y_1 - Y_2)^2 / 4 (each half's noise independent of the other's); it is taken
// out, and both figures are printed. A bias of the reference is not: what converges to the
// truth is an unbiased integrator's reference (the path tracer's), which is what a time to 2%
// of a photon-merging integrator is measured against (merging is biased: darker along edges
// while the radius is finite). The time to 2% is read off between the two renders around it
// (log error linear in log time).
// An integrator named INTEGRATOR:N stops its series at N passes (default REFERENCE_PASSES / 4).
// Usage: box_convergence SCENE INCLUDE_DIR [WIDTH HEIGHT REFERENCE_PASSES [INTEGRATOR...]]
//   e.g. box_convergence examples/led_box.pov out/example 160 120 1024
//        box_convergence grey_box.pov . 160 160 1024 path bidirectional
//        box_convergence examples/led_box.pov out/example 160 120 40960 path:8192 vcm:2048
// (scripts/example.sh makes out/example/cluster.tm25ray.)
#include <algorithm>
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

// The illumination of every pixel, row by row.
std::vector<double> illumination_image(const RenderResult& r, bool layers) {
    std::vector<double> image;
    image.reserve(size_t(r.film.nx()) * r.film.ny());
    for (int y = 0; y < r.film.ny(); ++y)
        for (int x = 0; x < r.film.nx(); ++x) image.push_back(illumination(r, x, y, layers));
    return image;
}

double mean_of(const std::vector<double>& a) {
    double sum = 0;
    for (double v : a) sum += v;
    return sum / double(a.size());
}

double mean_square_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double squares = 0;
    for (size_t i = 0; i < a.size(); ++i) squares += (a[i] - b[i]) * (a[i] - b[i]);
    return squares / double(a.size());
}

// The reference: the mean of two halves, and its own squared relative error as their
// difference measures it.
struct Reference {
    std::vector<double> image;
    double mean = 0, noise_squared = 0;
};

Reference make_reference(const RenderResult& first, const RenderResult& second, bool layers) {
    const std::vector<double> a = illumination_image(first, layers),
                              b = illumination_image(second, layers);
    Reference ref;
    for (size_t i = 0; i < a.size(); ++i) ref.image.push_back(0.5 * (a[i] + b[i]));
    ref.mean = mean_of(ref.image);
    ref.noise_squared = mean_square_difference(a, b) / 4 / (ref.mean * ref.mean);
    return ref;
}

// The time at which a series of renders, (seconds, error) as passes double, first reaches
// `target`: between the last render above it and the first at or below it, log error linear
// in log time; 0 while none has.
class TimeToError {
public:
    explicit TimeToError(double target) : target_(target) {}
    void add(double seconds, double error) {
        if (reached_ == 0 && error <= target_) {
            reached_ = seconds;
            if (error_ > target_ && error > 0 && seconds_ > 0)
                reached_ = seconds_ * std::pow(seconds / seconds_, std::log(error_ / target_) /
                                                                       std::log(error_ / error));
        }
        seconds_ = seconds, error_ = error;
    }
    double reached() const { return reached_; }

private:
    double target_, seconds_ = 0, error_ = 0, reached_ = 0;
};

// Renders of 1, 2, 4 ... `last` passes against the reference, one line each.
void print_series(const RenderScene& scene, RenderSettings settings, const Reference& reference,
                  bool layers, int last) {
    std::printf("%8s %10s %12s %14s\n", "passes", "seconds", "rel. RMSE", "without ref noise");
    settings.seed = 2;  // independent of the reference's halves
    TimeToError two_percent(0.02);
    for (int passes = 1; passes <= last; passes *= 2) {
        settings.passes = passes;
        const RenderResult r = render(scene, settings);
        if (r.layers.empty() == layers) {
            std::fprintf(stderr, "the reference has layers and this render not, or the reverse\n");
            std::exit(1);
        }
        const double raw_squared =
            mean_square_difference(illumination_image(r, layers), reference.image) /
            (reference.mean * reference.mean);
        const double error = std::sqrt(std::max(0.0, raw_squared - reference.noise_squared));
        std::printf("%8d %10.2f %12.4f %14.4f\n", passes, r.seconds, std::sqrt(raw_squared), error);
        std::fflush(stdout);
        const bool before = two_percent.reached() > 0;
        two_percent.add(r.seconds, error);
        if (!before && two_percent.reached() > 0)
            std::printf("2%% relative RMSE reached after about %.1f s (%d passes took %.1f s)\n",
                        two_percent.reached(), passes, r.seconds);
    }
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
    settings.passes = reference_passes / 2;
    const std::unique_ptr<RenderScene> reference_scene = scene_with(integrators.front());
    settings.seed = 1;
    const RenderResult first_half = render(*reference_scene, settings);
    settings.seed = 3;
    const RenderResult second_half = render(*reference_scene, settings);
    const bool layers = !first_half.layers.empty();
    const Reference reference = make_reference(first_half, second_half, layers);
    const double pixels = double(settings.width) * settings.height;
    const double seconds = first_half.seconds + second_half.seconds;
    std::printf(
        "%s at %d x %d; reference (%s) 2 x %d passes (%d samples per pixel each) in %.1f s: "
        "%.3g camera paths/s, %.3g photons/s, %.3g rays/s; its own relative RMSE %.4f; "
        "photon grid %.1f MiB, visible points %.1f MiB (largest pass)\n",
        argv[1], settings.width, settings.height, integrators.front().c_str(), settings.passes,
        first_half.samples_per_pass, seconds,
        pixels * 2 * settings.passes * first_half.samples_per_pass / seconds,
        (first_half.photons + second_half.photons) / seconds,
        (first_half.rays + second_half.rays) / seconds, std::sqrt(reference.noise_squared),
        first_half.photon_bytes / 1048576.0, first_half.visible_point_bytes / 1048576.0);
    for (size_t k = 0; k < integrators.size(); ++k) {
        std::printf("%s\n", integrators[k].c_str());
        print_series(*scene_with(integrators[k]), settings, reference, layers,
                     last_passes[k] > 0 ? last_passes[k] : reference_passes / 4);
    }
    return 0;
}
