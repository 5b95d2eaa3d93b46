#include "converters/analytic/synth.h"

#include "converters/colour/spectrum.h"
#include "converters/rays/io.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace rayset {

using analytic::Spectrum;

namespace {

struct KeyHelp {
    const char* key;
    const char* meaning;
};

struct SourceHelp {
    const char* name;
    const char* summary;
    std::vector<KeyHelp> keys;
};

const std::vector<SourceHelp>& catalogue() {
    static const std::vector<SourceHelp> sources = {
        {"disk",
         "one-sided Lambertian disk at the origin emitting toward +z, or tilted",
         {{"radius", "mm (1)"},
          {"tilt", "deg (0): its normal turned from +z toward +x"},
          {"flux", "W (1); or radiance"},
          {"radiance", "W/(mm^2 sr)"},
          {"wavelength", "nm (555); or spectrum"},
          {"spectrum", "file of nm, relative power"}}},
        {"rectangle",
         "one-sided Lambertian rectangle in z = 0 emitting toward +z",
         {{"size_x", "mm (1)"},
          {"size_y", "mm (1)"},
          {"flux", "W (1); or radiance"},
          {"radiance", "W/(mm^2 sr)"},
          {"wavelength", "nm (555); or spectrum"},
          {"spectrum", "file of nm, relative power"}}},
        {"sphere",
         "Lambertian sphere at the origin emitting outward",
         {{"radius", "mm (1)"},
          {"flux", "W (1); or radiance"},
          {"radiance", "W/(mm^2 sr)"},
          {"wavelength", "nm (555); or spectrum"},
          {"spectrum", "file of nm, relative power"}}},
        {"lobe",
         "point emitter at the origin, I = I0 cos^n toward +z",
         {{"n", "exponent >= 0 (1)"},
          {"flux", "W (1); or intensity"},
          {"intensity", "peak I0 in W/sr"},
          {"wavelength", "nm (555); or spectrum"},
          {"spectrum", "file of nm, relative power"}}},
        {"cluster",
         "square Lambertian chips in rings in z = 0 emitting toward +z",
         {{"rings", "chips per ring, centre first (1,6,12,20)"},
          {"chip", "chip side, mm (1)"},
          {"pitch", "ring spacing, mm (2)"},
          {"flux", "total W, shared equally (1); or chip_flux"},
          {"chip_flux", "W per chip, list cycled over the chips"},
          {"wavelength", "nm per chip, list cycled (630,530,460); or spectrum"},
          {"spectrum", "file of nm, relative power, for every chip"}}},
    };
    return sources;
}

// Reads the parameters of one source, knowing which keys it accepts.
class ParameterReader {
public:
    ParameterReader(const SourceHelp& help, const SourceParameters& parameters)
        : source_(help.name) {
        for (const auto& [key, value] : parameters) {
            // C++17 lambdas cannot capture a structured binding (clang refuses): a name of its own.
            const std::string& name = key;
            const bool known = std::any_of(help.keys.begin(), help.keys.end(),
                                           [&](const KeyHelp& k) { return name == k.key; });
            if (!known) {
                std::string list;
                for (const KeyHelp& k : help.keys)
                    list += std::string(list.empty() ? "" : ", ") + k.key;
                throw Error("synth " + source_ + ": unknown parameter '" + key +
                            "' (known: " + list + ")");
            }
            values_[key] = value;
        }
    }

    bool has(const std::string& key) const { return values_.count(key) != 0; }

    double number(const std::string& key, double fallback) const {
        auto it = values_.find(key);
        return it == values_.end() ? fallback : parse(key, it->second);
    }

    std::vector<double> list(const std::string& key, std::vector<double> fallback) const {
        auto it = values_.find(key);
        if (it == values_.end()) return fallback;
        std::vector<double> out;
        for (std::string_view field : split_fields(it->second, true))
            out.push_back(parse(key, field));
        if (out.empty()) throw Error("synth " + source_ + ": parameter '" + key + "' is empty");
        return out;
    }

    void exclusive(const char* a, const char* b) const {
        if (has(a) && has(b))
            throw Error("synth " + source_ + ": give either '" + a + "' or '" + b + "', not both");
    }

    Spectrum spectrum() const {
        exclusive("wavelength", "spectrum");
        if (has("spectrum")) return read_spectrum_file(values_.at("spectrum"));
        Spectrum s;
        s.wavelength_nm = number("wavelength", 555);
        return s;
    }

private:
    double parse(const std::string& key, std::string_view text) const {
        double value;
        if (!parse_double(text, value) || !std::isfinite(value))
            throw Error("synth " + source_ + ": parameter '" + key +
                        "' must be a finite number, not '" + std::string(text) + "'");
        return value;
    }

