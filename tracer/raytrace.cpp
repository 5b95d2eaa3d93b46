// raytrace: scene file -> path-traced image (OpenEXR + PNG preview) and illuminance maps.
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "converters/error.h"
#include "tracer/film/render_output.h"
#include "tracer/raytrace_options.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
// raytrace_bench.cpp
void run_raytrace_benchmark(RenderScene& scene, const RenderSettings& settings);
}

namespace {

using namespace rayset;
using namespace rayset::tracer;
namespace fs = std::filesystem;

OutputRequest output_request(const RaytraceOptions& o) {
    OutputRequest request;
    fs::path exr = o.output.empty() ? fs::path(o.scene).filename().replace_extension(".exr") : fs::path(o.output);
    fs::path png = o.png;
    if (exr.extension() == ".png") {  // +Oimage.png, as a POV-Ray user writes it: the preview
        if (png.empty()) png = exr;
        exr.replace_extension(".exr");
    }
    if (png.empty() && !o.no_png) png = fs::path(exr).replace_extension(".png");
    request.exr = exr.string();
    request.png = o.no_png ? "" : png.string();
    request.exposure = o.exposure;
    request.receiver_prefix = fs::path(exr).replace_extension("").string();
    return request;
}

int run(int argc, char** argv) {
    RaytraceOptions options;
    int exit_code = 0;
    if (!parse_raytrace_options(argc, argv, options, exit_code)) return exit_code;

    ParseOptions parse_options;
    parse_options.include_paths = options.include_paths;
    const SceneDescription description = parse_scene_file(options.scene, parse_options);
    RenderScene scene(description);

    RenderSettings settings;
    if (options.width) settings.width = options.width;
    if (options.height) settings.height = options.height;
    settings.passes = options.passes ? options.passes : description.global.passes;
    settings.time_limit = options.time_limit >= 0 ? options.time_limit : description.global.time_limit;
    settings.seed = options.seed;
    settings.threads = options.threads;
    settings.progress = !options.quiet;
    settings.photons_per_pass = options.photons_per_pass;
    settings.photon_radius = options.photon_radius;
    settings.naive_sources = options.naive_sources;
    if (options.bench) {
        run_raytrace_benchmark(scene, settings);
        return 0;
    }
    const OutputRequest request = output_request(options);
    for (const std::string& target : {request.exr, request.png}) {  // fail before, not after, the render
        const fs::path folder = fs::path(target).parent_path();
        if (!target.empty() && !folder.empty() && !fs::is_directory(folder))
            throw Error(target + ": the output folder does not exist");
    }
    const RenderResult result = render(scene, settings);
    std::vector<std::string> written = write_render_outputs(&result.film, result.receivers, request);
    for (const RenderLayer& layer : result.layers) {  // bidirectional: OUT.LAYER.exr, .png, receiver maps
        OutputRequest layer_request = request;
        auto with_layer = [&](const std::string& path) {
            return path.empty() ? path : fs::path(path).replace_extension("." + layer.name + fs::path(path).extension().string()).string();
        };
        layer_request.exr = with_layer(request.exr);
        layer_request.png = with_layer(request.png);
        layer_request.receiver_prefix = request.receiver_prefix + "." + layer.name;
        for (const std::string& file : write_render_outputs(&layer.film, layer.receivers, layer_request))
            written.push_back(file);
    }
    if (!options.quiet) {
        fmt::print("{} x {} pixels, {} passes in {:.2f} s, {:.3g} rays ({:.3g} rays/s)\n", settings.width,
                   settings.height, result.passes, result.seconds, double(result.rays), result.rays / result.seconds);
        if (result.photons)
            fmt::print("{:.3g} photons ({:.3g} photons/s), final gather radius {:.4g}; photon grid {:.1f} MiB, "
                       "visible points {:.1f} MiB (largest pass)\n",
                       double(result.photons), result.photons / result.seconds, result.photon_radius,
                       result.photon_bytes / 1048576.0, result.visible_point_bytes / 1048576.0);
        for (const std::string& file : written) fmt::print("wrote {}\n", file);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const rayset::Error& e) {
        std::fprintf(stderr, "raytrace: error: %s\n", e.what());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raytrace: internal error: %s\n", e.what());
    }
    return 1;
}
