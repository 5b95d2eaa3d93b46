// Operations on whole ray files that stream from one or more inputs (any format open_rays reads)
// to an output of any format, in memory independent of the number of rays: random subsampling
// that keeps the total flux, merging several files into one, and geometric transforms.
#pragma once

#include "converters/rays/ray_stream.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rayset {

// What an operation wrote.
struct RayOpReport {
    RayHeader header;                   // the header given to the writer
    RayTotals totals;                   // summed over the rays written
    std::vector<std::string> warnings;  // the readers' warnings and the operation's own decisions
    std::vector<std::string> dropped;   // header fields the output format could not hold
};

using Progress = std::function<void(double)>;

// ---- subsample ---------------------------------------------------------------------------------
// Keeps exactly `count` rays, or round(fraction x rays) when count is 0, each subset of that size
// equally likely (selection sampling, Knuth's Algorithm S, driven by Pcg32(seed)). The kept rays'
// fluxes are scaled by (input total / kept total), per flux column, so the output carries the
// input's total flux. That needs the kept total before the first ray is written: a first pass
// sums it, a second pass replays the same random sequence and writes. Kept rays keep their
// order and their positions and directions bit for bit.
struct SubsampleOptions {
    uint64_t count = 0;
    double fraction = 0;
    uint64_t seed = 1;
};
RayOpReport subsample_rays(const std::string& input, const std::string& output, RayFormat format,
                           const SubsampleOptions& options, const RayReadOptions& read = {},
                           const Progress& progress = {});

// ---- merge -------------------------------------------------------------------------------------
// Concatenates the rays of several files (a white LED shipped as blue and yellow files) in the
// order given. Totals add. The inputs are unified so that one header describes every ray:
// - length unit: `unit`, else the first input's; other inputs are converted.
// - spectrum: all none -> none; single wavelengths, all equal -> single wavelength, else
//   per-ray wavelength; tables only -> the distinct tables (equal ones merged), shared table
//   when one remains for all, else per-ray table with each ray pointed at its own. Any other mix
//   (none with spectral data, wavelengths with tables) cannot be held by one header: the
//   spectral data is dropped, with a warning.
// - flux columns: a column is written when some input carries it and every input carries it or
//   can derive it from the other column and its spectrum (PhotometricWeights). When spectral
//   data is dropped, luminous flux is written wherever every input knows it, so that the
//   photometry survives. No column known for every input: Error.
// - extra columns: the union; an input without one gets NaN there (warned).
// - descriptive fields, data origin and placement: the first input's; differing placements
//   are warned. Far-field data cannot be merged with near-field data (Error).
struct MergeOptions {
    std::optional<LengthUnit> unit;
};
RayOpReport merge_rays(const std::vector<std::string>& inputs, const std::string& output,
                       RayFormat format, const MergeOptions& options = {},
                       const RayReadOptions& read = {}, const Progress& progress = {});

// ---- transform ---------------------------------------------------------------------------------
using Matrix3 = std::array<double, 9>;  // row-major
inline constexpr Matrix3 kIdentity3{1, 0, 0, 0, 1, 0, 0, 0, 1};

// Rotation by `degrees` about `axis` (any length but zero), right-handed.
Matrix3 rotation_about_axis(const std::array<double, 3>& axis, double degrees);
Matrix3 multiply(const Matrix3& a, const Matrix3& b);  // a x b: b applies first
Matrix3 transpose(const Matrix3& m);                   // the inverse of a rotation

// origin' = rotation x (scale x origin converted to `unit`) + translation;
// direction' = rotation x direction, renormalised (untouched when the rotation is the identity).
// Polarisation ellipse axes (TM-25 extras) rotate with the directions. The header's data origin is
// a point of the rays' frame and moves with them; a Zemax placement says where that frame sits in a
// system and only has its length converted to the new unit.
struct RayTransform {
    std::optional<LengthUnit> unit;  // convert lengths first; default: keep
    double scale = 1;                // uniform, > 0
    Matrix3 rotation = kIdentity3;   // proper rotation (checked to 1e-6)
    std::array<double, 3> translation{0, 0, 0};
    std::optional<LengthUnit> translation_unit;  // default: the output's unit
};

// Applies a transform to chunks of rays described by one header; built once per input.
class RayTransformer {
public:
    // Checks the transform (naming `file` in errors) and prepares the output header.
    RayTransformer(const RayTransform& transform, const RayHeader& header, const std::string& file);
    const RayHeader& header() const { return header_; }
    void apply(RayChunk& chunk) const;

private:
    RayHeader header_;
    Matrix3 linear_;  // rotation x scale x unit factor
    Matrix3 rotation_;
    std::array<double, 3> translation_;
    bool rotates_ = false;                    // an identity rotation leaves directions bit for bit
    std::array<int, 3> ellipse_{-1, -1, -1};  // extras holding the polarisation ellipse axis
    size_t extras_ = 0;
};

RayOpReport transform_rays(const std::string& input, const std::string& output, RayFormat format,
                           const RayTransform& transform, const RayReadOptions& read = {},
                           const Progress& progress = {});

}  // namespace rayset
