// noise_floor: the paper's claim measured - primary light of a ray-file source has a noise
// floor under the naive model (its rays as photons) and none under the light model.
//
// Scene: a Lambertian disk (radius 1 mm, 1 W at 555 nm, a synthetic ray file of RAYS rays)
// 20 mm above a grey floor, facing it; an illuminance receiver of 64 x 64 cells over 80 x 80
// mm of the floor records primary light. Each method renders for 1, 2, 4, ... seconds (each
// budget a fresh render with the same seed) and its primary map is compared with
//   truth      - the disk's closed-form illuminance (independent of every model);
//   model      - the closed form times the model's far-field intensity over the disk's (the
//                value the light model converges to, up to its near-field part): the error
//                left against it is the render's noise, without the model's own bias.
// Prints one table: seconds, then relative RMS error over the cells for each method.
// Usage: noise_floor [RAYS] [MAX_SECONDS]     (defaults 1000000 and 32)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "converters/analytic/analytic_sources.h"
#include "converters/analytic/synth.h"
#include "converters/rays/ray_stream.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"
#include "tracer/render/ray_sources.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"

namespace {

using namespace rayset;
using namespace rayset::tracer;

constexpr double kHeight = 20;  // mm

struct Errors {
    double truth = 0, model = 0;
};

Errors map_errors(const ReceiverMap& map, const analytic::LambertianDisk& disk,
                  const lightmodel::ComplexSource& model) {
    double truth_squares = 0, model_squares = 0;
    int cells = 0;
    for (int j = 0; j < map.irradiance.ny(); ++j)
        for (int i = 0; i < map.irradiance.nx(); ++i) {
            const Vec3 p = map.cell_centre(i, j), q{p.x, p.z, kHeight};  // the disk's frame
            const double truth = 1e6 * disk.irradiance(q, {0, 0, -1});   // W/m^2
            const Vec3 w = normalized(q);
            const double model_value = truth * model.intensity(w) / disk.intensity(w);
            const double measured = luminance_weight(map.irradiance.mean(i, j));
            truth_squares += std::pow(measured / truth - 1, 2);
            model_squares += std::pow(measured / model_value - 1, 2);
            ++cells;
        }
    return {std::sqrt(truth_squares / cells), std::sqrt(model_squares / cells)};
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t rays = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
    const double max_seconds = argc > 2 ? std::atof(argv[2]) : 32;
    char folder_template[] = "/tmp/rayset-noise.XXXXXX";
    const std::string folder = mkdtemp(folder_template);
    const std::string ray_file = folder + "/disk.tm25ray", model_file = folder + "/disk.vdb";
    analytic::Spectrum spectrum;
    spectrum.wavelength_nm = 555;
    const auto disk = analytic::LambertianDisk::with_flux(1, 1, spectrum);
    {
        auto out = create_rays(ray_file, RayFormat::tm25, synth_header(disk, rays, 7));
        synthesize(disk, rays, 7, *out);
    }
    lightmodel::write_model(lightmodel::build_model(ray_file, {}), model_file);
    const lightmodel::ComplexSource model(
        std::make_shared<lightmodel::LightModel>(lightmodel::read_model(model_file)));

    auto scene_text = [&](const std::string& source) {
        return R"(global_settings { integrator "bidirectional" }
            plane { y, 0 pigment { rgb 0.5 } }
            ray_source { ")" +
               source + R"(" rotate <90, 0, 0> translate <0, 20, 0> }
            illuminance_receiver { <-40, 0, -40>, <0, 0, 80>, <80, 0, 0>
                resolution <64, 64> name "floor" })";
    };
    const RenderScene ours(parse_scene_text(scene_text(model_file), folder + "/ours.pov"));
    const RenderScene naive(parse_scene_text(scene_text(ray_file), folder + "/naive.pov"));

    std::printf(
        "disk 1 mm, 1 W, %llu rays, 20 mm above a 64 x 64 receiver (80 x 80 mm); relative RMS "
        "error of "
        "primary illuminance over the cells\n",
        static_cast<unsigned long long>(rays));
    std::printf("%8s | %9s %9s %8s | %9s %9s %8s | %s\n", "seconds", "ours", "ours", "passes",
                "naive", "naive", "passes", "naive / ours");
    std::printf("%8s | %9s %9s %8s | %9s %9s %8s | %s\n", "", "vs truth", "vs model", "",
                "vs truth", "vs model", "", "(vs truth)");
    for (double seconds = 1; seconds <= max_seconds; seconds *= 2) {
        RenderSettings settings;
        settings.render_image = false, settings.time_limit = seconds, settings.seed = 3;
        const RenderResult a = render(ours, settings);
        settings.naive_sources = true;
        const RenderResult b = render(naive, settings);
        const Errors ea = map_errors(a.layers[1].receivers.at(0), disk, model);
        const Errors eb = map_errors(b.layers[1].receivers.at(0), disk, model);
        std::printf("%8.0f | %9.4f %9.4f %8d | %9.4f %9.4f %8d | %.1f\n", seconds, ea.truth,
                    ea.model, a.passes, eb.truth, eb.model, b.passes, eb.truth / ea.truth);
        std::fflush(stdout);
    }
    std::system(("rm -rf '" + folder + "'").c_str());
    return 0;
}
