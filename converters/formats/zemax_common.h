// What the Zemax OpticStudio source-file codecs (binary .DAT/.SDF and text) share: the header
// codes, how a RayHeader maps onto the one flux column and optional wavelength column of a Zemax
// record, and the micrometre wavelengths Zemax stores. Private to zemax_binary.cpp and
// zemax_text.cpp.
#pragma once

#include "converters/rays/ray.h"
#include "core/error.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rayset {

// OpticStudio documents NbrRays "must be <= 4,000,000,000".
inline constexpr uint64_t kZemaxMaxRays = 4'000'000'000ULL;

// Ray format codes: 0 flux only (7 columns), 2 spectral (8th column: wavelength in um).
inline constexpr int32_t kZemaxFluxOnly = 0;
inline constexpr int32_t kZemaxSpectral = 2;

struct ZemaxLayout {
    bool lumens = false;      // flux type 1: the flux column is lm, otherwise W
    bool wavelength = false;  // an eighth column, um
    size_t columns() const { return wavelength ? 8 : 7; }
    int32_t ray_format() const { return wavelength ? kZemaxSpectral : kZemaxFluxOnly; }
    int32_t flux_type() const { return lumens ? 1 : 0; }
};

inline std::optional<LengthUnit> zemax_unit(int64_t code) {
    switch (code) {
        case 0: return LengthUnit::m;
        case 1: return LengthUnit::inch;
        case 2: return LengthUnit::cm;
        case 3: return LengthUnit::ft;
        case 4: return LengthUnit::mm;
        default: return std::nullopt;
    }
}

// The unit a writer stores and the factor its positions are multiplied by: um and nm have no
// Zemax code, so such positions are written in mm.
struct ZemaxUnit {
    uint32_t code = 4;
    LengthUnit unit = LengthUnit::mm;
    double scale = 1;  // 1 keeps positions bit-exact
};

inline ZemaxUnit zemax_unit_for(LengthUnit unit, std::vector<std::string>& dropped) {
    switch (unit) {
        case LengthUnit::m: return {0, unit, 1};
        case LengthUnit::inch: return {1, unit, 1};
        case LengthUnit::cm: return {2, unit, 1};
        case LengthUnit::ft: return {3, unit, 1};
        case LengthUnit::mm: return {4, unit, 1};
        case LengthUnit::um:
        case LengthUnit::nm: break;
    }
    dropped.push_back(std::string("length unit ") + to_string(unit) +
                      " (Zemax has no code for it: positions written in mm)");
    return {4, LengthUnit::mm, millimetres_per(unit)};
}

// The checks both variants make on the codes they read; say_format and say_flux report a bad
// code at that field and never return.
template <class SayFormat, class SayFlux>
ZemaxLayout zemax_layout(int64_t ray_format, int64_t flux_type, SayFormat&& say_format,
                         SayFlux&& say_flux) {
    if (ray_format != kZemaxFluxOnly && ray_format != kZemaxSpectral)
        say_format("ray format " + std::to_string(ray_format) +
                   " is not a Zemax ray format (0 flux only, 2 spectral)");
    if (flux_type != 0 && flux_type != 1)
        say_flux("flux type " + std::to_string(flux_type) +
                 " is not a Zemax flux type (0 watts, 1 lumens)");
    if (flux_type == 1 && ray_format != kZemaxFluxOnly)
        say_flux(
            "flux type 1 (lumens) is only allowed with ray format 0 (flux only), this file has ray "
            "format " +
            std::to_string(ray_format));
    ZemaxLayout layout;
    layout.lumens = flux_type == 1;
    layout.wavelength = ray_format == kZemaxSpectral;
    return layout;
}

// The header a decoder hands out. Per-ray fluxes are relative to the source flux.
inline RayHeader zemax_header(RayFormat format, const ZemaxLayout& layout, LengthUnit unit) {
    RayHeader header;
    header.format = format;
    header.unit = unit;
    header.has_radiant = !layout.lumens;
    header.has_luminous = layout.lumens;
    header.spectral = layout.wavelength ? SpectralKind::per_ray_wavelength : SpectralKind::none;
    return header;
}

inline void set_zemax_flux(Ray& ray, const ZemaxLayout& layout, float flux) {
    (layout.lumens ? ray.luminous : ray.radiant) = flux;
}
inline float zemax_flux(const Ray& ray, const ZemaxLayout& layout) {
    return layout.lumens ? ray.luminous : ray.radiant;
}

// Zemax stores micrometres, rayset nanometres. The product is rounded once to float, so
// um -> nm -> um comes back to within one float rounding (not always bit-exact).
inline float zemax_um_to_nm(float um) { return float(double(um) * 1000.0); }
inline float zemax_nm_to_um(float nm) { return float(double(nm) / 1000.0); }

// Decides the record a writer uses for rays described by `header`; `single_in_header` says the
// format can store one wavelength in its header (binary) rather than needing a column (text).
// Notes in `dropped` what Zemax cannot hold; fails when the rays carry no flux at all.
inline ZemaxLayout zemax_layout_for(const std::string& path, const RayHeader& header,
                                    bool single_in_header, std::vector<std::string>& dropped) {
    if (!header.has_radiant && !header.has_luminous)
        fail(path,
             "cannot write a Zemax source file: the rays carry neither radiant nor luminous flux");
    ZemaxLayout layout;
    layout.lumens = !header.has_radiant;  // one flux column: watts win, they pair with wavelengths
    if (header.has_radiant && header.has_luminous)
        dropped.push_back("per-ray luminous flux (Zemax keeps one flux column: watts)");
    bool wants_column = header.spectral == SpectralKind::per_ray_wavelength ||
                        (header.spectral == SpectralKind::single_wavelength && !single_in_header);
    if (header.spectral == SpectralKind::shared_table ||
        header.spectral == SpectralKind::per_ray_table)
        dropped.push_back("spectral tables (Zemax holds at most one wavelength per ray)");
    if (wants_column && layout.lumens)
        dropped.push_back("wavelengths (Zemax allows lumens only in flux-only files)");
    layout.wavelength = wants_column && !layout.lumens;
    if (!header.extras.empty())
        dropped.push_back("extra per-ray columns (" + std::to_string(header.extras.size()) + ")");
    if (header.far_field)
        dropped.push_back("far-field flag (Zemax records always have a start point)");
    return layout;
}

// The wavelength (nm) a writer stores for `ray`: single-wavelength rays carry the header's.
inline float zemax_ray_nm(const RayHeader& header, const Ray& ray) {
    return header.spectral == SpectralKind::single_wavelength ? header.single_wavelength
                                                              : ray.wavelength;
}

// Zemax has no "unknown" flux or wavelength: a writer refuses rays it would have to invent them
// for. `index` is 0-based.
inline void check_zemax_ray(const std::string& path, uint64_t index, float flux, bool wavelength,
                            float nm) {
    if (!std::isfinite(flux) || flux < 0)
        fail(path, "ray " + std::to_string(index + 1) + ": flux " + std::to_string(flux) +
                       " cannot be written: Zemax needs a non-negative flux for every ray");
    if (wavelength && !(std::isfinite(nm) && nm > 0))
        fail(path, "ray " + std::to_string(index + 1) + ": wavelength " + std::to_string(nm) +
                       " nm cannot be written: a Zemax spectral file needs a known wavelength for "
                       "every ray");
}

inline void check_zemax_count(const std::string& path, uint64_t count) {
    if (count > kZemaxMaxRays)
        fail(path, "cannot write " + std::to_string(count) +
                       " rays: a Zemax source file holds at most 4,000,000,000");
}

}  // namespace rayset
