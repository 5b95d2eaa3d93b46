// Ray files to and from numpy: a whole file through RayReader::read_in_parts (columns copied
// straight into preallocated arrays by the threads that read them), a file in chunks through
// RayReader::read, and any format the encoders write. The package's rayset/rays.py gives
// these a class of their own (Rays) and its header a dict.
#include "arrays.h"

#include <nanobind/stl/filesystem.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>

#include "converters/rays/ray_names.h"
#include "converters/rays/ray_stream.h"
#include "core/error.h"

namespace rayset::python {

namespace {

SpectralKind spectral_kind_named(const std::string& name) {
    std::string known;
    for (size_t i = 0; i < std::size(kSpectralNames); ++i) {
        if (name == kSpectralNames[i]) return SpectralKind(i);
        known += (known.empty() ? "" : ", ") + std::string(kSpectralNames[i]);
    }
    throw nb::value_error(fmt::format("unknown spectral kind '{}' ({})", name, known).c_str());
}

// The named extra kinds, and "additional" for a column that is none of them.
constexpr std::string_view kAdditional = "additional";
std::string_view extra_kind_name(ExtraKind kind) {
    for (const NamedExtra& e : kNamedExtras)
        if (e.kind == kind) return e.name;
    return kAdditional;
}
ExtraKind extra_kind_named(const std::string& name) {
    std::string known;
    for (const NamedExtra& e : kNamedExtras) {
        if (name == e.name) return e.kind;
        known += std::string(e.name) + ", ";
    }
    if (name == kAdditional) return ExtraKind::additional;
    throw nb::value_error(
        fmt::format("unknown extra kind '{}' ({}{})", name, known, kAdditional).c_str());
}

RayFormat format_named(const std::string& name) {
    if (auto format = ray_format_from_name(name)) return *format;
    throw nb::value_error(fmt::format("unknown ray format '{}' (tm25, lighttools, "
                                      "lighttools-text, zemax, zemax-text, speos, csv)",
                                      name)
                              .c_str());
}

RayReadOptions read_options(const std::optional<std::string>& format, const std::string& trust,
                            bool normalise, double tolerance, size_t chunk_size) {
    RayReadOptions o;
    if (format) o.format = format_named(*format);
    if (trust == "header")
        o.flux_policy = FluxPolicy::stated;
    else if (trust == "rays")
        o.flux_policy = FluxPolicy::rays;
    else if (!trust.empty() && trust != "default")
        throw nb::value_error("trust must be 'header', 'rays' or None");
    o.normalise_directions = normalise;
    o.direction_tolerance = float(tolerance);
    o.chunk_size = std::max<size_t>(chunk_size, 1);
    return o;
}

nb::tuple vec3(const Vec3f& v) { return nb::make_tuple(v.x, v.y, v.z); }
Vec3f vec3f(nb::handle h) {
    auto v = nb::cast<std::vector<float>>(h);
    if (v.size() != 3) throw nb::value_error("expected three numbers");
    return {v[0], v[1], v[2]};
}

nb::dict header_dict(const RayHeader& h) {
    nb::dict d;
    d["format"] = to_string(h.format);
    d["unit"] = to_string(h.unit);
    d["ray_count"] = h.ray_count;
    d["has_radiant"] = h.has_radiant;
    d["has_luminous"] = h.has_luminous;
    d["stated_radiant"] = h.stated_radiant;
    d["stated_luminous"] = h.stated_luminous;
    d["ray_set_flux"] = h.ray_set_flux;
    d["spectral"] = std::string(kSpectralNames[int(h.spectral)]);
    d["single_wavelength"] = h.single_wavelength;
    d["min_wavelength"] = h.min_wavelength;
    d["max_wavelength"] = h.max_wavelength;
    nb::list tables;
    for (const SpectralTable& t : h.spectral_tables)
        tables.append(nb::make_tuple(to_array(t.wavelength), to_array(t.weight)));
    d["spectral_tables"] = tables;
    nb::list extras;
    for (const ExtraColumn& e : h.extras)
        extras.append(nb::make_tuple(std::string(extra_kind_name(e.kind)), e.label));
    d["extras"] = extras;
    d["creation_method"] = h.creation_method;
    d["creation_date"] = h.creation_date;
    d["text"] = std::vector<std::string>(h.text.begin(), h.text.end());
    d["additional_text"] = h.additional_text;
    d["description"] = h.description;
    d["far_field"] = h.far_field;
    d["data_origin"] = vec3(h.data_origin);
    nb::dict placement;
    placement["location"] = vec3(h.placement.location);
    placement["rotation_rad"] = vec3(h.placement.rotation_rad);
    placement["scale"] = vec3(h.placement.scale);
    const auto& ia = h.placement.inclination_azimuth_deg;
    placement["inclination_azimuth_deg"] = nb::make_tuple(ia[0], ia[1], ia[2], ia[3]);
    d["placement"] = placement;
    return d;
}

// The keys header_dict writes; a key left out keeps RayHeader's default.
RayHeader header_from(const nb::dict& d) {
    RayHeader h;
    auto has = [&](const char* key) { return d.contains(key) && !d[key].is_none(); };
    auto number = [&](const char* key, double fallback) {
        return has(key) ? nb::cast<double>(d[key]) : fallback;
    };
    if (has("unit")) {
        const std::string unit = nb::cast<std::string>(d["unit"]);
        const auto* found = std::find_if(std::begin(kUnits), std::end(kUnits), [&](LengthUnit u) {
            return unit == to_string(u) || (unit == "inch" && u == LengthUnit::inch);
        });
        if (found == std::end(kUnits))
            throw nb::value_error(
                fmt::format("unknown unit '{}' (mm, cm, m, in, ft, um, nm)", unit).c_str());
        h.unit = *found;
    }
    if (has("ray_count")) h.ray_count = nb::cast<uint64_t>(d["ray_count"]);
    if (has("has_radiant")) h.has_radiant = nb::cast<bool>(d["has_radiant"]);
    if (has("has_luminous")) h.has_luminous = nb::cast<bool>(d["has_luminous"]);
    h.stated_radiant = number("stated_radiant", h.stated_radiant);
    h.stated_luminous = number("stated_luminous", h.stated_luminous);
    h.ray_set_flux = number("ray_set_flux", h.ray_set_flux);
    if (has("spectral")) h.spectral = spectral_kind_named(nb::cast<std::string>(d["spectral"]));
    h.single_wavelength = float(number("single_wavelength", h.single_wavelength));
    h.min_wavelength = float(number("min_wavelength", h.min_wavelength));
    h.max_wavelength = float(number("max_wavelength", h.max_wavelength));
    if (has("spectral_tables"))
        for (nb::handle table : nb::cast<nb::list>(d["spectral_tables"])) {
            nb::object pair = nb::borrow(table);
            if (nb::len(pair) != 2)
                throw nb::value_error("a spectral table is a pair (wavelength, weight)");
            SpectralTable t{nb::cast<std::vector<float>>(nb::list(pair[0])),
                            nb::cast<std::vector<float>>(nb::list(pair[1]))};
            h.spectral_tables.push_back(std::move(t));
        }
    if (has("extras"))
        for (nb::handle extra : nb::cast<nb::list>(d["extras"])) {
            nb::object pair = nb::borrow(extra);
            if (nb::len(pair) != 2)
                throw nb::value_error("an extra column is a pair (kind, label)");
            h.extras.push_back(
                {extra_kind_named(nb::cast<std::string>(pair[0])), nb::cast<std::string>(pair[1])});
        }
    if (has("creation_method")) h.creation_method = nb::cast<int32_t>(d["creation_method"]);
    if (has("creation_date")) h.creation_date = nb::cast<std::string>(d["creation_date"]);
    if (has("text")) {
        auto text = nb::cast<std::vector<std::string>>(d["text"]);
        if (text.size() > h.text.size()) throw nb::value_error("text holds at most nine fields");
        std::copy(text.begin(), text.end(), h.text.begin());
    }
    if (has("additional_text")) h.additional_text = nb::cast<std::string>(d["additional_text"]);
    if (has("description")) h.description = nb::cast<std::string>(d["description"]);
    if (has("far_field")) h.far_field = nb::cast<bool>(d["far_field"]);
    if (has("data_origin")) h.data_origin = vec3f(d["data_origin"]);
    if (has("placement")) {
        nb::dict p = nb::cast<nb::dict>(d["placement"]);
        if (p.contains("location")) h.placement.location = vec3f(p["location"]);
        if (p.contains("rotation_rad")) h.placement.rotation_rad = vec3f(p["rotation_rad"]);
        if (p.contains("scale")) h.placement.scale = vec3f(p["scale"]);
        if (p.contains("inclination_azimuth_deg")) {
            auto ia = nb::cast<std::vector<float>>(p["inclination_azimuth_deg"]);
            if (ia.size() != 4) throw nb::value_error("inclination_azimuth_deg holds four angles");
            std::copy(ia.begin(), ia.end(), h.placement.inclination_azimuth_deg.begin());
        }
    }
    return h;
}

nb::dict totals_dict(const RayTotals& t) {
    nb::dict d;
    d["radiant"] = t.radiant;
    d["luminous"] = t.luminous;
    d["rays"] = t.rays;
    d["zero_flux_rays"] = t.zero_flux_rays;
    return d;
}

// Arrays for `rows` rays: what read_rays and RayFile::read return, filled without the GIL.
// A column the header says the file does not carry holds NaN (spectrum -1) in every ray
// (ray.h): it is not copied, and the package stands a constant view in for it.
struct RayArrays {
    bool radiant_read, luminous_read, wavelength_read, spectrum_read;
    size_t extras;
    NewArray<float> origin, direction, radiant, luminous, wavelength, extra;
    NewArray<int32_t> spectrum;

