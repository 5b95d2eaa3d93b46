// raytrace: scene file -> path-traced image (OpenEXR + PNG preview) and illuminance maps,
// with a checkpoint to resume an interrupted render from.
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/film/checkpoint.h"
#include "tracer/film/render_output.h"
#include "tracer/raytrace_options.h"
#include "tracer/raytrace_resume.h"
#include "tracer/render/processes.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
// raytrace_bench.cpp
void run_raytrace_benchmark(RenderScene& scene, const RenderSettings& settings);
}  // namespace rayset::tracer

namespace {

using namespace rayset;
using namespace rayset::tracer;
namespace fs = std::filesystem;

OutputRequest output_request(const RaytraceOptions& o) {
    OutputRequest request;
    fs::path exr = o.output.empty() ? fs::path(o.scene).filename().replace_extension(".exr")
                                    : fs::path(o.output);
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

// The animation built-ins change the scene its text describes: a checkpoint made at another
// clock or frame is of another scene. Without animation options the identity is the text's.
void add_animation(CheckpointIdentity& identity, const AnimationSettings& animation) {
    if (!animation.clock_on) return;
    uint64_t hash = identity.scene_hash;  // FNV-1a, continued over the built-ins' bytes
    const double values[] = {animation.clock,
                             animation.clock_delta,
                             double(animation.frame_number),
                             double(animation.initial_frame),
                             double(animation.final_frame),
                             animation.initial_clock,
                             animation.final_clock};
    for (const double value : values) {
        unsigned char bytes[sizeof value];
        std::memcpy(bytes, &value, sizeof value);
        for (const unsigned char byte : bytes) hash = (hash ^ byte) * 1099511628211ull;
    }
    identity.scene_hash = hash;
    identity.scene +=
        fmt::format(" at clock {} (frame {})", animation.clock, animation.frame_number);
}

// The image and receiver files of a render and of each of its light layers.
std::vector<std::string> write_all_outputs(const RenderResult& result,
                                           const OutputRequest& request) {
    std::vector<std::string> written =
        write_render_outputs(&result.film, result.receivers, request);
    for (const RenderLayer& layer : result.layers) {  // OUT.LAYER.exr, .png, receiver maps
        OutputRequest layer_request = request;
        auto with_layer = [&](const std::string& path) {
            return path.empty() ? path
                                : fs::path(path)
                                      .replace_extension("." + layer.name +
                                                         fs::path(path).extension().string())
                                      .string();
        };
        layer_request.exr = with_layer(request.exr);
        layer_request.png = with_layer(request.png);
        layer_request.receiver_prefix = request.receiver_prefix + "." + layer.name;
        for (const std::string& file :
             write_render_outputs(&layer.film, layer.receivers, layer_request))
            written.push_back(file);
    }
    return written;
}

// What the scene language is told, for the animation frame `frame`.
ParseOptions parse_options_of(const RaytraceOptions& options, const AnimationSettings& frame) {
    ParseOptions parse_options;
    parse_options.include_paths = options.include_paths;
    parse_options.write_roots = options.write_roots;
    parse_options.max_memory_megabytes = options.max_parse_memory_mb;
    if (options.max_objects > 0) parse_options.max_objects = options.max_objects;
    if (options.max_lights > 0) parse_options.max_lights = options.max_lights;
    parse_options.declarations = options.declarations;
    parse_options.animation = frame;
    return parse_options;
}

// The options given, else the scene's global_settings, else the defaults.
RenderSettings render_settings(const RaytraceOptions& options, const SceneDescription& description,
                               const RenderSettings& size) {
    RenderSettings settings = size;
    settings.passes = options.passes ? options.passes : description.global.passes;
    settings.time_limit =
        options.time_limit >= 0 ? options.time_limit : description.global.time_limit;
    settings.seed = options.seed;
    settings.threads = options.threads;
    settings.progress = !options.quiet;
    settings.photons_per_pass = options.photons_per_pass;
    settings.photon_radius = options.photon_radius;
    settings.naive_sources = options.naive_sources;
    settings.spectral = options.spectral;
    return settings;
}

void print_scene_summary(const std::string& scene, const SceneDescription& description) {
    fmt::print("{}: {} objects, {} lights, {} ray sources, {} receivers, {}; {} files read\n",
               scene, description.objects.size(), description.lights.size(),
               description.ray_sources.size(), description.receivers.size(),
               description.has_camera ? "a camera" : "no camera", description.files.size());
}

// Fails before, not after, the render.
void check_output_folders(const OutputRequest& request) {
    for (const std::string& target : {request.exr, request.png}) {
        const fs::path folder = fs::path(target).parent_path();
        if (!target.empty() && !folder.empty() && !fs::is_directory(folder))
            throw Error(target + ": the output folder does not exist");
    }
}

// The state to continue from: the checkpoint with --resume (checked before the render: one that
// does not fit is refused and nothing is written), else none.
RenderResult starting_point(const RaytraceOptions& options, const std::string& checkpoint_path,
                            const CheckpointIdentity& identity, const SceneDescription& description,
                            const RenderSettings& settings) {
    if (!options.resume) {
        if (fs::exists(checkpoint_path) && !options.quiet)
            std::fprintf(
                stderr,
                "raytrace: note: starting afresh; %s will be replaced (--resume continues it)\n",
                checkpoint_path.c_str());
        return {};
    }
    if (!fs::exists(checkpoint_path))
        throw Error(checkpoint_path +
                    ": no checkpoint to resume from (it is removed when a render completes; "
                    "--keep-checkpoint keeps it)");
    RenderResult start =
        read_checkpoint(checkpoint_path, identity, blank_render(description, settings));
    if (!options.quiet)
        fmt::print("resuming from {}: {} passes done in {:.2f} s\n", checkpoint_path, start.passes,
                   start.seconds);
    return start;
}

void print_render_summary(const RenderSettings& settings, const RenderResult& result,
                          const std::vector<std::string>& written) {
    fmt::print(
        "{} x {} pixels, {} passes of {} sample{} per pixel in {:.2f} s, {:.3g} rays ({:.3g} "
        "rays/s)\n",
        settings.width, settings.height, result.passes, result.samples_per_pass,
        result.samples_per_pass == 1 ? "" : "s", result.seconds, double(result.rays),
        result.rays / result.seconds);
    if (result.photons)
        fmt::print(
            "{:.3g} photons ({:.3g} photons/s), final gather radius {:.4g}; photon grid {:.1f} "
            "MiB, "
            "visible points {:.1f} MiB (largest pass)\n",
            double(result.photons), result.photons / result.seconds, result.photon_radius,
            result.photon_bytes / 1048576.0, result.visible_point_bytes / 1048576.0);
    for (const std::string& file : written) fmt::print("wrote {}\n", file);
}

// A process other than the root of an MPI job renders its share of the passes; the root
// reads the checkpoint, writes every file and says what happened.
int render_share(const RenderScene& scene, const RenderSettings& settings) {
    const InterruptSignals interrupt;
    RenderControl control;
    control.stop = &interrupt.flag();
    render(scene, settings, {}, control);
    return interrupt.signal() ? interrupt.exit_code() : 0;
}

// The render with checkpoints and interruption, then its files; the exit code.
int render_to_files(const RenderScene& scene, const RenderSettings& settings,
                    const RaytraceOptions& options, const OutputRequest& request,
                    const AnimationSettings& frame) {
    const std::string checkpoint_path = request.receiver_prefix + ".checkpoint";
    CheckpointIdentity identity = checkpoint_identity(scene.description(), settings);
    add_animation(identity, frame);
    RenderResult start =
        starting_point(options, checkpoint_path, identity, scene.description(), settings);
    CheckpointSchedule checkpoints(checkpoint_path, identity, options.checkpoint_interval,
                                   start.passes);
    const InterruptSignals interrupt;  // SIGINT, SIGTERM: stop between or within passes
    RenderControl control;
    control.after_pass = [&](const RenderResult& state) { checkpoints.after_pass(state); };
    control.wants_state = [&] { return checkpoints.due(); };
    control.stop = &interrupt.flag();
    const RenderResult result = render(scene, settings, std::move(start), control);
    if (interrupt.signal() && result.passes == 0) {
        std::fprintf(
            stderr,
            "raytrace: interrupted (%s) before the first pass was complete; nothing written\n",
            interrupt.signal_name());
        return interrupt.exit_code();
    }

    std::vector<std::string> written = write_all_outputs(result, request);
    // The outputs first: a checkpoint is never removed before what it led to is on disk.
    if (interrupt.signal() || options.keep_checkpoint)
        checkpoints.write(result);
    else
        checkpoints.remove();
    if (interrupt.signal()) {
        std::fprintf(
            stderr,
            "raytrace: interrupted (%s) after %d passes; wrote the outputs of pass %d and %s.\n"
            "Continue with the same command and --resume.\n",
            interrupt.signal_name(), result.passes, result.passes, checkpoint_path.c_str());
        return interrupt.exit_code();
    }
    if (!options.quiet) print_render_summary(settings, result, written);
    return 0;
}

int run(int argc, char** argv) {
    RaytraceOptions options;
    int exit_code = 0;
    if (!parse_raytrace_options(argc, argv, options, exit_code)) return exit_code;
    const Processes& processes = Processes::world();
    if (!processes.is_root()) options.quiet = true;
    if (processes.size() > 1 && (options.parse_only || options.bench))
        throw Error(
            "--parse-only and --bench run in one process: start raytrace without mpirun for them");

    RenderSettings size;
    if (options.width) size.width = options.width;
    if (options.height) size.height = options.height;
    const AnimationFrames frames = animation_frames(options.animation, size.width, size.height);
    if (frames.last_frame > frames.first_frame && !options.quiet)
        std::fprintf(stderr,
                     "raytrace: note: rendering frame %d only of frames %d to %d (one frame "
                     "per run; +SF chooses it)\n",
                     frames.first_frame, frames.first_frame, frames.last_frame);
    const SceneDescription description =
        parse_scene_file(options.scene, parse_options_of(options, frames.first));
    if (options.parse_only) {
        print_scene_summary(options.scene, description);
        return 0;
    }
    RenderScene scene(description);
    if (!options.quiet)
        for (const std::string& note : scene.notes())
            std::fprintf(stderr, "raytrace: note: %s\n", note.c_str());
    const RenderSettings settings = render_settings(options, description, size);
    if (options.bench) {
        run_raytrace_benchmark(scene, settings);
        return 0;
    }
    if (!processes.is_root()) return render_share(scene, settings);
    const OutputRequest request = output_request(options);
    check_output_folders(request);
    return render_to_files(scene, settings, options, request, frames.first);
}

}  // namespace

int main(int argc, char** argv) {
    const MpiSession mpi(&argc, &argv);
    try {
        return run(argc, argv);
    } catch (const rayset::Error& e) {
        std::fprintf(stderr, "raytrace: error: %s\n", e.what());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raytrace: internal error: %s\n", e.what());
    }
    // The other processes of an MPI job would wait for this one forever.
    if (Processes::world().size() > 1) Processes::world().abort(1);
    return 1;
}
