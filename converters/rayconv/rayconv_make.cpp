// rayconv synth, emit and farfield: rays from analytic sources and from photometry, and
// photometry from rays.
#include "converters/analytic/synth.h"
#include "converters/photometry/emit.h"
#include "converters/photometry/farfield.h"
#include "converters/rayconv/rayconv.h"
#include "core/progress.h"

#include <fmt/format.h>
#include <cctype>

namespace rayset::rayconv {

namespace {

PhotometryFormat photometry_output(const std::string& path) {
    std::string e = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    for (auto& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (e == ".ies") return PhotometryFormat::ies;
    if (e == ".ldt") return PhotometryFormat::eulumdat;
    throw Error(path + ": the far-field output must end in .ies or .ldt");
}

PolarAxis polar_axis(const std::string& axis) {
    return axis == "-z" ? PolarAxis::minus_z : PolarAxis::plus_z;
}

void register_synth(CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "synth",
        "Write a ray file of an analytic source whose intensity, luminance and illuminance are "
        "known exactly "
        "(the ground truth the model and renderer are tested against). Rays have equal radiant "
        "flux; the same "
        "seed gives the same file.\n\nSources and their parameters (key=value):\n" +
            source_help());
    struct Args {
        std::string source, out, to;
        std::vector<std::string> parameters;
        uint64_t rays = 1000000, seed = 1;
        bool luminous = false;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("SOURCE", args->source, "disk, rectangle, sphere, lobe or cluster")->required();
    cmd->add_option("PARAMETERS", args->parameters,
                    "key=value pairs, e.g. radius=1 flux=2 wavelength=450");
    cmd->add_option("-o,--output", args->out, "Output ray file")->required();
    cmd->add_option("--to", args->to,
                    "Output format (default from the extension; .tm25ray is TM-25)");
    cmd->add_option("--rays", args->rays, "Number of rays")->check(CLI::PositiveNumber);
    cmd->add_option("--seed", args->seed, "Random seed");
    cmd->add_flag("--luminous", args->luminous,
                  "Also store each ray's luminous flux (lm, from V(lambda)) where the format can "
                  "hold both columns");
    cmd->callback([args] {
        auto source = make_source(args->source, parse_source_parameters(args->parameters));
        RayFormat format = output_format(args->out, args->to);
        ProgressBar bar("synthesising");
        SynthOptions options;
        options.progress = [&](double f) { bar.update(f); };
        options.luminous = args->luminous;
        auto writer =
            create_rays(args->out, format, synth_header(*source, args->rays, args->seed, options));
        synthesize(*source, args->rays, args->seed, *writer, options);
        bar.done();
        for (const auto& d : writer->dropped())
            std::fprintf(stderr, "note: %s cannot hold %s: not written\n", to_string(format),
                         d.c_str());
    });
}

void register_emit(CLI::App& app) {
    auto* cmd = app.add_subcommand("emit",
                                   "Write rays drawn from the intensity distribution of an IES or "
                                   "LDT file (type C), from a point, disk, "
                                   "rectangle or the file's luminous opening. Ray fluxes are equal "
                                   "and sum to the distribution's flux.");
    struct Args {
        std::string in, out, to, shape = "point", axis = "+z";
        double radius = 0, size_x = 0, size_y = 0;
        uint64_t rays = 1000000, seed = 1;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("IN", args->in, "IES or LDT file")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->out, "Output ray file")->required();
    cmd->add_option("--to", args->to, "Output format (default from the extension)");
    cmd->add_option("--rays", args->rays, "Number of rays")->check(CLI::PositiveNumber);
    cmd->add_option("--seed", args->seed, "Random seed");
    cmd->add_option("--shape", args->shape,
                    "Emitter shape: point, disk (--radius), rectangle (--size-x, --size-y), "
                    "opening (the file's luminous dimensions)")
        ->check(CLI::IsMember({"point", "disk", "rectangle", "opening"}));
    cmd->add_option("--radius", args->radius, "Disk radius, mm");
    cmd->add_option("--size-x", args->size_x, "Rectangle size along x (C0), mm");
    cmd->add_option("--size-y", args->size_y, "Rectangle size along y (C90), mm");
    cmd->add_option(
           "--axis", args->axis,
           "Ray-file axis that gamma 0 points along: +z (LED convention) or -z (nadir down)")
        ->check(CLI::IsMember({"+z", "-z"}));
    cmd->callback([args] {
        Photometry p = read_photometry(args->in);
        EmitOptions o;
        o.axis = polar_axis(args->axis);
        o.shape = args->shape == "disk"        ? EmitterShape::disk
                  : args->shape == "rectangle" ? EmitterShape::rectangle
                  : args->shape == "opening"   ? EmitterShape::opening
                                               : EmitterShape::point;
        if (o.shape == EmitterShape::disk && !(args->radius > 0))
            throw Error("--shape disk needs --radius (mm) above 0");
        if (o.shape == EmitterShape::rectangle && !(args->size_x > 0 && args->size_y > 0))
            throw Error("--shape rectangle needs --size-x and --size-y (mm) above 0");
        o.radius_mm = args->radius, o.size_x_mm = args->size_x, o.size_y_mm = args->size_y;
        o.name = args->in;
        ProgressBar bar("emitting");
        o.progress = [&](double f) { bar.update(f); };
        RayFormat format = output_format(args->out, args->to);
        auto writer = create_rays(args->out, format, emit_header(p, args->rays, args->seed, o));
        emit_rays(p, args->rays, args->seed, *writer, o);
        bar.done();
    });
}

void register_farfield(CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "farfield",
        "Far-field intensity of a ray file as an IES or LDT file (type C, no symmetry assumed). "
        "Each value is "
        "the mean intensity over the cell around its grid angles; the polar caps (gamma 0 and 180) "
        "are one "
        "cell each, one value in every C plane. By default the intensity is a kernel density "
        "estimate, a local "
        "log-quadratic fit (lobes) or an edge fit (the horizon of a flat emitter), the kind and "
        "the bandwidth "
        "chosen per direction from the rays (--smoothing auto), far less noisy than binning at "
        "10^4-10^7 rays; --smoothing none bins the rays (each cell's flux "
        "over its exact solid angle), --smoothing DEG uses one kernel bandwidth. The values' total "
        "flux equals "
        "the rays'; they are written with the "
        "digits their standard errors support (to the error's second significant digit), and the "
        "keyword "
        "_SMOOTHING records the method. Gamma is measured from +z (the emission axis of LED ray "
        "files; --axis -z for "
        "nadir down), C0 is +x, C90 is +y.");
    struct Args {
        std::string in, out, axis = "+z", smoothing = "auto";
        double c_step = 5, gamma_step = 2.5;
        bool radiometric = false;
        ReadFlags read;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("IN", args->in, "Ray file")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->out, "Output .ies or .ldt")->required();
    cmd->add_option("--c-step", args->c_step, "C-plane step, degrees (divides 360)");
    cmd->add_option("--gamma-step", args->gamma_step, "Gamma step, degrees (divides 180)");
    cmd->add_option("--axis", args->axis, "Polar axis: +z or -z")
        ->check(CLI::IsMember({"+z", "-z"}));
    cmd->add_flag("--radiometric", args->radiometric,
                  "W/sr instead of candela (keyword _RADIOMETRIC marks it)");
    cmd->add_option("--smoothing", args->smoothing,
                    "auto (kernel density, bandwidth from the rays; default), none (binning) or a "
                    "kernel bandwidth "
                    "in degrees");
    add_read_flags(*cmd, args->read);
    cmd->callback([args] {
        PhotometryFormat format = photometry_output(args->out);
        auto reader = open_input(args->in, args->read);
        FarFieldOptions o;
        o.c_step_deg = args->c_step, o.gamma_step_deg = args->gamma_step;
        o.axis = polar_axis(args->axis);
        o.quantity =
            args->radiometric ? FarFieldQuantity::radiometric : FarFieldQuantity::photometric;
        parse_smoothing(args->smoothing, o);
        ProgressBar bar(o.smoothing == FarFieldSmoothing::none ? "binning" : "estimating");
        o.progress = [&](double f) { bar.update(f); };
        FarField ff = far_field(*reader, o);
        bar.done();
        round_to_uncertainty(ff);
        write_photometry(args->out, ff.photometry, format);
        print_warnings(*reader);
        const char* unit = args->radiometric ? "W" : "lm";
        fmt::print(
            "{} rays, total {:.7g} {}, maximum {:.7g} {} at C {:g}, gamma {:g} deg\nsmoothing: {}\n"
            "values rounded to the second digit of their standard errors: the file's flux is "
            "{:.7g} {}\n",
            ff.rays, ff.total_flux, unit, ff.max_intensity, args->radiometric ? "W/sr" : "cd",
            ff.max_c_deg, ff.max_gamma_deg, ff.method, written_flux(ff), unit);
    });
}

}  // namespace

void register_make(CLI::App& app) {
    register_synth(app);
    register_emit(app);
    register_farfield(app);
}

}  // namespace rayset::rayconv
