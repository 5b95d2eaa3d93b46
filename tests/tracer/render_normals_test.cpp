// Normal patterns: the shading normal's tilt against closed forms and against POV-Ray's own
// renders of tiles lit by one distant light (scenes/normals.pov, deterministic patterns, pixel
// for pixel; scenes/normal_noise.pov, noise patterns, in mean and spread). What a pixel shows
// here is computed from the hit its centre ray makes as POV-Ray shades it: the pigment times
// N'.L, N' the BSDF's tilted shading normal and L toward the light. (The BSDF itself scales
// its diffuse lobe up where the normal is tilted, to keep its albedo; the furnace test with
// bumped walls in render_physics_test.cpp holds it to that.)
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

// The bump the first object's material has at `point` of a surface with outward normal `n`.
Vec3 bump_of(const std::string& object, Vec3 point, Vec3 n) {
    const RenderScene scene(parse_scene_text(object, "test.pov"));
    std::optional<Material> scratch;
    return scene.material(0, -1, point, n, scratch).bump;
}

// A gradient's value rises by 1 per unit: POV-Ray tilts the normal by 2/15 of the bump size
// per unit of slope, against the slope; a pattern scaled evenly keeps its steepness, scaled
// along the surface it steepens, across it it flattens; no_bump_scale keeps the slope of the
// scaled pattern itself.
TEST(NormalPatterns, TiltDownTheSlopeByPovRaysRule) {
    const Vec3 up{0, 1, 0}, p{0.3, 0, 0.4};
    auto tilt_x = [&](const std::string& normal) {
        return bump_of("plane { y, 0 normal { " + normal + " } }", p, up).x;
    };
    EXPECT_NEAR(tilt_x("gradient x 0.6"), -2.0 / 15 * 0.6, 1e-9);
    EXPECT_NEAR(tilt_x("gradient -x 0.6"), 2.0 / 15 * 0.6, 1e-9);
    EXPECT_NEAR(tilt_x("gradient x 0.6 scale 0.5"), -2.0 / 15 * 0.6, 1e-9);
    EXPECT_NEAR(tilt_x("gradient x 0.6 scale <0.5, 1, 1>"), -2 * 2.0 / 15 * 0.6, 1e-9);
    EXPECT_NEAR(tilt_x("gradient x 0.6 scale <1, 0.5, 1>"), -0.5 * 2.0 / 15 * 0.6, 1e-9);
    EXPECT_NEAR(tilt_x("gradient x 0.6 scale 0.5 no_bump_scale"), -2 * 2.0 / 15 * 0.6, 1e-9);
    // Turned with the pattern: gradient z turned 90 degrees about y slopes along x.
    EXPECT_NEAR(tilt_x("gradient z 0.6 rotate y*90"), -2.0 / 15 * 0.6, 1e-9);
    // A sine wave's slope: d/dx (sin(2 pi x) + 1) / 2 = pi cos(2 pi x), to the step's O(h^2).
    EXPECT_NEAR(tilt_x("gradient x 0.6 sine_wave"), -2.0 / 15 * 0.6 * kPi * std::cos(2 * kPi * p.x),
                2e-3);
    // The tilt turns with the surface: on a wall facing x the same gradient tilts nothing
    // along the wall, only lengthens the normal.
    const Vec3 wall = bump_of("plane { x, 0 normal { gradient z 0.6 } }", {0, 0.2, 0.3}, {1, 0, 0});
    EXPECT_NEAR(wall.z, -2.0 / 15 * 0.6, 1e-9);
    EXPECT_NEAR(wall.y, 0, 1e-12);
}

TEST(NormalPatterns, LitTilesAgreeWithPovRayPixelForPixel) {
    const int width = 240, height = 180;
    test::LitTiles tiles;
    if (!test::render_lit_tiles(test::tracer_scene("normals.pov"), 1e5 * Vec3{-3, 8, -2}, width,
                                height, tiles))
        GTEST_SKIP() << "povray is not installed";
    int agree = 0;
    for (size_t i = 0; i < tiles.ours.size(); ++i)
        agree += test::agrees_with_povray(tiles.ours[i], &tiles.povray[3 * i]);
    const double fraction = double(agree) / double(tiles.ours.size());
    std::printf("normals.pov: lit colours agree on %d of %zu pixels (%.4f)\n", agree,
                tiles.ours.size(), fraction);
    EXPECT_GE(fraction, 0.98);
}

// Noise normals cannot agree point for point (noise.h); what they show is the spread of
// brightness their tilts make. Each tile's brightness agrees with POV-Ray's in mean and
// standard deviation within four standard errors of their difference (a two-sided normal tail
// of 6e-5), counting one independent value per lattice cell of the pattern: a tile's middle
// 6 x 6 units hold (6 / scale)^2 cells, and with n of them the mean's standard error is
// sd / sqrt(n) and the standard deviation's relative one 1 / sqrt(2 n), for each renderer.
TEST(NormalPatterns, NoiseTiltsAgreeWithPovRayInMeanAndSpread) {
    const int width = 720, height = 480;
    test::LitTiles tiles;
    if (!test::render_lit_tiles(test::tracer_scene("normal_noise.pov"), 1e6 * Vec3{0, 1, -1}, width,
                                height, tiles))
        GTEST_SKIP() << "povray is not installed";
    struct Tile {
        const char* name;
        double scale;
    };
    const Tile tile_of[] = {{"bumps", 0.15},  {"dents", 0.2}, {"wrinkles", 0.2},
                            {"granite", 0.6}, {"bozo", 0.15}, {"crackle", 0.15}};
    // Tiles are 8 x 8 units in a 24 x 16 view, 30 pixels per unit, left to right, top row
    // first: the middle 6 x 6 units of each.
    const double z = 4;
    for (int tile = 0; tile < 6; ++tile) {
        const int cx = 120 + 240 * (tile % 3), cy = 120 + 240 * (tile / 3);
        double sum[2] = {0, 0}, squares[2] = {0, 0};
        int n = 0;
        for (int y = cy - 90; y < cy + 90; ++y)
            for (int x = cx - 90; x < cx + 90; ++x) {
                const size_t i = size_t(y) * width + x;
                const double values[2] = {tiles.ours[i].red, tiles.povray[3 * i] / 255.0};
                for (int k = 0; k < 2; ++k)
                    sum[k] += values[k], squares[k] += values[k] * values[k];
                ++n;
            }
        double mean[2], sd[2];
        for (int k = 0; k < 2; ++k) {
            mean[k] = sum[k] / n;
            sd[k] = std::sqrt(std::max(0.0, squares[k] / n - mean[k] * mean[k]));
        }
        const double cells = std::pow(6 / tile_of[tile].scale, 2);
        const double mean_bound = z * sd[1] * std::sqrt(2 / cells);
        const double sd_bound = z * sd[1] * std::sqrt(1 / cells);
        std::printf(
            "%-8s brightness mean %.4f (POV-Ray %.4f, bound %.4f), sd %.4f (POV-Ray %.4f, "
            "bound %.4f)\n",
            tile_of[tile].name, mean[0], mean[1], mean_bound, sd[0], sd[1], sd_bound);
        EXPECT_NEAR(mean[0], mean[1], mean_bound) << tile_of[tile].name;
        EXPECT_NEAR(sd[0], sd[1], sd_bound) << tile_of[tile].name;
    }
}

}  // namespace
}  // namespace rayset::tracer
