#include "tracer/tracer_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "converters/analytic/analytic_sources.h"
#include "converters/analytic/synth.h"
#include "core/error.h"
#include "lightmodel/model_support.h"
#include "support/test_support.h"
#include "tracer/render/renderer.h"
#include "tracer/render/rgb.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::test {

std::string closed_box_scene(const ClosedBox& box) {
    char head[256];
    std::snprintf(head, sizeof head,
                  "global_settings { integrator \"%s\" spectral %s }\n"
                  "box { <-50, -50, -50>, <50, 50, 50> pigment { rgb %s } finish { diffuse %.17g "
                  "ambient 0 } }\n",
                  box.integrator.c_str(), box.spectral ? "on" : "off", box.pigment.c_str(),
                  box.diffuse);
    std::string text = head;
    // corner, edge1, edge2 with cross(edge1, edge2) pointing into the box
    const char* const walls[][4] = {{"floor", "<-50, -50, -50>", "<0, 0, 100>", "<100, 0, 0>"},
                                    {"ceiling", "<-50, 50, -50>", "<100, 0, 0>", "<0, 0, 100>"},
                                    {"left", "<-50, -50, -50>", "<0, 100, 0>", "<0, 0, 100>"},
                                    {"right", "<50, -50, -50>", "<0, 0, 100>", "<0, 100, 0>"},
                                    {"near", "<-50, -50, -50>", "<100, 0, 0>", "<0, 100, 0>"},
                                    {"far", "<-50, -50, 50>", "<0, 100, 0>", "<100, 0, 0>"}};
    const std::string cells = std::to_string(box.cells);
    for (const auto& w : walls)
        text += std::string("illuminance_receiver { ") + w[1] + ", " + w[2] + ", " + w[3] +
                " resolution <" + cells + ", " + cells + "> name \"" + w[0] + "\" }\n";
    for (const std::string& s : box.sources)
        text += "ray_source { \"" + s + "\" rotate <90, 0, 0> }\n";
    return text + box.more;
}

WallAverage wall_average(const std::vector<tracer::ReceiverMap>& maps) {
    double sum = 0, squares = 0;
    int cells = 0;
    for (const tracer::ReceiverMap& map : maps)
        for (int j = 0; j < map.irradiance.ny(); ++j)
            for (int i = 0; i < map.irradiance.nx(); ++i) {
                sum += tracer::luminance_weight(map.irradiance.mean(i, j));
                const double se =
                    map.irradiance.photometric_standard_error(i, j) / tracer::kLumensPerWatt;
                squares += se * se, ++cells;
            }
    return {sum / cells, std::sqrt(squares) / cells};
}

analytic::LambertianDisk disk_source() {
    analytic::Spectrum spectrum;
    spectrum.wavelength_nm = 555;
    return analytic::LambertianDisk::with_flux(1, 1, spectrum);
}

void write_disk_rays(const std::string& path, uint64_t rays) {
    auto out = create_rays(path, RayFormat::tm25, synth_header(disk_source(), rays, 7));
    synthesize(disk_source(), rays, 7, *out);
}

const DiskFiles& disk_files() {
    static const std::unique_ptr<DiskFiles> files = [] {
        auto f = std::make_unique<DiskFiles>();
        const ModelFiles made =
            synthesised_model(f->scratch.path().string(), "disk", disk_source(), 1000000, 7);
        f->rays = made.rays, f->model = made.model;
        return f;
    }();
    return *files;
}

std::string disk_in_box_scene(const std::string& source) {
    return R"(
        global_settings { integrator "bidirectional" }
        camera { location <0, 0, -45> direction <0, 0, 1> right <1, 0, 0> up <0, 1, 0> angle 90 }
        box { <-50, -50, -50>, <50, 50, 50> pigment { rgb 1 } finish { diffuse 0.5 ambient 0 } }
        light_source { <20, 40, 0> color rgb 0.0001 }
        illuminance_receiver { <-50, -49.9, -50>, <0, 0, 100>, <100, 0, 0>
            resolution <3, 3> name "floor" }
        ray_source { ")" +
           source + R"(" rotate <90, 0, 0> translate <0, 20, 0> }
    )";
}

std::string disk_over_black_floor(const std::string& source, const std::string& integrator) {
    return "global_settings { integrator \"" + integrator + R"(" }
        plane { y, 0 pigment { rgb 0 } }
        ray_source { ")" +
           source +
           R"(" rotate <90, 0, 0> translate <0, 20, 0> }
        illuminance_receiver { <-40, 0, -40>, <0, 0, 80>, <80, 0, 0>
            resolution <4, 4> name "floor" }
    )";
}

