// rayconv convert: any ray format to any other, IES <-> EULUMDAT.
#include "converters/photometry/photometry.h"
#include "converters/rayconv/rayconv.h"
#include "core/progress.h"

#include <cstdio>

namespace rayset::rayconv {

namespace {

PhotometryFormat photometry_format(const std::string& path, const std::string& to) {
    std::string t = to;
    if (t.empty()) {
        std::string e = path.size() >= 4 ? path.substr(path.size() - 4) : "";
        for (auto& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (e == ".ies") t = "ies";
        if (e == ".ldt") t = "ldt";
    }
    if (t == "ies") return PhotometryFormat::ies;
    if (t == "ldt" || t == "eulumdat") return PhotometryFormat::eulumdat;
    throw Error(path +
                ": cannot tell the photometric output format: end the name with .ies or .ldt, or "
                "give --to ies|ldt");
}

}  // namespace

void register_convert(CLI::App& app) {
    auto* cmd = app.add_subcommand("convert",
                                   "Convert a ray file to another ray format, or a photometric "
                                   "file to the other photometric format. Every "
                                   "field both formats hold is kept; what the target cannot hold "
                                   "is listed. The output appears only when "
                                   "complete.");
    struct Args {
        std::string in, out, to;
        ReadFlags read;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("IN", args->in, "Input file")->required()->check(CLI::ExistingFile);
    cmd->add_option("OUT", args->out, "Output file")->required();
    cmd->add_option(
        "--to", args->to,
        "Output format: tm25, lighttools, lighttools-text, zemax, zemax-text, speos, csv; or ies, "
        "ldt. "
        "Default: from the output's extension (.tm25ray, .dat, .sdf, .csv, .ies, .ldt)");
    add_read_flags(*cmd, args->read);
    cmd->callback([args] {
        if (is_photometry(args->in)) {
            Photometry p = read_photometry(args->in);
            write_photometry(args->out, p, photometry_format(args->out, args->to));
            return;
        }
        RayFormat format = output_format(args->out, args->to);
        auto reader = open_input(args->in, args->read);
        auto writer = create_rays(args->out, format, reader->header());
        ProgressBar bar("converting");
        copy_rays(*reader, *writer, [&](double f) { bar.update(f); });
        bar.done();
        print_warnings(*reader);
        for (const auto& d : writer->dropped())
            std::fprintf(stderr, "note: %s cannot hold %s: not written\n", to_string(format),
                         d.c_str());
    });
}

}  // namespace rayset::rayconv