    // Every row is filled (the callers check the count), so the memory is not zeroed first.
    RayArrays(size_t rows, const RayHeader& h)
        : radiant_read(h.has_radiant),
          luminous_read(h.has_luminous),
          wavelength_read(h.spectral == SpectralKind::per_ray_wavelength),
          spectrum_read(h.spectral == SpectralKind::shared_table ||
                        h.spectral == SpectralKind::per_ray_table),
          extras(h.extras.size()),
          origin({rows, 3}, false),
          direction({rows, 3}, false),
          radiant({radiant_read ? rows : 0}, false),
          luminous({luminous_read ? rows : 0}, false),
          wavelength({wavelength_read ? rows : 0}, false),
          extra({rows, extras}, false),
          spectrum({spectrum_read ? rows : 0}, false) {}

    // Rays columns[0, n) at row `at`.
    void put(const RayColumns& c, size_t n, size_t at) {
        for (size_t i = 0; i < n; ++i) {
            float* o = origin.data + 3 * (at + i);
            float* d = direction.data + 3 * (at + i);
            o[0] = c.ox[i], o[1] = c.oy[i], o[2] = c.oz[i];
            d[0] = c.dx[i], d[1] = c.dy[i], d[2] = c.dz[i];
        }
        if (radiant_read) std::memcpy(radiant.data + at, c.radiant.data(), n * sizeof(float));
        if (luminous_read) std::memcpy(luminous.data + at, c.luminous.data(), n * sizeof(float));
        if (wavelength_read)
            std::memcpy(wavelength.data + at, c.wavelength.data(), n * sizeof(float));
        if (spectrum_read) std::memcpy(spectrum.data + at, c.spectrum.data(), n * sizeof(int32_t));
        if (extras) std::memcpy(extra.data + at * extras, c.extra.data(), n * extras * 4);
    }
    // Rays chunk.rays[first, first + n) at row `at`.
    void put(const RayChunk& chunk, size_t first, size_t n, size_t at) {
        for (size_t i = 0; i < n; ++i) {
            const Ray& r = chunk.rays[first + i];
            const size_t row = at + i;
            float* o = origin.data + 3 * row;
            float* d = direction.data + 3 * row;
            o[0] = r.origin.x, o[1] = r.origin.y, o[2] = r.origin.z;
            d[0] = r.direction.x, d[1] = r.direction.y, d[2] = r.direction.z;
            if (radiant_read) radiant.data[row] = r.radiant;
            if (luminous_read) luminous.data[row] = r.luminous;
            if (wavelength_read) wavelength.data[row] = r.wavelength;
            if (spectrum_read) spectrum.data[row] = r.spectrum;
        }
        if (extras)
            std::memcpy(extra.data + at * extras, chunk.extra.data() + first * extras,
                        n * extras * sizeof(float));
    }
    // Columns not read are None.
    nb::dict dict() const {
        nb::dict d;
        d["origin"] = origin.array, d["direction"] = direction.array;
        d["radiant"] = radiant_read ? nb::cast(radiant.array) : nb::none();
        d["luminous"] = luminous_read ? nb::cast(luminous.array) : nb::none();
        d["wavelength"] = wavelength_read ? nb::cast(wavelength.array) : nb::none();
        d["spectrum"] = spectrum_read ? nb::cast(spectrum.array) : nb::none();
        d["extra"] = extra.array;
        return d;
    }
};

nb::dict read_rays(const Path& file, const std::optional<std::string>& format,
                   const std::string& trust, bool normalise, double tolerance) {
    const RayReadOptions options = read_options(format, trust, normalise, tolerance, 1 << 12);
    const std::string path = file.string();
    std::unique_ptr<RayReader> reader;
    {
        nb::gil_scoped_release release;
        reader = open_rays(path, options);
    }
    const uint64_t rows = reader->header().ray_count;
    RayArrays arrays(size_t(rows), reader->header());
    {
        nb::gil_scoped_release release;
        // The parts cover disjoint ranges of rays, so their threads write disjoint rows.
        std::atomic<bool> overflow{false};
        reader->read_in_parts([&](size_t, const RayColumns& columns) {
            const size_t n = columns.size();
            if (columns.first_index + n > rows) {
                overflow = true;
                return;
            }
            arrays.put(columns, n, size_t(columns.first_index));
        });
        if (overflow || reader->totals().rays != rows)
            throw Error(fmt::format("{}: the header counts {} rays but {} were read", path, rows,
                                    reader->totals().rays));
    }
    nb::dict d = arrays.dict();
    d["header"] = header_dict(reader->header());
    d["file_header"] = header_dict(reader->file_header());
    d["totals"] = totals_dict(reader->totals());
    d["warnings"] = reader->warnings();
    return d;
}

// A file read in chunks of any size, in file order, in constant memory.
class RayFile {
public:
    RayFile(const Path& path, const std::optional<std::string>& format, const std::string& trust,
            bool normalise, double tolerance) {
        const RayReadOptions o = read_options(format, trust, normalise, tolerance, 1 << 14);
        nb::gil_scoped_release release;
        reader_ = open_rays(path.string(), o);
    }

