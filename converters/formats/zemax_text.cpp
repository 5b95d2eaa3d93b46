// Zemax OpticStudio text source file: a first line "nrays dim_units ray_format flux_type", then
// one ray a line, 7 columns (x y z l m n flux) or 8 (wavelength in um). The only real files seen
// are hand-made: they pad the first line with zeros to the row width and one of them has 8
// columns under ray format 0, so both are accepted. Layout in ../shared/formats.md.
#include "converters/formats/codecs.h"
#include "converters/formats/zemax_common.h"
#include "converters/rays/io.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

namespace rayset {

namespace {

constexpr const char* kColumnNames[8] = {"x", "y", "z", "l", "m", "n", "flux", "wavelength"};
constexpr const char* kFirstLine = "'nrays dim_units ray_format flux_type'";

uint32_t column_of(std::string_view line, std::string_view field) {
    return uint32_t(field.data() - line.data()) + 1;
}

bool blank(std::string_view line) { return split_fields(line).empty(); }

// The codes of the first line, written as integers or (hand-made files) as "9.000000".
struct FirstLine {
    uint64_t rays = 0;
    int64_t units = 0, ray_format = 0, flux_type = 0;
};

class ZemaxTextDecoder : public RayDecoder {
public:
    explicit ZemaxTextDecoder(const std::string& path) : in_(path) {
        if (!next_nonblank(line_))
            fail(path,
                 "the file is empty or blank: expected a first line " + std::string(kFirstLine));
        const FirstLine first = parse_first_line(line_);
        const auto unit = zemax_unit(first.units);
        if (!unit)
            fail_field(
                1, fmt::format(
                       "dimension units code {} is not a Zemax unit (0 m, 1 in, 2 cm, 3 ft, 4 mm)",
                       first.units));
        layout_ = zemax_layout(
            first.ray_format, first.flux_type,
            [&](const std::string& what) { fail_field(2, what); },
            [&](const std::string& what) { fail_field(3, what); });
        header_ = zemax_header(RayFormat::zemax_text, layout_, *unit);
        header_.ray_count = first.rays;
        if (first.rays > 0) decide_columns(first);
    }

    bool decode(RayColumns& chunk, size_t max_rays) override {
        chunk.clear();
        chunk.first_index = next_;
        if (next_ >= header_.ray_count) {
            check_no_more_rows();
            return false;
        }
        lines_.clear();
        const size_t n = static_cast<size_t>(
            std::min<uint64_t>(std::max<size_t>(max_rays, 1), header_.ray_count - next_));
        for (size_t i = 0; i < n; ++i) {
            if (!pending_ && !next_nonblank(line_))
                in_.fail_here(
                    fmt::format("the file ends after {} rays, but its first line states {}",
                                next_ + i, header_.ray_count));
            pending_ = false;
            Ray ray;
            parse_row(line_, ray);
            chunk.push_back(ray);
            lines_.push_back(in_.line_number());
        }
        next_ += n;
        return true;
    }

    // Exact for the rays of the last chunk read (errors are found there); otherwise where the
    // ray is when no blank lines come between rays.
    Location locate(uint64_t index) const override {
        const uint64_t first = next_ - lines_.size();
        if (index >= first && index - first < lines_.size())
            return Location::line(lines_[index - first]);
        return Location::line(first_row_line_ + index);
    }

    bool flux_is_relative() const override { return true; }

private:
    bool next_nonblank(std::string& line) {
        while (in_.next(line))
            if (!blank(line)) return true;
        return false;
    }

    [[noreturn]] void fail_field(size_t index, const std::string& what) const {
        in_.fail_here(what, column_of(line_, fields_[index]));
    }

    FirstLine parse_first_line(const std::string& line) {
        fields_ = split_fields(line);
        if (fields_.size() < 4)
            in_.fail_here(fmt::format("the first line has {} values, expected 4: {}",
                                      fields_.size(), kFirstLine));
        int64_t values[4] = {};
        for (size_t i = 0; i < fields_.size(); ++i) {
            double v;
            if (!parse_double(fields_[i], v) || !std::isfinite(v) || v != std::floor(v) ||
                std::abs(v) > 1e15)
                fail_field(i,
                           fmt::format("value {} '{}' is not a whole number; the first line is {}",
                                       i + 1, fields_[i], kFirstLine));
            if (i >= 4 && v != 0)
                fail_field(
                    i,
                    fmt::format(
                        "value {} is {}: only 4 values are known ({}); files pad the line with 0",
                        i + 1, fields_[i], kFirstLine));
            if (i < 4) values[i] = int64_t(v);
        }
        if (values[0] < 0 || uint64_t(values[0]) > kZemaxMaxRays)
            fail_field(0,
                       fmt::format("ray count {} is not between 0 and 4,000,000,000", values[0]));
        return {uint64_t(values[0]), values[1], values[2], values[3]};
    }

