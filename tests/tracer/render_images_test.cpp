// Image-based features in the renderer: image_map pigments, bump_map normals and height fields,
// against POV-Ray's own renders pixel for pixel and against closed forms. The images are
// written by the tests into a scratch folder beside a copy of the scene (no image files in
// the repository).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/error.h"

#include "support/image_writing.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/scene_language/shape_geometry.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

using test::agrees_with_povray;

// A pixel value of the 8 x 6 test image: every pixel another colour, in [0, 1].
float colour_value(int column, int row, int channel) {
    const int k = (column * 7 + row * 13 + channel * 5) % 17;
    return float(std::round(255.0 * k / 16)) / 255.0f;
}

// colours.png (8 x 6, 8-bit sRGB), ramp.exr (4 x 3, linear floats) and grey.pgm (5 x 4, 8-bit
// linear) in `dir`.
void write_test_images(const test::ScratchDir& dir) {
    std::vector<float> colours;
    for (int row = 0; row < 6; ++row)
        for (int column = 0; column < 8; ++column)
            for (int channel = 0; channel < 3; ++channel)
                colours.push_back(colour_value(column, row, channel));
    test::write_image(dir.file("colours.png"), 8, 6, 3, colours);
    std::vector<float> ramp;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 4; ++column)
            ramp.insert(ramp.end(),
                        {0.05f + 0.3f * column, 0.1f + 0.4f * row, 0.9f - 0.2f * column});
    test::write_image(dir.file("ramp.exr"), 4, 3, 3, ramp, true);
    std::vector<float> grey;
    for (int i = 0; i < 20; ++i) grey.push_back(float((i * 47) % 256) / 255);
    test::write_image(dir.file("grey.pgm"), 5, 4, 1, grey);
}

// The scene `name` of tests/tracer/scenes copied into `dir` beside the test images.
std::string scene_beside_images(const test::ScratchDir& dir, const std::string& name) {
    write_test_images(dir);
    const std::string scene_file = dir.file(name);
    test::write_file(scene_file, test::read_file(test::tracer_scene(name)));
    return scene_file;
}

// The share of pixels whose flat-lit colour (the emission of the surface the centre ray meets)
// agrees with POV-Ray's render; -1 when povray is not installed.
double flat_colours_agreement(const std::string& scene_file, int width, int height) {
    std::vector<uint8_t> reference;
    std::string message;
    if (!test::povray_render(scene_file, width, height, reference, message)) {
        std::printf("%s\n", message.c_str());
        return -1;
    }
    const RenderScene scene(parse_scene_file(scene_file));
    const std::vector<SurfaceHit> hits = centre_hits(scene, width, height);
    const double to_pigment = scene.units().per_square_metre();
    int agree = 0, seen = 0;
    std::optional<Material> scratch;
    for (size_t i = 0; i < hits.size(); ++i) {
        Rgb ours{};
        if (hits[i].object >= 0) ours = to_pigment * scene.material(hits[i], scratch).emission;
        agree += agrees_with_povray(ours, &reference[3 * i]);
        seen += hits[i].object >= 0;
    }
    EXPECT_GT(seen, width * height / 3);  // black in both cannot carry the agreement
    return double(agree) / double(hits.size());
}

// Planar maps repeated and once, bilinear over linear floats (EXR), normalised distance over a
// linear PPM, spherical and cylindrical maps of an sRGB PNG, all transformed.
TEST(RenderImages, ImageMapsAgreeWithPovRayPixelForPixel) {
    test::ScratchDir dir;
    const std::string scene_file = scene_beside_images(dir, "image_maps.pov");
    const double fraction = flat_colours_agreement(scene_file, 320, 240);
    if (fraction < 0) GTEST_SKIP() << "povray is not installed";
    std::printf("image_maps.pov: colours agree on %.4f of the pixels\n", fraction);
    EXPECT_GE(fraction, 0.98);
}

// The first object's bump at `point` of a surface with outward normal `n`, the scene's images
// in `dir`.
Vec3 bump_of(const test::ScratchDir& dir, const std::string& object, Vec3 point, Vec3 n) {
    test::write_file(dir.file("bump.pov"), object);
    const RenderScene scene(parse_scene_file(dir.file("bump.pov")));
    std::optional<Material> scratch;
    return scene.material(0, -1, point, n, scratch).bump;
}

