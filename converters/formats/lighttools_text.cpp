// LightTools text ray data: "# ..." comment lines, "key: value" lines, lt_startofdata, one ray
// a line (x y z kx ky kz flux [wavelength nm]), lt_endofdata. Verified against real exports of
// LightTools 8.7 and 2024.03 (CRLF line endings, 7 significant digits, "e-016" exponents).
#include "converters/formats/codecs.h"
#include "converters/formats/lighttools_common.h"
#include "converters/rays/io.h"
#include "converters/rays/text_row_count.h"

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>

namespace rayset {

namespace {

constexpr std::string_view kStart = "lt_startofdata";
constexpr std::string_view kEnd = "lt_endofdata";
constexpr size_t kTotalWidth = 24;  // the longest shortest-round-trip double is 24 characters

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return out;
}

uint32_t column_of(const std::string& line, std::string_view token) {
    return static_cast<uint32_t>(token.data() - line.data()) + 1;
}

// Only "millimeters" is seen in real files; the other names follow the same spelling and the
// unit list of the binary header, and common variants are accepted on reading.
struct UnitName {
    const char* name;
    LengthUnit unit;
};
constexpr UnitName kUnitNames[] = {
    {"millimeters", LengthUnit::mm}, {"centimeters", LengthUnit::cm},
    {"meters", LengthUnit::m},       {"inches", LengthUnit::inch},
    {"feet", LengthUnit::ft},        {"micrometers", LengthUnit::um},
    {"nanometers", LengthUnit::nm},  {"millimetres", LengthUnit::mm},
    {"centimetres", LengthUnit::cm}, {"metres", LengthUnit::m},
    {"micrometres", LengthUnit::um}, {"nanometres", LengthUnit::nm},
    {"microns", LengthUnit::um},     {"mm", LengthUnit::mm},
    {"cm", LengthUnit::cm},          {"m", LengthUnit::m},
    {"in", LengthUnit::inch},        {"ft", LengthUnit::ft},
    {"um", LengthUnit::um},          {"nm", LengthUnit::nm},
};

const char* unit_name(LengthUnit unit) {
    for (const UnitName& u : kUnitNames)
        if (u.unit == unit) return u.name;  // the first entry of each unit is LightTools' spelling
    return "millimeters";
}

// What the header lines give, gathered up to lt_startofdata.
struct HeaderLines {
    std::map<std::string, uint64_t> seen;  // key -> line, to reject repeated keys
    std::vector<std::string> comments;
    std::optional<bool> photometric;
    std::optional<LengthUnit> unit;
    Vec3f origin;
    double total = std::nan("");
};

class LightToolsTextDecoder : public RayDecoder {
public:
    explicit LightToolsTextDecoder(const std::string& path) : in_(path) {
        parse_header();
        count_rays();
    }

