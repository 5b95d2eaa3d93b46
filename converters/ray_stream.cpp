#include "converters/ray_stream.h"

#include "converters/codecs.h"
#include "converters/io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rayset {

double millimetres_per(LengthUnit unit) {
    switch (unit) {
    case LengthUnit::mm: return 1;
    case LengthUnit::cm: return 10;
    case LengthUnit::m: return 1000;
    case LengthUnit::inch: return 25.4;
    case LengthUnit::ft: return 304.8;
    case LengthUnit::um: return 1e-3;
    case LengthUnit::nm: return 1e-6;
    }
    return 1;
}

const char* to_string(LengthUnit unit) {
    switch (unit) {
    case LengthUnit::mm: return "mm";
    case LengthUnit::cm: return "cm";
    case LengthUnit::m: return "m";
    case LengthUnit::inch: return "in";
    case LengthUnit::ft: return "ft";
    case LengthUnit::um: return "um";
    case LengthUnit::nm: return "nm";
    }
    return "?";
}

namespace {

struct FormatEntry {
    RayFormat format;
    const char* name;  // as users type it (--from/--to)
    const char* description;
    bool (*sniff)(const Head&, uint64_t);
    std::unique_ptr<RayDecoder> (*open)(const std::string&);
    std::unique_ptr<RayEncoder> (*create)(const std::string&, const RayHeader&);
};

// Detection order matters: formats with a magic first, SPEOS (no magic) last.
const FormatEntry kFormats[] = {
    {RayFormat::tm25, "tm25", "IES TM-25-13 ray file", sniff_tm25, open_tm25, create_tm25},
    {RayFormat::lighttools_binary, "lighttools", "LightTools binary ray data (LTRF)", sniff_lighttools_binary,
     open_lighttools_binary, create_lighttools_binary},
    {RayFormat::lighttools_text, "lighttools-text", "LightTools text ray data", sniff_lighttools_text,
     open_lighttools_text, create_lighttools_text},
    {RayFormat::zemax_binary, "zemax", "Zemax binary source file (.DAT/.SDF)", sniff_zemax_binary, open_zemax_binary,
     create_zemax_binary},
    {RayFormat::csv, "csv", "CSV rays (rayset)", sniff_csv, open_csv, create_csv},
    {RayFormat::zemax_text, "zemax-text", "Zemax text source file", sniff_zemax_text, open_zemax_text,
     create_zemax_text},
    {RayFormat::speos, "speos", "SPEOS binary ray file", sniff_speos, open_speos, create_speos},
};

const FormatEntry& entry(RayFormat format) {
    for (const auto& e : kFormats)
        if (e.format == format) return e;
    throw Error("internal error: unknown ray format");
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

}  // namespace

const char* to_string(RayFormat format) { return entry(format).name; }

std::optional<RayFormat> ray_format_from_name(const std::string& name) {
    std::string n = lower(name);
    for (const auto& e : kFormats)
        if (n == e.name) return e.format;
    // Unambiguous extensions only: ".ray" and ".txt" are used by several formats.
    if (n == ".tm25ray" || n == "tm25ray") return RayFormat::tm25;
    if (n == ".dat" || n == ".sdf") return RayFormat::zemax_binary;
    if (n == ".csv") return RayFormat::csv;
    return std::nullopt;
}

RayFormat detect_ray_format(const std::string& path) {
    Head head = read_head(path, 4096);
    uint64_t size = file_size(path);
    if (size == 0) fail(path, "the file is empty");
    for (const auto& e : kFormats)
        if (e.sniff(head, size)) return e.format;
    fail(path, "not a ray file of a known format: no TM-25 ('TM25') or LightTools ('LTRF', '# LightTools') "
               "magic, no Zemax identifier 1010, not SPEOS (28-byte header + 32-byte records) nor rayset CSV "
               "('x,y,z,kx,ky,kz' header). If it is one of these, name it with --from.");
}

bool totals_agree(double stated, double sum) {
    return std::isfinite(stated) && std::abs(stated - sum) <= 1e-4 * std::max(std::abs(stated), std::abs(sum));
}

double total_to_write(double stated, double sum) { return totals_agree(stated, sum) ? stated : sum; }

size_t read_f32_records(BinaryInput& in, size_t columns, uint64_t count, size_t max_rays, uint64_t& next,
                        std::vector<float>& records, RayChunk& chunk) {
    chunk.clear();
    chunk.first_index = next;
    if (next >= count) return 0;
    const size_t n = static_cast<size_t>(std::min<uint64_t>(std::max<size_t>(max_rays, 1), count - next));
    records.resize(n * columns);
    in.read(records.data(), records.size() * sizeof(float), "a ray record");
    chunk.rays.resize(n);
    next += n;
    return n;
}

// ---------------------------------------------------------------------------------------------
namespace {

struct Sums {
    double radiant = 0, luminous = 0;
};

Sums sum_fluxes(RayDecoder& decoder, size_t chunk_size) {
    Sums sums;
    RayChunk chunk;
    while (decoder.read(chunk, chunk_size))
        for (const Ray& r : chunk.rays) {
            // Invalid values are reported with their location by the validating pass.
            if (std::isfinite(r.radiant)) sums.radiant += r.radiant;
            if (std::isfinite(r.luminous)) sums.luminous += r.luminous;
        }
    return sums;
}

}  // namespace

RayReader::RayReader(std::unique_ptr<RayDecoder> decoder, std::string path, RayReadOptions options)
    : decoder_(std::move(decoder)), path_(std::move(path)), options_(options) {
    header_ = decoder_->header();
    options_.chunk_size = std::max<size_t>(options_.chunk_size, 1);
}

RayReader::~RayReader() = default;

std::unique_ptr<RayReader> open_rays(const std::string& path, const RayReadOptions& options) {
    RayFormat format = options.format ? *options.format : detect_ray_format(path);
    const FormatEntry& e = entry(format);
    auto decoder = e.open(path);
    const bool relative = decoder->flux_is_relative();
    FluxPolicy policy = options.flux_policy;
    if (policy == FluxPolicy::format_default) policy = relative ? FluxPolicy::stated : FluxPolicy::rays;

    std::vector<std::string> notes;
    double radiant_scale = 1, luminous_scale = 1;
    RayHeader header = decoder->header();
    if (policy == FluxPolicy::stated) {
        // A first pass sums the rays so that they can be scaled while streaming the second.
        Sums sums = sum_fluxes(*decoder, options.chunk_size);
        decoder = e.open(path);
        auto decide = [&](bool present, double stated, double sum, const char* what, const char* unit) {
            if (!present) return 1.0;
            if (!(std::isfinite(stated) && stated > 0)) {
                if (!relative)
                    notes.push_back(fmt::format("{}: the header states no {} total; the rays' own fluxes are used", path, what));
                return 1.0;
            }
            if (sum <= 0 || totals_agree(stated, sum)) return 1.0;
            if (!relative)
                notes.push_back(fmt::format("{}: the rays' {} flux sums to {:.7g} {} but the header states {:.7g} {}: "
                                            "rays scaled to the header (--trust rays keeps them as they are)",
                                            path, what, sum, unit, stated, unit));
            return stated / sum;
        };
        radiant_scale = decide(header.has_radiant, header.stated_radiant, sums.radiant, "radiant", "W");
        luminous_scale = decide(header.has_luminous, header.stated_luminous, sums.luminous, "luminous", "lm");
        if (header.has_radiant && radiant_scale != 1) header.stated_radiant = sums.radiant * radiant_scale;
        if (header.has_luminous && luminous_scale != 1) header.stated_luminous = sums.luminous * luminous_scale;
    }
    auto reader = std::make_unique<RayReader>(std::move(decoder), path, options);
    reader->header_ = header;
    reader->radiant_scale_ = radiant_scale;
    reader->luminous_scale_ = luminous_scale;
    reader->warnings_ = std::move(notes);
    reader->options_.flux_policy = policy;
    return reader;
}

double RayReader::progress() const {
    uint64_t n = header_.ray_count;
    return n ? std::min(1.0, double(totals_.rays) / double(n)) : 0.0;
}

bool RayReader::read(RayChunk& chunk) {
    if (!decoder_->read(chunk, options_.chunk_size)) {
        // End of the rays: checks that need all of them.
        if (totals_.rays == 0) fail(path_, "the file holds no rays");
        const bool no_light = (!header_.has_radiant || totals_.radiant <= 0) && (!header_.has_luminous || totals_.luminous <= 0);
        if (no_light) fail(path_, "every ray has zero flux: the file carries no light");
        if (totals_.zero_flux_rays)
            warnings_.push_back(fmt::format("{}: {} of {} rays have zero flux (kept; they carry no light)", path_,
                                            totals_.zero_flux_rays, totals_.rays));
        if (options_.flux_policy == FluxPolicy::rays) {
            auto check = [&](bool present, double stated, double sum, const char* what, const char* unit) {
                if (present && std::isfinite(stated) && stated > 0 && !totals_agree(stated, sum))
                    warnings_.push_back(fmt::format("{}: the rays' {} flux sums to {:.7g} {} but the header states {:.7g} {}: "
                                                    "the rays are used (--trust header scales them to the header)",
                                                    path_, what, sum, unit, stated, unit));
            };
            check(header_.has_radiant, header_.stated_radiant, totals_.radiant, "radiant", "W");
            check(header_.has_luminous, header_.stated_luminous, totals_.luminous, "luminous", "lm");
        }
        return false;
    }
    validate(chunk);
    return true;
}

namespace {
// One comparison chain per value: false for NaN and infinities as well as out-of-range values.
inline bool finite_float(float v) { return std::abs(v) <= std::numeric_limits<float>::max(); }
inline bool flux_ok(float v) { return v >= 0 && v <= std::numeric_limits<float>::max(); }
}  // namespace

void RayReader::validate(RayChunk& chunk) {
    const double tolerance = options_.direction_tolerance;
    // |d| within [1 - tol, 1 + tol] as a test on |d|^2, which needs no square root per ray.
    const float min_length2 = float((1 - tolerance) * (1 - tolerance)), max_length2 = float((1 + tolerance) * (1 + tolerance));
    const bool radiant = header_.has_radiant, luminous = header_.has_luminous;
    const bool per_ray_table = header_.spectral == SpectralKind::per_ray_table;
    const int32_t tables = static_cast<int32_t>(header_.spectral_tables.size());
    const float radiant_scale = float(radiant_scale_), luminous_scale = float(luminous_scale_);
    double radiant_sum = 0, luminous_sum = 0;
    for (size_t i = 0; i < chunk.rays.size(); ++i) {
        Ray& r = chunk.rays[i];
        const Vec3f& d = r.direction;
        const float length2 = d.x * d.x + d.y * d.y + d.z * d.z;
        bool ok = finite_float(r.origin.x) && finite_float(r.origin.y) && finite_float(r.origin.z) &&
                  length2 >= min_length2 && length2 <= max_length2 && (!radiant || flux_ok(r.radiant)) &&
                  (!luminous || flux_ok(r.luminous)) && (std::isnan(r.wavelength) || flux_ok(r.wavelength)) &&
                  (!per_ray_table || (r.spectrum >= 0 && r.spectrum < tables));
        if (!ok) check_ray(chunk, i);  // throws, or normalises an accepted direction
        bool zero = true;
        if (radiant) {
            if (radiant_scale != 1) r.radiant = float(double(r.radiant) * radiant_scale_);
            radiant_sum += r.radiant;
            zero = r.radiant == 0;
        }
        if (luminous) {
            if (luminous_scale != 1) r.luminous = float(double(r.luminous) * luminous_scale_);
            luminous_sum += r.luminous;
            zero = zero && r.luminous == 0;
        }
        totals_.zero_flux_rays += zero;
    }
    totals_.radiant += radiant_sum;
    totals_.luminous += luminous_sum;
    totals_.rays += chunk.rays.size();
}

// The slow path for a ray the fast test did not pass: says exactly what is wrong, or (for a
// direction the user allowed with --normalise) fixes it.
void RayReader::check_ray(RayChunk& chunk, size_t i) {
    Ray& r = chunk.rays[i];
    auto bad = [&](const std::string& what) {
        uint64_t index = chunk.first_index + i;
        fail(path_, decoder_->locate(index), fmt::format("ray {}: {}", index + 1, what));
    };
    if (!finite_float(r.origin.x) || !finite_float(r.origin.y) || !finite_float(r.origin.z))
        bad(fmt::format("origin ({}, {}, {}) is not a finite number", r.origin.x, r.origin.y, r.origin.z));
    const Vec3f& d = r.direction;
    if (!finite_float(d.x) || !finite_float(d.y) || !finite_float(d.z))
        bad(fmt::format("direction ({}, {}, {}) is not a finite number", d.x, d.y, d.z));
    if (header_.has_radiant && !flux_ok(r.radiant)) bad(fmt::format("radiant flux {} is not a non-negative number", r.radiant));
    if (header_.has_luminous && !flux_ok(r.luminous)) bad(fmt::format("luminous flux {} is not a non-negative number", r.luminous));
    // NaN means "unknown wavelength" in real files; anything else must be a wavelength.
    if (!std::isnan(r.wavelength) && !(r.wavelength > 0 && finite_float(r.wavelength)))
        bad(fmt::format("wavelength {} nm is not a positive number (NaN would mean unknown)", r.wavelength));
    const size_t tables = header_.spectral_tables.size();
    if (header_.spectral == SpectralKind::per_ray_table && (r.spectrum < 0 || size_t(r.spectrum) >= tables))
        bad(fmt::format("spectrum index {} is outside the file's {} spectral tables", r.spectrum + 1, tables));
    const double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
    if (std::abs(length - 1) > options_.direction_tolerance) {
        if (!options_.normalise_directions || length == 0)
            bad(fmt::format("direction ({}, {}, {}) has length {:.6g}, not 1{}", d.x, d.y, d.z, length,
                            length == 0 ? "" : " (--normalise accepts and renormalises such directions)"));
        r.direction = {float(d.x / length), float(d.y / length), float(d.z / length)};
    }
}

std::unique_ptr<RayEncoder> create_rays(const std::string& path, RayFormat format, const RayHeader& header) {
    return entry(format).create(path, header);
}

void copy_rays(RayReader& in, RayEncoder& out, const std::function<void(double)>& progress) {
    RayChunk chunk;
    while (in.read(chunk)) {
        out.write(chunk);
        if (progress) progress(in.progress());
    }
    out.finish();
}

}  // namespace rayset
