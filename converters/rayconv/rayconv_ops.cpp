// rayconv subsample, merge and transform.
#include "converters/rayconv/rayconv.h"
#include "converters/rays/io.h"
#include "converters/rays/ray_ops.h"
#include "core/progress.h"

#include <fmt/format.h>
#include <cmath>

namespace rayset::rayconv {

namespace {

void report(const RayOpReport& r, RayFormat format) {
    for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    for (const auto& d : r.dropped)
        std::fprintf(stderr, "note: %s cannot hold %s: not written\n", to_string(format),
                     d.c_str());
}

std::optional<LengthUnit> unit_from_name(const std::string& name) {
    if (name.empty()) return std::nullopt;
    for (LengthUnit u : {LengthUnit::mm, LengthUnit::cm, LengthUnit::m, LengthUnit::inch,
                         LengthUnit::ft, LengthUnit::um, LengthUnit::nm})
        if (name == to_string(u)) return u;
    throw Error("unknown length unit '" + name + "' (mm, cm, m, in, ft, um, nm)");
}

std::vector<double> numbers(const std::string& text, size_t count, const char* option) {
    std::vector<double> v;
    for (auto field : split_fields(text, true)) {
        double x;
        if (!parse_double(field, x)) break;
        v.push_back(x);
    }
    if (v.size() != count)
        throw Error(fmt::format("{} {}: expected {} comma-separated numbers", option, text, count));
    return v;
}

// "x,90", "y,-45", or "ax,ay,az,degrees"
Matrix3 rotation_from(const std::string& text) {
    auto comma = text.find(',');
    std::string head = text.substr(0, comma);
    if (comma != std::string::npos && (head == "x" || head == "y" || head == "z")) {
        double deg = numbers(text.substr(comma + 1), 1, "--rotate")[0];
        std::array<double, 3> axis{head == "x" ? 1.0 : 0.0, head == "y" ? 1.0 : 0.0,
                                   head == "z" ? 1.0 : 0.0};
        return rotation_about_axis(axis, deg);
    }
    auto v = numbers(text, 4, "--rotate");
    return rotation_about_axis({v[0], v[1], v[2]}, v[3]);
}

void register_subsample(CLI::App& app) {
    auto* cmd =
        app.add_subcommand("subsample",
                           "Keep a random subset of the rays (every subset of that size equally "
                           "likely) and scale their fluxes so the total flux is unchanged");
    struct Args {
        std::string in, out, to;
        uint64_t count = 0, seed = 1;
        double fraction = 0;
        ReadFlags read;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("IN", args->in, "Ray file")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->out, "Output ray file")->required();
    cmd->add_option("--to", args->to, "Output format (default from the extension)");
    auto* count = cmd->add_option("--count", args->count, "Number of rays to keep");
    cmd->add_option("--fraction", args->fraction, "Fraction of the rays to keep (0..1)")
        ->excludes(count);
    cmd->add_option("--seed", args->seed, "Random seed");
    add_read_flags(*cmd, args->read);
    cmd->callback([args] {
        if (args->count == 0 && !(args->fraction > 0 && args->fraction <= 1))
            throw Error("give --count N or --fraction F (0 < F <= 1)");
        RayFormat format = output_format(args->out, args->to);
        ProgressBar bar("subsampling");
        auto r =
            subsample_rays(args->in, args->out, format, {args->count, args->fraction, args->seed},
                           args->read.options(), [&](double f) { bar.update(f); });
        bar.done();
        report(r, format);
    });
}

void register_merge(CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "merge",
        "Concatenate ray files into one (e.g. a white LED's blue and yellow files); "
        "units, flux columns and spectra are unified, totals add");
    struct Args {
        std::vector<std::string> in;
        std::string out, to, unit;
        ReadFlags read;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("IN", args->in, "Ray files, two or more")
        ->required()
        ->expected(2, -1)
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->out, "Output ray file")->required();
    cmd->add_option("--to", args->to, "Output format (default from the extension)");
    cmd->add_option("--unit", args->unit, "Length unit of the output (default: the first input's)");
    add_read_flags(*cmd, args->read);
    cmd->callback([args] {
        RayFormat format = output_format(args->out, args->to);
        ProgressBar bar("merging");
        auto r = merge_rays(args->in, args->out, format, {unit_from_name(args->unit)},
                            args->read.options(), [&](double f) { bar.update(f); });
        bar.done();
        report(r, format);
    });
}

void register_transform(CLI::App& app) {
    auto* cmd = app.add_subcommand("transform",
                                   "Move, rotate, scale or change the length unit of a ray file. "
                                   "Order: unit change, scale, rotation, translation. Directions "
                                   "rotate with the origins.");
    struct Args {
        std::string in, out, to, unit, translate, rotate;
        double scale = 1;
        ReadFlags read;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("IN", args->in, "Ray file")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->out, "Output ray file")->required();
    cmd->add_option("--to", args->to, "Output format (default from the extension)");
    cmd->add_option("--unit", args->unit,
                    "Convert lengths to this unit: mm, cm, m, in, ft, um, nm");
    cmd->add_option("--scale", args->scale, "Uniform scale factor")->check(CLI::PositiveNumber);
    cmd->add_option("--rotate", args->rotate,
                    "Right-handed rotation: 'x,90' about an axis, or 'ax,ay,az,degrees'");
    cmd->add_option("--translate", args->translate, "Translation 'dx,dy,dz' in the output unit");
    add_read_flags(*cmd, args->read);
    cmd->callback([args] {
        RayTransform t;
        t.unit = unit_from_name(args->unit);
        t.scale = args->scale;
        if (!args->rotate.empty()) t.rotation = rotation_from(args->rotate);
        if (!args->translate.empty()) {
            auto v = numbers(args->translate, 3, "--translate");
            t.translation = {v[0], v[1], v[2]};
        }
        RayFormat format = output_format(args->out, args->to);
        ProgressBar bar("transforming");
        auto r = transform_rays(args->in, args->out, format, t, args->read.options(),
                                [&](double f) { bar.update(f); });
        bar.done();
        report(r, format);
    });
}

}  // namespace

void register_ops(CLI::App& app) {
    register_subsample(app);
    register_merge(app);
    register_transform(app);
}

}  // namespace rayset::rayconv
