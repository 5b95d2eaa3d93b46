// rayset's public API: far-field photometry as IES LM-63 and EULUMDAT files hold it, read and
// written, and the far field of a ray file. Link rayset::converters. docs/api.md has the whole
// public API and examples.
//
// Units: angles in degrees, intensity in cd (W/sr for a radiometric far field), flux lm (W),
// luminous opening in metres. Errors: rayset::Error (rays.h), naming the file and the line.
#pragma once

#include "converters/photometry/farfield.h"
#include "converters/photometry/photometry.h"

#include <rayset/rays.h>

namespace rayset {

// ---- Photometry files (converters/photometry/photometry.h) --------------------------------------

// struct Photometry
//   Intensity on a grid of angles of one photometric type, as both formats hold it:
//   type             PhotometricType::C (vertical = gamma from nadir 0..180, horizontal = C
//                    plane), B or A (vertical and horizontal -90..90)
//   vertical_deg     ascending
//   horizontal_deg   ascending; possibly only a symmetric part of the sphere, as stored
//   candela          absolute cd, candela[h * vertical_deg.size() + v] (index(h, v))
//   lamp_count, rated_lumens (lm; not above zero: absolute photometry), input_watts (W),
//   ballast_factor, width_m, length_m, height_m, round (the luminous opening), keywords (IES
//   keywords and the EULUMDAT header lines, by key)
//   intensity(h, v)  cd toward (horizontal, vertical) degrees anywhere on the sphere: symmetry
//                    unfolded, bilinear between grid angles
//   total_flux()     lm: the intensity integrated over the sphere
//   max_candela()    the largest value of the table
// enum class PhotometricType { C = 1, B = 2, A = 3 }
// enum class PhotometryFormat { ies, eulumdat }
//
// Photometry read_photometry(const std::string& path);
//   Reads IES LM-63 (1986 to 2019) or EULUMDAT, told apart by content. Throws Error naming the
//   file and line of what is wrong.
// PhotometryFormat detect_photometry_format(const std::string& path);
//   IES or EULUMDAT from the content; throws Error when it is neither.
// void write_photometry(const std::string& path, const Photometry& photometry,
//                       PhotometryFormat format);
//   Writes through a temporary file renamed into place (a failed write leaves nothing). Throws
//   Error when the format cannot hold the photometry (EULUMDAT: type C only, vertical angles
//   within 0..180, ...) or a table that does not match its angles.

// ---- Far field of rays (converters/photometry/farfield.h) ---------------------------------------

// FarField far_field(RayReader& reader, const FarFieldOptions& options = {});
//   Type C intensities of every ray of `reader` on a grid of C planes and gamma angles, each
//   value the mean intensity over the cell around its grid angles; the values' flux equals the
//   rays'. What `rayconv farfield` writes, which uses smoothing "auto" and
//   round_to_uncertainty(). Throws Error naming the file when the rays cannot give the quantity
//   (photometric: luminous flux, or radiant flux with a spectrum; radiometric: the reverse) or
//   for a step that does not divide 360 or 180.
//
// struct FarFieldOptions
//   c_step_deg       5, divides 360
//   gamma_step_deg   2.5, divides 180
//   axis             PolarAxis::plus_z (gamma from +z, the LED convention) or minus_z (nadir
//                    down); C0 is +x and C90 is +y either way
//   quantity         FarFieldQuantity::photometric (cd) or radiometric (W/sr, marked by the
//                    keyword _RADIOMETRIC)
//   smoothing        FarFieldSmoothing::none (default here: each cell's flux over its solid
//                    angle), automatic (kernel density and local fits, bandwidth per direction
//                    from the rays) or fixed (one kernel bandwidth, smoothing_deg)
//   progress         std::function<void(double)>, the fraction done
// void parse_smoothing(const std::string& text, FarFieldOptions& options);
//   "auto", "none" or a bandwidth in degrees, as `rayconv farfield --smoothing` takes it; throws
//   Error for anything else.
//
// struct FarField
//   photometry       type C, gamma 0..180, C 0..360 (the 360 plane repeats 0), absolute
//   flux, solid_angle, variance, sigma_deg
//                    per cell, indexed as photometry.candela: lm (W), sr, the variance of the
//                    intensity (its standard error squared), the kernel bandwidth (smoothed only)
//   method           how the values were made (the keyword _SMOOTHING)
//   flux_scale       smoothed: the factor that keeps the rays' flux
//   rays, total_flux, max_intensity, max_c_deg, max_gamma_deg
//
// void round_to_uncertainty(FarField& far);
//   Rounds the intensities to the digits their standard errors support (the error's second
//   significant digit), as rayconv does before writing.
// double written_flux(const FarField& far);
//   Sum of intensity x solid angle over the cells: the flux a file written from it holds.

}  // namespace rayset