    std::string source_;
    std::map<std::string, std::string> values_;
};

std::unique_ptr<analytic::Source> make_cluster(const ParameterReader& p) {
    analytic::ChipCluster::Layout layout;
    layout.rings.clear();
    for (double count : p.list("rings", {1, 6, 12, 20})) {
        if (count != std::floor(count) || count < 0 || count > 100000)
            throw Error("synth cluster: rings must be whole numbers of chips, not " +
                        format_double(count));
        layout.rings.push_back(int(count));
    }
    layout.chip_side = p.number("chip", 1);
    layout.pitch = p.number("pitch", 2);
    p.exclusive("flux", "chip_flux");
    p.exclusive("wavelength", "spectrum");
    Spectrum shared;
    std::vector<double> wavelengths;
    if (p.has("spectrum"))
        shared = p.spectrum();
    else
        wavelengths = p.list("wavelength", {630, 530, 460});
    if (p.has("chip_flux"))
        return std::make_unique<analytic::ChipCluster>(layout, p.list("chip_flux", {}), wavelengths,
                                                       shared);
    // Equal shares of the total: count the chips first.
    int chips = 0;
    for (int n : layout.rings) chips += n;
    const double total = p.number("flux", 1);
    if (!(total > 0))
        throw Error("synth cluster: flux must be a positive number of W, not " +
                    format_double(total));
    return std::make_unique<analytic::ChipCluster>(
        layout, std::vector<double>{total / std::max(chips, 1)}, wavelengths, shared);
}

}  // namespace

SourceParameters parse_source_parameters(const std::vector<std::string>& words) {
    SourceParameters out;
    for (const std::string& word : words) {
        const size_t eq = word.find('=');
        if (eq == std::string::npos || eq == 0)
            throw Error("synth: expected key=value, not '" + word + "'");
        std::string key = word.substr(0, eq);
        if (std::any_of(out.begin(), out.end(), [&](const auto& kv) { return kv.first == key; }))
            throw Error("synth: parameter '" + key + "' is given twice");
        out.emplace_back(std::move(key), word.substr(eq + 1));
    }
    return out;
}

std::unique_ptr<analytic::Source> make_source(const std::string& name,
                                              const SourceParameters& parameters) {
    const auto& sources = catalogue();
    auto it = std::find_if(sources.begin(), sources.end(),
                           [&](const SourceHelp& s) { return name == s.name; });
    if (it == sources.end()) {
        std::string list;
        for (const SourceHelp& s : sources) list += std::string(list.empty() ? "" : ", ") + s.name;
        throw Error("synth: unknown source '" + name + "' (known: " + list + ")");
    }
    const ParameterReader p(*it, parameters);
    using namespace analytic;
    if (name == "cluster") return make_cluster(p);
    if (name == "lobe") {
        p.exclusive("flux", "intensity");
        const double n = p.number("n", 1);
        if (p.has("intensity"))
            return std::make_unique<CosineLobe>(n, p.number("intensity", 0), p.spectrum());
        return std::make_unique<CosineLobe>(
            CosineLobe::with_flux(n, p.number("flux", 1), p.spectrum()));
    }
    p.exclusive("flux", "radiance");
    const bool by_radiance = p.has("radiance");
    const double radiance = p.number("radiance", 0), flux = p.number("flux", 1);
    if (name == "disk") {
        const double radius = p.number("radius", 1), tilt = p.number("tilt", 0);
        if (by_radiance)
            return std::make_unique<LambertianDisk>(radius, radiance, p.spectrum(), tilt);
        return std::make_unique<LambertianDisk>(
            LambertianDisk::with_flux(radius, flux, p.spectrum(), tilt));
    }
    if (name == "rectangle") {
        const double sx = p.number("size_x", 1), sy = p.number("size_y", 1);
        if (by_radiance)
            return std::make_unique<LambertianRectangle>(sx, sy, radiance, p.spectrum());
        return std::make_unique<LambertianRectangle>(
            LambertianRectangle::with_flux(sx, sy, flux, p.spectrum()));
    }
    const double radius = p.number("radius", 1);
    if (by_radiance) return std::make_unique<LambertianSphere>(radius, radiance, p.spectrum());
    return std::make_unique<LambertianSphere>(
        LambertianSphere::with_flux(radius, flux, p.spectrum()));
}

