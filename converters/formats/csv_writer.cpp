// Writer of rayset CSV ray data; the format is described at the top of csv.cpp.
#include "converters/formats/codecs.h"
#include "converters/formats/csv_common.h"
#include "converters/rays/io.h"

#include <fmt/format.h>
#include <cmath>
#include <set>

namespace rayset {

namespace {

using namespace csv;

std::string floats(const float* v, size_t n) {
    std::string out;
    for (size_t i = 0; i < n; ++i) out += (i ? " " : "") + format_float(v[i]);
    return out;
}

class CsvEncoder : public RayEncoder {
public:
    CsvEncoder(const std::string& path, const RayHeader& header) : out_(path), header_(header) {
        if (!header.has_radiant && !header.has_luminous)
            fail(path, "cannot write rayset CSV: the rays carry neither radiant nor luminous flux");
        write_metadata();
        write_columns();
    }

    void write(const RayChunk& chunk) override {
        const size_t extras = header_.extras.size();
        if (chunk.extra.size() != chunk.size() * extras)
            fail(out_.path(),
                 fmt::format(
                     "internal error: a chunk of {} rays has {} extra values for {} extra columns",
                     chunk.size(), chunk.extra.size(), extras));
        std::string text;
        for (size_t i = 0; i < chunk.size(); ++i) {
            const Ray& r = chunk.rays[i];
            const float position[6] = {r.origin.x,    r.origin.y,    r.origin.z,
                                       r.direction.x, r.direction.y, r.direction.z};
            for (size_t j = 0; j < 6; ++j) text += (j ? "," : "") + format_float(position[j]);
            if (header_.has_radiant) text += "," + format_float(r.radiant);
            if (header_.has_luminous) text += "," + format_float(r.luminous);
            if (header_.spectral == SpectralKind::per_ray_wavelength)
                text += "," + format_float(r.wavelength);
            if (header_.spectral == SpectralKind::per_ray_table)
                text += "," + std::to_string(r.spectrum);
            for (size_t j = 0; j < extras; ++j)
                text += "," + format_float(chunk.extra[i * extras + j]);
            text += '\n';
        }
        out_.write(text);
    }

    void finish() override { out_.commit(); }

private:
    void meta(std::string_view key, const std::string& value) {
        out_.write(fmt::format("# {}: {}\n", key, value));
    }

    void write_metadata() {
        const RayHeader& h = header_;
        out_.write(std::string(kFirstLine) + "\n");
        meta("unit", to_string(h.unit));
        if (!std::isnan(h.stated_radiant))
            meta("stated_radiant_W", format_double(h.stated_radiant));
        if (!std::isnan(h.stated_luminous))
            meta("stated_luminous_lm", format_double(h.stated_luminous));
        meta("spectral", std::string(kSpectralNames[static_cast<size_t>(h.spectral)]));
        if (!std::isnan(h.single_wavelength))
            meta("single_wavelength_nm", format_float(h.single_wavelength));
        if (!std::isnan(h.min_wavelength))
            meta("min_wavelength_nm", format_float(h.min_wavelength));
        if (!std::isnan(h.max_wavelength))
            meta("max_wavelength_nm", format_float(h.max_wavelength));
        for (const SpectralTable& t : h.spectral_tables) {
            std::string pairs;
            for (size_t i = 0; i < t.wavelength.size() && i < t.weight.size(); ++i)
                pairs += (i ? " " : "") + format_float(t.wavelength[i]) + " " +
                         format_float(t.weight[i]);
            meta("spectral_table", pairs);
        }
        if (h.creation_method != 0) meta("creation_method", std::to_string(h.creation_method));
        auto text = [&](std::string_view key, const std::string& value) {
            if (!value.empty()) meta(key, escape(value));
        };
        text("creation_date", h.creation_date);
        for (size_t i = 0; i < h.text.size(); ++i) text(kTextKeys[i], h.text[i]);
        text("additional_text", h.additional_text);
        text("description", h.description);
        if (h.far_field) meta("far_field", "yes");
        const SourcePlacement defaults;
        auto vec = [&](std::string_view key, const Vec3f& v, const Vec3f& default_value) {
            if (!(v == default_value))
                meta(key, fmt::format("{} {} {}", format_float(v.x), format_float(v.y),
                                      format_float(v.z)));
        };
        vec("data_origin", h.data_origin, Vec3f{});
        vec("placement_location", h.placement.location, defaults.location);
        vec("placement_rotation_rad", h.placement.rotation_rad, defaults.rotation_rad);
        vec("placement_scale", h.placement.scale, defaults.scale);
        if (h.placement.inclination_azimuth_deg != defaults.inclination_azimuth_deg)
            meta("placement_inclination_azimuth_deg",
                 floats(h.placement.inclination_azimuth_deg.data(), 4));
    }

    // Extra labels become column names: one that is empty, holds a comma, or means something
    // else in this format is renamed, and the rename reported.
    std::string extra_name(const ExtraColumn& extra, size_t index, std::set<std::string>& used) {
        for (const NamedExtra& e : kNamedExtras)
            if (extra.kind == e.kind && !used.count(std::string(e.name)))
                return std::string(e.name);
        std::string name;
        for (char c : extra.label)
            name += (c == ',' || c == '\n' || c == '\r' || c == ' ' || c == '\t') ? '_' : c;
        if (name.empty()) name = "extra_" + std::to_string(index + 1);
        while (is_reserved_column(name) || used.count(name)) name += "_extra";
        if (name != extra.label)
            dropped_.push_back(
                fmt::format("extra column label '{}' (written as '{}')", extra.label, name));
        return name;
    }

    void write_columns() {
        std::string line = "x,y,z,kx,ky,kz";
        if (header_.has_radiant) line += "," + std::string(kRadiant);
        if (header_.has_luminous) line += "," + std::string(kLuminous);
        if (header_.spectral == SpectralKind::per_ray_wavelength)
            line += "," + std::string(kWavelength);
        if (header_.spectral == SpectralKind::per_ray_table) line += "," + std::string(kSpectrum);
        std::set<std::string> used;
        for (size_t i = 0; i < header_.extras.size(); ++i) {
            std::string name = extra_name(header_.extras[i], i, used);
            used.insert(name);
            line += "," + name;
        }
        out_.write(line + "\n");
    }

    AtomicOutput out_;
    RayHeader header_;
};

}  // namespace

std::unique_ptr<RayEncoder> create_csv(const std::string& path, const RayHeader& header) {
    return std::make_unique<CsvEncoder>(path, header);
}

}  // namespace rayset
