// Helpers shared by the ray operations' sources (ray_ops.cpp, ray_merge.cpp).
#pragma once

#include "converters/rays/ray.h"
#include "converters/rays/ray_stream.h"

namespace rayset::detail {

// Appends ray i of `in` and its extras to `out`.
inline void copy_ray(const RayChunk& in, size_t i, RayChunk& out) {
    out.rays.push_back(in.rays[i]);
    const size_t extras = in.rays.empty() ? 0 : in.extra.size() / in.rays.size();
    out.extra.insert(out.extra.end(), in.extra.begin() + i * extras,
                     in.extra.begin() + (i + 1) * extras);
}

// Adds the rays of `chunk` (described by `header`) to `totals`, as RayReader counts them.
inline void add_totals(RayTotals& totals, const RayHeader& header, const RayChunk& chunk) {
    for (const Ray& r : chunk.rays) {
        if (header.has_radiant) totals.radiant += r.radiant;
        if (header.has_luminous) totals.luminous += r.luminous;
        const bool zero =
            (!header.has_radiant || r.radiant == 0) && (!header.has_luminous || r.luminous == 0);
        totals.zero_flux_rays += zero;
    }
    totals.rays += chunk.rays.size();
}

}  // namespace rayset::detail