std::string cornell_with_receiver() {
    const auto cornell = std::filesystem::path(__FILE__).parent_path() / "scenes" / "cornell.pov";
    return read_file(cornell.string()) +
           "illuminance_receiver { <5, 0.01, 5>, <0, 0, 45>, <45, 0, 0> resolution <4, 3> name "
           "\"floor\" }\n";
}

namespace {

// Reads a binary PPM (P6, maxval 255) as POV-Ray writes it with +FP (comment lines allowed).
bool read_ppm(const std::string& path, int& width, int& height, std::vector<uint8_t>& rgb) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    in >> magic;
    if (magic != "P6") return false;
    int values[3], n = 0;
    while (n < 3 && in) {
        in >> std::ws;
        if (in.peek() == '#') {
            std::string comment;
            std::getline(in, comment);
            continue;
        }
        in >> values[n++];
    }
    in.get();
    width = values[0], height = values[1];
    if (values[2] != 255) return false;
    rgb.resize(size_t(width) * height * 3);
    in.read(reinterpret_cast<char*>(rgb.data()), std::streamsize(rgb.size()));
    return bool(in);
}

}  // namespace

bool agrees_with_povray(Rgb ours, const uint8_t* pov) {
    auto close = [](double value, uint8_t reference) {
        return std::abs(255 * value - reference) <=
               0.02 * std::max(255 * value, double(reference)) + 0.5;
    };
    return close(ours.red, pov[0]) && close(ours.green, pov[1]) && close(ours.blue, pov[2]);
}

bool render_lit_tiles(const std::string& scene_file, Vec3 light, int width, int height,
                      LitTiles& out) {
    std::string message;
    if (!povray_render(scene_file, width, height, out.povray, message)) {
        std::printf("%s\n", message.c_str());
        return false;
    }
    const tracer::RenderScene scene(tracer::parse_scene_file(scene_file));
    std::optional<tracer::Material> scratch;
    for (const tracer::SurfaceHit& hit : tracer::centre_hits(scene, width, height)) {
        out.object.push_back(hit.object);
        if (hit.object < 0) {
            out.ours.push_back({});
            continue;
        }
        const tracer::Material& material = scene.material(hit, scratch);
        const tracer::Bsdf bsdf(material, hit.normal, hit.shading_normal, hit.normal);
        const double cos_light = dot(bsdf.shading_normal(), normalized(light - hit.point));
        out.ours.push_back(std::max(0.0, cos_light) * material.diffuse);
    }
    return true;
}

std::string tracer_scene(const std::string& name) {
    return (std::filesystem::path(__FILE__).parent_path() / "scenes" / name).string();
}

bool povray_render(const std::string& scene, int width, int height, std::vector<uint8_t>& rgb,
                   std::string& message, double file_gamma, const std::string& library_path,
                   const std::string& more_options) {
    if (run_command("command -v povray").status != 0) {
        message =
            "povray is not installed (Debian package povray; scripts/install-deps.sh "
            "installs it): comparison against POV-Ray skipped";
        return false;
    }
    ScratchDir dir;
    const CommandResult pov = run_command(
        "cd '" + dir.path().string() + "' && povray +I'" + scene + "' +L'" +
        std::filesystem::path(scene).parent_path().string() + "' " +
        (library_path.empty() ? "" : "+L'" + library_path + "' ") + "+W" + std::to_string(width) +
        " +H" + std::to_string(height) +
        " +Opov.ppm +FP -D -GA File_Gamma=" + std::to_string(file_gamma) + more_options + " 2>&1");
    // An animation's frame is written with its number (pov13.ppm): the one image so named.
    std::string image;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("pov", 0) != 0 || entry.path().extension() != ".ppm") continue;
        if (!image.empty())
            throw std::runtime_error("povray wrote more than one image of " + scene);
        image = entry.path().string();
    }
    int w = 0, h = 0;
    if (pov.status != 0 || !read_ppm(image, w, h, rgb) || w != width || h != height) {
        throw std::runtime_error("povray failed on " + scene + ": " + pov.output);
    }
    return true;
}

tracer::RenderResult render_text(const std::string& text, const tracer::RenderSettings& settings) {
    const tracer::RenderScene scene(tracer::parse_scene_text(text, "test.pov"));
    return tracer::render(scene, settings);
}

std::string render_error(const std::string& text) {
    try {
        const tracer::RenderScene scene(tracer::parse_scene_text(text, "test.pov"));
        tracer::RenderSettings settings;
        settings.width = 4, settings.height = 3, settings.passes = 1, settings.threads = 1;
        tracer::render(scene, settings);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace rayset::test
