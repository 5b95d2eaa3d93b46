// RayColumns::to_rays writes four rays at a time with transposes: every field of every ray,
// in the blocks of four and in the rest, must be what ray(i) reads from the columns.
#include <gtest/gtest.h>

#include "converters/rays/ray.h"

#include <cstring>
#include <random>

namespace rayset {
namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(RayColumns, ToRaysKeepsEveryFieldOfEveryRay) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> value(-1e3f, 1e3f);
    for (size_t n : {0, 1, 3, 4, 5, 7, 8, 9, 4099}) {
        RayColumns columns;
        columns.resize(n);
        columns.first_index = 12345;
        columns.extra = {1.5f, 2.5f};
        for (size_t i = 0; i < n; ++i) {
            Ray r;
            r.origin = {value(rng), value(rng), value(rng)};
            r.direction = {value(rng), value(rng), value(rng)};
            r.radiant = value(rng);
            r.luminous = i % 3 == 0 ? kUnknown : value(rng);  // NaN must come through as NaN
            r.wavelength = i % 5 == 0 ? -0.0f : value(rng);
            r.spectrum = static_cast<int32_t>(rng() % 2000) - 1000;
            columns.set(i, r);
        }
        RayChunk chunk;
        chunk.rays.resize(n + 3);  // a chunk reused from a larger one
        columns.to_rays(chunk);
        ASSERT_EQ(chunk.size(), n);
        EXPECT_EQ(chunk.first_index, 12345u);
        EXPECT_EQ(chunk.extra, columns.extra);
        for (size_t i = 0; i < n; ++i) {
            const Ray want = columns.ray(i), got = chunk.rays[i];
            const float w[9] = {want.origin.x,    want.origin.y,    want.origin.z,
                                want.direction.x, want.direction.y, want.direction.z,
                                want.radiant,     want.luminous,    want.wavelength};
            const float g[9] = {got.origin.x,    got.origin.y,    got.origin.z,
                                got.direction.x, got.direction.y, got.direction.z,
                                got.radiant,     got.luminous,    got.wavelength};
            for (int f = 0; f < 9; ++f)
                ASSERT_TRUE(same_bits(w[f], g[f])) << "n " << n << " ray " << i << " field " << f;
            ASSERT_EQ(got.spectrum, want.spectrum) << "n " << n << " ray " << i;
        }
    }
}

}  // namespace
}  // namespace rayset