    // The first ray's column count fixes the layout; ray format 0 with an eighth (wavelength)
    // column is accepted because a real hand-made file has it.
    void decide_columns(const FirstLine& first) {
        if (!next_nonblank(line_))
            in_.fail_here(
                fmt::format("the first line states {} rays but no ray follows it", first.rays));
        pending_ = true;
        first_row_line_ = in_.line_number();
        const size_t columns = split_fields(line_).size();
        if (columns == 8 && layout_.lumens)
            in_.fail_here(
                "the ray has 8 columns (a wavelength), but flux type 1 (lumens) allows only "
                "flux-only rays of 7");
        if (columns == 7 && layout_.wavelength)
            in_.fail_here(
                "the ray has 7 columns, but ray format 2 (spectral) needs 8: x y z l m n flux "
                "wavelength");
        if (columns != 7 && columns != 8)
            in_.fail_here(
                fmt::format("the ray has {} columns; a Zemax ray has 7 (x y z l m n flux) or 8 "
                            "(and wavelength in um)",
                            columns));
        layout_.wavelength = columns == 8;
        header_.spectral =
            layout_.wavelength ? SpectralKind::per_ray_wavelength : SpectralKind::none;
    }

    void parse_row(const std::string& line, Ray& ray) {
        fields_ = split_fields(line);
        const size_t columns = layout_.columns();
        if (fields_.size() != columns)
            in_.fail_here(fmt::format("{} columns, expected {} like the first ray (line {})",
                                      fields_.size(), columns, first_row_line_));
        float v[8];
        for (size_t i = 0; i < columns; ++i) {
            if (!parse_float(fields_[i], v[i]))
                fail_field(
                    i, fmt::format("column {} ({}) '{}' is not a number (or is out of float range)",
                                   i + 1, kColumnNames[i], fields_[i]));
            if (!std::isfinite(v[i]))
                fail_field(i, fmt::format("column {} ({}) is '{}': not a finite number", i + 1,
                                          kColumnNames[i], fields_[i]));
        }
        ray.origin = {v[0], v[1], v[2]};
        ray.direction = {v[3], v[4], v[5]};
        set_zemax_flux(ray, layout_, v[6]);
        if (layout_.wavelength) ray.wavelength = zemax_um_to_nm(v[7]);
    }

    void check_no_more_rows() {
        if (pending_ || next_nonblank(line_))
            in_.fail_here(fmt::format("more rays follow than the {} the first line states",
                                      header_.ray_count));
    }

    TextInput in_;
    ZemaxLayout layout_;
    std::string line_;
    std::vector<std::string_view> fields_;  // of line_
    bool pending_ = false;                  // line_ holds the first ray, not yet handed out
    uint64_t first_row_line_ = 2;
    uint64_t next_ = 0;
    std::vector<uint64_t> lines_;  // line of each ray of the last chunk
};

// The first line is rewritten by finish() once the count is known: padding it to the width of
// the largest count keeps it the same length (trailing spaces, which every reader skips).
constexpr size_t kFirstLineWidth = 10 + 3 * 2;

class ZemaxTextEncoder : public RayEncoder {
public:
    ZemaxTextEncoder(const std::string& path, const RayHeader& header)
        : out_(path), header_(header) {
        layout_ = zemax_layout_for(path, header, false, dropped_);
        unit_ = zemax_unit_for(header.unit, dropped_);
        if (!header.description.empty())
            dropped_.push_back("description (the text format has none)");
        if (std::isfinite(header.stated_radiant) || std::isfinite(header.stated_luminous))
            dropped_.push_back(
                "stated total flux (the text format has none: the rays' own fluxes stand)");
        const SourcePlacement p = header.placement, none;
        if (!(p.location == none.location && p.rotation_rad == none.rotation_rad &&
              p.scale == none.scale && p.inclination_azimuth_deg == none.inclination_azimuth_deg))
            dropped_.push_back("source placement (the text format has none)");
        out_.write(first_line(0));
    }

