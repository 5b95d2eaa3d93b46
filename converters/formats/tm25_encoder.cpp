// IES TM-25-13 ray files: the encoder. It writes the header up front with the ray count and
// totals left open, streams the rays, and patches count and totals in finish().
#include "converters/formats/codecs.h"
#include "converters/formats/tm25_layout.h"
#include "converters/rays/io.h"
#include "core/text_encoding.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>

namespace rayset {
namespace {

using namespace tm25;

const char* kind_name(ExtraKind kind) {
    switch (kind) {
        case ExtraKind::stokes_s1: return "Stokes S1";
        case ExtraKind::stokes_s2: return "Stokes S2";
        case ExtraKind::stokes_s3: return "Stokes S3";
        case ExtraKind::ellipse_x: return "polarisation ellipse x";
        case ExtraKind::ellipse_y: return "polarisation ellipse y";
        case ExtraKind::ellipse_z: return "polarisation ellipse z";
        case ExtraKind::tristimulus_x: return "tristimulus X";
        case ExtraKind::tristimulus_z: return "tristimulus Z";
        case ExtraKind::additional: break;
    }
    return "additional";
}

class Tm25Encoder final : public RayEncoder {
public:
    Tm25Encoder(const std::string& path, const RayHeader& header) : out_(path), header_(header) {
        plan_columns();
        check_spectra();
        note_dropped();
        write_header();
    }
    void write(const RayChunk& chunk) override;
    void finish() override;

private:
    [[noreturn]] void fail_here(const std::string& what) const {
        fail(out_.path(), "cannot write TM-25: " + what);
    }
    void plan_columns();
    void check_spectra();
    void note_dropped();
    void write_header();
    // UTF-32LE text of exactly `chars` code points, NUL-padded; longer text is cut and noted.
    void write_text(const std::string& text, size_t chars, const std::string& what);

