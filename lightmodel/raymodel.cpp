// raymodel: build the paper's complex light-source model from a ray file, store it as one
// OpenVDB file, and summarise a stored model.
#include "core/error.h"
#include "core/progress.h"
#include "core/text_encoding.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

namespace {

using namespace rayset::lightmodel;

nlohmann::json summary(const LightModel& m, const std::string& path) {
    auto frame = [](const LatticeFrame& f) {
        return nlohmann::json{{"resolution", f.resolution()},
                              {"cell_mm", f.cell_size()},
                              {"dims", {f.dims()[0], f.dims()[1], f.dims()[2]}},
                              {"origin_mm", {f.origin().x, f.origin().y, f.origin().z}}};
    };
    const Box b = m.bounds();
    nlohmann::json j;
    j["model"] = path;
    j["source"] = {{"path", m.source.path},
                   {"format", m.source.format},
                   {"rays", m.source.rays},
                   {"radiant_W", m.source.radiant},
                   {"luminous_lm", m.source.luminous},
                   {"unit", m.source.unit}};
    j["flux_unit"] = m.flux_unit;
    j["total_flux"] = m.total_flux();
    j["total_luminous_lm"] = m.total_luminous();
    j["density_lattice"] = frame(m.density_frame);
    j["density_lattice"]["occupied_cells"] = m.voxels.size();
    j["density_lattice"]["boundary_cells"] = m.boundary_voxels.size();
    j["flux_lattice"] = frame(m.flux_frame);
    j["flux_lattice"]["cells_with_light"] = m.flux_cells.size();
    j["intensity_lattice"] = frame(m.intensity_frame);
    j["intensity_lattice"]["diagrams"] = m.diagrams.size();
    j["spheres"] = m.spheres.size();
    j["body_bounds_mm"] = {{b.lower.x, b.lower.y, b.lower.z}, {b.upper.x, b.upper.y, b.upper.z}};
    if (std::filesystem::exists(path)) j["file_bytes"] = std::filesystem::file_size(path);
    return rayset::with_utf8_strings(j);
}

void print(const nlohmann::json& j) {
    std::printf(
        "model        %s (%s bytes)\n", j["model"].get<std::string>().c_str(),
        j.contains("file_bytes") ? std::to_string(j["file_bytes"].get<uint64_t>()).c_str() : "?");
    std::printf("source       %s (%s, %llu rays, unit %s)\n",
                j["source"]["path"].get<std::string>().c_str(),
                j["source"]["format"].get<std::string>().c_str(),
                (unsigned long long)j["source"]["rays"].get<uint64_t>(),
                j["source"]["unit"].get<std::string>().c_str());
    std::printf("total flux   %.9g %s (rays: %.9g W, %.9g lm)\n", j["total_flux"].get<double>(),
                j["flux_unit"].get<std::string>().c_str(), j["source"]["radiant_W"].get<double>(),
                j["source"]["luminous_lm"].get<double>());
    for (const char* name : {"density_lattice", "flux_lattice", "intensity_lattice"}) {
        const auto& f = j[name];
        std::printf("%-18s %d (%d x %d x %d cells of %.4g mm)", name, f["resolution"].get<int>(),
                    f["dims"][0].get<int>(), f["dims"][1].get<int>(), f["dims"][2].get<int>(),
                    f["cell_mm"].get<double>());
        if (f.contains("occupied_cells"))
            std::printf(", %zu occupied, %zu boundary", f["occupied_cells"].get<size_t>(),
                        f["boundary_cells"].get<size_t>());
        if (f.contains("cells_with_light"))
            std::printf(", %zu with light", f["cells_with_light"].get<size_t>());
        if (f.contains("diagrams")) std::printf(", %zu diagrams", f["diagrams"].get<size_t>());
        std::printf("\n");
    }
    std::printf("body         %zu spheres\n", j["spheres"].get<size_t>());
}

// The command line of `raymodel build` and `raymodel info`.
struct Command {
    ModelOptions options;
    std::string input, output;
    bool json = false;
};

// One of visit_model_options' options as --NAME, dashes for underscores.
template <class T>
void add_model_option(CLI::App& build, std::string name, T& value, const char* help) {
    std::replace(name.begin(), name.end(), '_', '-');
    CLI::Option* option = build.add_option("--" + name, value, help);
    if constexpr (std::is_same_v<T, DiagramSmoothing>) {
        const std::map<std::string, DiagramSmoothing> names = {
            {diagram_smoothing_name(DiagramSmoothing::automatic), DiagramSmoothing::automatic},
            {diagram_smoothing_name(DiagramSmoothing::none), DiagramSmoothing::none}};
        option->transform(CLI::CheckedTransformer(names).description(""));
        option->type_name("auto|none")->default_str(diagram_smoothing_name(value));
    } else {
        option->capture_default_str();
    }
}

CLI::App* add_build_command(CLI::App& app, Command& c) {
    ModelOptions& o = c.options;
    auto* build =
        app.add_subcommand("build", "Build a model from a ray file of any supported format");
    build->add_option("rayfile", c.input, "Ray file (TM-25, LightTools, Zemax, SPEOS, CSV)")
        ->required()
        ->check(CLI::ExistingFile);
    build->add_option("-o,--output", c.output, "Model file to write (.vdb)")->required();
    visit_model_options(o, [&](const std::string& name, auto& value, const char* help) {
        add_model_option(*build, name, value, help);
    });
    build->add_option("--threads", o.threads, "Worker threads; 0 = all cores")
        ->capture_default_str();
    build->add_flag("--json", c.json, "Print the summary as JSON");
    return build;
}

// The model built with a progress bar per pass, written, and summarised.
void run_build(Command& c) {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<rayset::ProgressBar> bar;
    int current = 0;
    const char* labels[] = {"", "bounds", "lattices", "origins", "spheres"};
    const LightModel model = build_model(c.input, c.options, [&](int pass, double fraction) {
        if (pass != current) {
            if (bar) bar->done();
            bar = std::make_unique<rayset::ProgressBar>(
                std::string("pass ") + std::to_string(pass) + "/4 " + labels[pass]);
            current = pass;
        }
        bar->update(fraction);
    });
    if (bar) bar->done();
    write_model(model, c.output);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json j = summary(model, c.output);
    j["build_seconds"] = seconds;
    if (c.json) {
        std::printf("%s\n", j.dump(2).c_str());
        return;
    }
    print(j);
    std::printf("built in     %.2f s\n", seconds);
}

void run_info(const Command& c) {
    const nlohmann::json j = summary(read_model(c.input), c.input);
    if (c.json)
        std::printf("%s\n", j.dump(2).c_str());
    else
        print(j);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "raymodel: the complex light-source model of a ray file (Zhdanov et al.; "
        "docs/light-model.md).\n\n"
        "The model is what the tracer renders a ray file with: a body of spheres that cameras see, "
        "a\n"
        "flux lattice and goniometric diagrams that light sampling and photon emission draw "
        "from.\n\n"
        "Examples:\n"
        "  raymodel build LED.TM25RAY -o LED.vdb          build with the paper's defaults\n"
        "  raymodel build LED.TM25RAY -o LED.vdb --flux-resolution 16 --threads 2\n"
        "  raymodel info LED.vdb [--json]                 what a model holds\n"
        "  vdb_print -l LED.vdb                           the grids, as OpenVDB sees them\n"
        "Run 'raymodel COMMAND --help' for the options of each command."};
    app.require_subcommand(1);
    Command command;
    CLI::App* build = add_build_command(app, command);
    CLI::App* info = app.add_subcommand("info", "Summarise a model file");
    info->add_option("model", command.input, "Model file (.vdb)")
        ->required()
        ->check(CLI::ExistingFile);
    info->add_flag("--json", command.json, "Print the summary as JSON");

    try {
        app.parse(argc, argv);
        if (*build)
            run_build(command);
        else if (*info)
            run_info(command);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;  // --help, or a usage error
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raymodel: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
