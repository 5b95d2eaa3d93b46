// rayset CSV ray data: a plain format for scripts and spreadsheets (docs/formats/csv.md).
//
//   # rayset CSV ray data
//   # unit: mm
//   # stated_radiant_W: 1.68
//   # spectral: per_ray_wavelength
//   x,y,z,kx,ky,kz,radiant_W,wavelength_nm
//   0.5,-1.25,0,0,0,1,0.001,450
//
// - Optional leading comment lines start with '#'. "# key: value", where key starts with a
//   lower-case letter and holds letters, digits and '_' up to the colon, is header metadata; an
//   unknown key is an error (most likely a typo that would silently lose information). Any
//   other comment is free text and ignored.
// - Metadata keys (each at most once, except spectral_table):
//     unit                  mm, cm, m, in, ft, um or nm (default mm)
//     stated_radiant_W      total radiant flux the source states, W
//     stated_luminous_lm    total luminous flux the source states, lm
//     spectral              none, single_wavelength, per_ray_wavelength, shared_table or
//                           per_ray_table (default: per_ray_wavelength with a wavelength_nm
//                           column, per_ray_table with a spectrum column, else none)
//     single_wavelength_nm, min_wavelength_nm, max_wavelength_nm
//     spectral_table        "nm weight nm weight ...", one line per table, in order
//     creation_method       integer (TM-25: 0 simulated, 1 measured)
//     creation_date, name, manufacturer, model_creator, ray_file_creator, equipment, camera,
//     operating_conditions, additional_info, data_reference, additional_text, description
//                           text; backslash, newline and CR are written \\, \n and \r
//     far_field             yes or no
//     data_origin, placement_location, placement_rotation_rad, placement_scale
//                           three numbers separated by spaces
//     placement_inclination_azimuth_deg   four numbers separated by spaces
// - The column line starts with x,y,z,kx,ky,kz (position in `unit`, unit direction). Any of
//   these may follow, in any order: radiant_W, luminous_lm (at least one of the two),
//   wavelength_nm, spectrum (0-based index into the spectral tables, -1 none), stokes_s1,
//   stokes_s2, stokes_s3, ellipse_x, ellipse_y, ellipse_z, tristimulus_x, tristimulus_z; any
//   other name is an extra column with that label. Names are case-sensitive and unique.
// - Then one ray a line: as many comma-separated numbers as columns, no quoting; spaces around
//   a number are allowed; "nan" is an unknown value. Blank lines are skipped. Fluxes are
//   absolute. Line endings LF or CRLF.
#include "converters/formats/codecs.h"
#include "converters/formats/csv_common.h"
#include "converters/rays/io.h"
#include "converters/rays/text_row_count.h"

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <map>

