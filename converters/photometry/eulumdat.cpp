// EULUMDAT reader and writer: one field per line, in the fixed order of Stockmar's layout.
#include "converters/photometry/eulumdat.h"

#include "converters/rays/io.h"
#include "core/error.h"

#include <cmath>
#include <limits>

namespace rayset {

namespace {

std::string trim(std::string_view s) {
    size_t b = s.find_first_not_of(" \t");
    if (b == std::string_view::npos) return {};
    size_t e = s.find_last_not_of(" \t");
    return std::string(s.substr(b, e - b + 1));
}

// Decimal commas are common in European files.
bool parse_ldt_number(std::string text, double& out) {
    for (char& c : text)
        if (c == ',') c = '.';
    return parse_double(text, out) && std::isfinite(out);
}

class LineReader {
public:
    explicit LineReader(TextInput& in) : in_(in) {}

    std::string text(const std::string& what) {
        std::string line;
        if (!in_.next(line))
            rayset::fail(in_.path(), Location::line(in_.line_number() + 1),
                         "file ends where " + what +
                             " was expected: the file is truncated or the counts are wrong");
        return trim(line);
    }

    double number(const std::string& what) {
        std::string t = text(what);
        double value;
        if (!parse_ldt_number(t, value))
            in_.fail_here("expected " + what + " (a number), found '" + t + "'");
        return value;
    }

    double non_negative(const std::string& what) {
        double value = number(what);
        if (value < 0) in_.fail_here(what + " is " + format_double(value) + ": expected 0 or more");
        return value;
    }

    int integer(const std::string& what, int lo, int hi) {
        double value = number(what);
        if (value != std::floor(value) || value < lo || value > hi)
            in_.fail_here(what + " is " + format_double(value) + ": expected a whole number from " +
                          std::to_string(lo) + " to " + std::to_string(hi));
        return static_cast<int>(value);
    }

    std::vector<double> angles(size_t count, const std::string& what, double lo, double hi) {
        std::vector<double> out(count);
        for (size_t i = 0; i < count; ++i) {
            out[i] = number(what + " #" + std::to_string(i + 1) + " of " + std::to_string(count));
            if (out[i] < lo || out[i] > hi)
                fail_here(what + " #" + std::to_string(i + 1) + " is " + format_double(out[i]) +
                          ": expected " + format_double(lo) + " to " + format_double(hi) +
                          " degrees");
            if (i > 0 && out[i] <= out[i - 1])
                fail_here(what + "s are not ascending: " + format_double(out[i - 1]) + " then " +
                          format_double(out[i]));
        }
        return out;
    }