    // The next up to `count` rays, or None after the last.
    std::optional<nb::dict> read(size_t count) {
        if (count == 0) throw nb::value_error("count must be positive");
        const uint64_t left = reader_->header().ray_count - position_;
        const size_t rows = size_t(std::min<uint64_t>(count, left));
        if (rows == 0) return std::nullopt;
        RayArrays arrays(rows, reader_->header());
        {
            nb::gil_scoped_release release;
            size_t filled = 0;
            while (filled < rows) {
                if (used_ == pending_.size()) {
                    used_ = 0;
                    if (!reader_->read(pending_))
                        throw Error(fmt::format("{}: the header counts {} rays but {} were read",
                                                reader_->path(), reader_->header().ray_count,
                                                position_ + filled));
                }
                const size_t n = std::min(rows - filled, pending_.size() - used_);
                arrays.put(pending_, used_, n, filled);
                used_ += n, filled += n;
            }
        }
        nb::dict d = arrays.dict();
        d["first_index"] = position_;
        position_ += rows;
        return d;
    }

    nb::dict header() const { return header_dict(reader_->header()); }
    nb::dict file_header() const { return header_dict(reader_->file_header()); }
    nb::dict totals() const { return totals_dict(reader_->totals()); }
    std::vector<std::string> warnings() const { return reader_->warnings(); }
    uint64_t position() const { return position_; }
    const std::string& path() const { return reader_->path(); }

private:
    std::unique_ptr<RayReader> reader_;
    RayChunk pending_;  // rays read but not yet handed out from used_ on
    size_t used_ = 0;
    uint64_t position_ = 0;
};

using F32Rows = nb::ndarray<const float, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;
using F32 = nb::ndarray<const float, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using I32 = nb::ndarray<const int32_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using F32Table = nb::ndarray<const float, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

// A file written in chunks; nothing is left at the path unless finish() completes.
class RayWriter {
public:
    RayWriter(const Path& path, const std::string& format, const nb::dict& header)
        : header_(header_from(header)) {
        const RayFormat f = format_named(format);
        header_.format = f;
        nb::gil_scoped_release release;
        encoder_ = create_rays(path.string(), f, header_);
    }