namespace rayset {

namespace {

using namespace csv;

// What a column of the file holds.
enum class Role { position, radiant, luminous, wavelength, spectrum, extra };
struct Column {
    Role role;
    size_t index;  // position component 0..5 or extra number
};

uint32_t column_of(const std::string& line, std::string_view token) {
    return static_cast<uint32_t>(token.data() - line.data()) + 1;
}

bool parse_floats(std::string_view value, float* out, size_t n) {
    std::vector<std::string_view> f = split_fields(value);
    if (f.size() != n) return false;
    for (size_t i = 0; i < n; ++i)
        if (!parse_float(f[i], out[i]) || !std::isfinite(out[i])) return false;
    return true;
}

std::string_view trim_blanks(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// The header field a metadata key of each kind sets, or null for a key of another kind.
std::string* text_field(RayHeader& h, std::string_view key) {
    for (size_t i = 0; i < std::size(kTextKeys); ++i)
        if (key == kTextKeys[i]) return &h.text[i];
    if (key == "creation_date") return &h.creation_date;
    if (key == "additional_text") return &h.additional_text;
    if (key == "description") return &h.description;
    return nullptr;
}

double* double_field(RayHeader& h, std::string_view key) {
    if (key == "stated_radiant_W") return &h.stated_radiant;
    if (key == "stated_luminous_lm") return &h.stated_luminous;
    return nullptr;
}

float* float_field(RayHeader& h, std::string_view key) {
    if (key == "single_wavelength_nm") return &h.single_wavelength;
    if (key == "min_wavelength_nm") return &h.min_wavelength;
    if (key == "max_wavelength_nm") return &h.max_wavelength;
    return nullptr;
}

Vec3f* vector_field(RayHeader& h, std::string_view key) {
    if (key == "data_origin") return &h.data_origin;
    if (key == "placement_location") return &h.placement.location;
    if (key == "placement_rotation_rad") return &h.placement.rotation_rad;
    if (key == "placement_scale") return &h.placement.scale;
    return nullptr;
}

class CsvDecoder : public RayDecoder {
public:
    explicit CsvDecoder(const std::string& path) : in_(path) {
        header_.format = RayFormat::csv;
        parse_comments_and_columns();
        header_.ray_count = count_rows(path, in_.offset(), in_.line_number() + 1, {}).rows;
    }

    bool decode(RayColumns& chunk, size_t max_rays) override {
        chunk.clear();
        chunk.first_index = next_;
        if (next_ >= header_.ray_count) return false;
        lines_.clear();
        const size_t extras = header_.extras.size();
        while (chunk.size() < std::max<size_t>(max_rays, 1) && next_ < header_.ray_count) {
            if (!in_.next(line_))
                in_.fail_here("the file ended before its last ray: it changed while being read");
            if (line_.find_first_not_of(" \t") == std::string::npos) continue;
            const std::vector<std::string_view> fields = split_fields(line_, true);
            if (fields.size() != columns_.size())
                in_.fail_here(fmt::format(
                    "expected {} comma-separated values (one per column of line {}) but found {}",
                    columns_.size(), column_line_, fields.size()));
            Ray ray;
            chunk.extra.resize(chunk.extra.size() + extras);
            float* extra = chunk.extra.data() + chunk.extra.size() - extras;
            for (size_t j = 0; j < fields.size(); ++j) store(ray, extra, columns_[j], fields[j]);
            chunk.push_back(ray);
            lines_.push_back(in_.line_number());
            ++next_;
        }
        return chunk.size() > 0;
    }

    // Blank lines may sit between rows, so only the rays of the last chunk have a known line.
    Location locate(uint64_t index) const override {
        uint64_t first = next_ - lines_.size();
        if (index >= first && index < next_) return Location::line(lines_[index - first]);
        return {};
    }

private:
    void store(Ray& ray, float* extra, const Column& column, std::string_view field) {
        float v = 0;
        if (field.empty())
            in_.fail_here("empty value: write nan for an unknown one", column_of(line_, field));
        if (!parse_float(field, v))
            in_.fail_here(fmt::format("'{}' is not a number", field), column_of(line_, field));
        switch (column.role) {
            case Role::position: {
                float* p[6] = {&ray.origin.x,    &ray.origin.y,    &ray.origin.z,
                               &ray.direction.x, &ray.direction.y, &ray.direction.z};
                *p[column.index] = v;
                break;
            }
            case Role::radiant: ray.radiant = v; break;
            case Role::luminous: ray.luminous = v; break;
            case Role::wavelength: ray.wavelength = v; break;
            case Role::spectrum:
                if (!(v == std::floor(v) && v >= -1 && v < 2147483647.0f))
                    in_.fail_here(
                        fmt::format("spectrum index '{}' is not a whole number >= -1", field),
                        column_of(line_, field));
                ray.spectrum = static_cast<int32_t>(v);
                break;
            case Role::extra: extra[column.index] = v; break;
        }
    }

    void parse_comments_and_columns() {
        std::map<std::string, uint64_t> seen;
        std::optional<SpectralKind> spectral;
        bool found = false;
        while (in_.next(line_)) {
            const size_t start = line_.find_first_not_of(" \t");
            if (start == std::string::npos) continue;
            if (line_[start] != '#') {
                found = true;
                break;
            }
            size_t key_begin = line_.find_first_not_of(" \t", start + 1);
            if (key_begin == std::string::npos ||
                !std::islower(static_cast<unsigned char>(line_[key_begin])))
                continue;  // free-text comment
            size_t key_end = key_begin;
            while (
                key_end < line_.size() &&
                (std::isalnum(static_cast<unsigned char>(line_[key_end])) || line_[key_end] == '_'))
                ++key_end;
            if (key_end == line_.size() || line_[key_end] != ':') continue;
            const std::string key = line_.substr(key_begin, key_end - key_begin);
            std::string_view value(line_);
            value.remove_prefix(
                std::min(line_.size(), key_end + (line_.compare(key_end, 2, ": ") == 0 ? 2 : 1)));
            auto [it, fresh] = seen.emplace(key, in_.line_number());
            if (!fresh && key != "spectral_table")
                in_.fail_here(
                    fmt::format("{} is given a second time (first on line {})", key, it->second),
                    uint32_t(key_begin + 1));
            apply_metadata(key, value, uint32_t(key_begin + 1), spectral);
        }
        if (in_.line_number() == 0) fail(in_.path(), "the file is empty");
        if (!found)
            in_.fail_here(
                "no column line (x,y,z,kx,ky,kz,...) after the comments: the file is truncated or "
                "not rayset CSV");
        parse_columns(spectral);
    }

    void apply_metadata(const std::string& key, std::string_view raw, uint32_t column,
                        std::optional<SpectralKind>& spectral) {
        // Text keeps its spaces; around anything else they are noise.
        const std::string_view value = trim_blanks(raw);
        if (std::string* text = text_field(header_, key)) {
            if (!unescape(raw, *text))
                fail_metadata(key, value,
                              "valid text (a backslash must be followed by \\, n or r)");
        } else if (double* number = double_field(header_, key)) {
            if (!parse_double(value, *number)) fail_metadata(key, value, "a number");
        } else if (float* number = float_field(header_, key)) {
            if (!parse_float(value, *number)) fail_metadata(key, value, "a number");
        } else if (Vec3f* vector = vector_field(header_, key)) {
            float f[3];
            if (!parse_floats(value, f, 3)) fail_metadata(key, value, "three finite numbers");
            *vector = {f[0], f[1], f[2]};
        } else if (key == "placement_inclination_azimuth_deg") {
            if (!parse_floats(value, header_.placement.inclination_azimuth_deg.data(), 4))
                fail_metadata(key, value, "four finite numbers");
        } else if (key == "unit") {
            header_.unit = parse_unit(key, value);
        } else if (key == "spectral") {
            spectral = parse_spectral_kind(key, value);
        } else if (key == "spectral_table") {
            parse_spectral_table(key, value, header_.spectral_tables.emplace_back());
        } else if (key == "creation_method") {
            header_.creation_method = parse_creation_method(key, value);
        } else if (key == "far_field") {
            if (value != "yes" && value != "no") fail_metadata(key, value, "yes or no");
            header_.far_field = value == "yes";
        } else {
            in_.fail_here(
                fmt::format("unknown metadata key '{}' (see docs/formats/csv.md; a comment "
                            "that is not metadata must not start with 'word:')",
                            key),
                column);
        }
    }

    LengthUnit parse_unit(const std::string& key, std::string_view value) const {
        for (LengthUnit u : kUnits)
            if (value == to_string(u)) return u;
        fail_metadata(key, value, "a length unit (mm, cm, m, in, ft, um or nm)");
    }

    SpectralKind parse_spectral_kind(const std::string& key, std::string_view value) const {
        for (size_t k = 0; k < std::size(kSpectralNames); ++k)
            if (value == kSpectralNames[k]) return static_cast<SpectralKind>(k);
        fail_metadata(key, value,
                      "a spectral kind (none, single_wavelength, per_ray_wavelength, shared_table "
                      "or per_ray_table)");
    }

    void parse_spectral_table(const std::string& key, std::string_view value,
                              SpectralTable& table) const {
        std::vector<std::string_view> f = split_fields(value);
        for (size_t i = 0; i < f.size(); ++i) {
            float v = 0;
            if (!parse_float(f[i], v) || !std::isfinite(v))
                fail_metadata(key, value, "pairs of finite numbers (nm weight ...)");
            (i % 2 ? table.weight : table.wavelength).push_back(v);
        }
        if (f.empty() || f.size() % 2)
            fail_metadata(key, value, "pairs of numbers (nm weight ...)");
    }

    int32_t parse_creation_method(const std::string& key, std::string_view value) const {
        double v = 0;
        if (!parse_double(value, v)) fail_metadata(key, value, "a number");
        if (v != std::floor(v) || std::abs(v) > 1e9) fail_metadata(key, value, "a whole number");
        return static_cast<int32_t>(v);
    }

    [[noreturn]] void fail_metadata(const std::string& key, std::string_view value,
                                    const std::string& expected) const {
        in_.fail_here(fmt::format("{} '{}' is not {}", key, value, expected),
                      column_of(line_, value));
    }

    void parse_columns(std::optional<SpectralKind> spectral) {
        column_line_ = in_.line_number();
        const std::vector<std::string_view> names = split_fields(line_, true);
        for (size_t i = 0; i < 6; ++i)
            if (names.size() <= i || names[i] != kPositionColumns[i])
                in_.fail_here("the column line must start with x,y,z,kx,ky,kz",
                              names.size() > i ? column_of(line_, names[i]) : 1);
        std::map<std::string_view, bool> seen;
        for (size_t i = 0; i < names.size(); ++i) {
            const std::string_view name = names[i];
            if (name.empty())
                in_.fail_here(fmt::format("column {} has no name", i + 1), column_of(line_, name));
            if (!seen.emplace(name, true).second)
                in_.fail_here(fmt::format("column '{}' appears twice", name),
                              column_of(line_, name));
            if (i < 6) {
                columns_.push_back({Role::position, i});
            } else if (name == kRadiant) {
                columns_.push_back({Role::radiant, 0});
                header_.has_radiant = true;
            } else if (name == kLuminous) {
                columns_.push_back({Role::luminous, 0});
                header_.has_luminous = true;
            } else if (name == kWavelength) {
                columns_.push_back({Role::wavelength, 0});
            } else if (name == kSpectrum) {
                columns_.push_back({Role::spectrum, 0});
            } else {
                ExtraColumn extra{ExtraKind::additional, std::string(name)};
                for (const NamedExtra& e : kNamedExtras)
                    if (name == e.name) extra.kind = e.kind;
                columns_.push_back({Role::extra, header_.extras.size()});
                header_.extras.push_back(std::move(extra));
            }
        }
        if (!header_.has_radiant && !header_.has_luminous)
            in_.fail_here(
                fmt::format("no {} or {} column: every ray needs a flux", kRadiant, kLuminous));
        check_spectral(spectral, seen.count(kWavelength) > 0, seen.count(kSpectrum) > 0);
    }

    void check_spectral(std::optional<SpectralKind> spectral, bool wavelength_column,
                        bool spectrum_column) {
        const SpectralKind kind = spectral            ? *spectral
                                  : wavelength_column ? SpectralKind::per_ray_wavelength
                                  : spectrum_column   ? SpectralKind::per_ray_table
                                                      : SpectralKind::none;
        const std::string_view name = kSpectralNames[static_cast<size_t>(kind)];
        if (wavelength_column != (kind == SpectralKind::per_ray_wavelength))
            in_.fail_here(fmt::format("spectral kind {} {} a {} column", name,
                                      wavelength_column ? "does not take" : "needs", kWavelength));
        if (spectrum_column != (kind == SpectralKind::per_ray_table))
            in_.fail_here(fmt::format("spectral kind {} {} a {} column", name,
                                      spectrum_column ? "does not take" : "needs", kSpectrum));
        const size_t tables = header_.spectral_tables.size();
        if ((kind == SpectralKind::shared_table && tables != 1) ||
            (kind == SpectralKind::per_ray_table && tables == 0))
            in_.fail_here(fmt::format(
                "spectral kind {} but {} spectral_table lines in the comments", name, tables));
        if (kind == SpectralKind::single_wavelength && !(header_.single_wavelength > 0))
            in_.fail_here("spectral kind single_wavelength needs a positive single_wavelength_nm");
        header_.spectral = kind;
    }

    TextInput in_;
    std::string line_;
    std::vector<Column> columns_;
    uint64_t column_line_ = 0;
    uint64_t next_ = 0;
    std::vector<uint64_t> lines_;  // line of each ray of the last chunk
};

}  // namespace

bool sniff_csv(const Head& head, uint64_t size) {
    std::string_view text(reinterpret_cast<const char*>(head.data()), head.size());
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    if (text.substr(0, kFirstLine.size()) == kFirstLine) return true;
    while (!text.empty()) {
        const size_t end = std::min(text.find('\n'), text.size());
        std::string_view line = text.substr(0, end);
        line.remove_prefix(std::min(line.find_first_not_of(" \t\r"), line.size()));
        if (!line.empty() && line.front() != '#') return line.substr(0, 5) == "x,y,z";
        text.remove_prefix(std::min(end + 1, text.size()));
    }
    return false;
}

std::unique_ptr<RayDecoder> open_csv(const std::string& path) {
    return std::make_unique<CsvDecoder>(path);
}

}  // namespace rayset