// A ramp image rising by s per pixel along x: POV-Ray leans the normal against the slope by
// bump_size x s, per pixel whatever the image's size and even scale (its renders of ramps lit
// from either side); an uneven scale along x flattens it.
TEST(RenderImages, BumpMapOfARampTiltsByItsStepPerPixel) {
    test::ScratchDir dir;
    std::vector<float> ramp;
    for (int i = 0; i < 16; ++i) ramp.push_back(float(17 * i) / 255);
    test::write_image(dir.file("ramp.pgm"), 16, 1, 1, ramp);
    const double step = 17.0 / 255;
    const Vec3 up{0, 1, 0}, p{0.41, 0, 0.3};
    auto tilt = [&](const std::string& normal) {
        return bump_of(dir, "plane { y, 0 normal { " + normal + " } }", p, up);
    };
    const Vec3 plain = tilt("bump_map { pgm \"ramp.pgm\" bump_size 2 } rotate x*90");
    std::printf("ramp bump: tilt %.6f (closed form %.6f)\n", plain.x, -2 * step);
    EXPECT_NEAR(plain.x, -2 * step, 1e-6);
    EXPECT_NEAR(plain.z, 0, 1e-6);  // heights read as floats
    EXPECT_NEAR(tilt("bump_map { pgm \"ramp.pgm\" } rotate x*90").x, -0.5 * step, 1e-6);
    EXPECT_NEAR(tilt("bump_map { pgm \"ramp.pgm\" bump_size 2 } rotate x*90 scale 3").x, -2 * step,
                1e-6);
    EXPECT_NEAR(tilt("bump_map { pgm \"ramp.pgm\" bump_size 2 } rotate x*90 scale <3, 1, 1>").x,
                -2 * step / 3, 1e-6);
}

// Bump maps of colour and grey images, repeated, scaled evenly and unevenly, turned about the
// surface's normal, interpolated (2 and 4), on thin tiles lit from one side, against POV-Ray's
// render.
TEST(RenderImages, BumpMapsAgreeWithPovRayPixelForPixel) {
    test::ScratchDir dir;
    const std::string scene_file = scene_beside_images(dir, "bump_maps.pov");
    const int width = 240, height = 180;
    test::LitTiles tiles;
    if (!test::render_lit_tiles(scene_file, 1e5 * Vec3{-3, 8, -2}, width, height, tiles))
        GTEST_SKIP() << "povray is not installed";
    int agree = 0;
    for (size_t i = 0; i < tiles.ours.size(); ++i)
        agree += agrees_with_povray(tiles.ours[i], &tiles.povray[3 * i]);
    const double fraction = double(agree) / double(tiles.ours.size());
    std::printf("bump_maps.pov: lit colours agree on %d of %zu pixels (%.4f)\n", agree,
                tiles.ours.size(), fraction);
    EXPECT_GE(fraction, 0.98);
}

// The height field of `image` written as a grey PGM of `columns` x `rows` (rows from the top).
HeightFieldShape height_field_of(const test::ScratchDir& dir, int columns, int rows,
                                 const std::vector<float>& image, const std::string& more = "") {
    test::write_image(dir.file("field.pgm"), columns, rows, 1, image);
    test::write_file(dir.file("field.pov"), "height_field { pgm \"field.pgm\" " + more + " }");
    return std::get<HeightFieldShape>(parse_scene_file(dir.file("field.pov")).objects.at(0).shape);
}

// The first crossing of the vertical line down through (x, z), and its unit normal.
bool hit_from_above(const HeightFieldShape& field, double x, double z, double& y, Vec3& normal) {
    std::vector<ShapeHit> hits;
    if (!shape_hits(field, {x, 5, z}, {0, -1, 0}, hits) || hits.empty()) return false;
    const ShapeHit* first = &hits[0];
    for (const ShapeHit& h : hits)
        if (h.t < first->t) first = &h;
    y = 5 - first->t;
    normal = normalized(first->normal);
    return true;
}

