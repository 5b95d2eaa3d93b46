// rayview: look at ray files, light models, IES / EULUMDAT photometry and the tracer's EXR
// images in VTK; render them off-screen to PNG or export them for ParaView.
#include "core/error.h"
#include "viz/export.h"
#include "viz/scene.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <sstream>

namespace {

using namespace rayset::viz;

rayset::lightmodel::Coord parse_cell(const std::string& text) {
    rayset::lightmodel::Coord c{};
    char comma1 = 0, comma2 = 0;
    std::istringstream in(text);
    if (!(in >> c[0] >> comma1 >> c[1] >> comma2 >> c[2]) || comma1 != ',' || comma2 != ',' ||
        !in.eof() || c[0] < 0 || c[1] < 0 || c[2] < 0)
        throw rayset::Error("--cell: '" + text + "' is not i,j,k (intensity-lattice cell, from 0)");
    return c;
}

void parse_size(const std::string& text, SceneOptions& scene) {
    int w = 0, h = 0;
    char x = 0;
    std::istringstream in(text);
    if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || !in.eof() || w < 16 || h < 16 ||
        w > 16384 || h > 16384)
        throw rayset::Error("--size: '" + text + "' is not WIDTHxHEIGHT in pixels (16 to 16384)");
    scene.width = w, scene.height = h;
}

constexpr const char* kDescription =
    "rayview: see ray files, light models, photometry and rendered images (VTK).\n\n"
    "Views by kind of file (the first is the default):\n"
    "  ray file (TM-25, LightTools, Zemax, SPEOS, CSV)  rays, farfield, polar\n"
    "  model (.vdb, raymodel build)                     spheres, density, flux, diagram\n"
    "  IES LM-63 / EULUMDAT                             farfield, polar\n"
    "  OpenEXR image (raytrace)                         image\n\n"
    "Examples:\n"
    "  rayview LED.TM25RAY                              interactive window: drag to orbit\n"
    "  rayview LED.vdb --show density --threshold 10    slider moves the threshold; 'p' over the\n"
    "                                                   model shows that cell's diagram beside it\n"
    "  rayview LED.vdb --show diagram --cell 2,2,0 --png d.png --size 1200x900 --camera "
    "30,-60,1.2\n"
    "  rayview LED.TM25RAY --show polar --compare lamp.ies --png polar.png\n"
    "  rayview LED.vdb --export LED-vtk                 .vti / .vtp files and LED.vtm for "
    "ParaView\n"
    "  rayview render.exr --layer Y --png render.png\n"
    "Off-screen rendering needs an X server; on a machine without a display run it under\n"
    "'xvfb-run -a rayview ...'.";

// What the command line asks for.
struct Command {
    std::string file, compare, show, cell, layer = "Y", png, size = "1200x900", camera, export_dir;
    ViewOptions options;
    bool colour_by_flux = false;
};

void add_options(CLI::App& app, Command& c) {
    app.add_option("file", c.file, "Ray file, model (.vdb), IES / LDT file or EXR image")
        ->required()
        ->check(CLI::ExistingFile);
    app.add_option("--show", c.show,
                   "View: rays|farfield|polar|density|spheres|flux|diagram|image");
    app.add_option("--cell", c.cell,
                   "diagram: intensity-lattice cell i,j,k (default: the one carrying most flux)");
    app.add_option("--layer", c.layer,
                   "image: channel or layer (Y, R,G,B of a layer, or any channel name)")
        ->capture_default_str();
    app.add_option("--threshold", c.options.density_threshold,
                   "density: rays per voxel drawn or contoured")
        ->capture_default_str();
    app.add_flag("--contour", c.options.contour,
                 "density: contour surface at the threshold instead of voxels");
    app.add_option("--points", c.options.rays.max_rays, "rays: rays sampled from the file")
        ->capture_default_str();
    app.add_option("--seed", c.options.rays.seed, "rays: seed of the sampling")
        ->capture_default_str();
    app.add_flag("--colour-by-flux", c.colour_by_flux,
                 "rays: colour by flux even when wavelengths are known");
    app.add_option("--compare", c.compare,
                   "A second file: polar curves overlaid, other views side by side")
        ->check(CLI::ExistingFile);
    app.add_option("--png", c.png, "Render off-screen to this PNG instead of opening a window");
    app.add_option("--size", c.size, "PNG size WIDTHxHEIGHT")->capture_default_str();
    app.add_option(
        "--camera", c.camera,
        "azimuth,elevation[,zoom]: turns in degrees from the view's start, zoom > 1 closer");
    app.add_option("--export", c.export_dir,
                   "Write every dataset of FILE as VTK XML files and a .vtm into this folder");
}

// --show, or the first view of the input's kind.
View chosen_view(const Command& c, const Input& input) {
    if (c.show.empty()) return views_of(input.kind()).front();
    const auto v = view_from_name(c.show);
    if (!v)
        throw rayset::Error("--show: unknown view '" + c.show +
                            "' (rays|farfield|polar|density|spheres|flux|diagram|image)");
    return *v;
}

void show(const Command& c, Input& input, View view, const ViewOptions& options) {
    SceneOptions scene_options;
    parse_size(c.size, scene_options);
    if (!c.camera.empty()) scene_options.camera = parse_camera(c.camera);
    scene_options.offscreen = !c.png.empty();
    std::unique_ptr<Input> second;
    if (!c.compare.empty()) second = std::make_unique<Input>(c.compare);
    Scene scene = build_scene(input, second.get(), view, options, scene_options);
    if (!c.png.empty()) {
        write_png(scene, c.png);
        std::printf("wrote %s\n", c.png.c_str());
    } else {
        interact(scene, input, view, options);
    }
}

void run(const Command& c) {
    ViewOptions options = c.options;
    options.colour_by_flux = c.colour_by_flux;
    options.layer = c.layer;
    if (!c.cell.empty()) options.cell = parse_cell(c.cell);
    Input input(c.file);
    const View view = chosen_view(c, input);
    if (!c.export_dir.empty()) {
        for (const auto& path : export_input(input, options, c.export_dir))
            std::printf("wrote %s\n", path.c_str());
        if (c.png.empty() && c.show.empty()) return;
    }
    show(c, input, view, options);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{kDescription};
    Command command;
    add_options(app, command);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    try {
        run(command);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rayview: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
