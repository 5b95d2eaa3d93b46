// IES LM-63 writer, and the IesFile a Photometry maps to.
#include "converters/photometry/ies.h"
#include "converters/rays/io.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace rayset {

namespace {

constexpr size_t line_width = 80;

// Appends numbers separated by blanks, starting a new line before one would pass line_width.
class WrappedLine {
public:
    explicit WrappedLine(std::string& out) : out_(out) {}
    void add(double value) {
        std::string text = format_double(value);
        if (column_ > 0 && column_ + 1 + text.size() > line_width) end();
        if (column_ > 0) {
            out_ += ' ';
            ++column_;
        }
        out_ += text;
        column_ += text.size();
    }
    void end() {
        if (column_ > 0) out_ += "\r\n";
        column_ = 0;
    }

private:
    std::string& out_;
    size_t column_ = 0;
};

const char* version_line(IesVersion v) {
    switch (v) {
        case IesVersion::lm63_1986: return nullptr;
        case IesVersion::lm63_1991: return "IESNA91";
        case IesVersion::lm63_1995: return "IESNA:LM-63-1995";
        case IesVersion::lm63_2002: return "IESNA:LM-63-2002";
        case IesVersion::lm63_2019: return "IES:LM-63-2019";
    }
    return nullptr;
}

void check_for_writing(const std::string& path, const IesFile& f) {
    auto bad = [&](const std::string& what) { fail(path, "cannot write as IES: " + what); };
    if (f.vertical_deg.empty() || f.horizontal_deg.empty()) bad("no angles");
    if (f.candela.size() != f.vertical_deg.size() * f.horizontal_deg.size())
        bad(std::to_string(f.candela.size()) + " candela values for " +
            std::to_string(f.vertical_deg.size()) + " x " +
            std::to_string(f.horizontal_deg.size()) + " angles");
    for (const auto* a : {&f.vertical_deg, &f.horizontal_deg})
        for (size_t i = 0; i < a->size(); ++i)
            if (!std::isfinite((*a)[i]) || (i > 0 && (*a)[i] <= (*a)[i - 1]))
                bad("angles not finite and ascending");
    for (double c : f.candela)
        if (!std::isfinite(c) || c < 0)
            bad("candela value " + format_double(c) + " (expected finite and not negative)");
    const auto& h = f.horizontal_deg;
    double first = h.front(), last = h.back();
    std::string range = format_double(first) + ".." + format_double(last);
    if (f.photometric_type == 1) {
        if (!((h.size() == 1 && first == 0) ||
              (first == 0 && (last == 90 || last >= 180) && last <= 360) ||
              (first == 90 && last == 270 && f.version == IesVersion::lm63_1995)))
            bad("type C horizontal angles run " + range +
                "; LM-63 allows 0, 0..90, 0..180, 0..(180 to 360)" +
                (f.version == IesVersion::lm63_1995 ? " or 90..270" : ""));
        if (f.vertical_deg.front() < 0 || f.vertical_deg.back() > 180)
            bad("type C vertical angles outside 0..180");
    } else if (f.photometric_type == 2 || f.photometric_type == 3) {
        if (!((first == -90 || first == 0) && last == 90))
            bad("type A/B horizontal angles run " + range + "; LM-63 allows -90..90 or 0..90");
        if (f.vertical_deg.front() < -90 || f.vertical_deg.back() > 90)
            bad("type A/B vertical angles outside -90..90");
    } else {
        bad("photometric type " + std::to_string(f.photometric_type) + " (expected 1, 2 or 3)");
    }
    if (f.lamp_count < 1)
        bad("lamp count " + std::to_string(f.lamp_count) + " (expected 1 or more)");
    for (const auto& k : f.keywords)
        if (k.key.find_first_of("[]\r\n") != std::string::npos)
            bad("keyword '" + k.key + "' contains a bracket or line break");
}

}  // namespace

void write_ies(const std::string& path, const IesFile& f) {
    check_for_writing(path, f);
    std::string out;
    if (const char* v = version_line(f.version)) out += std::string(v) + "\r\n";
    for (const auto& k : f.keywords) {
        size_t start = 0;
        bool first = true;
        while (true) {
            size_t end = k.value.find('\n', start);
            std::string part =
                k.value.substr(start, end == std::string::npos ? std::string::npos : end - start);
            if (k.key.empty()) {
                out += part;
            } else {
                out += "[" + (first ? k.key : std::string("MORE")) + "]" +
                       (part.empty() ? "" : " " + part);
            }
            out += "\r\n";
            first = false;
            if (end == std::string::npos) break;
            start = end + 1;
        }
    }
    WrappedLine numbers(out);
    switch (f.tilt.kind) {
        case IesTilt::Kind::none: out += "TILT=NONE\r\n"; break;
        case IesTilt::Kind::file: out += "TILT=" + f.tilt.file_name + "\r\n"; break;
        case IesTilt::Kind::include:
            out += "TILT=INCLUDE\r\n";
            numbers.add(f.tilt.lamp_to_luminaire_geometry);
            numbers.end();
            numbers.add(double(f.tilt.angles_deg.size()));
            numbers.end();
            for (double a : f.tilt.angles_deg) numbers.add(a);
            numbers.end();
            for (double m : f.tilt.multipliers) numbers.add(m);
            numbers.end();
            break;
    }
    for (double x : {double(f.lamp_count), f.lumens_per_lamp, f.multiplier,
                     double(f.vertical_deg.size()), double(f.horizontal_deg.size()),
                     double(f.photometric_type), double(f.units), f.width, f.length, f.height})
        numbers.add(x);
    numbers.end();
    for (double x : {f.ballast_factor, f.generation, f.input_watts}) numbers.add(x);
    numbers.end();
    for (double a : f.vertical_deg) numbers.add(a);
    numbers.end();
    for (double a : f.horizontal_deg) numbers.add(a);
    numbers.end();
    // Each horizontal angle's candela values start on a new line, as LM-63 asks.
    const size_t nv = f.vertical_deg.size();
    for (size_t h = 0; h < f.horizontal_deg.size(); ++h) {
        for (size_t v = 0; v < nv; ++v) numbers.add(f.candela[h * nv + v]);
        numbers.end();
    }
    AtomicOutput file(path);
    file.write(out);
    file.commit();
}

