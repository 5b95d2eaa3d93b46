// IES LM-63 reader: keyword lines up to TILT=, then a stream of numbers that may wrap across
// lines anywhere; every number is checked and every error names file:line.
#include "converters/photometry/ies.h"

#include "converters/rays/io.h"
#include "core/error.h"

#include <cmath>
#include <filesystem>
#include <limits>

namespace rayset {

namespace {

std::string trim(std::string_view s) {
    size_t b = s.find_first_not_of(" \t");
    if (b == std::string_view::npos) return {};
    size_t e = s.find_last_not_of(" \t");
    return std::string(s.substr(b, e - b + 1));
}

bool starts_with(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

std::string ordinal(size_t i) { return "#" + std::to_string(i + 1); }

// Numbers separated by blanks or commas, across lines, each remembering its line.
class NumberStream {
public:
    explicit NumberStream(TextInput& in) : in_(in) {}

    bool next(std::string& token) {
        while (pos_ == tokens_.size()) {
            if (!in_.next(line_)) return false;
            tokens_.clear();
            pos_ = 0;
            for (auto field : split_fields(line_, true)) {
                for (auto word : split_fields(field))
                    if (!word.empty() && word != "\x1a")
                        tokens_.emplace_back(word);  // DOS end-of-file mark
            }
        }
        token = tokens_[pos_++];
        return true;
    }

    double number(const std::string& what) {
        std::string token;
        if (!next(token)) in_.fail_here("file ends where " + what + " was expected");
        double value;
        if (!parse_double(token, value))
            in_.fail_here("expected " + what + ", found '" + token + "'");
        if (!std::isfinite(value))
            in_.fail_here(what + " is " + token + ": expected a finite number");
        return value;
    }

    int integer(const std::string& what, int lo, int hi) {
        double value = number(what);
        if (value != std::floor(value) || value < lo || value > hi)
            in_.fail_here(what + " is " + format_double(value) + ": expected a whole number from " +
                          std::to_string(lo) + " to " + std::to_string(hi));
        return static_cast<int>(value);
    }

    // Ascending angles within [lo, hi].
    std::vector<double> angles(size_t count, const std::string& what, double lo, double hi) {
        std::vector<double> out(count);
        for (size_t i = 0; i < count; ++i) {
            out[i] = number(what + " " + ordinal(i) + " of " + std::to_string(count));
            if (out[i] < lo || out[i] > hi)
                fail_here(what + " " + ordinal(i) + " is " + format_double(out[i]) + ": expected " +
                          format_double(lo) + " to " + format_double(hi) + " degrees");
            if (i > 0 && out[i] <= out[i - 1])
                fail_here(what + "s are not ascending: " + format_double(out[i - 1]) + " then " +
                          format_double(out[i]));
        }
        return out;
    }

    [[noreturn]] void fail_here(const std::string& what) const { in_.fail_here(what); }
    uint64_t line() const { return in_.line_number(); }

private:
    TextInput& in_;
    std::string line_;
    std::vector<std::string> tokens_;
    size_t pos_ = 0;
};

// Data counts cannot exceed what the file could hold (each number takes at least 2 bytes), so a
// corrupt count fails here instead of allocating gigabytes.
void check_count(NumberStream& s, uint64_t count, uint64_t file_bytes, const std::string& what) {
    if (count > file_bytes / 2 + 1)
        s.fail_here(what + " ask for " + std::to_string(count) + " numbers but the file has only " +
                    std::to_string(file_bytes) +
                    " bytes: the counts are wrong or the file is truncated");
}

void read_tilt_data(NumberStream& s, IesTilt& tilt, uint64_t file_bytes) {
    tilt.lamp_to_luminaire_geometry =
        s.integer("TILT lamp-to-luminaire geometry (1, 2 or 3)", 1, 3);
    int count =
        s.integer("number of TILT angle/multiplier pairs", 1, std::numeric_limits<int>::max());
    check_count(s, 2 * uint64_t(count), file_bytes, "the TILT pairs");
    tilt.angles_deg = s.angles(size_t(count), "TILT angle", 0, 180);
    tilt.multipliers.resize(size_t(count));
    for (int i = 0; i < count; ++i) {
        double m =
            s.number("TILT multiplier " + ordinal(size_t(i)) + " of " + std::to_string(count));
        if (m < 0)
            s.fail_here("TILT multiplier " + ordinal(size_t(i)) + " is negative (" +
                        format_double(m) + ")");
        tilt.multipliers[size_t(i)] = m;
    }
}

void read_tilt_file(const std::string& ies_path, uint64_t tilt_line, IesTilt& tilt) {
    namespace fs = std::filesystem;
    fs::path tilt_path = fs::path(ies_path).parent_path() / tilt.file_name;
    std::error_code ec;
    if (!fs::is_regular_file(tilt_path, ec))
        fail(ies_path, Location::line(tilt_line),
             "TILT file '" + tilt.file_name + "' not found (looked for " + tilt_path.string() +
                 "): put it beside the IES file, or replace the TILT= line with TILT=NONE");
    TextInput in(tilt_path.string());
    NumberStream s(in);
    read_tilt_data(s, tilt, in.size());
}

IesVersion version_of(const std::string& line, TextInput& in) {
    if (line == "IESNA91") return IesVersion::lm63_1991;
    if (line == "IESNA:LM-63-1986") return IesVersion::lm63_1986;
    if (line == "IESNA:LM-63-1991") return IesVersion::lm63_1991;
    if (line == "IESNA:LM-63-1995") return IesVersion::lm63_1995;
    if (line == "IESNA:LM-63-2002") return IesVersion::lm63_2002;
    if (line == "IES:LM-63-2019") return IesVersion::lm63_2019;
    in.fail_here("unknown version line '" + line +
                 "': expected IESNA91, IESNA:LM-63-1995, IESNA:LM-63-2002 or IES:LM-63-2019");
}

// Keyword lines up to the TILT= line; returns the text after "TILT=".
std::string read_header(TextInput& in, IesFile& f) {
    std::string line;
    bool first = true;
    while (in.next(line)) {
        std::string text = trim(line);
        if (first) {
            first = false;
            if (starts_with(text, "IESNA") || starts_with(text, "IES:")) {
                f.version = version_of(text, in);
                continue;
            }
            f.version = IesVersion::lm63_1986;
        }
        if (starts_with(text, "TILT=")) return trim(std::string_view(text).substr(5));
        if (text.empty()) continue;
        if (text.front() != '[') {
            f.keywords.push_back({"", text});
            continue;
        }
        size_t close = text.find(']');
        if (close == std::string::npos)
            in.fail_here("keyword line without ']': expected [KEYWORD] text");
        std::string key = trim(std::string_view(text).substr(1, close - 1));
        std::string value = trim(std::string_view(text).substr(close + 1));
        if (key.empty()) in.fail_here("empty keyword '[]': expected [KEYWORD] text");
        if (key == "MORE") {
            if (f.keywords.empty() || f.keywords.back().key.empty())
                in.fail_here("[MORE] with no keyword before it to continue");
            f.keywords.back().value += "\n" + value;
            continue;
        }
        f.keywords.push_back({key, value});
    }
    in.fail_here("file ends before the TILT= line: is this an IES LM-63 file?");
}

void check_horizontal_range(NumberStream& s, const IesFile& f) {
    const auto& h = f.horizontal_deg;
    double first = h.front(), last = h.back();
    std::string range = format_double(first) + ".." + format_double(last);
    if (f.photometric_type == 1) {
        bool ok = (h.size() == 1 && first == 0) || (first == 0 && (last == 90 || last >= 180)) ||
                  (first == 90 && last == 270);
        if (!ok)
            s.fail_here(
                "type C horizontal angles run " + range +
                ": expected 0 (axial), 0..90, 0..180, 0..(more than 180 up to 360) or 90..270");
    } else if (!((first == -90 || first == 0) && last == 90)) {
        s.fail_here("type A/B horizontal angles run " + range + ": expected -90..90 or 0..90");
    }
}

// TILT=NONE, TILT=INCLUDE (its data follow) or TILT=<file beside this one>.
void read_tilt(const std::string& path, const std::string& tilt, uint64_t tilt_line, TextInput& in,
               NumberStream& s, IesTilt& out) {
    if (tilt == "NONE") {
        out.kind = IesTilt::Kind::none;
    } else if (tilt == "INCLUDE") {
        out.kind = IesTilt::Kind::include;
        read_tilt_data(s, out, in.size());
    } else {
        if (tilt.empty())
            in.fail_here("TILT= names nothing: expected TILT=NONE, TILT=INCLUDE or TILT=<file>");
        out.kind = IesTilt::Kind::file;
        out.file_name = tilt;
        read_tilt_file(path, tilt_line, out);
    }
}

struct AngleCounts {
    int vertical = 0, horizontal = 0;
    uint64_t line = 0;  // where the file gives them
};

// The lamp and luminaire fields between TILT and the angles.
AngleCounts read_lamp_fields(NumberStream& s, IesFile& f) {
    const int int_max = std::numeric_limits<int>::max();
    f.lamp_count = s.integer("number of lamps", 1, int_max);
    f.lumens_per_lamp = s.number("lumens per lamp");
    if (!(f.lumens_per_lamp > 0 || f.lumens_per_lamp == -1))
        s.fail_here("lumens per lamp is " + format_double(f.lumens_per_lamp) +
                    ": expected a positive number, or -1 for absolute photometry");
    f.multiplier = s.number("candela multiplier");
    if (!(f.multiplier > 0))
        s.fail_here("candela multiplier is " + format_double(f.multiplier) +
                    ": expected a positive number");
    AngleCounts counts;
    counts.vertical = s.integer("number of vertical angles", 1, int_max);
    counts.horizontal = s.integer("number of horizontal angles", 1, int_max);
    counts.line = s.line();
    double type = s.number("photometric type");
    if (type != 1 && type != 2 && type != 3)
        s.fail_here("unknown photometric type " + format_double(type) +
                    ": expected 1 (type C), 2 (type B) or 3 (type A)");
    f.photometric_type = static_cast<int>(type);
    double units = s.number("units type");
    if (units != 1 && units != 2)
        s.fail_here("units type is " + format_double(units) + ": expected 1 (feet) or 2 (metres)");
    f.units = static_cast<int>(units);
    f.width = s.number("luminous opening width");
    f.length = s.number("luminous opening length");
    f.height = s.number("luminous opening height");
    f.ballast_factor = s.number("ballast factor");
    if (!(f.ballast_factor > 0))
        s.fail_here("ballast factor is " + format_double(f.ballast_factor) +
                    ": expected a positive number");
    f.generation = s.number(f.version == IesVersion::lm63_2019
                                ? "file generation type"
                                : "ballast-lamp photometric factor / future use field");
    f.input_watts = s.number("input watts");
    if (f.input_watts < 0)
        s.fail_here("input watts is " + format_double(f.input_watts) + ": expected 0 or more");
    return counts;
}

// The angles, then the candela values plane by plane, and nothing after them.
void read_angles_and_candela(NumberStream& s, const AngleCounts& counts, uint64_t file_size,
                             IesFile& f) {
    const size_t nv = size_t(counts.vertical), nh = size_t(counts.horizontal);
    const std::string counts_line = std::to_string(counts.line);
    const uint64_t values = uint64_t(nv) * uint64_t(nh);
    check_count(s, values + uint64_t(nv) + uint64_t(nh), file_size,
                "the angle counts (line " + counts_line + ")");
    bool type_c = f.photometric_type == 1;
    f.vertical_deg = s.angles(nv, "vertical angle", type_c ? 0 : -90, type_c ? 180 : 90);
    f.horizontal_deg = s.angles(nh, "horizontal angle", type_c ? 0 : -90, type_c ? 360 : 90);
    check_horizontal_range(s, f);
    f.candela.resize(size_t(values));
    for (size_t h = 0; h < nh; ++h) {
        for (size_t v = 0; v < nv; ++v) {
            double& c = f.candela[h * nv + v];
            c = s.number("candela value " + ordinal(v) + " of " + std::to_string(nv) +
                         " for horizontal angle " + format_double(f.horizontal_deg[h]) +
                         " (the counts on line " + counts_line + " ask for " + std::to_string(nv) +
                         " x " + std::to_string(nh) + ")");
            if (c < 0) s.fail_here("candela value " + format_double(c) + " is negative");
        }
    }
    std::string extra;
    if (s.next(extra))
        s.fail_here("unexpected '" + extra + "' after the last of the " + std::to_string(values) +
                    " candela values: the counts on line " + counts_line +
                    " do not match the data");
}

}  // namespace

IesFile read_ies(const std::string& path) {
    TextInput in(path);
    IesFile f;
    const std::string tilt = read_header(in, f);
    const uint64_t tilt_line = in.line_number();
    NumberStream s(in);
    read_tilt(path, tilt, tilt_line, in, s, f.tilt);
    const AngleCounts counts = read_lamp_fields(s, f);
    read_angles_and_candela(s, counts, in.size(), f);
    return f;
}

Photometry ies_to_photometry(const IesFile& f) {
    Photometry p;
    p.type = static_cast<PhotometricType>(f.photometric_type);
    p.vertical_deg = f.vertical_deg;
    p.horizontal_deg = f.horizontal_deg;
    p.candela.resize(f.candela.size());
    for (size_t i = 0; i < f.candela.size(); ++i) p.candela[i] = f.candela[i] * f.multiplier;
    p.lamp_count = f.lamp_count;
    p.rated_lumens = f.lumens_per_lamp > 0 ? f.lamp_count * f.lumens_per_lamp : std::nan("");
    p.input_watts = f.input_watts;
    p.ballast_factor = f.ballast_factor;
    const double metres = f.units == 1 ? 0.3048 : 1.0;
    p.width_m = std::fabs(f.width) * metres;
    p.length_m = std::fabs(f.length) * metres;
    p.height_m = std::fabs(f.height) * metres;
    p.round = f.width < 0 || f.length < 0 || f.height < 0;
    for (const auto& k : f.keywords) {
        std::string key = k.key.empty() ? "OTHER" : k.key;
        auto [it, inserted] = p.keywords.emplace(key, k.value);
        if (!inserted) it->second += "\n" + k.value;
    }
    return p;
}

}  // namespace rayset