    void write(const F32Rows& origin, const F32Rows& direction, const F32& radiant,
               const F32& luminous, const F32& wavelength, const I32& spectrum,
               const F32Table& extra) {
        if (!encoder_) throw nb::value_error("the writer is finished");
        const size_t n = origin.shape(0);
        check_rows(n, direction.shape(0), "direction");
        check_rows(n, radiant.shape(0), "radiant");
        check_rows(n, luminous.shape(0), "luminous");
        check_rows(n, wavelength.shape(0), "wavelength");
        check_rows(n, spectrum.shape(0), "spectrum");
        const size_t extras = header_.extras.size();
        if (extra.shape(0) != n || extra.shape(1) != extras)
            throw nb::value_error(fmt::format("extra: expected {} x {} values (the header's "
                                              "extras), got {} x {}",
                                              n, extras, extra.shape(0), extra.shape(1))
                                      .c_str());
        nb::gil_scoped_release release;
        constexpr size_t kChunk = 1 << 12;
        for (size_t first = 0; first < n; first += kChunk) {
            const size_t count = std::min(kChunk, n - first);
            chunk_.clear();
            chunk_.first_index = written_ + first;
            chunk_.rays.resize(count);
            for (size_t i = 0; i < count; ++i) {
                const size_t k = first + i;
                Ray& r = chunk_.rays[i];
                r.origin = {origin(k, 0), origin(k, 1), origin(k, 2)};
                r.direction = {direction(k, 0), direction(k, 1), direction(k, 2)};
                r.radiant = radiant(k), r.luminous = luminous(k);
                r.wavelength = wavelength(k), r.spectrum = spectrum(k);
            }
            chunk_.extra.assign(extra.data() + first * extras,
                                extra.data() + (first + count) * extras);
            encoder_->write(chunk_);
        }
        written_ += n;
    }

