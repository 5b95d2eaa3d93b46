// Far-field photometry of a ray file: type C intensities on a grid of C planes and gamma
// angles, estimated from the rays by kernel density estimation (farfield_smoothing.h) or, without
// smoothing, as each cell's flux over its exact solid angle.
//
// Frame: gamma is the angle from the polar axis (+z of the ray file by default; -z for a
// luminaire whose nadir is -z, the IES convention), C = atan2(y, x) counter-clockwise from +x
// seen from the +z side, so C0 is +x and C90 is +y with either polar axis.
//
// Cells: the grid angles are gamma_j = j * dgamma (0..180) and C_i = i * dC (0..360 - dC). Cell
// (i, j) holds the directions with gamma in [gamma_j - dgamma/2, gamma_j + dgamma/2) clipped to
// [0, 180] (the last one includes 180) and C in [C_i - dC/2, C_i + dC/2) modulo 360. Its solid
// angle is dC (cos(lower gamma) - cos(upper gamma)) exactly, the cells tile the sphere, and
// so sum(I * solid angle) over the cells is the rays' total flux to rounding. The polar cells
// (gamma 0 and 180) are caps: one direction, one value in every C plane.
//
// Smoothed values are the cells' means of the kernel estimate (with the bandwidth chosen at the
// cell's grid angle), scaled by one factor so that sum(I * solid angle) is again the rays' total
// flux: a bandwidth that changes from direction to direction does not keep the flux by itself
// (the factor differs from 1 by 0.5% or less at 10^6 rays, FarField::flux_scale).
#pragma once

#include "converters/photometry/photometry.h"
#include "converters/rays/ray_stream.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rayset {

enum class PolarAxis { plus_z, minus_z };
// photometric: luminous flux (lm) -> cd. radiometric: radiant flux (W) -> W/sr, stored in the
// candela table and flagged by the keyword _RADIOMETRIC.
enum class FarFieldQuantity { photometric, radiometric };

enum class FarFieldSmoothing {
    automatic,  // the bandwidth chosen per direction from the rays
    fixed,      // one bandwidth, FarFieldOptions::smoothing_deg
    none        // the histogram: each cell's flux over its solid angle
};

struct FarFieldOptions {
    double c_step_deg = 5;        // must divide 360
    double gamma_step_deg = 2.5;  // must divide 180
    PolarAxis axis = PolarAxis::plus_z;
    FarFieldQuantity quantity = FarFieldQuantity::photometric;
    FarFieldSmoothing smoothing = FarFieldSmoothing::none;
    double smoothing_deg = 0;  // fixed: the kernel's sigma, degrees
    std::function<void(double)> progress;
};

// "auto", "none" or a bandwidth in degrees, as `rayconv farfield --smoothing` takes it; throws
// Error for anything else.
void parse_smoothing(const std::string& text, FarFieldOptions& options);

// The C and gamma cells of a grid (see the top of this file).
class FarFieldGrid {
public:
    explicit FarFieldGrid(const FarFieldOptions& options);  // throws Error for a bad step
    size_t c_count() const { return c_count_; }             // C0 .. 360 - dC
    size_t gamma_count() const { return gamma_count_; }     // gamma 0 .. 180
    double c_step_deg() const { return c_step_; }
    double gamma_step_deg() const { return gamma_step_; }
    // Lower and upper gamma (degrees) of cell row j.
    double gamma_low(size_t j) const;
    double gamma_high(size_t j) const;
    double solid_angle(size_t j) const;  // sr, the same for every C
    // Cell of a unit direction, with gamma measured from `axis`.
    void locate(double x, double y, double z, PolarAxis axis, size_t& i, size_t& j) const;

private:
    double c_step_, gamma_step_;
    size_t c_count_, gamma_count_;
};

struct FarField {
    // Type C, vertical 0..180, horizontal 0..360 where the 360 plane repeats 0 (no symmetry),
    // absolute (rated_lumens -1). candela holds W/sr for radiometric far fields.
    Photometry photometry;
    // Per cell, indexed like photometry.candela (the 360 plane repeats the 0 plane):
    std::vector<double> flux;         // lm or W
    std::vector<double> solid_angle;  // sr
    // Estimated variance of the intensity (the square of its standard error): for the
    // histogram, the sum of squared ray fluxes / solid angle^2.
    std::vector<double> variance;
    std::vector<double> sigma_deg;  // smoothed: the kernel bandwidth of each value
    std::string method;             // how the values were made, as the keyword _SMOOTHING says
    double flux_scale = 1;          // smoothed: the factor that keeps the flux (see above)
    uint64_t rays = 0;
    double total_flux = 0;                    // sum of the cells = sum of the rays
    double max_intensity = 0;                 // cd or W/sr
    double max_c_deg = 0, max_gamma_deg = 0;  // where it is
};

// Bins every ray of `reader`. Photometric far fields need luminous flux or radiant flux with
// spectral information; radiometric ones need radiant flux or luminous flux with spectral
// information. Throws Error naming the file when the rays cannot give the quantity.
FarField far_field(RayReader& reader, const FarFieldOptions& options = {});

// The intensities rounded to the digits their standard errors support: to the second significant
// digit of the error (18.38155 +- 0.135 -> 18.38; 123.456 +- 12.3 -> 123); values without an
// error (no rays, or a zero variance) are kept. The cells' flux and the total are left as they
// were: rounding moves the file's flux by about 1e-4 of it, which written_flux() tells.
void round_to_uncertainty(FarField& far);
double written_flux(const FarField& far);  // sum of intensity x solid angle over the cells

}  // namespace rayset