// A ramp image is the plane y = x; a 2 x 2 image with one raised corner (x = 1, z = 0) is the
// two triangles POV-Ray's trace shows, split along the diagonal from (0, 1) to (1, 0): height
// x on one, 1 - z on the other. Inside is below the surface over the square.
TEST(RenderImages, HeightFieldsAreTheirTrianglesExactly) {
    test::ScratchDir dir;
    std::vector<float> ramp;
    for (int row = 0; row < 3; ++row)
        for (int i = 0; i < 6; ++i) ramp.push_back(float(51 * i) / 255);
    const HeightFieldShape plane = height_field_of(dir, 6, 3, ramp);
    double worst = 0;
    for (const auto& [x, z] : std::vector<std::pair<double, double>>{
             {0.13, 0.71}, {0.5, 0.5}, {0.92, 0.08}, {0.37, 0.99}, {0.61, 0.27}}) {
        double y = 0;
        Vec3 n;
        ASSERT_TRUE(hit_from_above(plane, x, z, y, n)) << x << ", " << z;
        worst = std::max({worst, std::abs(y - x), length(n - normalized(Vec3{-1, 1, 0}))});
    }
    std::printf("ramp field: largest error of heights and normals %.2e\n", worst);
    EXPECT_LT(worst, 1e-6);  // the 8-bit heights i / 5 read as floats

    const HeightFieldShape corner = height_field_of(dir, 2, 2, {0, 0, 0, 1});
    for (const auto& [x, z] : std::vector<std::pair<double, double>>{
             {0.7, 0.2}, {0.2, 0.7}, {0.6, 0.5}, {0.4, 0.5}, {0.5, 0.6}, {0.5, 0.4}}) {
        double y = 0;
        Vec3 n;
        ASSERT_TRUE(hit_from_above(corner, x, z, y, n));
        const bool first = x + z <= 1;
        EXPECT_NEAR(y, first ? x : 1 - z, 1e-12) << x << ", " << z;
        const Vec3 expected = normalized(first ? Vec3{-1, 1, 0} : Vec3{0, 1, 1});
        EXPECT_NEAR(length(n - expected), 0, 1e-12) << x << ", " << z;
        bool in = false;
        ASSERT_TRUE(shape_inside(corner, {x, y - 1e-9, z}, in));
        EXPECT_TRUE(in);
        ASSERT_TRUE(shape_inside(corner, {x, y + 1e-9, z}, in));
        EXPECT_FALSE(in);
    }
    bool in = true;
    ASSERT_TRUE(shape_inside(corner, {1.2, -1, 0.5}, in));
    EXPECT_FALSE(in);
    // A slanting line meets the surface where it crosses it, cell by cell.
    std::vector<ShapeHit> hits;
    ASSERT_TRUE(shape_hits(plane, {-1, 0.3, 0.4}, {1, 0, 0.05}, hits));
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 1.3, 1e-6);
    // water_level: crossings below it are not the field's.
    const HeightFieldShape watered = height_field_of(dir, 2, 2, {0, 0, 0, 1}, "water_level 0.5");
    double y = 0;
    Vec3 n;
    EXPECT_FALSE(hit_from_above(watered, 0.3, 0.5, y, n));
    EXPECT_TRUE(hit_from_above(watered, 0.55, 0.4, y, n));
}

// Height fields scaled, turned, smooth, with water, clipped by a sphere and in an intersection
// and a difference, against POV-Ray's render.
TEST(RenderImages, HeightFieldsAgreeWithPovRayPixelForPixel) {
    test::ScratchDir dir;
    const std::string scene_file = scene_beside_images(dir, "height_fields.pov");
    const double fraction = flat_colours_agreement(scene_file, 320, 240);
    if (fraction < 0) GTEST_SKIP() << "povray is not installed";
    std::printf("height_fields.pov: colours agree on %.4f of the pixels\n", fraction);
    EXPECT_GE(fraction, 0.98);
}

// What is not rendered is refused where the scene writes it, saying what to do.
TEST(RenderImages, UnreadImageTypesAndFunctionFieldsAreRefused) {
    test::ScratchDir dir;
    auto error = [&](const std::string& scene) {
        test::write_file(dir.file("s.pov"), scene);
        try {
            const RenderScene render(parse_scene_file(dir.file("s.pov")));
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    test::write_file(dir.file("a.pot"), "GIF87a");
    test::write_file(dir.file("a.iff"), "FORM");
    EXPECT_EQ(error("height_field { pot \"a.pot\" }"),
              "not supported: pot images (convert it to PNG, TGA or EXR) at " + dir.file("s.pov") +
                  ":1:1");
    const std::string iff =
        error("plane { z, 0 pigment { image_map { iff \"a.iff\" } } finish { emission 1 } }");
    EXPECT_NE(iff.find("not supported: iff images (convert it to PNG, TGA or EXR) at "),
              std::string::npos)
        << iff;
    EXPECT_NE(error("height_field { function 4, 4 { x * y } }")
                  .find("not supported: height_field of a function"),
              std::string::npos);
}

}  // namespace
}  // namespace rayset::tracer
