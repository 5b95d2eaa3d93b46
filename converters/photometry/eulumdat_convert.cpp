// EULUMDAT <-> Photometry: cd/klm <-> cd, stored symmetry planes <-> horizontal angles, and the
// "_LDT_..." keywords that carry what Photometry has no field for.
#include "converters/photometry/eulumdat.h"
#include "converters/rays/io.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

namespace rayset {

namespace {

std::string join(const double* values, size_t n) {
    std::string s;
    for (size_t i = 0; i < n; ++i) s += (i ? " " : "") + format_double(values[i]);
    return s;
}

double mirror_90_270(double c) { return std::fmod(540.0 - c, 360.0); }  // (180 - c) mod 360

const std::string* keyword(const Photometry& p, const char* key) {
    auto it = p.keywords.find(key);
    return it == p.keywords.end() ? nullptr : &it->second;
}

std::string one_line(const Photometry& p, const char* key) {
    const std::string* v = keyword(p, key);
    if (!v) return {};
    std::string s = *v;
    std::replace(s.begin(), s.end(), '\n', ' ');
    return s;
}

// Numbers from an _LDT_ keyword: exactly n, or fail naming the keyword.
std::vector<double> numbers_of(const std::string& path, const char* key, const std::string& value,
                               size_t n) {
    std::vector<double> out;
    bool all_numbers = true;
    for (auto field : split_fields(value)) {
        double x = 0;
        all_numbers = all_numbers && parse_double(field, x) && std::isfinite(x);
        out.push_back(x);
    }
    if (!all_numbers || out.size() != n)
        fail(path, std::string("cannot write as EULUMDAT: keyword ") + key + " is '" + value +
                       "': expected " + std::to_string(n) + " numbers");
    return out;
}

// Dc / Dg: the spacing of equidistant angles, 0 otherwise (and for a single angle).
double spacing(const std::vector<double>& a) {
    if (a.size() < 2) return 0;
    double d = a[1] - a[0];
    for (size_t i = 2; i < a.size(); ++i)
        if (std::fabs(a[i] - a[i - 1] - d) > 1e-9 * std::max(1.0, d)) return 0;
    return d;
}

// Flux below the horizon (gamma 0..90) by the same quadrature as total_flux().
double downward_flux(const Photometry& p) {
    Photometry lower = p;
    lower.vertical_deg.clear();
    for (double v : p.vertical_deg)
        if (v <= 90) lower.vertical_deg.push_back(v);
    if (lower.vertical_deg.empty()) return 0;
    bool add_90 = lower.vertical_deg.back() < 90 && p.vertical_deg.back() > 90;
    if (add_90) lower.vertical_deg.push_back(90);
    lower.candela.clear();
    for (size_t h = 0; h < p.horizontal_deg.size(); ++h)
        for (double v : lower.vertical_deg)
            lower.candela.push_back(p.intensity(p.horizontal_deg[h], v));
    return lower.total_flux();
}

}  // namespace

Photometry eulumdat_to_photometry(const EulumdatFile& f) {
    Photometry p;
    p.type = PhotometricType::C;
    p.vertical_deg = f.gamma_angles_deg;
    const size_t planes = eulumdat_stored_planes(f.isym, f.mc), ng = size_t(f.ng),
                 mc = size_t(f.mc);
    const EulumdatLampSet& set = f.lamp_sets.at(0);
    const double scale = f.conversion_factor * std::fabs(set.lumens) / 1000.0;
    std::vector<size_t> order(planes);  // stored plane for each horizontal angle, ascending
    if (f.isym == 1) {
        p.horizontal_deg = {0.0};
        order[0] = 0;
    } else if (f.isym == 3) {
        // Stored C270 .. C0 .. C90 are the mirror images of 270 .. 180 .. 90.
        for (size_t k = 0; k < planes; ++k) {
            p.horizontal_deg.push_back(
                mirror_90_270(f.c_angles_deg[(3 * mc / 4 + planes - 1 - k) % mc]));
            order[k] = planes - 1 - k;
        }
    } else {
        for (size_t k = 0; k < planes; ++k) {
            p.horizontal_deg.push_back(f.c_angles_deg[k]);
            order[k] = k;
        }
    }
    p.candela.resize(planes * ng);
    for (size_t h = 0; h < planes; ++h)
        for (size_t g = 0; g < ng; ++g)
            p.candela[h * ng + g] = f.intensities[order[h] * ng + g] * scale;
    p.lamp_count = std::abs(set.count);
    p.rated_lumens = set.count > 0 ? set.lumens : std::nan("");
    p.input_watts = set.watts;
    p.ballast_factor = 1;
    p.round = f.luminous_width_mm == 0 && f.luminous_length_mm > 0;
    p.length_m = f.luminous_length_mm / 1000;
    p.width_m = p.round ? p.length_m : f.luminous_width_mm / 1000;
    p.height_m = *std::max_element(f.luminous_height_mm.begin(), f.luminous_height_mm.end()) / 1000;

    auto put = [&](const char* key, const std::string& value) {
        if (!value.empty()) p.keywords[key] = value;
    };
    put("MANUFAC", f.company);
    put("TEST", f.report_number);
    put("LUMINAIRE", f.luminaire_name);
    put("LUMCAT", f.luminaire_number);
    put("ISSUEDATE", f.date_user);
    put("LAMP", set.type);
    put("_LDT_ITYP", std::to_string(f.ityp));
    double body[3] = {f.luminaire_length_mm, f.luminaire_width_mm, f.luminaire_height_mm};
    if (body[0] || body[1] || body[2]) put("_LDT_LUMINAIRE_MM", join(body, 3));
    const auto& hs = f.luminous_height_mm;
    if (!(hs[0] == hs[1] && hs[1] == hs[2] && hs[2] == hs[3]))
        put("_LDT_LUMINOUS_HEIGHTS_MM", join(hs.data(), 4));
    put("_LDT_DFF", format_double(f.downward_flux_percent));
    put("_LDT_LORL", format_double(f.light_output_ratio_percent));
    if (f.tilt_deg != 0) put("_LDT_TILT", format_double(f.tilt_deg));
    if (std::any_of(f.direct_ratios.begin(), f.direct_ratios.end(),
                    [](double x) { return x != 0; }))
        put("_LDT_DIRECT_RATIOS", join(f.direct_ratios.data(), 10));
    put("_LDT_LAMP_COLOR", set.color);
    put("_LDT_LAMP_RENDERING", set.rendering);
    std::string more;
    for (size_t s = 1; s < f.lamp_sets.size(); ++s) {
        const auto& m = f.lamp_sets[s];
        more += (s > 1 ? "\n" : "") + std::to_string(m.count) + "|" + m.type + "|" +
                format_double(m.lumens) + "|" + m.color + "|" + m.rendering + "|" +
                format_double(m.watts);
    }
    put("_LDT_MORE_LAMP_SETS", more);
    return p;
}

namespace {

// The distribution around the full circle: C angles 0 <= C < 360 and each plane's intensities
// (cd) at the vertical angles, read through Photometry::intensity (exact at grid planes).
struct Circle {
    std::vector<double> c;
    std::vector<std::vector<double>> rows;
};

double wrap_360(double a) {
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360.0 : a;
}

Circle full_circle(const std::string& path, const Photometry& p) {
    const auto& h = p.horizontal_deg;
    std::vector<double> angles;
    if (h.size() == 1) {
        angles = {0.0};
    } else if (h.front() == 0 && (h.back() == 90 || h.back() == 180)) {
        for (double a : h) {
            angles.push_back(a);
            angles.push_back(360 - a);
            if (h.back() == 90) angles.push_back(180 - a), angles.push_back(180 + a);
        }
    } else if (h.front() == 90 && h.back() == 270) {
        angles = {0.0};
        for (double a : h) angles.push_back(a), angles.push_back(mirror_90_270(a));
    } else {
        if (h.front() < 0 || h.back() > h.front() + 360)
            fail(path, "cannot write as EULUMDAT: horizontal angles run " +
                           format_double(h.front()) + ".." + format_double(h.back()) +
                           "; EULUMDAT C angles lie in 0..360");
        angles = h;
        if (h.back() - h.front() >= 360) angles.pop_back();  // C360 is C0 again
    }
    for (double& a : angles) a = wrap_360(a);
    std::sort(angles.begin(), angles.end());
    Circle circle;
    for (double a : angles) {
        if (!circle.c.empty() && a - circle.c.back() <= 1e-9)
            continue;  // mirror planes that coincide
        circle.c.push_back(a);
        circle.rows.emplace_back();
        for (double v : p.vertical_deg) circle.rows.back().push_back(p.intensity(a, v));
    }
    return circle;
}

size_t find_plane(const Circle& circle, double angle) {
    angle = wrap_360(angle);
    for (size_t k = 0; k < circle.c.size(); ++k)
        if (std::fabs(circle.c[k] - angle) <= 1e-9 || std::fabs(circle.c[k] - angle) >= 360 - 1e-9)
            return k;
    return circle.c.size();
}

// Whether every plane has a mirror image plane with the same values.
template <class Mirror>
bool symmetric(const Circle& circle, Mirror mirror) {
    for (size_t k = 0; k < circle.c.size(); ++k) {
        size_t j = find_plane(circle, mirror(circle.c[k]));
        if (j == circle.c.size() || circle.rows[j] != circle.rows[k]) return false;
    }
    return true;
}

// The most compact Isym the data allows, and the planes (indices into circle) it stores.
int choose_symmetry(const Circle& circle, std::vector<size_t>& stored) {
    const auto& c = circle.c;
    const size_t mc = c.size();
    stored.clear();
    auto across_0_180 = [](double a) { return 360 - a; };
    auto across_90_270 = [](double a) { return 180 - a; };
    if (std::all_of(circle.rows.begin(), circle.rows.end(),
                    [&](const auto& r) { return r == circle.rows[0]; })) {
        stored = {0};
        return 1;
    }
    bool from_0 = c[0] == 0;
    if (from_0 && mc % 4 == 0 && c[mc / 4] == 90 && symmetric(circle, across_0_180) &&
        symmetric(circle, across_90_270)) {
        for (size_t k = 0; k <= mc / 4; ++k) stored.push_back(k);
        return 4;
    }
    if (from_0 && mc % 2 == 0 && c[mc / 2] == 180 && symmetric(circle, across_0_180)) {
        for (size_t k = 0; k <= mc / 2; ++k) stored.push_back(k);
        return 2;
    }
    if (from_0 && mc % 4 == 0 && c[mc / 4] == 90 && c[3 * mc / 4] == 270 &&
        symmetric(circle, across_90_270)) {
        for (size_t k = 0; k <= mc / 2; ++k) stored.push_back((3 * mc / 4 + k) % mc);
        return 3;
    }
    for (size_t k = 0; k < mc; ++k) stored.push_back(k);
    return 0;
}

// Types A and B have no EULUMDAT frame; the table must be complete and gamma within 0..180.
void check_writable(const Photometry& p, const std::string& path) {
    if (p.type != PhotometricType::C)
        fail(path, std::string("cannot write as EULUMDAT: it holds type C photometry only and ") +
                       "this is type " + (p.type == PhotometricType::B ? "B" : "A") +
                       "; write it as IES instead");
    if (p.vertical_deg.empty() || p.horizontal_deg.empty() ||
        p.candela.size() != p.vertical_deg.size() * p.horizontal_deg.size())
        fail(path, "cannot write as EULUMDAT: " + std::to_string(p.candela.size()) +
                       " candela values for " + std::to_string(p.vertical_deg.size()) + " x " +
                       std::to_string(p.horizontal_deg.size()) + " angles");
    if (p.vertical_deg.front() < 0 || p.vertical_deg.back() > 180)
        fail(path, "cannot write as EULUMDAT: vertical angles outside 0..180");
}

// Mc, Ng, the angles and their spacings Dc and Dg.
void set_angles(EulumdatFile& f, const Circle& circle, const std::vector<double>& gamma_deg) {
    f.c_angles_deg = circle.c;
    f.mc = int(circle.c.size());
    f.gamma_angles_deg = gamma_deg;
    f.ng = int(gamma_deg.size());
    f.dc = spacing(f.c_angles_deg);
    f.dg = spacing(f.gamma_angles_deg);
}

// Lamp set 1 describes the photometry itself: without rated lumens it is absolute (negative
// count) and its lumens are the luminaire's flux.
EulumdatLampSet first_lamp_set(const Photometry& p, double flux) {
    const bool absolute = !(p.rated_lumens > 0);
    EulumdatLampSet set;
    set.count = absolute ? -std::max(1, p.lamp_count) : std::max(1, p.lamp_count);
    set.lumens = absolute ? (flux > 0 ? flux : 1000) : p.rated_lumens;
    set.type = one_line(p, "LAMP");
    set.color = one_line(p, "_LDT_LAMP_COLOR");
    set.rendering = one_line(p, "_LDT_LAMP_RENDERING");
    set.watts = p.input_watts;
    return set;
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    for (size_t a = 0, b;; a = b + 1) {
        b = text.find(separator, a);
        parts.push_back(text.substr(a, b == std::string::npos ? std::string::npos : b - a));
        if (b == std::string::npos) return parts;
    }
}

// One line of _LDT_MORE_LAMP_SETS: count|type|lumens|colour|rendering|watts.
EulumdatLampSet parse_lamp_set(const std::string& path, const std::string& line) {
    const std::vector<std::string> parts = split(line, '|');
    EulumdatLampSet set;
    double count = 0;
    if (parts.size() != 6 || !parse_double(parts[0], count) || count != std::floor(count) ||
        count == 0 || !parse_double(parts[2], set.lumens) || !(set.lumens > 0) ||
        !parse_double(parts[5], set.watts))
        fail(path, "cannot write as EULUMDAT: _LDT_MORE_LAMP_SETS line '" + line +
                       "': expected count|type|lumens|colour|rendering|watts");
    set.count = int(count);
    set.type = parts[1];
    set.color = parts[3];
    set.rendering = parts[4];
    return set;
}

// Intensities of the stored planes in cd/klm of lamp set 1.
void set_intensities(EulumdatFile& f, const Circle& circle, const std::vector<size_t>& stored) {
    const size_t ng = size_t(f.ng);
    const double to_cd_klm = 1000.0 / f.lamp_sets[0].lumens;
    for (size_t k : stored)
        for (size_t g = 0; g < ng; ++g) f.intensities.push_back(circle.rows[k][g] * to_cd_klm);
}

void set_text_lines(EulumdatFile& f, const Photometry& p, const std::string& path) {
    f.company = one_line(p, "MANUFAC");
    f.report_number = one_line(p, "TEST");
    f.luminaire_name = one_line(p, "LUMINAIRE");
    f.luminaire_number = one_line(p, "LUMCAT");
    f.file_name = std::filesystem::path(path).filename().string();
    f.date_user = one_line(p, "ISSUEDATE");
}

// The numbers of an _LDT_ keyword (exactly n), or nothing when the photometry lacks it.
std::optional<std::vector<double>> keyword_numbers(const Photometry& p, const std::string& path,
                                                   const char* key, size_t n) {
    const std::string* value = keyword(p, key);
    if (!value) return std::nullopt;
    return numbers_of(path, key, *value, n);
}

std::optional<double> keyword_number(const Photometry& p, const std::string& path,
                                     const char* key) {
    const auto x = keyword_numbers(p, path, key, 1);
    if (!x) return std::nullopt;
    return (*x)[0];
}

// The luminous area from the opening, the luminaire's body from _LDT_LUMINAIRE_MM or else the
// luminous area.
void set_dimensions(EulumdatFile& f, const Photometry& p, const std::string& path) {
    f.luminous_length_mm = (p.round ? std::max(p.length_m, p.width_m) : p.length_m) * 1000;
    f.luminous_width_mm = p.round ? 0 : p.width_m * 1000;
    if (const auto x = keyword_numbers(p, path, "_LDT_LUMINOUS_HEIGHTS_MM", 4))
        std::copy(x->begin(), x->end(), f.luminous_height_mm.begin());
    else
        f.luminous_height_mm.fill(p.height_m * 1000);
    if (const auto x = keyword_numbers(p, path, "_LDT_LUMINAIRE_MM", 3)) {
        f.luminaire_length_mm = (*x)[0];
        f.luminaire_width_mm = (*x)[1];
        f.luminaire_height_mm = (*x)[2];
    } else {
        f.luminaire_length_mm = f.luminous_length_mm;
        f.luminaire_width_mm = f.luminous_width_mm;
        f.luminaire_height_mm = p.height_m * 1000;
    }
}

void set_type_indicator(EulumdatFile& f, const Photometry& p, const std::string& path) {
    const std::string* v = keyword(p, "_LDT_ITYP");
    if (!v) {
        f.ityp = f.isym == 1 ? 1 : 3;
        return;
    }
    const double ityp = numbers_of(path, "_LDT_ITYP", *v, 1)[0];
    if (ityp != std::floor(ityp) || ityp < 0 || ityp > 3)
        fail(path, "cannot write as EULUMDAT: _LDT_ITYP '" + *v + "' is not 0..3");
    f.ityp = int(ityp);
}

// DFF and LORL from their _LDT_ keywords, else from the intensities; tilt and direct ratios from
// theirs, else 0.
void set_ratios_and_tilt(EulumdatFile& f, const Photometry& p, const std::string& path,
                         double flux) {
    const bool absolute = !(p.rated_lumens > 0);
    const auto dff = keyword_number(p, path, "_LDT_DFF");
    f.downward_flux_percent = dff ? *dff : flux > 0 ? 100 * downward_flux(p) / flux : 0;
    const auto lorl = keyword_number(p, path, "_LDT_LORL");
    f.light_output_ratio_percent = lorl ? *lorl : absolute ? 100 : 100 * flux / p.rated_lumens;
    f.conversion_factor = 1;
    f.tilt_deg = keyword_number(p, path, "_LDT_TILT").value_or(0);
    if (const auto x = keyword_numbers(p, path, "_LDT_DIRECT_RATIOS", 10))
        std::copy(x->begin(), x->end(), f.direct_ratios.begin());
}

}  // namespace

EulumdatFile eulumdat_from_photometry(const Photometry& p, const std::string& path) {
    check_writable(p, path);
    EulumdatFile f;
    const Circle circle = full_circle(path, p);
    std::vector<size_t> stored;
    f.isym = choose_symmetry(circle, stored);
    set_angles(f, circle, p.vertical_deg);
    const double flux = p.total_flux();
    f.lamp_sets.push_back(first_lamp_set(p, flux));
    if (const std::string* more = keyword(p, "_LDT_MORE_LAMP_SETS"))
        for (const std::string& line : split(*more, '\n'))
            f.lamp_sets.push_back(parse_lamp_set(path, line));
    set_intensities(f, circle, stored);
    set_text_lines(f, p, path);
    set_dimensions(f, p, path);
    set_type_indicator(f, p, path);
    set_ratios_and_tilt(f, p, path, flux);
    return f;
}

}  // namespace rayset
