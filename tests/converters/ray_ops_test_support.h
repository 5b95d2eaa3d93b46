// Small ray files made by hand for the ray operation tests (subsample, merge, transform).
#pragma once

#include "converters/rays/ray_stream.h"
#include "core/random.h"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace rayset::test {

// n rays: origin x = index (so a ray's index can be read back from it), y and z spread over a
// few mm, directions spread over the sphere, fluxes varying from ray to ray.
inline std::vector<Ray> numbered_rays(size_t n, bool radiant, bool luminous, uint64_t seed = 3) {
    Pcg32 rng(seed);
    std::vector<Ray> rays(n);
    for (size_t i = 0; i < n; ++i) {
        Ray& r = rays[i];
        r.origin = {float(i), float(rng.uniform() * 6 - 3), float(rng.uniform() * 0.5)};
        const double z = 2 * rng.uniform() - 1, phi = 6.283185307179586 * rng.uniform(),
                     s = std::sqrt(1 - z * z);
        r.direction = {float(s * std::cos(phi)), float(s * std::sin(phi)), float(z)};
        if (radiant) r.radiant = float(1e-3 * (1 + i % 7));
        if (luminous) r.luminous = float(0.25 * (1 + i % 5));
    }
    return rays;
}

inline void write_rays(const std::string& path, RayFormat format, RayHeader header,
                       const std::vector<Ray>& rays, const std::vector<float>& extra = {}) {
    header.ray_count = rays.size();
    auto out = create_rays(path, format, header);
    RayChunk chunk;
    chunk.rays = rays;
    chunk.extra = extra;
    out->write(chunk);
    out->finish();
}

struct ReadBack {
    RayHeader header;
    std::vector<Ray> rays;
    std::vector<float> extra;
    RayTotals totals;
};

inline ReadBack read_rays(const std::string& path) {
    auto reader = open_rays(path);
    ReadBack back;
    back.header = reader->header();
    RayChunk chunk;
    while (reader->read(chunk)) {
        back.rays.insert(back.rays.end(), chunk.rays.begin(), chunk.rays.end());
        back.extra.insert(back.extra.end(), chunk.extra.begin(), chunk.extra.end());
    }
    back.totals = reader->totals();
    return back;
}

inline bool same_bits(const Vec3f& a, const Vec3f& b) {
    return std::memcmp(&a, &b, sizeof(Vec3f)) == 0;
}

}  // namespace rayset::test
