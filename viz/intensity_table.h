// Far-field intensity as a type C table, whatever file it comes from: binned from a ray file's
// rays (converters/photometry/farfield.h) or read from IES LM-63 / EULUMDAT. The photometric solid
// and the polar curves are both drawn from this one table, so they agree with each other and with
// `rayconv farfield` / `rayconv info`.
#pragma once

#include "converters/photometry/farfield.h"
#include "converters/photometry/photometry.h"

#include <optional>
#include <string>

namespace rayset::viz {

struct IntensityTable {
    Photometry photometry;  // type C
    std::string unit;       // "cd", or "W/sr" for rays that carry no luminous information
    std::string label;      // file name, for legends
    // Where gamma = 0 points in the model frame: +1 for ray files (LED rays emit along +z),
    // -1 for IES / LDT (nadir along -z, the luminaire convention).
    int axis = 1;
    double max_intensity = 0, max_c_deg = 0, max_gamma_deg = 0;  // on the table's grid
    // The standard error of every value, as a table on the same grid (interpolated alike);
    // empty for files that state none (IES, EULUMDAT).
    std::optional<Photometry> standard_error;
};

// Views draw the intensity within kBandErrors standard errors as its uncertainty band.
inline constexpr double kBandErrors = 2;

// Far field of a ray file on `options`' grid (default 5 deg x 2.5 deg, as rayconv farfield):
// luminous intensity (cd) when the rays' luminous flux is known, else radiant (W/sr).
IntensityTable intensity_of_rays(const std::string& path, FarFieldOptions options = {});
// An IES or EULUMDAT file. Throws Error for photometric types A and B, which have no C planes.
IntensityTable intensity_of_photometry(const std::string& path);

}  // namespace rayset::viz
