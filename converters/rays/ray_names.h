// The names of a ray file header's kinds, as text formats (CSV) and the Python module spell them.
#pragma once

#include "converters/rays/ray.h"

#include <string_view>

namespace rayset {

struct NamedExtra {
    ExtraKind kind;
    std::string_view name;
};
inline constexpr NamedExtra kNamedExtras[] = {
    {ExtraKind::stokes_s1, "stokes_s1"},         {ExtraKind::stokes_s2, "stokes_s2"},
    {ExtraKind::stokes_s3, "stokes_s3"},         {ExtraKind::ellipse_x, "ellipse_x"},
    {ExtraKind::ellipse_y, "ellipse_y"},         {ExtraKind::ellipse_z, "ellipse_z"},
    {ExtraKind::tristimulus_x, "tristimulus_x"}, {ExtraKind::tristimulus_z, "tristimulus_z"},
};

// Indexed by SpectralKind.
inline constexpr std::string_view kSpectralNames[] = {
    "none", "single_wavelength", "per_ray_wavelength", "shared_table", "per_ray_table"};

inline constexpr LengthUnit kUnits[] = {LengthUnit::mm,   LengthUnit::cm, LengthUnit::m,
                                        LengthUnit::inch, LengthUnit::ft, LengthUnit::um,
                                        LengthUnit::nm};

}  // namespace rayset
