// The ray stream every part of rayset reads rays through: one ray record, the file-level
// header that gives it meaning, and a chunk of rays as readers hand them out.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace rayset {

inline constexpr float kUnknown = std::numeric_limits<float>::quiet_NaN();

struct Vec3f {
    float x = 0, y = 0, z = 0;
    friend bool operator==(const Vec3f& a, const Vec3f& b) {
        return a.x == b.x && a.y == b.y && a.z == b.z;
    }
};

// One measured or simulated ray. Lengths are in the header's unit; the direction is a unit
// vector (readers reject anything else); a flux that the file does not carry is NaN.
// Fluxes are absolute once a reader has handed them out (relative files are scaled, see
// RayReadOptions). A NaN wavelength means "unknown", which some real files use.
struct Ray {
    Vec3f origin;
    Vec3f direction;
    float radiant = kUnknown;     // W
    float luminous = kUnknown;    // lm (or tristimulus Y for TM-25 tristimulus files)
    float wavelength = kUnknown;  // nm
    int32_t spectrum = -1;        // 0-based index into RayHeader::spectral_tables, -1 = none
};

enum class LengthUnit { mm, cm, m, inch, ft, um, nm };
double millimetres_per(LengthUnit unit);
const char* to_string(LengthUnit unit);

// How a file describes the spectrum of its rays (TM-25's spectral data identifier).
enum class SpectralKind {
    none = 0,                // no spectral information: photometric or broadband radiometric
    single_wavelength = 1,   // every ray at RayHeader::single_wavelength
    per_ray_wavelength = 2,  // Ray::wavelength
    shared_table = 3,        // every ray has spectral_tables[0]
    per_ray_table = 4,       // Ray::spectrum indexes spectral_tables
};

struct SpectralTable {
    std::vector<float> wavelength;  // nm, ascending
    std::vector<float> weight;      // relative
};

// Per-ray columns beyond the standard ones, kept through conversions where the target
// format can hold them. TM-25's polarisation and tristimulus columns are named kinds so its
// writer can set the right flags; anything else is `additional` with the file's label.
enum class ExtraKind {
    stokes_s1,
    stokes_s2,
    stokes_s3,
    ellipse_x,
    ellipse_y,
    ellipse_z,
    tristimulus_x,
    tristimulus_z,
    additional,
};
struct ExtraColumn {
    ExtraKind kind = ExtraKind::additional;
    std::string label;
};

enum class RayFormat {
    tm25,
    lighttools_binary,
    lighttools_text,
    zemax_binary,
    zemax_text,
    speos,
    csv
};
const char* to_string(RayFormat format);

// Where the file's placement of the source (Zemax, LightTools) is recorded, kept for round trips.
struct SourcePlacement {
    Vec3f location;
    Vec3f rotation_rad;
    Vec3f scale{1, 1, 1};
    std::array<float, 4> inclination_azimuth_deg{0, 0, 0,
                                                 0};  // Zemax: incl. begin/end, azimuth begin/end
};

struct RayHeader {
    RayFormat format = RayFormat::tm25;  // the format the rays were read from
    LengthUnit unit = LengthUnit::mm;

    uint64_t ray_count = 0;    // exact once the reader has opened the file
    bool has_radiant = false;  // which per-ray flux columns the rays carry
    bool has_luminous = false;

    // Totals as the file states them (NaN when it does not) and as the rays sum after any
    // scaling the reader applied; see RayReader::totals().
    double stated_radiant = std::nan("");
    double stated_luminous = std::nan("");
    // Zemax "ray-set flux": the part of the source flux (stated total) the rays in this file
    // stand for, in the same unit; kept for round trips, never used to scale. NaN = none.
    double ray_set_flux = std::nan("");

    SpectralKind spectral = SpectralKind::none;
    float single_wavelength = kUnknown;  // nm
    float min_wavelength = kUnknown;     // nm
    float max_wavelength = kUnknown;     // nm
    std::vector<SpectralTable> spectral_tables;

    std::vector<ExtraColumn> extras;  // per-ray values live in RayChunk::extra

    // Descriptive fields. TM-25 has nine text fields in this order: name, manufacturer,
    // model creator, ray-file creator, equipment/software, camera, operating conditions,
    // additional info, data reference.
    int32_t creation_method = 0;  // TM-25: 0 simulation, 1 measured (-1 seen too)
    std::string creation_date;
    std::array<std::string, 9> text;
    std::string additional_text;
    std::string description;  // Zemax description, LightTools comment lines

    bool far_field = false;     // LightTools far-field data: origins are meaningless
    Vec3f data_origin;          // LightTools data origin
    SourcePlacement placement;  // Zemax location / rotation / scale
};

// A run of consecutive rays. `extra` holds header.extras.size() values per ray, row-major.
struct RayChunk {
    std::vector<Ray> rays;
    std::vector<float> extra;
    uint64_t first_index = 0;  // index in the file of rays[0]

    size_t size() const { return rays.size(); }
    void clear() {
        rays.clear();
        extra.clear();
    }
};

// The same run of rays one array per field, as decoders fill it and the reader validates it:
// loops over contiguous floats vectorise, loops over 40-byte Ray records do not. A column the
// file does not carry holds what Ray holds then (NaN, spectrum -1). `extra` as in RayChunk.
struct RayColumns {
    std::vector<float> ox, oy, oz, dx, dy, dz, radiant, luminous, wavelength;
    std::vector<int32_t> spectrum;
    std::vector<float> extra;
    uint64_t first_index = 0;  // index in the file of the first ray

    size_t size() const { return ox.size(); }
    void resize(size_t n) {
        for (auto* column : {&ox, &oy, &oz, &dx, &dy, &dz, &radiant, &luminous, &wavelength})
            column->resize(n);
        spectrum.resize(n);
    }
    void clear() { resize(0), extra.clear(); }
    Ray ray(size_t i) const {
        return {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}, radiant[i],
                luminous[i],           wavelength[i],         spectrum[i]};
    }
    void set(size_t i, const Ray& r) {
        ox[i] = r.origin.x, oy[i] = r.origin.y, oz[i] = r.origin.z;
        dx[i] = r.direction.x, dy[i] = r.direction.y, dz[i] = r.direction.z;
        radiant[i] = r.radiant, luminous[i] = r.luminous, wavelength[i] = r.wavelength,
        spectrum[i] = r.spectrum;
    }
    void push_back(const Ray& r) { resize(size() + 1), set(size() - 1, r); }
    // The rays as records (what encoders and most consumers take); ray_columns.cpp.
    void to_rays(RayChunk& chunk) const;
};

}  // namespace rayset