    [[noreturn]] void fail_here(const std::string& what) const { in_.fail_here(what); }
    [[noreturn]] void fail_at(uint64_t line, const std::string& what) const {
        rayset::fail(in_.path(), Location::line(line), what);
    }
    uint64_t line() const { return in_.line_number(); }

private:
    TextInput& in_;
};

// Isym 2, 3 and 4 store planes that must sit at fixed C angles.
void check_symmetry_planes(LineReader& r, const EulumdatFile& f, uint64_t isym_line) {
    auto need = [&](size_t index, double angle) {
        if (f.c_angles_deg[index] != angle)
            r.fail_at(isym_line, "Isym " + std::to_string(f.isym) + " needs C angle #" +
                                     std::to_string(index + 1) + " to be " + format_double(angle) +
                                     " but it is " + format_double(f.c_angles_deg[index]));
    };
    size_t mc = size_t(f.mc);
    if (f.isym >= 2) need(0, 0);
    if (f.isym == 2) need(mc / 2, 180);
    if (f.isym == 3) {
        need(mc / 4, 90);
        need(3 * mc / 4, 270);
    }
    if (f.isym == 4) need(mc / 4, 90);
}

}  // namespace

size_t eulumdat_stored_planes(int isym, int mc) {
    switch (isym) {
        case 1: return 1;
        case 2:
        case 3: return size_t(mc) / 2 + 1;
        case 4: return size_t(mc) / 4 + 1;
        default: return size_t(mc);
    }
}

bool looks_like_eulumdat(std::string_view head) {
    std::vector<std::string> lines;
    size_t pos = 0;
    while (lines.size() < 7 && pos < head.size()) {
        size_t end = head.find('\n', pos);
        if (end == std::string_view::npos) return false;  // fewer than 7 complete lines
        lines.push_back(trim(head.substr(pos, end - pos)));
        if (!lines.back().empty() && lines.back().back() == '\r') lines.back().pop_back();
        pos = end + 1;
    }
    if (lines.size() < 7) return false;
    double v[6];
    for (int i = 0; i < 6; ++i)
        if (!parse_ldt_number(lines[size_t(i) + 1], v[i])) return false;
    auto whole = [](double x, double lo, double hi) {
        return x == std::floor(x) && x >= lo && x <= hi;
    };
    return whole(v[0], 0, 3) && whole(v[1], 0, 4) && whole(v[2], 1, 1e6) && v[3] >= 0 &&
           whole(v[4], 1, 1e6) && v[5] >= 0;
}

namespace {

constexpr int kIntMax = std::numeric_limits<int>::max();

// Lines 2-7: Ityp, Isym, Mc, Dc, Ng, Dg. Returns the line of Isym, which errors about the
// planes a symmetry needs point at.
uint64_t read_counts(LineReader& r, EulumdatFile& f) {
    f.ityp = r.integer("Ityp (type indicator)", 0, 3);
    f.isym = r.integer("Isym (symmetry indicator)", 0, 4);
    const uint64_t isym_line = r.line();
    f.mc = r.integer("Mc (number of C planes)", 1, kIntMax);
    if ((f.isym == 2 && f.mc % 2) || ((f.isym == 3 || f.isym == 4) && f.mc % 4))
        r.fail_here("Mc is " + std::to_string(f.mc) + ": Isym " + std::to_string(f.isym) +
                    " needs a multiple of " + (f.isym == 2 ? "2" : "4"));
    f.dc = r.non_negative("Dc (distance between C planes)");
    f.ng = r.integer("Ng (number of gamma angles)", 1, kIntMax);
    f.dg = r.non_negative("Dg (distance between gamma angles)");
    return isym_line;
}

// Each value takes a line of at least 2 bytes: counts beyond that are corrupt, not allocations.
void check_counts_fit(const LineReader& r, const EulumdatFile& f, uint64_t file_size) {
    const size_t planes = eulumdat_stored_planes(f.isym, f.mc);
    if ((planes + 1) * uint64_t(f.ng) + uint64_t(f.mc) > file_size / 2 + 1)
        r.fail_here("Mc " + std::to_string(f.mc) + " and Ng " + std::to_string(f.ng) +
                    " ask for more values than the " + std::to_string(file_size) +
                    "-byte file can hold");
}

// Lines 8-12.
void read_text_lines(LineReader& r, EulumdatFile& f) {
    f.report_number = r.text("line 8 (measurement report number)");
    f.luminaire_name = r.text("line 9 (luminaire name)");
    f.luminaire_number = r.text("line 10 (luminaire number)");
    f.file_name = r.text("line 11 (file name)");
    f.date_user = r.text("line 12 (date/user)");
}

// Lines 13-21: the luminaire's body and its luminous area.
void read_dimensions(LineReader& r, EulumdatFile& f) {
    f.luminaire_length_mm = r.non_negative("luminaire length/diameter (mm)");
    f.luminaire_width_mm = r.non_negative("luminaire width (mm)");
    f.luminaire_height_mm = r.non_negative("luminaire height (mm)");
    f.luminous_length_mm = r.non_negative("luminous area length/diameter (mm)");
    f.luminous_width_mm = r.non_negative("luminous area width (mm)");
    const char* sides[] = {"C0", "C90", "C180", "C270"};
    for (int i = 0; i < 4; ++i)
        f.luminous_height_mm[size_t(i)] =
            r.non_negative(std::string("luminous area height at ") + sides[i] + " (mm)");
}

// Lines 22-25: DFF, LORL, the conversion factor and the tilt.
void read_ratios_and_tilt(LineReader& r, EulumdatFile& f) {
    f.downward_flux_percent = r.number("DFF (downward flux fraction, %)");
    f.light_output_ratio_percent = r.number("LORL (light output ratio, %)");
    f.conversion_factor = r.number("conversion factor for luminous intensities");
    if (!(f.conversion_factor > 0))
        r.fail_here("conversion factor is " + format_double(f.conversion_factor) +
                    ": expected a positive number");
    f.tilt_deg = r.number("tilt of the luminaire during measurement");
}

EulumdatLampSet read_lamp_set(LineReader& r, int index) {
    const std::string which = "lamp set " + std::to_string(index + 1) + ": ";
    EulumdatLampSet set;
    set.count = r.integer(which + "number of lamps", -kIntMax, kIntMax);
    if (set.count == 0)
        r.fail_here(which +
                    "number of lamps is 0: expected a count (negative for absolute photometry)");
    set.type = r.text(which + "lamp type");
    set.lumens = r.number(which + "total luminous flux (lm)");
    if (!(set.lumens > 0))
        r.fail_here(which + "flux is " + format_double(set.lumens) +
                    ": expected a positive number of lumens");
    set.color = r.text(which + "colour appearance");
    set.rendering = r.text(which + "colour rendering");
    set.watts = r.non_negative(which + "wattage including ballast (W)");
    return set;
}

// The number of sets, then six lines per set. Each set takes at least 12 bytes, which bounds
// the count.
void read_lamp_sets(LineReader& r, EulumdatFile& f, uint64_t file_size) {
    const int sets = r.integer("number of lamp sets", 1,
                               int(std::min<uint64_t>(file_size / 12 + 1, uint64_t(kIntMax))));
    for (int s = 0; s < sets; ++s) f.lamp_sets.push_back(read_lamp_set(r, s));
}

// All Mc C angles (C360 would repeat C0) and the Ng gamma angles.
void read_angles(LineReader& r, EulumdatFile& f, uint64_t isym_line) {
    f.c_angles_deg = r.angles(size_t(f.mc), "C angle", 0, 360);
    if (f.c_angles_deg.back() == 360)
        r.fail_here("C angle 360 repeats C0: expected angles from 0 up to, not including, 360");
    f.gamma_angles_deg = r.angles(size_t(f.ng), "gamma angle", 0, 180);
    check_symmetry_planes(r, f, isym_line);
}

void read_intensities(LineReader& r, EulumdatFile& f) {
    const size_t planes = eulumdat_stored_planes(f.isym, f.mc);
    f.intensities.resize(planes * size_t(f.ng));
    for (size_t p = 0; p < planes; ++p) {
        for (size_t g = 0; g < size_t(f.ng); ++g) {
            double& value = f.intensities[p * size_t(f.ng) + g];
            value = r.non_negative(
                "intensity (cd/klm) #" + std::to_string(g + 1) + " of " + std::to_string(f.ng) +
                " of stored C plane #" + std::to_string(p + 1) + " of " + std::to_string(planes) +
                " (Isym " + std::to_string(f.isym) + ", Mc " + std::to_string(f.mc) + ")");
        }
    }
}

// Only blank lines and a DOS end-of-file mark may follow the last intensity.
void check_nothing_after(TextInput& in, const LineReader& r) {
    std::string line;
    while (in.next(line))
        if (!trim(line).empty() && trim(line) != "\x1a")
            r.fail_here("unexpected '" + trim(line) +
                        "' after the last intensity: Mc, Ng or Isym do not match the data");
}

}  // namespace

EulumdatFile read_eulumdat(const std::string& path) {
    TextInput in(path);
    LineReader r(in);
    EulumdatFile f;
    f.company = r.text("line 1 (company identification)");
    const uint64_t isym_line = read_counts(r, f);
    check_counts_fit(r, f, in.size());
    read_text_lines(r, f);
    read_dimensions(r, f);
    read_ratios_and_tilt(r, f);
    read_lamp_sets(r, f, in.size());
    for (size_t i = 0; i < 10; ++i)
        f.direct_ratios[i] = r.number("direct ratio #" + std::to_string(i + 1) + " of 10");
    read_angles(r, f, isym_line);
    read_intensities(r, f);
    check_nothing_after(in, r);
    return f;
}

void write_eulumdat(const std::string& path, const EulumdatFile& f) {
    size_t planes = eulumdat_stored_planes(f.isym, f.mc);
    if (f.isym < 0 || f.isym > 4 || f.mc < 1 || f.ng < 1 || f.c_angles_deg.size() != size_t(f.mc) ||
        f.gamma_angles_deg.size() != size_t(f.ng) ||
        f.intensities.size() != planes * size_t(f.ng) || f.lamp_sets.empty())
        fail(path, "cannot write as EULUMDAT: inconsistent data (Isym " + std::to_string(f.isym) +
                       ", Mc " + std::to_string(f.mc) + ", Ng " + std::to_string(f.ng) + ", " +
                       std::to_string(f.c_angles_deg.size()) + " C angles, " +
                       std::to_string(f.gamma_angles_deg.size()) + " gamma angles, " +
                       std::to_string(f.intensities.size()) + " intensities, " +
                       std::to_string(f.lamp_sets.size()) + " lamp sets)");
    std::string out;
    auto text = [&](const std::string& s) {
        if (s.find_first_of("\r\n") != std::string::npos)
            fail(path, "cannot write as EULUMDAT: a text field has a line break: '" + s + "'");
        out += s;
        out += "\r\n";
    };
    auto number = [&](double x) {
        if (!std::isfinite(x))
            fail(path, "cannot write as EULUMDAT: a value is " + format_double(x));
        text(format_double(x));
    };
    text(f.company);
    for (double x : {double(f.ityp), double(f.isym), double(f.mc), f.dc, double(f.ng), f.dg})
        number(x);
    for (const auto* s :
         {&f.report_number, &f.luminaire_name, &f.luminaire_number, &f.file_name, &f.date_user})
        text(*s);
    for (double x : {f.luminaire_length_mm, f.luminaire_width_mm, f.luminaire_height_mm,
                     f.luminous_length_mm, f.luminous_width_mm})
        number(x);
    for (double x : f.luminous_height_mm) number(x);
    for (double x :
         {f.downward_flux_percent, f.light_output_ratio_percent, f.conversion_factor, f.tilt_deg})
        number(x);
    number(double(f.lamp_sets.size()));
    for (const auto& s : f.lamp_sets) {
        number(s.count);
        text(s.type);
        number(s.lumens);
        text(s.color);
        text(s.rendering);
        number(s.watts);
    }
    for (double x : f.direct_ratios) number(x);
    for (double x : f.c_angles_deg) number(x);
    for (double x : f.gamma_angles_deg) number(x);
    for (double x : f.intensities) number(x);
    AtomicOutput file(path);
    file.write(out);
    file.commit();
}

}  // namespace rayset