    void write(const RayChunk& chunk) override {
        check_zemax_count(out_.path(), written_ + chunk.rays.size());
        text_.clear();
        for (size_t i = 0; i < chunk.rays.size(); ++i) {
            const Ray& ray = chunk.rays[i];
            const float flux = zemax_flux(ray, layout_);
            const float nm = zemax_ray_nm(header_, ray);
            check_zemax_ray(out_.path(), written_ + i, flux, layout_.wavelength, nm);
            const float v[8] = {scaled(ray.origin.x),
                                scaled(ray.origin.y),
                                scaled(ray.origin.z),
                                ray.direction.x,
                                ray.direction.y,
                                ray.direction.z,
                                flux,
                                zemax_nm_to_um(nm)};
            for (size_t c = 0; c < layout_.columns(); ++c) {
                if (c) text_ += '\t';
                text_ += format_float(v[c]);
            }
            text_ += '\n';
        }
        out_.write(text_);
        written_ += chunk.rays.size();
    }

    void finish() override {
        const std::string line = first_line(written_);
        out_.patch(0, line.data(), line.size());
        out_.commit();
    }

private:
    float scaled(float v) const { return unit_.scale == 1 ? v : float(v * unit_.scale); }

    std::string first_line(uint64_t count) const {
        std::string line = fmt::format("{} {} {} {}", count, unit_.code, layout_.ray_format(),
                                       layout_.flux_type());
        line.resize(kFirstLineWidth, ' ');
        return line + '\n';
    }

    AtomicOutput out_;
    RayHeader header_;
    ZemaxLayout layout_;
    ZemaxUnit unit_;
    std::string text_;
    uint64_t written_ = 0;
};

// Whole numbers, as the first line holds them.
bool whole_numbers(const std::vector<std::string_view>& fields) {
    for (auto f : fields) {
        double v;
        if (!parse_double(f, v) || !std::isfinite(v) || v != std::floor(v)) return false;
    }
    return true;
}

}  // namespace

// Strict, since there is no magic: a first line of 4 to 8 whole numbers that are valid codes
// (padding 0), followed by a ray of 7 or 8 numbers when the head holds one.
bool sniff_zemax_text(const Head& head, uint64_t size) {
    std::string_view text(reinterpret_cast<const char*>(head.data()), head.size());
    auto take_line = [&](std::string_view& line) {
        size_t end = text.find('\n');
        if (end == std::string_view::npos && head.size() < size)
            return false;  // cut off by the head
        line = text.substr(0, end);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
        return true;
    };
    std::string_view line;
    if (!take_line(line)) return false;
    auto first = split_fields(line);
    if (first.size() < 4 || first.size() > 8 || !whole_numbers(first)) return false;
    double v[8];
    for (size_t i = 0; i < first.size(); ++i) parse_double(first[i], v[i]);
    for (size_t i = 4; i < first.size(); ++i)
        if (v[i] != 0) return false;
    // The unit code is compared as a double first: converting one beyond int64's range is
    // undefined.
    if (v[0] < 0 || v[1] < 0 || v[1] > 4 || !zemax_unit(int64_t(v[1])) ||
        (v[2] != 0 && v[2] != 2) || (v[3] != 0 && v[3] != 1))
        return false;
    if (v[0] == 0) return true;
    do {
        if (!take_line(line))
            return true;  // the first ray lies beyond the head: the first line decides
    } while (blank(line) && !text.empty());
    auto row = split_fields(line);
    if (row.size() != 7 && row.size() != 8) return false;
    for (auto f : row) {
        float x;
        if (!parse_float(f, x)) return false;
    }
    return true;
}

std::unique_ptr<RayDecoder> open_zemax_text(const std::string& path) {
    return std::make_unique<ZemaxTextDecoder>(path);
}

std::unique_ptr<RayEncoder> create_zemax_text(const std::string& path, const RayHeader& header) {
    return std::make_unique<ZemaxTextEncoder>(path, header);
}

}  // namespace rayset