    // Completes the file; returns the header fields the format could not hold.
    std::vector<std::string> finish() {
        if (!encoder_) throw nb::value_error("the writer is finished");
        {
            nb::gil_scoped_release release;
            encoder_->finish();
        }
        std::vector<std::string> dropped = encoder_->dropped();
        encoder_.reset();
        return dropped;
    }
    // Drops an unfinished file.
    void abandon() { encoder_.reset(); }
    uint64_t written() const { return written_; }

private:
    RayHeader header_;
    std::unique_ptr<RayEncoder> encoder_;
    RayChunk chunk_;
    uint64_t written_ = 0;
};

}  // namespace

void bind_rays(nb::module_& m) {
    m.def("read_rays", &read_rays, nb::arg("path"), nb::arg("format") = nb::none(),
          nb::arg("trust") = "", nb::arg("normalise") = false,
          nb::arg("direction_tolerance") = 1e-3,
          "Reads a whole ray file into a dict of numpy arrays (origin, direction, radiant, "
          "luminous, wavelength, spectrum, extra) with header, file_header, totals and "
          "warnings. Parts of the file are read on all cores.");
    m.def(
        "detect_ray_format",
        [](const Path& path) { return std::string(to_string(detect_ray_format(path.string()))); },
        nb::arg("path"), "The format of a ray file, from its content.");

    nb::class_<RayFile>(m, "RayFile", "A ray file read in chunks, in file order.")
        .def(nb::init<const Path&, const std::optional<std::string>&, const std::string&, bool,
                      double>(),
             nb::arg("path"), nb::arg("format") = nb::none(), nb::arg("trust") = "",
             nb::arg("normalise") = false, nb::arg("direction_tolerance") = 1e-3,
             "Opens and checks the file's structure; rays are read by read().")
        .def("read", &RayFile::read, nb::arg("count"),
             "The next up to `count` rays as a dict of arrays (and first_index), or None at the "
             "end.")
        .def_prop_ro("header", &RayFile::header, "The header, totals as the rays will sum.")
        .def_prop_ro("file_header", &RayFile::file_header, "The header as the file states it.")
        .def_prop_ro("totals", &RayFile::totals, "Flux and ray counts of the rays read so far.")
        .def_prop_ro("warnings", &RayFile::warnings, "Warnings found so far.")
        .def_prop_ro("position", &RayFile::position, "Rays handed out so far.")
        .def_prop_ro("path", &RayFile::path, "The file's path.");

    nb::class_<RayWriter>(m, "RayWriter", "A ray file written in chunks.")
        .def(nb::init<const Path&, const std::string&, const nb::dict&>(), nb::arg("path"),
             nb::arg("format"), nb::arg("header"),
             "Starts a file of `format` whose rays `header` describes.")
        .def("write", &RayWriter::write, nb::arg("origin"), nb::arg("direction"),
             nb::arg("radiant"), nb::arg("luminous"), nb::arg("wavelength"), nb::arg("spectrum"),
             nb::arg("extra"), "Writes rays (float32 columns; extra: rows x header extras).")
        .def("finish", &RayWriter::finish,
             "Completes the file and moves it into place; returns the header fields dropped.")
        .def("abandon", &RayWriter::abandon, "Drops the unfinished file.")
        .def_prop_ro("written", &RayWriter::written, "Rays written so far.");
}

}  // namespace rayset::python