    bool decode(RayColumns& chunk, size_t max_rays) override {
        chunk.clear();
        chunk.first_index = next_;
        if (next_ >= header_.ray_count) return false;
        lines_.clear();
        const size_t columns = layout_.columns();
        while (chunk.size() < std::max<size_t>(max_rays, 1) && next_ < header_.ray_count) {
            if (!in_.next(line_))
                in_.fail_here("the file ended before its last ray: it changed while being read");
            const std::vector<std::string_view> fields = split_fields(line_);
            if (fields.empty()) continue;
            if (fields.size() != columns)
                in_.fail_here(
                    fmt::format("expected {} numbers (x y z kx ky kz flux{}) but found {}", columns,
                                layout_.wavelength ? " wavelength" : "", fields.size()));
            float v[8];
            for (size_t j = 0; j < columns; ++j)
                if (!parse_float(fields[j], v[j]))
                    in_.fail_here(fmt::format("'{}' is not a number", fields[j]),
                                  column_of(line_, fields[j]));
            Ray ray;
            ray.origin = {v[0], v[1], v[2]};
            ray.direction = {v[3], v[4], v[5]};
            set_lighttools_flux(ray, layout_, v[6]);
            if (layout_.wavelength) ray.wavelength = v[7];
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

    bool flux_is_relative() const override { return true; }

private:
    void parse_header() {
        HeaderLines lines;
        read_header_lines(lines);
        if (!lines.photometric) fail_missing("lt_datatype", "radiant_power or luminous_flux?");
        if (!lines.unit) fail_missing("lt_length_units", "the unit of the positions is unknown");
        if (!std::isfinite(lines.total))
            fail_missing("lt_radiant_flux",
                         "the relative ray fluxes cannot be scaled without the total");
        layout_.photometric = *lines.photometric;

        std::string description;
        for (const std::string& c : lines.comments)
            description += (description.empty() ? "" : "\n") + c;
        std::string name = std::move(header_.text[0]);
        header_ = lighttools_header(RayFormat::lighttools_text, layout_, *lines.unit, lines.origin,
                                    lines.total);
        header_.text[0] = std::move(name);
        header_.description = std::move(description);
    }

    // Reads up to and including lt_startofdata.
    void read_header_lines(HeaderLines& lines) {
        while (in_.next(line_)) {
            std::string_view text = trim(line_);
            if (text.empty()) continue;
            if (text.front() == '#') {
                lines.comments.emplace_back(trim(text.substr(1)));
                continue;
            }
            if (text == kStart) return;
            read_key_line(text, lines);
        }
        in_.fail_here(fmt::format(
            "the file ends without {}: it is truncated or not LightTools ray data", kStart));
    }

    void read_key_line(std::string_view text, HeaderLines& lines) {
        // A header line that ends the file was most likely cut short: say so rather than
        // complain about its content.
        if (in_.offset() == in_.size())
            in_.fail_here(
                fmt::format("the file ends inside the header, before {}: it is truncated", kStart));
        size_t colon = text.find(':');
        if (colon == std::string_view::npos)
            in_.fail_here(fmt::format("expected 'key: value' or {} but found '{}'{}", kStart,
                                      text.substr(0, 40),
                                      std::isalpha(static_cast<unsigned char>(text.front()))
                                          ? ""
                                          : ": is lt_startofdata missing?"));
        const std::string key = lower(trim(text.substr(0, colon)));
        const std::string_view value = trim(text.substr(colon + 1));
        auto [it, fresh] = lines.seen.emplace(key, in_.line_number());
        if (!fresh)
            in_.fail_here(
                fmt::format("{} is given a second time (first on line {})", key, it->second));
        apply_key(key, value, lines);
    }

    void apply_key(const std::string& key, std::string_view value, HeaderLines& lines) {
        if (key == "lt_rdf_version") {
            check_version(value);
        } else if (key == "dataname") {
            header_.text[0] = std::string(value);
        } else if (key == "lt_datatype") {
            lines.photometric = parse_datatype(value);
        } else if (key == "lt_far_field_data") {
            check_near_field(value);
        } else if (key == "lt_color_info") {
            layout_.wavelength = parse_color_info(value);
        } else if (key == "lt_length_units") {
            lines.unit = parse_unit(value);
        } else if (key == "lt_data_origin") {
            lines.origin = parse_origin(value);
        } else if (key == "lt_radiant_flux" || key == "lt_luminous_flux") {
            lines.total = parse_total(key, value, lines);
        } else if (key.rfind("lt_", 0) == 0) {
            in_.fail_here(
                fmt::format("unknown key {}: this LightTools ray data is not supported", key));
        }
        // Other keys are descriptive entries LightTools may add; they do not change the rays.
    }

    void check_version(std::string_view value) const {
        double version = 0;
        if (!parse_double(value, version) || std::floor(version) != 2)
            fail_value(
                value,
                fmt::format("lt_rdf_version '{}' is not supported (only version 2.0 is known)",
                            value));
    }

    bool parse_datatype(std::string_view value) const {
        const std::string v = lower(value);
        if (v != "radiant_power" && v != "luminous_flux")
            fail_value(value, fmt::format("unknown lt_datatype '{}' (expected radiant_power or "
                                          "luminous_flux)",
                                          value));
        return v == "luminous_flux";
    }

    void check_near_field(std::string_view value) const {
        const std::string v = lower(value);
        if (v == "yes")
            fail_value(value,
                       "far-field LightTools ray data is not supported: its row layout is "
                       "unknown; export near-field rays instead");
        if (v != "no")
            fail_value(value,
                       fmt::format("unknown lt_far_field_data '{}' (expected no or yes)", value));
    }

    // Whether rows carry a wavelength.
    bool parse_color_info(std::string_view value) const {
        const std::string v = lower(value);
        if (v != "none" && v != "wavelength")
            fail_value(value, fmt::format("lt_color_info '{}' is not supported (expected none or "
                                          "wavelength; the row layout of tristimulus data is "
                                          "unknown)",
                                          value));
        return v == "wavelength";
    }

    LengthUnit parse_unit(std::string_view value) const {
        const std::string v = lower(value);
        for (const UnitName& u : kUnitNames)
            if (v == u.name) return u.unit;
        fail_value(value, fmt::format("unknown lt_length_units '{}' (expected millimeters, "
                                      "centimeters, meters, inches, feet, micrometers or "
                                      "nanometers)",
                                      value));
    }

    Vec3f parse_origin(std::string_view value) const {
        Vec3f origin;
        std::vector<std::string_view> f = split_fields(value);
        if (f.size() != 3 || !parse_float(f[0], origin.x) || !parse_float(f[1], origin.y) ||
            !parse_float(f[2], origin.z) || !std::isfinite(origin.x) || !std::isfinite(origin.y) ||
            !std::isfinite(origin.z))
            fail_value(value,
                       fmt::format("lt_data_origin '{}' is not three finite numbers", value));
        return origin;
    }

    double parse_total(const std::string& key, std::string_view value,
                       const HeaderLines& lines) const {
        // LightTools 8.7 writes lt_radiant_flux for luminous data too: the key names the
        // total whatever lt_datatype says.
        if (lines.seen.count(key == "lt_radiant_flux" ? "lt_luminous_flux" : "lt_radiant_flux"))
            in_.fail_here(
                "the file gives both lt_radiant_flux and lt_luminous_flux; one total is expected");
        double total = 0;
        if (!parse_double(value, total) || !std::isfinite(total) || total < 0)
            fail_value(value, fmt::format("{} '{}' is not a non-negative number", key, value));
        return total;
    }

    [[noreturn]] void fail_value(std::string_view value, const std::string& what) const {
        in_.fail_here(what, column_of(line_, value));
    }

    [[noreturn]] void fail_missing(const char* key, const char* why) const {
        in_.fail_here(fmt::format("no {} line before {}: {}", key, kStart, why));
    }

    void count_rays() {
        const RowCount count = count_rows(in_.path(), in_.offset(), in_.line_number() + 1, kEnd);
        if (!count.end_line)
            fail(in_.path(), Location::line(std::max(count.last_line, in_.line_number())),
                 fmt::format("the file ends without {}: it is truncated", kEnd));
        if (count.after_end)
            fail(in_.path(), Location::line(count.after_end),
                 fmt::format("unexpected text after {}", kEnd));
        header_.ray_count = count.rows;
    }

    TextInput in_;
    LightToolsLayout layout_;
    std::string line_;
    uint64_t next_ = 0;
    std::vector<uint64_t> lines_;  // line of each ray of the last chunk
};

class LightToolsTextEncoder : public RayEncoder {
public:
    LightToolsTextEncoder(const std::string& path, const RayHeader& header)
        : out_(path), header_(header) {
        std::optional<LightToolsLayout> layout = lighttools_layout_for(header, dropped_);
        if (!layout)
            fail(path,
                 "cannot write LightTools ray data: the rays carry neither radiant nor luminous "
                 "flux");
        layout_ = *layout;
        bool other_text = !header.creation_date.empty() || !header.additional_text.empty();
        for (size_t i = 1; i < header.text.size(); ++i)
            other_text = other_text || !header.text[i].empty();
        if (other_text)
            dropped_.push_back("descriptive text other than the name and the comment lines");
        write_header();
    }

    void write(const RayChunk& chunk) override {
        std::string text;
        for (size_t i = 0; i < chunk.size(); ++i) {
            const Ray& ray = chunk.rays[i];
            const float flux = layout_.photometric ? ray.luminous : ray.radiant;
            const float nm = lighttools_wavelength(header_, ray);
            check_lighttools_ray(out_.path(), written_ + i, flux, layout_.wavelength, nm);
            const float v[8] = {ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
                                ray.direction.y, ray.direction.z, flux,         nm};
            for (size_t j = 0; j < layout_.columns(); ++j) {
                if (j) text += ' ';
                text += format_float(v[j]);
            }
            text += kNewline;
            sum_ += flux;
        }
        out_.write(text);
        written_ += chunk.size();
    }

    void finish() override {
        out_.write(std::string(kEnd) + kNewline);
        const double stated =
            layout_.photometric ? header_.stated_luminous : header_.stated_radiant;
        const std::string total =
            fmt::format("{:>{}}", format_double(total_to_write(stated, sum_)), kTotalWidth);
        out_.patch(total_at_, total.data(), total.size());
        out_.commit();
    }

private:
    // LightTools is a Windows program and exports CRLF; its importer gets what it writes.
    static constexpr const char* kNewline = "\r\n";

    void line(const std::string& text) { out_.write(text + kNewline); }

    void write_header() {
        std::vector<std::string> comments;
        const std::string& description = header_.description;
        for (size_t start = 0; !description.empty();) {
            const size_t end = description.find('\n', start);
            comments.push_back(description.substr(
                start, end == std::string::npos ? std::string::npos : end - start));
            if (end == std::string::npos) break;
            start = end + 1;
        }
        // The first line is what identifies the format (see sniff_lighttools_text).
        if (comments.empty() || comments.front().rfind("LightTools", 0) != 0)
            comments.insert(comments.begin(), "LightTools ray data written by rayset");
        for (const std::string& c : comments) line("# " + c);
        line("lt_rdf_version: 2.0");
        if (!header_.text[0].empty()) {
            std::string name = header_.text[0];
            std::replace_if(
                name.begin(), name.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
            line("dataname: " + name);
        }
        line(std::string("lt_datatype: ") +
             (layout_.photometric ? "luminous_flux" : "radiant_power"));
        line("lt_far_field_data: no");
        line(std::string("lt_color_info: ") + (layout_.wavelength ? "wavelength" : "none"));
        line(std::string("lt_length_units: ") + unit_name(header_.unit));
        const Vec3f& o = header_.data_origin;
        line("lt_data_origin: " + format_float(o.x) + " " + format_float(o.y) + " " +
             format_float(o.z));
        // LightTools itself names the total lt_radiant_flux for luminous data as well. The value
        // is patched by finish() into a fixed-width field.
        out_.write("lt_radiant_flux: ");
        total_at_ = out_.offset();
        line(std::string(kTotalWidth, ' '));
        line(std::string(kStart));
    }

    AtomicOutput out_;
    RayHeader header_;
    LightToolsLayout layout_;
    uint64_t total_at_ = 0;
    uint64_t written_ = 0;
    double sum_ = 0;
};

}  // namespace

bool sniff_lighttools_text(const Head& head, uint64_t size) {
    std::string_view text(reinterpret_cast<const char*>(head.data()), head.size());
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    return text.substr(0, 12) == "# LightTools" || text.substr(0, 15) == "lt_rdf_version:" ||
           text.find("\nlt_rdf_version:") != std::string_view::npos;
}

std::unique_ptr<RayDecoder> open_lighttools_text(const std::string& path) {
    return std::make_unique<LightToolsTextDecoder>(path);
}

std::unique_ptr<RayEncoder> create_lighttools_text(const std::string& path,
                                                   const RayHeader& header) {
    return std::make_unique<LightToolsTextEncoder>(path, header);
}

}  // namespace rayset