    AtomicOutput out_;
    RayHeader header_;
    int spectral_id_ = 0;
    Flags flags_{};
    Columns columns_;
    std::vector<int> extra_column_;  // record column of each header extra
    double mm_per_unit_ = 1;
    uint64_t count_ = 0;
    double radiant_sum_ = 0, luminous_sum_ = 0;
    std::vector<float> buffer_;
};

void Tm25Encoder::plan_columns() {
    const RayHeader& h = header_;
    spectral_id_ = static_cast<int>(h.spectral);
    const bool radiant_only =
        h.spectral == SpectralKind::per_ray_wavelength || h.spectral == SpectralKind::per_ray_table;
    if (!h.has_radiant && !h.has_luminous)
        fail_here("the rays carry neither radiant nor luminous flux");
    if (radiant_only && !h.has_radiant)
        fail_here("spectral data id " + std::to_string(spectral_id_) +
                  " needs radiant flux per ray, which the rays do not carry");
    if (radiant_only && h.has_luminous)
        dropped_.push_back("luminous flux of each ray (TM-25 spectral data id " +
                           std::to_string(spectral_id_) + " allows radiant flux only)");
    // Which extras are TM-25's own columns; the rest become additional columns.
    constexpr int kKinds = static_cast<int>(ExtraKind::additional);
    int of_kind[kKinds];
    std::fill(of_kind, of_kind + kKinds, -1);
    int additional = 0;
    for (size_t e = 0; e < h.extras.size(); ++e) {
        ExtraKind kind = h.extras[e].kind;
        if (kind == ExtraKind::additional) {
            ++additional;
            continue;
        }
        int& slot = of_kind[static_cast<int>(kind)];
        if (slot >= 0) fail_here(std::string("two extra columns are both ") + kind_name(kind));
        slot = static_cast<int>(e);
    }
    auto count_of = [&](int from, int to) {
        int n = 0;
        for (int k = from; k < to; ++k) n += of_kind[k] >= 0;
        return n;
    };
    const int stokes_n = count_of(0, 6), tristimulus_n = count_of(6, 8);
    if (stokes_n != 0 && stokes_n != 6)
        fail_here(
            "TM-25 stores Stokes S1 S2 S3 and the polarisation ellipse axis only all six together");
    if (tristimulus_n != 0 && tristimulus_n != 2)
        fail_here("TM-25 stores tristimulus X and Z only together");
    if (stokes_n && !h.has_radiant) fail_here("Stokes columns need radiant flux per ray");
    if (tristimulus_n && (!h.has_luminous || h.spectral != SpectralKind::none))
        fail_here("tristimulus columns need luminous flux (Y) per ray and no spectral information");

    flags_[position] = flags_[direction] = 1;
    flags_[radiant] = h.has_radiant;
    flags_[wavelength] = h.spectral == SpectralKind::per_ray_wavelength;
    flags_[luminous] = h.has_luminous && !radiant_only;
    flags_[stokes] = stokes_n == 6;
    flags_[tristimulus] = tristimulus_n == 2;
    flags_[spectrum_index] = h.spectral == SpectralKind::per_ray_table;
    columns_ = column_layout(flags_, additional);

    extra_column_.assign(h.extras.size(), -1);
    int next_additional = columns_.additional;
    for (size_t e = 0; e < h.extras.size(); ++e) {
        int kind = static_cast<int>(h.extras[e].kind);
        if (kind == kKinds)
            extra_column_[e] = next_additional++;
        else if (kind < 6)
            extra_column_[e] = columns_.stokes + kind;
        else
            extra_column_[e] = columns_.tristimulus + (kind - 6);
    }
    mm_per_unit_ = millimetres_per(h.unit);  // TM-25 positions are in mm
}

void Tm25Encoder::check_spectra() {
    const RayHeader& h = header_;
    if (h.spectral == SpectralKind::single_wavelength &&
        !(std::isfinite(h.single_wavelength) && h.single_wavelength > 0))
        fail_here("a single-wavelength file needs a positive wavelength, not " +
                  format_float(h.single_wavelength));
    if ((h.spectral == SpectralKind::shared_table || h.spectral == SpectralKind::per_ray_table) &&
        h.spectral_tables.empty())
        fail_here("spectral data id " + std::to_string(spectral_id_) +
                  " needs spectral tables, but there are none");
    if (h.spectral_tables.size() > INT32_MAX) fail_here("too many spectral tables");
    for (size_t t = 0; t < h.spectral_tables.size(); ++t) {
        const SpectralTable& table = h.spectral_tables[t];
        std::string name = "spectral table " + std::to_string(t + 1);
        if (table.wavelength.empty() || table.wavelength.size() != table.weight.size() ||
            table.weight.size() > INT32_MAX)
            fail_here(name + " has " + std::to_string(table.wavelength.size()) +
                      " wavelengths and " + std::to_string(table.weight.size()) + " weights");
        size_t bad = 0;
        std::string problem =
            table_problem(table.wavelength.data(), table.weight.data(), table.weight.size(), bad);
        if (!problem.empty())
            fail_here(name + ", point " + std::to_string(bad / 2 + 1) + ": " + problem);
    }
}

void Tm25Encoder::note_dropped() {
    const RayHeader& h = header_;
    // A description that one of the text fields already carries is not lost.
    if (!h.description.empty() &&
        std::find(h.text.begin(), h.text.end(), h.description) == h.text.end())
        dropped_.push_back("description");
    if (h.far_field) dropped_.push_back("far-field flag (TM-25 rays always have origins)");
    if (!(h.data_origin == Vec3f{})) dropped_.push_back("data origin");
    const SourcePlacement& p = h.placement;
    const SourcePlacement none;
    if (!(p.location == none.location && p.rotation_rad == none.rotation_rad &&
          p.scale == none.scale && p.inclination_azimuth_deg == none.inclination_azimuth_deg))
        dropped_.push_back("source placement (location, rotation, scale, angles)");
}

void Tm25Encoder::write_text(const std::string& text, size_t chars, const std::string& what) {
    // 8-bit text from another format (a Latin-1 Zemax description) is made UTF-8 first.
    std::u32string code_points;
    utf8_to_utf32(to_utf8(text), code_points);
    if (code_points.size() > chars) {
        code_points.resize(chars);
        dropped_.push_back(what + " past its first " + std::to_string(chars) + " characters");
    }
    code_points.resize(chars, U'\0');
    out_.write(code_points.data(), 4 * chars);
}

void Tm25Encoder::write_header() {
    const RayHeader& h = header_;
    out_.write(kMagic, 4);
    out_.put(kVersion);
    out_.put(static_cast<int32_t>(h.creation_method));
    out_.put(0.0f);  // totals and ray count: patched by finish()
    out_.put(0.0f);
    out_.put(uint64_t{0});
    char date[kDateBytes] = {};
    if (h.creation_date.size() > kDateBytes)
        dropped_.push_back("creation date past its first 28 bytes");
    std::memcpy(date, h.creation_date.data(), std::min(kDateBytes, h.creation_date.size()));
    out_.write(date, kDateBytes);
    out_.put(int32_t{0});  // ray start position: meaning unknown, 0 in every file seen
    out_.put(static_cast<int32_t>(spectral_id_));
    out_.put(h.single_wavelength);
    out_.put(h.min_wavelength);
    out_.put(h.max_wavelength);
    out_.put(static_cast<int32_t>(h.spectral_tables.size()));
    out_.put(
        static_cast<int32_t>(columns_.additional >= 0 ? columns_.count - columns_.additional : 0));
    std::u32string additional_text;
    utf8_to_utf32(to_utf8(h.additional_text), additional_text);
    const size_t text_chars = padded(4 * additional_text.size()) / 4;
    if (text_chars > INT32_MAX / 4) fail_here("the additional text is too long");
    out_.put(static_cast<int32_t>(4 * text_chars));
    const char reserved[kFlagsAt - kReservedAt] = {};
    out_.write(reserved, sizeof reserved);
    out_.write(flags_.data(), sizeof flags_);
    for (size_t k = 0; k < kTextCount; ++k)
        write_text(h.text[k], kTextChars, std::string("text field '") + text_name(k) + "'");

    for (const SpectralTable& table : h.spectral_tables) {
        out_.put(static_cast<int32_t>(table.wavelength.size()));
        for (size_t k = 0; k < table.wavelength.size(); ++k) {
            out_.put(table.wavelength[k]);
            out_.put(table.weight[k]);
        }
    }
    const char zeros[kBlockAlign] = {};
    out_.write(zeros, padded(out_.offset() - kTablesAt) - (out_.offset() - kTablesAt));
    for (const ExtraColumn& extra : h.extras)
        if (extra.kind == ExtraKind::additional)
            write_text(extra.label, kLabelChars, "column label '" + extra.label + "'");
    write_text(h.additional_text, text_chars, "additional text");
}

void Tm25Encoder::write(const RayChunk& chunk) {
    const size_t n = chunk.rays.size(), extras = header_.extras.size();
    if (chunk.extra.size() != n * extras)
        fail_here("internal error: a chunk of " + std::to_string(n) + " rays has " +
                  std::to_string(chunk.extra.size()) + " extra values for " +
                  std::to_string(extras) + " extra columns");
    const Columns& c = columns_;
    const size_t tables = header_.spectral_tables.size();
    const bool scale = mm_per_unit_ != 1;
    buffer_.resize(n * c.count);
    for (size_t i = 0; i < n; ++i) {
        const Ray& ray = chunk.rays[i];
        float* r = buffer_.data() + i * c.count;
        const Vec3f& o = ray.origin;
        if (scale) {
            r[0] = static_cast<float>(o.x * mm_per_unit_);
            r[1] = static_cast<float>(o.y * mm_per_unit_);
            r[2] = static_cast<float>(o.z * mm_per_unit_);
        } else {
            r[0] = o.x, r[1] = o.y, r[2] = o.z;
        }
        r[3] = ray.direction.x, r[4] = ray.direction.y, r[5] = ray.direction.z;
        if (c.radiant >= 0) r[c.radiant] = ray.radiant, radiant_sum_ += ray.radiant;
        if (c.wavelength >= 0) r[c.wavelength] = ray.wavelength;
        if (c.luminous >= 0) r[c.luminous] = ray.luminous, luminous_sum_ += ray.luminous;
        if (c.spectrum >= 0) {
            if (ray.spectrum < 0 || static_cast<size_t>(ray.spectrum) >= tables)
                fail_here("ray " + std::to_string(chunk.first_index + i + 1) +
                          " has spectrum index " + std::to_string(ray.spectrum + 1) +
                          " but there are " + std::to_string(tables) + " spectral tables");
            r[c.spectrum] = static_cast<float>(ray.spectrum + 1);
        }
        const float* e = chunk.extra.data() + i * extras;
        for (size_t k = 0; k < extras; ++k) r[extra_column_[k]] = e[k];
    }
    out_.write(buffer_.data(), 4 * buffer_.size());
    count_ += n;
}

void Tm25Encoder::finish() {
    // A total the header does not state is the sum of the rays written, where there is one.
    auto total = [](double stated, bool column, double sum) {
        return static_cast<float>(std::isnan(stated) && column ? sum : stated);
    };
    const float luminous_total =
        total(header_.stated_luminous, flags_[luminous] == 1, luminous_sum_);
    const float radiant_total = total(header_.stated_radiant, flags_[radiant] == 1, radiant_sum_);
    out_.patch(kLuminousTotalAt, &luminous_total, 4);
    out_.patch(kRadiantTotalAt, &radiant_total, 4);
    out_.patch(kRayCountAt, &count_, 8);
    out_.commit();
}

}  // namespace

std::unique_ptr<RayEncoder> create_tm25(const std::string& path, const RayHeader& header) {
    return std::make_unique<Tm25Encoder>(path, header);
}

}  // namespace rayset
