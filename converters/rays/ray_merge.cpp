// merge_rays: several ray files into one, under one header that describes every ray.
#include "converters/colour/spectrum.h"
#include "converters/rays/ray_ops.h"
#include "converters/rays/ray_ops_detail.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <memory>

namespace rayset {

namespace {

const char* spectral_name(SpectralKind kind) {
    switch (kind) {
        case SpectralKind::none: return "no spectral data";
        case SpectralKind::single_wavelength: return "a single wavelength";
        case SpectralKind::per_ray_wavelength: return "per-ray wavelengths";
        case SpectralKind::shared_table: return "a spectral table";
        case SpectralKind::per_ray_table: return "per-ray spectral tables";
    }
    return "?";
}

bool is_wavelength(SpectralKind k) {
    return k == SpectralKind::single_wavelength || k == SpectralKind::per_ray_wavelength;
}
bool is_table(SpectralKind k) {
    return k == SpectralKind::shared_table || k == SpectralKind::per_ray_table;
}

struct Source {
    std::string path;
    std::unique_ptr<RayReader> reader;
    std::unique_ptr<PhotometricWeights> weights;
    double length_scale = 1;
    std::vector<int32_t> table_map;  // the input's table index -> the output's
    std::vector<int> extra_from;     // per output extra: the input's index, -1 when it has none
    bool derive_radiant = false, derive_luminous = false;
    const RayHeader& header() const { return reader->header(); }
};

// Chooses the output's spectral description; fills each source's table map. Returns an empty
// string, or why the spectral data had to be dropped.
std::string plan_spectra(std::vector<Source>& sources, RayHeader& out) {
    const auto all = [&](bool (*test)(SpectralKind)) {
        return std::all_of(sources.begin(), sources.end(),
                           [&](const Source& s) { return test(s.header().spectral); });
    };
    out.spectral_tables.clear();
    out.single_wavelength = kUnknown;
    if (all([](SpectralKind k) { return k == SpectralKind::none; })) {
        out.spectral = SpectralKind::none;
    } else if (all(is_wavelength)) {
        const float first = sources[0].header().single_wavelength;
        const bool one_line = std::all_of(sources.begin(), sources.end(), [&](const Source& s) {
            return s.header().spectral == SpectralKind::single_wavelength &&
                   s.header().single_wavelength == first;
        });
        out.spectral =
            one_line ? SpectralKind::single_wavelength : SpectralKind::per_ray_wavelength;
        if (one_line) out.single_wavelength = first;
    } else if (all(is_table)) {
        bool all_shared = true;
        for (Source& s : sources) {
            all_shared = all_shared && s.header().spectral == SpectralKind::shared_table;
            for (const SpectralTable& t : s.header().spectral_tables) {
                auto same = [&](const SpectralTable& u) {
                    return u.wavelength == t.wavelength && u.weight == t.weight;
                };
                auto found =
                    std::find_if(out.spectral_tables.begin(), out.spectral_tables.end(), same);
                s.table_map.push_back(static_cast<int32_t>(found - out.spectral_tables.begin()));
                if (found == out.spectral_tables.end()) out.spectral_tables.push_back(t);
            }
        }
        out.spectral = all_shared && out.spectral_tables.size() == 1 ? SpectralKind::shared_table
                                                                     : SpectralKind::per_ray_table;
    } else {
        out.spectral = SpectralKind::none;
        std::string why = "spectral data dropped: one header cannot describe";
        for (size_t i = 0; i < sources.size(); ++i)
            why += fmt::format("{} {} ({})", i ? "," : "", sources[i].path,
                               spectral_name(sources[i].header().spectral));
        return why;
    }
    return {};
}

// Which flux columns every ray can carry; sets what each source derives. Returns warnings.
std::vector<std::string> plan_columns(std::vector<Source>& sources, RayHeader& out,
                                      bool spectrum_dropped) {
    bool any_radiant = false, any_luminous = false, all_radiant = true, all_luminous = true;
    for (const Source& s : sources) {
        any_radiant = any_radiant || s.header().has_radiant;
        any_luminous = any_luminous || s.header().has_luminous;
        all_radiant = all_radiant && s.weights->radiant_known();
        all_luminous = all_luminous && s.weights->luminous_known();
    }
    out.has_radiant = any_radiant && all_radiant;
    out.has_luminous = all_luminous && (any_luminous || spectrum_dropped);
    std::vector<std::string> notes;
    auto columns = [](const RayHeader& h) {
        return std::string(h.has_radiant && h.has_luminous ? "radiant and luminous flux"
                           : h.has_radiant                 ? "radiant flux"
                                                           : "luminous flux") +
               (h.spectral == SpectralKind::none
                    ? " without spectral data"
                    : " with " + std::string(spectral_name(h.spectral)));
    };
    if (!out.has_radiant && !out.has_luminous) {
        std::string what;
        for (const Source& s : sources)
            what += fmt::format("; {} carries {}", s.path, columns(s.header()));
        fail(sources[0].path,
             "cannot merge: no flux column (radiant or luminous) is known for every input" + what);
    }
    for (Source& s : sources) {
        const RayHeader& h = s.header();
        s.derive_radiant = out.has_radiant && !h.has_radiant;
        s.derive_luminous = out.has_luminous && !h.has_luminous;
        if (h.has_radiant && !out.has_radiant)
            notes.push_back(fmt::format(
                "radiant flux of {} dropped: not every input carries it or can derive it", s.path));
        if (h.has_luminous && !out.has_luminous)
            notes.push_back(fmt::format(
                "luminous flux of {} dropped: not every input carries it or can derive it",
                s.path));
    }
    return notes;
}

// The union of the inputs' extra columns, by kind (TM-25's own) or label (additional ones).
std::vector<std::string> plan_extras(std::vector<Source>& sources, RayHeader& out) {
    auto same = [](const ExtraColumn& a, const ExtraColumn& b) {
        return a.kind == b.kind && (a.kind != ExtraKind::additional || a.label == b.label);
    };
    out.extras.clear();
    for (const Source& s : sources)
        for (const ExtraColumn& e : s.header().extras)
            if (std::none_of(out.extras.begin(), out.extras.end(),
                             [&](const ExtraColumn& o) { return same(o, e); }))
                out.extras.push_back(e);
    std::vector<std::string> notes;
    for (Source& s : sources) {
        const auto& mine = s.header().extras;
        for (const ExtraColumn& o : out.extras) {
            auto found = std::find_if(mine.begin(), mine.end(),
                                      [&](const ExtraColumn& e) { return same(o, e); });
            s.extra_from.push_back(found == mine.end() ? -1
                                                       : static_cast<int>(found - mine.begin()));
            if (found == mine.end())
                notes.push_back(
                    fmt::format("{} has no extra column '{}': NaN written there for its rays",
                                s.path, o.label));
        }
    }
    return notes;
}

Vec3f scaled(const Vec3f& v, double k) { return {float(v.x * k), float(v.y * k), float(v.z * k)}; }

bool nearly_equal(const Vec3f& a, const Vec3f& b) {
    auto near = [](float x, float y) {
        return std::abs(x - y) <= 1e-6f * std::max({1.0f, std::abs(x), std::abs(y)});
    };
    return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z);
}

// Rewrites one input chunk into the output's terms.
void convert(const Source& s, const RayHeader& out, const RayChunk& in, RayChunk& chunk) {
    const RayHeader& h = s.header();
    const size_t in_extras = h.extras.size(), out_extras = out.extras.size();
    chunk.rays = in.rays;
    chunk.extra.assign(in.rays.size() * out_extras, kUnknown);
    for (size_t i = 0; i < chunk.rays.size(); ++i) {
        Ray& r = chunk.rays[i];
        auto underivable = [&](const char* what) {
            fail(s.path,
                 fmt::format("ray {}: its {} flux cannot be derived from its spectrum ({}), so the "
                             "merged file "
                             "cannot carry {} flux for every ray",
                             in.first_index + i + 1, what,
                             std::isnan(r.wavelength) ? "unknown wavelength" : "no light", what));
        };
        if (s.length_scale != 1) r.origin = scaled(r.origin, s.length_scale);
        if (s.derive_radiant && !std::isfinite(r.radiant = float(s.weights->radiant(r))))
            underivable("radiant");
        if (s.derive_luminous && !std::isfinite(r.luminous = float(s.weights->luminous(r))))
            underivable("luminous");
        if (!out.has_radiant) r.radiant = kUnknown;
        if (!out.has_luminous) r.luminous = kUnknown;
        switch (out.spectral) {
            case SpectralKind::per_ray_wavelength:
                if (h.spectral == SpectralKind::single_wavelength)
                    r.wavelength = h.single_wavelength;
                break;
            case SpectralKind::per_ray_table:
                r.spectrum = s.table_map[h.spectral == SpectralKind::shared_table ? 0 : r.spectrum];
                break;
            default: r.wavelength = kUnknown; r.spectrum = -1;
        }
        for (size_t e = 0; e < out_extras; ++e)
            if (s.extra_from[e] >= 0)
                chunk.extra[i * out_extras + e] = in.extra[i * in_extras + s.extra_from[e]];
    }
}

std::vector<Source> open_sources(const std::vector<std::string>& inputs,
                                 const RayReadOptions& read) {
    std::vector<Source> sources;
    for (const std::string& path : inputs) {
        Source s;
        s.path = path;
        s.reader = open_rays(path, read);
        s.weights = std::make_unique<PhotometricWeights>(s.reader->header());
        sources.push_back(std::move(s));
    }
    return sources;
}

// The output's unit and ray count; each source's scale to that unit. Origins of far-field rays
// mean nothing, so they cannot share a file with near-field ones.
void plan_units(std::vector<Source>& sources, RayHeader& out) {
    const bool far_field = sources[0].header().far_field;
    out.ray_count = 0;
    for (Source& s : sources) {
        s.length_scale = millimetres_per(s.header().unit) / millimetres_per(out.unit);
        out.ray_count += s.header().ray_count;
        if (s.header().far_field != far_field)
            fail(s.path,
                 fmt::format("cannot merge far-field rays (whose origins mean nothing) with "
                             "near-field rays: {} is {}far-field, {} is {}far-field",
                             sources[0].path, far_field ? "" : "not ", s.path,
                             far_field ? "not " : ""));
    }
}

// The wavelength range spanning every input's.
void plan_wavelength_range(const std::vector<Source>& sources, RayHeader& out) {
    out.min_wavelength = out.max_wavelength = kUnknown;
    if (out.spectral == SpectralKind::none) return;
    for (const Source& s : sources) {
        const RayHeader& h = s.header();
        for (float w : {h.min_wavelength, h.max_wavelength, h.single_wavelength}) {
            if (std::isnan(w)) continue;
            if (!(out.min_wavelength <= w)) out.min_wavelength = w;
            if (!(out.max_wavelength >= w)) out.max_wavelength = w;
        }
    }
}

// Totals add; a derived column has no stated total, so the writer sums the rays instead.
void plan_totals(const std::vector<Source>& sources, RayHeader& out) {
    double radiant = 0, luminous = 0;
    for (const Source& s : sources) {
        radiant += s.derive_radiant ? std::nan("") : s.header().stated_radiant;
        luminous += s.derive_luminous ? std::nan("") : s.header().stated_luminous;
    }
    out.stated_radiant = out.has_radiant ? radiant : std::nan("");
    out.stated_luminous = out.has_luminous ? luminous : std::nan("");
}

// The first input's data origin and placement are kept; returns a warning for each input whose
// own differ.
std::vector<std::string> plan_placement(const std::vector<Source>& sources, RayHeader& out) {
    const RayHeader& first = sources[0].header();
    out.data_origin = scaled(first.data_origin, sources[0].length_scale);
    out.placement.location = scaled(first.placement.location, sources[0].length_scale);
    std::vector<std::string> notes;
    for (size_t i = 1; i < sources.size(); ++i) {
        const RayHeader& h = sources[i].header();
        const double k = sources[i].length_scale;
        const SourcePlacement& p = h.placement;
        if (!nearly_equal(scaled(h.data_origin, k), out.data_origin) ||
            !nearly_equal(scaled(p.location, k), out.placement.location) ||
            !nearly_equal(p.rotation_rad, first.placement.rotation_rad) ||
            !nearly_equal(p.scale, first.placement.scale))
            notes.push_back(fmt::format(
                "{} has another data origin or placement than {}; the first one's is kept",
                sources[i].path, sources[0].path));
    }
    return notes;
}

// Writes every input's rays in order, converted to the output's terms.
void write_merged(std::vector<Source>& sources, const std::string& output, RayFormat format,
                  RayOpReport& report, const Progress& progress) {
    const RayHeader& out = report.header;
    auto writer = create_rays(output, format, out);
    double done = 0;
    const double total_rays = std::max<double>(1, double(out.ray_count));
    RayChunk in, chunk;
    for (Source& s : sources) {
        while (s.reader->read(in)) {
            convert(s, out, in, chunk);
            chunk.first_index = report.totals.rays;
            writer->write(chunk);
            detail::add_totals(report.totals, out, chunk);
            if (progress)
                progress((done + s.reader->progress() * double(s.header().ray_count)) / total_rays);
        }
        done += double(s.header().ray_count);
        for (const std::string& w : s.reader->warnings()) report.warnings.push_back(w);
    }
    writer->finish();
    report.dropped = writer->dropped();
}

void append(std::vector<std::string>& to, std::vector<std::string> notes) {
    for (std::string& note : notes) to.push_back(std::move(note));
}

}  // namespace

RayOpReport merge_rays(const std::vector<std::string>& inputs, const std::string& output,
                       RayFormat format, const MergeOptions& options, const RayReadOptions& read,
                       const Progress& progress) {
    if (inputs.empty()) throw Error("merge: no input files given");
    std::vector<Source> sources = open_sources(inputs, read);
    RayOpReport report;
    RayHeader& out = report.header;
    out = sources[0].header();
    out.unit = options.unit.value_or(out.unit);
    plan_units(sources, out);
    const std::string spectrum_dropped = plan_spectra(sources, out);
    if (!spectrum_dropped.empty()) report.warnings.push_back(spectrum_dropped);
    append(report.warnings, plan_columns(sources, out, !spectrum_dropped.empty()));
    append(report.warnings, plan_extras(sources, out));
    plan_wavelength_range(sources, out);
    plan_totals(sources, out);
    append(report.warnings, plan_placement(sources, out));
    write_merged(sources, output, format, report, progress);
    return report;
}

}  // namespace rayset