std::string source_help() {
    std::string out;
    for (const SourceHelp& s : catalogue()) {
        out += std::string(s.name) + ": " + s.summary + "\n";
        for (const KeyHelp& k : s.keys) out += "  " + std::string(k.key) + "=  " + k.meaning + "\n";
    }
    return out;
}

Spectrum read_spectrum_file(const std::string& path) {
    TextInput in(path);
    Spectrum spectrum;
    spectrum.table_file = path;
    SpectralTable& t = spectrum.table;
    std::string line;
    while (in.next(line)) {
        auto fields = split_fields(line, line.find(',') != std::string::npos);
        if (fields.empty() || fields[0].empty() || fields[0][0] == '#') continue;
        double w, p;
        if (fields.size() != 2 || !parse_double(fields[0], w) || !parse_double(fields[1], p))
            in.fail_here("expected two numbers, wavelength (nm) and relative power, not '" + line +
                         "'");
        if (!(w > 0 && std::isfinite(w)))
            in.fail_here("wavelength " + format_double(w) + " nm is not a positive number");
        if (!(p >= 0 && std::isfinite(p)))
            in.fail_here("relative power " + format_double(p) + " is not a number >= 0");
        if (!t.wavelength.empty() && !(w > t.wavelength.back()))
            in.fail_here("wavelength " + format_double(w) +
                         " nm does not ascend (the line before has " +
                         format_float(t.wavelength.back()) + " nm)");
        t.wavelength.push_back(float(w));
        t.weight.push_back(float(p));
    }
    if (t.wavelength.size() < 2)
        fail(path, "a spectrum needs at least two rows of wavelength (nm) and relative power");
    if (!std::any_of(t.weight.begin(), t.weight.end(), [](float v) { return v > 0; }))
        fail(path, "every relative power is zero: the spectrum carries no light");
    return spectrum;
}

RayHeader synth_header(const analytic::Source& source, uint64_t ray_count, uint64_t seed,
                       const SynthOptions& options) {
    RayHeader h;
    h.unit = LengthUnit::mm;
    h.ray_count = ray_count;
    h.has_radiant = true;
    h.stated_radiant = source.total_flux();
    source.describe_spectrum(h);
    h.has_luminous = options.luminous;
    // With a wavelength per ray the luminous total depends on how many rays each chip drew, so
    // only the rays can state it (the writer sums them).
    if (options.luminous && h.spectral != SpectralKind::per_ray_wavelength)
        h.stated_luminous = source.luminous_flux();
    h.creation_method = 0;
    const std::string what = source.name() + " " + source.parameters();
    const std::string run = "rays=" + std::to_string(ray_count) + " seed=" + std::to_string(seed);
    h.text[0] = "rayset synthetic " + source.name();
    h.text[1] = "rayset";
    h.text[2] = "rayset synth (analytic source)";
    h.text[3] = "rayset synth";
    h.text[4] = "rayset converters/synth";
    h.text[7] = what + " " + run;
    h.description = h.text[7];
    return h;
}

void synthesize(const analytic::Source& source, uint64_t ray_count, uint64_t seed, RayEncoder& out,
                const SynthOptions& options) {
    if (ray_count == 0) throw Error("synth: the ray count must be at least 1");
    const RayHeader header =
        synth_header(source, ray_count, seed, {options.luminous, options.chunk_size, {}});
    const PhotometricWeights weights(header);
    const float flux = float(source.total_flux() / double(ray_count));
    const bool per_ray_efficacy = header.spectral == SpectralKind::per_ray_wavelength;
    const float luminous =
        options.luminous && !per_ray_efficacy ? float(flux * weights.efficacy(Ray{})) : kUnknown;
    Pcg32 rng(seed);
    RayChunk chunk;
    const size_t chunk_size = std::max<size_t>(options.chunk_size, 1);
    for (uint64_t done = 0; done < ray_count;) {
        const size_t n = size_t(std::min<uint64_t>(chunk_size, ray_count - done));
        chunk.clear();
        chunk.first_index = done;
        for (size_t i = 0; i < n; ++i) {
            Ray ray = source.sample_ray(rng);
            ray.radiant = flux;
            if (options.luminous)
                ray.luminous = per_ray_efficacy ? float(flux * weights.efficacy(ray)) : luminous;
            chunk.rays.push_back(ray);
        }
        out.write(chunk);
        done += n;
        if (options.progress) options.progress(double(done) / double(ray_count));
    }
    out.finish();
}

}  // namespace rayset
