// Rendering a scene file to numpy: the scene read and rendered as raytrace reads and renders it
// (the same parse options, settings and render function), the film's values as raytrace's
// OpenEXR holds them (float32 R, G, B radiance and Y luminance), and its receivers and layers.
#include "arrays.h"

#include <nanobind/stl/filesystem.h>
#include <nanobind/stl/map.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <Python.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <map>
#include <thread>

#include "core/error.h"
#include "tracer/film/film.h"
#include "tracer/render/renderer.h"
#include "tracer/render/rgb.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::python {

namespace {

using namespace rayset::tracer;

// A grid's means as raytrace's EXR channels hold them (render_output.cpp): float32 of the
// double means, Y = 683 x luminance weights, and the standard error of Y.
nb::dict grid_dict(const SampleGrid& grid) {
    const size_t h = size_t(grid.ny()), w = size_t(grid.nx());
    NewArray<float> rgb({h, w, 3}), y({h, w}), y_error({h, w});
    for (size_t j = 0; j < h; ++j)
        for (size_t i = 0; i < w; ++i) {
            const Rgb m = grid.mean(int(i), int(j));
            const size_t k = j * w + i;
            rgb.data[3 * k] = float(m.red);
            rgb.data[3 * k + 1] = float(m.green);
            rgb.data[3 * k + 2] = float(m.blue);
            y.data[k] = float(photometric(m));
            y_error.data[k] = float(grid.photometric_standard_error(int(i), int(j)));
        }
    nb::dict d;
    d["rgb"] = rgb.array, d["Y"] = y.array, d["Y_stderr"] = y_error.array;
    d["samples"] = grid.samples();
    return d;
}

nb::dict receivers_dict(const std::vector<ReceiverMap>& receivers) {
    nb::dict d;
    for (const ReceiverMap& map : receivers) {
        nb::dict r = grid_dict(map.irradiance);
        NewArray<double> centres({size_t(map.irradiance.ny()), size_t(map.irradiance.nx()), 3});
        for (int j = 0; j < map.irradiance.ny(); ++j)
            for (int i = 0; i < map.irradiance.nx(); ++i)
                put(centres.data, size_t(j) * map.irradiance.nx() + i, map.cell_centre(i, j));
        r["centre"] = centres.array;
        d[map.receiver.name.c_str()] = r;
    }
    return d;
}

nb::dict render_scene(const Path& scene_path, int width, int height, int passes,
                      std::optional<double> time_limit, uint64_t seed, int threads,
                      const std::vector<std::string>& include_paths,
                      const std::map<std::string, double>& declarations,
                      std::optional<double> clock, const std::vector<std::string>& allow_write,
                      int photons_per_pass, double photon_radius, bool naive_sources, bool spectral,
                      bool progress) {
    if (width <= 0 || height <= 0) throw nb::value_error("width and height must be positive");
    ParseOptions parse;
    parse.include_paths = include_paths;
    parse.write_roots = allow_write;
    parse.declarations.assign(declarations.begin(), declarations.end());
    // What raytrace's animation_frames gives without animation options: the image size and,
    // with +K, the clock.
    parse.animation.image_width = width;
    parse.animation.image_height = height;
    parse.animation.clock = clock.value_or(0);
    parse.animation.clock_on = clock.has_value();

    // The render runs on a thread of its own while this one, Python's, looks for Ctrl-C
    // (signal handlers run on Python's main thread only): a pending KeyboardInterrupt sets the
    // renderer's stop flag, the render returns its completed passes and the exception is raised.
    std::atomic<bool> stop{false}, done{false};
    RenderResult result;
    {
        nb::gil_scoped_release release;
        const SceneDescription description = parse_scene_file(scene_path.string(), parse);
        const RenderScene scene(description);
        for (const std::string& note : scene.notes())
            std::fprintf(stderr, "rayset.render: note: %s\n", note.c_str());
        RenderSettings settings;
        settings.width = width, settings.height = height;
        settings.passes = passes > 0 ? passes : description.global.passes;
        settings.time_limit = time_limit ? *time_limit : description.global.time_limit;
        settings.seed = seed;
        settings.threads = threads;
        settings.progress = progress;
        settings.photons_per_pass = photons_per_pass;
        settings.photon_radius = photon_radius;
        settings.naive_sources = naive_sources;
        settings.spectral = spectral;
        RenderControl control;
        control.stop = &stop;
        std::exception_ptr error;
        std::thread worker([&] {
            try {
                result = render(scene, settings, {}, control);
            } catch (...) {
                error = std::current_exception();
            }
            done = true;
        });
        while (!done) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            nb::gil_scoped_acquire acquire;
            if (!stop && PyErr_CheckSignals() != 0) stop = true;
        }
        worker.join();
        if (error) std::rethrow_exception(error);
    }
    if (stop) throw nb::python_error();  // the KeyboardInterrupt PyErr_CheckSignals set

    nb::dict d = grid_dict(result.film);
    d["receivers"] = receivers_dict(result.receivers);
    nb::dict layers;
    for (const RenderLayer& layer : result.layers) {
        nb::dict l = grid_dict(layer.film);
        l["receivers"] = receivers_dict(layer.receivers);
        layers[layer.name.c_str()] = l;
    }
    d["layers"] = layers;
    d["passes"] = result.passes;
    d["samples_per_pass"] = result.samples_per_pass;
    d["seconds"] = result.seconds;
    d["rays"] = result.rays;
    d["photons"] = result.photons;
    d["photon_radius"] = result.photon_radius;
    return d;
}

}  // namespace

void bind_render(nb::module_& m) {
    m.def("render", &render_scene, nb::arg("scene_path"), nb::arg("width") = 320,
          nb::arg("height") = 240, nb::arg("passes") = 0, nb::arg("time_limit") = nb::none(),
          nb::arg("seed") = 0, nb::arg("threads") = 0,
          nb::arg("include_paths") = std::vector<std::string>(),
          nb::arg("declarations") = std::map<std::string, double>(), nb::arg("clock") = nb::none(),
          nb::arg("allow_write") = std::vector<std::string>(), nb::arg("photons_per_pass") = 0,
          nb::arg("photon_radius") = 0.0, nb::arg("naive_sources") = false,
          nb::arg("spectral") = false, nb::arg("progress") = false,
          "Renders a scene file as raytrace does: rgb (H x W x 3 radiance, W/(m^2 sr)), Y "
          "(luminance, cd/m^2) and Y_stderr as float32, the values of raytrace's OpenEXR; "
          "receivers and layers by name; passes, seconds, rays.");
}

}  // namespace rayset::python
