// Goniometric diagrams from a limited set of rays: the kernel density estimate of the far field
// (converters/photometry/farfield_smoothing.h), twiced von Mises-Fisher kernels over rays binned
// at 2.5 degrees (coarser bins up to a quarter of the bandwidth), applied to the rays of each
// intensity cell.
//
// Bandwidth: chosen per direction by the Goldenshluger-Lepski rule from all the rays of the
// source (a ladder from 4 to 16 degrees), and used for that direction in every cell. The cells'
// diagrams are alike (every cell of a flat emitter has the same horizon), so their smoothing
// biases add up across cells while their noise does not: the rule is applied where the two
// meet, in the sum, which is the model's far field. With one bandwidth per direction that sum
// is exactly the kernel estimate of all the rays. Where the rule prefers a local fit for all the
// rays (a log-quadratic fit on the flanks of a narrow lobe, an edge fit toward the horizon of a
// flat emitter), every cell's kernel estimate is multiplied by the fit's ratio to the kernel
// estimate of all the rays there, so that the sum is that fit.
//
// Grid: the diagrams' resolution follows the bandwidths: the step at the horizon is a third of
// the flux-weighted lower quartile of the bandwidths chosen at probe directions (a 20 x 24
// grid), at least 40 bands x 12 sectors (the histogram's grid) and at most 256 x 512; many rays
// with a narrow lobe give a fine grid, few rays or a broad emission a coarse one. The diagram's
// cell-centre densities are the estimates there (the twiced kernel's negative values in the dark
// are 0), normalised to integrate to 1, so each cell's flux, counted from its rays, is kept.
//
// Memory: one histogram of 10368 bins (0.7 MB with its coarser levels) per cell that holds rays;
// the one of all the rays is their sum, made when the diagrams are.
#pragma once

#include "converters/photometry/farfield_smoothing.h"
#include "lightmodel/goniometric_diagram.h"

#include <memory>
#include <vector>

namespace rayset::lightmodel {

class DiagramEstimate {
public:
    // Each cell's rays: kernels only. All rays: kernels and local fits.
    static constexpr DirectionResolution kResolution{2.5, 3, 4, 16, 4, false};
    static constexpr DirectionResolution kAllRays{2.5, 3, 4, 16, 4, true};

    explicit DiagramEstimate(size_t cells);

    // A ray of intensity cell `cell` (< cells): its unit direction and flux (finite, >= 0).
    void add(size_t cell, Vec3 w, double flux);

    // The diagrams of the cells `wanted`, in that order; `bands` and `sectors` 0 choose the grid
    // from the rays (see above). Ends the adding.
    std::vector<GoniometricDiagram> diagrams(const std::vector<size_t>& wanted, int bands = 0,
                                             int sectors = 0);

private:
    std::vector<std::unique_ptr<DirectionHistogram>> cells_;  // made when the first ray comes
};

}  // namespace rayset::lightmodel
