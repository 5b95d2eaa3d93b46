// rayconv: read, inspect and convert ray files (TM-25, LightTools, Zemax, SPEOS, CSV) and
// photometric files (IES LM-63, EULUMDAT), and make test sources with known answers.
#include "converters/rayconv/rayconv.h"

#include "converters/photometry/photometry.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

namespace rayset::rayconv {

RayReadOptions ReadFlags::options() const {
    RayReadOptions o;
    if (!from.empty()) {
        auto f = ray_format_from_name(from);
        if (!f)
            throw Error("--from " + from +
                        ": unknown format (tm25, lighttools, lighttools-text, zemax, zemax-text, "
                        "speos, csv)");
        o.format = *f;
    }
    if (trust == "header") o.flux_policy = FluxPolicy::stated;
    if (trust == "rays") o.flux_policy = FluxPolicy::rays;
    o.normalise_directions = normalise;
    return o;
}

void add_read_flags(CLI::App& command, ReadFlags& flags) {
    command
        .add_option("--from", flags.from,
                    "Input ray format, if detection from the content is not wanted")
        ->check(CLI::IsMember(
            {"tm25", "lighttools", "lighttools-text", "zemax", "zemax-text", "speos", "csv"}));
    command
        .add_option("--trust", flags.trust,
                    "When the header's total flux and the sum of the rays disagree: 'header' "
                    "scales the rays to "
                    "the header, 'rays' keeps them. Default: header for formats whose per-ray flux "
                    "is relative "
                    "(LightTools, Zemax, SPEOS), rays for TM-25 and CSV")
        ->check(CLI::IsMember({"header", "rays"}));
    command.add_flag("--normalise", flags.normalise,
                     "Accept directions that are not unit vectors and renormalise them");
}

namespace {
std::string extension_of(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return e;
}
}  // namespace

bool is_photometry(const std::string& path) {
    std::string e = extension_of(path);
    if (e == ".ies" || e == ".ldt") return true;
    try {
        detect_ray_format(path);
        return false;
    } catch (const Error&) {
    }
    try {
        detect_photometry_format(path);
        return true;
    } catch (const Error&) {
        return false;
    }
}

std::unique_ptr<RayReader> open_input(const std::string& path, const ReadFlags& flags) {
    return open_rays(path, flags.options());
}

void print_warnings(const RayReader& reader) {
    for (const auto& w : reader.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
}

RayFormat output_format(const std::string& path, const std::string& to) {
    if (!to.empty()) {
        auto f = ray_format_from_name(to);
        if (!f)
            throw Error("--to " + to +
                        ": unknown format (tm25, lighttools, lighttools-text, zemax, zemax-text, "
                        "speos, csv)");
        return *f;
    }
    if (auto f = ray_format_from_name(extension_of(path))) return *f;
    throw Error(path + ": cannot tell the output format from the name ('" + extension_of(path) +
                "' is used by several formats or none): name it with --to (tm25, lighttools, "
                "lighttools-text, "
                "zemax, zemax-text, speos, csv)");
}

}  // namespace rayset::rayconv

int main(int argc, char** argv) {
    using namespace rayset::rayconv;
    CLI::App app{
        "rayconv: read, inspect and convert LED ray files and photometric files.\n\n"
        "Ray files: IES TM-25-13 (.TM25RAY), LightTools binary and text, Zemax binary (.DAT/.SDF) "
        "and text,\n"
        "SPEOS binary, and CSV. The format is detected from the content (the .ray extension is "
        "ambiguous).\n"
        "Photometric files: IES LM-63 (1986..2019) and EULUMDAT (.ldt).\n\n"
        "Examples:\n"
        "  rayconv info LED.TM25RAY                       totals, bounding box, spectrum, "
        "directions\n"
        "  rayconv convert LED.TM25RAY LED.csv            any ray format to any other\n"
        "  rayconv convert lamp.ies lamp.ldt              IES <-> EULUMDAT\n"
        "  rayconv farfield LED.TM25RAY -o LED.ies        far-field intensity of the rays\n"
        "  rayconv emit lamp.ies -o lamp.tm25ray          rays drawn from an intensity "
        "distribution\n"
        "  rayconv synth disk radius=1 flux=1 -o d.tm25ray  analytic source with known answers\n"
        "  rayconv subsample | merge | transform ...      ray-set operations\n"
        "Run 'rayconv COMMAND --help' for the options of each command."};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Help for every command");
    register_info(app);
    register_convert(app);
    register_make(app);
    register_ops(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;  // --help, or a usage error
    } catch (const rayset::Error& e) {
        std::fprintf(stderr, "rayconv: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rayconv: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
