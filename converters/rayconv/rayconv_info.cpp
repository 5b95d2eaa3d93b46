// rayconv info: what a ray file or photometric file holds.
#include "converters/photometry/photometry.h"
#include "converters/rayconv/rayconv.h"
#include "converters/rays/ray_summary.h"
#include "core/progress.h"
#include "core/text_encoding.h"

#include <fmt/format.h>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

namespace rayset::rayconv {

namespace {

using json = nlohmann::json;

const char* spectral_name(SpectralKind kind) {
    switch (kind) {
        case SpectralKind::none: return "none";
        case SpectralKind::single_wavelength: return "single wavelength";
        case SpectralKind::per_ray_wavelength: return "per-ray wavelength";
        case SpectralKind::shared_table: return "one spectral table";
        case SpectralKind::per_ray_table: return "per-ray spectral table";
    }
    return "?";
}

// NaN becomes JSON null, which is what "unknown" means there.
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json ray_json(const std::string& path, const RayReader& reader, const RaySummary& s) {
    const RayHeader& h = reader.header();
    const RayHeader& f = reader.file_header();
    json j;
    j["file"] = path;
    j["kind"] = "rays";
    j["format"] = to_string(f.format);
    j["unit"] = to_string(h.unit);
    j["rays"] = s.rays;
    j["header"] = {{"radiant_W", number(f.stated_radiant)},
                   {"luminous_lm", number(f.stated_luminous)},
                   {"rays", f.ray_count},
                   {"creation_method", f.creation_method},
                   {"creation_date", f.creation_date}};
    j["rays_total"] = {{"radiant_W", h.has_radiant ? json(s.radiant) : json(nullptr)},
                       {"luminous_lm", h.has_luminous ? json(s.luminous) : json(nullptr)},
                       {"luminous_from_spectrum_lm", number(s.luminous_from_spectrum)}};
    j["flux_scale"] = {{"radiant", reader.radiant_scale()}, {"luminous", reader.luminous_scale()}};
    j["bounding_box"] = {{"min", {s.min_origin.x, s.min_origin.y, s.min_origin.z}},
                         {"max", {s.max_origin.x, s.max_origin.y, s.max_origin.z}}};
    j["spectral"] = {{"kind", spectral_name(h.spectral)},
                     {"single_wavelength_nm", number(h.single_wavelength)},
                     {"tables", h.spectral_tables.size()},
                     {"ray_wavelength_min_nm", number(s.min_wavelength)},
                     {"ray_wavelength_max_nm", number(s.max_wavelength)},
                     {"unknown_wavelength_rays", s.unknown_wavelength_rays}};
    j["directions"] = {{"mean", {s.mean_direction.x, s.mean_direction.y, s.mean_direction.z}},
                       {"max_angle_from_mean_deg", s.max_angle_from_mean_deg},
                       {"sphere_coverage", s.sphere_coverage}};
    j["zero_flux_rays"] = s.zero_flux_rays;
    json text = json::object();
    static const char* names[9] = {
        "name",   "manufacturer",         "model_creator",   "rayfile_creator", "equipment",
        "camera", "operating_conditions", "additional_info", "data_reference"};
    for (int i = 0; i < 9; ++i)
        if (!f.text[i].empty()) text[names[i]] = f.text[i];
    if (!f.description.empty()) text["description"] = f.description;
    j["text"] = text;
    json extras = json::array();
    for (const auto& e : h.extras) extras.push_back(e.label);
    j["extra_columns"] = extras;
    j["warnings"] = reader.warnings();
    return j;
}

void print_rays(const json& j) {
    auto val = [](const json& v, const char* unit) {
        return v.is_null() ? std::string("-") : fmt::format("{:.7g} {}", v.get<double>(), unit);
    };
    fmt::print("file        {}\nformat      {}\nrays        {}\nunit        {}\n",
               j["file"].get<std::string>(), j["format"].get<std::string>(),
               j["rays"].get<uint64_t>(), j["unit"].get<std::string>());
    fmt::print("flux        header: {}, {}\n", val(j["header"]["radiant_W"], "W"),
               val(j["header"]["luminous_lm"], "lm"));
    fmt::print("            rays:   {}, {}", val(j["rays_total"]["radiant_W"], "W"),
               val(j["rays_total"]["luminous_lm"], "lm"));
    if (!j["rays_total"]["luminous_from_spectrum_lm"].is_null())
        fmt::print(" ({} from the spectrum)",
                   val(j["rays_total"]["luminous_from_spectrum_lm"], "lm"));
    fmt::print("\n");
    const auto& b = j["bounding_box"];
    fmt::print("origins     x {:.6g} .. {:.6g}, y {:.6g} .. {:.6g}, z {:.6g} .. {:.6g} {}\n",
               b["min"][0].get<double>(), b["max"][0].get<double>(), b["min"][1].get<double>(),
               b["max"][1].get<double>(), b["min"][2].get<double>(), b["max"][2].get<double>(),
               j["unit"].get<std::string>());
    const auto& s = j["spectral"];
    fmt::print("spectrum    {}", s["kind"].get<std::string>());
    if (!s["single_wavelength_nm"].is_null())
        fmt::print(", {:.6g} nm", s["single_wavelength_nm"].get<double>());
    if (!s["ray_wavelength_min_nm"].is_null())
        fmt::print(", rays {:.6g} .. {:.6g} nm", s["ray_wavelength_min_nm"].get<double>(),
                   s["ray_wavelength_max_nm"].get<double>());
    if (s["tables"].get<size_t>()) fmt::print(", {} table(s)", s["tables"].get<size_t>());
    if (s["unknown_wavelength_rays"].get<uint64_t>())
        fmt::print(", {} rays of unknown wavelength", s["unknown_wavelength_rays"].get<uint64_t>());
    fmt::print("\n");
    const auto& d = j["directions"];
    fmt::print(
        "directions  mean ({:.4f}, {:.4f}, {:.4f}), within {:.1f} deg of it, {:.1f}% of the sphere "
        "reached\n",
        d["mean"][0].get<double>(), d["mean"][1].get<double>(), d["mean"][2].get<double>(),
        d["max_angle_from_mean_deg"].get<double>(), 100 * d["sphere_coverage"].get<double>());
    for (const auto& [key, value] : j["text"].items())
        fmt::print("{:<16}{}\n", key, value.get<std::string>());
}

const char* type_name(PhotometricType t) {
    return t == PhotometricType::A ? "A" : t == PhotometricType::B ? "B" : "C";
}

void info_photometry(const std::string& path, bool as_json) {
    Photometry p = read_photometry(path);
    json j;
    j["file"] = path;
    j["kind"] = "photometry";
    j["format"] = detect_photometry_format(path) == PhotometryFormat::ies ? "ies" : "eulumdat";
    j["type"] = type_name(p.type);
    j["vertical_angles"] = {{"count", p.vertical_deg.size()},
                            {"min", p.vertical_deg.empty() ? 0 : p.vertical_deg.front()},
                            {"max", p.vertical_deg.empty() ? 0 : p.vertical_deg.back()}};
    j["horizontal_angles"] = {{"count", p.horizontal_deg.size()},
                              {"min", p.horizontal_deg.empty() ? 0 : p.horizontal_deg.front()},
                              {"max", p.horizontal_deg.empty() ? 0 : p.horizontal_deg.back()}};
    j["total_flux_lm"] = p.total_flux();
    j["rated_lumens"] = p.rated_lumens > 0 ? json(p.rated_lumens) : json(nullptr);
    j["max_intensity_cd"] = p.max_candela();
    j["input_watts"] = p.input_watts;
    j["opening_m"] = {
        {"width", p.width_m}, {"length", p.length_m}, {"height", p.height_m}, {"round", p.round}};
    j["keywords"] = p.keywords;
    j = with_utf8_strings(j);
    if (as_json) {
        std::cout << j.dump(2) << "\n";
        return;
    }
    fmt::print("file        {}\nformat      {}\ntype        {}\n", j["file"].get<std::string>(),
               j["format"].get<std::string>(), type_name(p.type));
    fmt::print("angles      {} vertical ({:g} .. {:g} deg), {} horizontal ({:g} .. {:g} deg)\n",
               p.vertical_deg.size(), j["vertical_angles"]["min"].get<double>(),
               j["vertical_angles"]["max"].get<double>(), p.horizontal_deg.size(),
               j["horizontal_angles"]["min"].get<double>(),
               j["horizontal_angles"]["max"].get<double>());
    fmt::print("flux        {:.6g} lm from the intensities", p.total_flux());
    if (p.rated_lumens > 0) fmt::print(", lamps rated {:.6g} lm", p.rated_lumens);
    fmt::print("\nmaximum     {:.6g} cd\n", p.max_candela());
    for (const auto& [key, value] : j["keywords"].items())
        fmt::print("{:<16}{}\n", key, value.get<std::string>());
}

}  // namespace

void register_info(CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "info",
        "Summarise a ray file (counts, totals from header and rays, bounding box, "
        "spectrum, direction coverage) or a photometric file (type, angles, lumens, "
        "maximum intensity)");
    struct Args {
        std::string file;
        bool json = false;
        ReadFlags read;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("FILE", args->file, "Ray file or IES/LDT file")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_flag("--json", args->json, "Machine-readable output");
    add_read_flags(*cmd, args->read);
    cmd->callback([args] {
        if (is_photometry(args->file)) return info_photometry(args->file, args->json);
        auto reader = open_input(args->file, args->read);
        ProgressBar bar("reading");
        RaySummary s = summarise_rays(*reader, [&](double f) { bar.update(f); });
        bar.done();
        const json j = with_utf8_strings(ray_json(args->file, *reader, s));
        if (args->json) {
            std::cout << j.dump(2) << "\n";
        } else {
            print_rays(j);
            print_warnings(*reader);
        }
    });
}

}  // namespace rayset::rayconv
