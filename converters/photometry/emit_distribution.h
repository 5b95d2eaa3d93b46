// The intensity distribution of a type C photometry as emit() samples it: the stored symmetry
// unfolded to the full sphere and the intensity bilinear in (C, gamma) between grid angles, the
// same function Photometry::intensity() evaluates. Its flux is integrated exactly and directions
// are drawn from it exactly (see docs/synthetic-sources.md, "Photometry to rays").
#pragma once

#include "converters/photometry/photometry.h"
#include "core/random.h"

#include <string>
#include <vector>

namespace rayset {

class IntensityDistribution {
public:
    // Throws Error (naming `name`) for types A and B, negative or non-finite candela values,
    // angles out of range, and a distribution without flux.
    IntensityDistribution(const Photometry& photometry, const std::string& name);

    // Exact integral over the sphere of the interpolated intensity: lm for a candela table (W for
    // a radiometric one). It differs from Photometry::total_flux(), a zonal sum, by the
    // quadrature error of that sum.
    double total_flux() const { return total_; }
    // Interpolated intensity at C and gamma in degrees (gamma 0..180, C any).
    double intensity(double c_deg, double gamma_deg) const;
    // A direction drawn with density proportional to the intensity: C in [0, 360), gamma in
    // [0, 180], degrees.
    void sample(Pcg32& rng, double& c_deg, double& gamma_deg) const;

private:
    double value(size_t k, size_t j) const { return values_[k * gamma_.size() + j]; }
    // Fills cumulative_, sin_max_ and total_ from the nodes and their values.
    void integrate_cells();

    std::vector<double> c_;           // unfolded C nodes, c_.front() + 360 == c_.back()
    std::vector<double> gamma_;       // stored gamma nodes
    std::vector<double> values_;      // [k * gamma_.size() + j]
    std::vector<double> cumulative_;  // running flux over cells (k, j), k-major
    std::vector<double> sin_max_;     // largest sin(gamma) in each gamma band
    double total_ = 0;
};

}  // namespace rayset