namespace {

// LM-63-2002 and 2019 have no 90..270 symmetry: the bilateral data is written for 0..360, each
// plane C taking the values of its mirror image 180 - C.
void unfold_90_270(Photometry& p) {
    const auto& h = p.horizontal_deg;
    std::vector<double> full;
    for (double a : h) {
        full.push_back(a);
        double mirror = std::fmod(540.0 - a, 360.0);
        if (mirror < 90 || mirror > 270) full.push_back(mirror);
    }
    if (!std::count(full.begin(), full.end(), 0.0))
        full.push_back(0.0);  // C0 is the mirror of C180 only
    std::sort(full.begin(), full.end());
    full.push_back(360.0);
    std::vector<double> candela;
    const size_t nv = p.vertical_deg.size();
    for (double c : full) {
        double folded = c < 90 || c > 270 ? std::fmod(540.0 - c, 360.0) : c;
        auto it = std::lower_bound(h.begin(), h.end(), folded);
        if (it != h.end() && *it == folded) {
            size_t i = size_t(it - h.begin());
            candela.insert(candela.end(), p.candela.begin() + long(i * nv),
                           p.candela.begin() + long((i + 1) * nv));
        } else {
            for (double v : p.vertical_deg) candela.push_back(p.intensity(c, v));
        }
    }
    p.horizontal_deg = full;
    p.candela = candela;
}

const char* const lm63_order[] = {"TEST",         "TESTLAB",      "TESTDATE",   "NEARFIELD",
                                  "ISSUEDATE",    "MANUFAC",      "LUMCAT",     "LUMINAIRE",
                                  "LAMPCAT",      "LAMP",         "BALLASTCAT", "BALLAST",
                                  "MAINTCAT",     "DISTRIBUTION", "FLASHAREA",  "COLORCONSTANT",
                                  "LAMPPOSITION", "FILEGENINFO",  "SEARCH",     "OTHER"};

}  // namespace

IesFile ies_from_photometry(const Photometry& photometry, const std::string& path,
                            IesVersion version) {
    Photometry p = photometry;
    if (p.candela.size() != p.vertical_deg.size() * p.horizontal_deg.size() ||
        p.vertical_deg.empty() || p.horizontal_deg.empty())
        fail(path, "cannot write as IES: " + std::to_string(p.candela.size()) +
                       " candela values for " + std::to_string(p.vertical_deg.size()) + " x " +
                       std::to_string(p.horizontal_deg.size()) + " angles");
    if (p.type == PhotometricType::C && p.horizontal_deg.size() > 1 &&
        p.horizontal_deg.front() == 90 && p.horizontal_deg.back() == 270 &&
        version != IesVersion::lm63_1995)
        unfold_90_270(p);
    IesFile f;
    f.version = version;
    for (const char* key : lm63_order) {
        auto it = p.keywords.find(key);
        if (it != p.keywords.end())
            f.keywords.push_back({it->first, it->second});
        else if (version == IesVersion::lm63_2019 &&
                 (std::string(key) == "TEST" || std::string(key) == "TESTLAB" ||
                  std::string(key) == "ISSUEDATE" || std::string(key) == "MANUFAC"))
            f.keywords.push_back({key, ""});  // required by LM-63-2019
    }
    for (const auto& [key, value] : p.keywords)
        if (std::find(std::begin(lm63_order), std::end(lm63_order), key) == std::end(lm63_order))
            f.keywords.push_back({key, value});
    f.lamp_count = std::max(1, p.lamp_count);
    f.lumens_per_lamp = p.rated_lumens > 0 ? p.rated_lumens / f.lamp_count : -1;
    f.multiplier = 1;
    f.photometric_type = static_cast<int>(p.type);
    f.units = 2;
    f.width = p.round ? -p.width_m : p.width_m;
    f.length = p.round ? -p.length_m : p.length_m;
    f.height = p.height_m;
    f.ballast_factor = p.ballast_factor;
    f.generation =
        version == IesVersion::lm63_2019 ? 1.00001 : 1;  // 2019: "undefined" generation type
    f.input_watts = p.input_watts;
    f.vertical_deg = p.vertical_deg;
    f.horizontal_deg = p.horizontal_deg;
    f.candela = p.candela;
    return f;
}

}  // namespace rayset
