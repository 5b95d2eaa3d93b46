// What the LightTools binary (LTRF) and text ray-data codecs share: the meaning of the header
// fields, and how a RayHeader maps onto the one flux column and optional wavelength column a
// LightTools record has. Private to lighttools_binary.cpp and lighttools_text.cpp.
#pragma once

#include "converters/rays/ray.h"
#include "core/error.h"

#include <fmt/format.h>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace rayset {

// Record layout, as both variants store it: x y z kx ky kz flux [wavelength nm].
struct LightToolsLayout {
    bool photometric = false;  // data type 1: the flux column is lm, otherwise W
    bool wavelength = false;   // colour info 2: an eighth column, nm
    size_t columns() const { return wavelength ? 8 : 7; }
};

// The header a decoder hands out. Per-ray fluxes are relative (flux_is_relative): `total` is
// what they are scaled to.
inline RayHeader lighttools_header(RayFormat format, const LightToolsLayout& layout,
                                   LengthUnit unit, const Vec3f& origin, double total) {
    RayHeader header;
    header.format = format;
    header.unit = unit;
    header.has_radiant = !layout.photometric;
    header.has_luminous = layout.photometric;
    (layout.photometric ? header.stated_luminous : header.stated_radiant) = total;
    header.spectral = layout.wavelength ? SpectralKind::per_ray_wavelength : SpectralKind::none;
    header.data_origin = origin;
    return header;
}

inline void set_lighttools_flux(Ray& ray, const LightToolsLayout& layout, float flux) {
    (layout.photometric ? ray.luminous : ray.radiant) = flux;
}

// Binary length-unit codes 1..7; code 0 is handled by the binary decoder.
inline std::optional<LengthUnit> lighttools_unit(uint32_t code) {
    switch (code) {
        case 1: return LengthUnit::mm;
        case 2: return LengthUnit::cm;
        case 3: return LengthUnit::m;
        case 4: return LengthUnit::inch;
        case 5: return LengthUnit::ft;
        case 6: return LengthUnit::um;
        case 7: return LengthUnit::nm;
        default: return std::nullopt;
    }
}

inline uint32_t lighttools_unit_code(LengthUnit unit) {
    switch (unit) {
        case LengthUnit::mm: return 1;
        case LengthUnit::cm: return 2;
        case LengthUnit::m: return 3;
        case LengthUnit::inch: return 4;
        case LengthUnit::ft: return 5;
        case LengthUnit::um: return 6;
        case LengthUnit::nm: return 7;
    }
    return 1;
}

// Decides the layout a writer uses for rays described by `header`, noting in `dropped` what
// LightTools cannot hold. Returns nullopt when the rays carry no flux LightTools can store.
inline std::optional<LightToolsLayout> lighttools_layout_for(const RayHeader& header,
                                                             std::vector<std::string>& dropped) {
    if (!header.has_radiant && !header.has_luminous) return std::nullopt;
    LightToolsLayout layout;
    // One flux column: radiant wins because LightTools pairs it with a per-ray wavelength.
    layout.photometric = !header.has_radiant;
    if (header.has_radiant && header.has_luminous)
        dropped.push_back("per-ray luminous flux (LightTools keeps one flux column: radiant)");
    if (header.has_radiant && std::isfinite(header.stated_luminous))
        dropped.push_back("stated luminous total (LightTools states one total: radiant)");
    switch (header.spectral) {
        case SpectralKind::none: break;
        case SpectralKind::single_wavelength:
        case SpectralKind::per_ray_wavelength: layout.wavelength = true; break;
        case SpectralKind::shared_table:
        case SpectralKind::per_ray_table:
            dropped.push_back("spectral tables (LightTools holds at most one wavelength per ray)");
            break;
    }
    if (!header.extras.empty())
        dropped.push_back("extra per-ray columns (" + std::to_string(header.extras.size()) + ")");
    if (header.far_field)
        dropped.push_back(
            "far-field flag (only near-field LightTools records are known; written as near-field)");
    return layout;
}

// The wavelength a writer stores for `ray`: single-wavelength rays carry the header's.
inline float lighttools_wavelength(const RayHeader& header, const Ray& ray) {
    return header.spectral == SpectralKind::single_wavelength ? header.single_wavelength
                                                              : ray.wavelength;
}

// LightTools has no "unknown" flux or wavelength: a writer refuses rays it would have to invent
// them for. `index` is 0-based.
inline void check_lighttools_ray(const std::string& path, uint64_t index, float flux,
                                 bool wavelength, float nm) {
    if (!std::isfinite(flux) || flux < 0)
        fail(path, fmt::format("ray {}: flux {} cannot be written: LightTools needs a non-negative "
                               "flux for every ray",
                               index + 1, flux));
    if (wavelength && !(std::isfinite(nm) && nm > 0))
        fail(path, fmt::format("ray {}: wavelength {} nm cannot be written: LightTools needs a "
                               "known wavelength for "
                               "every ray",
                               index + 1, nm));
}

}  // namespace rayset
