// What `rayconv info` tells about a ray file, gathered in one streaming pass.
#pragma once

#include "converters/rays/ray_stream.h"

#include <functional>

namespace rayset {

struct RaySummary {
    uint64_t rays = 0;
    double radiant = 0, luminous = 0;  // summed as read (after scaling)
    double luminous_from_spectrum =
        std::nan("");              // radiant x V(lambda) where the spectrum is known
    Vec3f min_origin, max_origin;  // bounding box, header unit
    float min_wavelength = kUnknown, max_wavelength = kUnknown;
    uint64_t unknown_wavelength_rays = 0;
    // Flux-weighted mean direction, and the share of the sphere that directions reach, on a
    // partition into kCoverageCells cells (bands uniform in z times 200 azimuth sectors, about
    // 1.4 degrees across; the share adds the cells' exact solid angles). The widest angle from
    // the mean is measured to the centres of the reached cells, so it is exact to about a cell.
    static constexpr int kZBands = 100, kPhiBands = 200, kCoverageCells = kZBands * kPhiBands;
    Vec3f mean_direction;
    double max_angle_from_mean_deg = 0;
    double sphere_coverage = 0;  // 0..1
    uint64_t zero_flux_rays = 0;
};

// The summary's inner loop exists twice: portable (SSE2, any x86-64, or plain C++) and, where
// the CPU has it, AVX2, which `fastest` picks. Both give the same bits; tests compare them.
enum class SummaryKernel { fastest, portable };

RaySummary summarise_rays(RayReader& reader, const std::function<void(double)>& progress = {},
                          SummaryKernel kernel = SummaryKernel::fastest);

}  // namespace rayset
