#include "converters/rays/ray_stream.h"

#include "converters/formats/codecs.h"
#include "converters/rays/io.h"

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <cmath>
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
    {RayFormat::lighttools_binary, "lighttools", "LightTools binary ray data (LTRF)",
     sniff_lighttools_binary, open_lighttools_binary, create_lighttools_binary},
    {RayFormat::lighttools_text, "lighttools-text", "LightTools text ray data",
     sniff_lighttools_text, open_lighttools_text, create_lighttools_text},
    {RayFormat::zemax_binary, "zemax", "Zemax binary source file (.DAT/.SDF)", sniff_zemax_binary,
     open_zemax_binary, create_zemax_binary},
    {RayFormat::csv, "csv", "CSV rays (rayset)", sniff_csv, open_csv, create_csv},
    {RayFormat::zemax_text, "zemax-text", "Zemax text source file", sniff_zemax_text,
     open_zemax_text, create_zemax_text},
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
    // Text formats saved as UTF-16 or UTF-32 (TextInput reads them as UTF-8).
    const std::string_view raw(reinterpret_cast<const char*>(head.data()), head.size());
    if (code_unit_bytes(text_start(raw).encoding) > 1) {
        const std::string text = text_head_as_utf8(raw);
        const Head utf8(text.begin(), text.end());
        for (const auto& e : kFormats)
            if (e.sniff(utf8, size)) return e.format;
    }
    fail(path,
         "not a ray file of a known format: no TM-25 ('TM25') or LightTools ('LTRF', '# "
         "LightTools') "
         "magic, no Zemax identifier 1010, not SPEOS (28-byte header + 32-byte records) nor rayset "
         "CSV "
         "('x,y,z,kx,ky,kz' header). If it is one of these, name it with --from.");
}

bool totals_agree(double stated, double sum) {
    return std::isfinite(stated) &&
           std::abs(stated - sum) <= 1e-4 * std::max(std::abs(stated), std::abs(sum));
}

double total_to_write(double stated, double sum) {
    return totals_agree(stated, sum) ? stated : sum;
}

size_t read_f32_records(BinaryInput& in, size_t columns, uint64_t count, size_t max_rays,
                        uint64_t& next, std::vector<float>& records, RayColumns& chunk) {
    chunk.clear();
    chunk.first_index = next;
    if (next >= count) return 0;
    const size_t n =
        static_cast<size_t>(std::min<uint64_t>(std::max<size_t>(max_rays, 1), count - next));
    records.resize(n * columns);
    in.read(records.data(), records.size() * sizeof(float), "a ray record");
    chunk.resize(n);
    next += n;
    return n;
}

bool RayDecoder::read(RayChunk& chunk, size_t max_rays) {
    const bool more = decode(scratch_, max_rays);
    scratch_.to_rays(chunk);
    return more;
}

// ---------------------------------------------------------------------------------------------
namespace {

struct Sums {
    double radiant = 0, luminous = 0;
};

Sums sum_fluxes(RayDecoder& decoder, size_t chunk_size) {
    Sums sums;
    RayColumns chunk;
    while (decoder.decode(chunk, chunk_size))
        for (size_t i = 0; i < chunk.size(); ++i) {
            // Invalid values are reported with their location by the validating pass.
            if (std::isfinite(chunk.radiant[i])) sums.radiant += chunk.radiant[i];
            if (std::isfinite(chunk.luminous[i])) sums.luminous += chunk.luminous[i];
        }
    return sums;
}

}  // namespace

std::unique_ptr<RayReader> open_rays(const std::string& path, const RayReadOptions& options) {
    RayFormat format = options.format ? *options.format : detect_ray_format(path);
    const FormatEntry& e = entry(format);
    auto decoder = e.open(path);
    const bool relative = decoder->flux_is_relative();
    FluxPolicy policy = options.flux_policy;
    if (policy == FluxPolicy::format_default)
        policy = relative ? FluxPolicy::stated : FluxPolicy::rays;

    std::vector<std::string> notes;
    double radiant_scale = 1, luminous_scale = 1;
    RayHeader header = decoder->header();
    if (policy == FluxPolicy::stated) {
        // A first pass sums the rays so that they can be scaled while streaming the second.
        Sums sums = sum_fluxes(*decoder, options.chunk_size);
        decoder = e.open(path);
        auto decide = [&](bool present, double stated, double sum, const char* what,
                          const char* unit) {
            if (!present) return 1.0;
            if (!(std::isfinite(stated) && stated > 0)) {
                if (!relative)
                    notes.push_back(fmt::format(
                        "{}: the header states no {} total; the rays' own fluxes are used", path,
                        what));
                return 1.0;
            }
            if (sum <= 0 || totals_agree(stated, sum)) return 1.0;
            if (!relative)
                notes.push_back(fmt::format(
                    "{}: the rays' {} flux sums to {:.7g} {} but the header states {:.7g} {}: "
                    "rays scaled to the header (--trust rays keeps them as they are)",
                    path, what, sum, unit, stated, unit));
            return stated / sum;
        };
        radiant_scale =
            decide(header.has_radiant, header.stated_radiant, sums.radiant, "radiant", "W");
        luminous_scale =
            decide(header.has_luminous, header.stated_luminous, sums.luminous, "luminous", "lm");
        if (header.has_radiant && radiant_scale != 1)
            header.stated_radiant = sums.radiant * radiant_scale;
        if (header.has_luminous && luminous_scale != 1)
            header.stated_luminous = sums.luminous * luminous_scale;
    }
    auto reader = std::make_unique<RayReader>(std::move(decoder), path, options);
    reader->header_ = header;
    reader->radiant_scale_ = radiant_scale;
    reader->luminous_scale_ = luminous_scale;
    reader->warnings_ = std::move(notes);
    reader->options_.flux_policy = policy;
    reader->reopen_ = [open = e.open, path] { return open(path); };
    return reader;
}

std::unique_ptr<RayEncoder> create_rays(const std::string& path, RayFormat format,
                                        const RayHeader& header) {
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
