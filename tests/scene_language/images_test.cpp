// Image files read while parsing (image_map, bump_map, height_field): POV-Ray's gamma of each
// format, the colours image_map shows, the heights of a height field, and clear errors for
// files that are missing, not images or cut short.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/colour.h"
#include "scene_language/scene_test_support.h"
#include "support/image_writing.h"
#include "support/test_support.h"
#include "tracer/scene_language/image_mapping.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

using namespace scene_test;

// The image_map of the first object of `scene` (written into `dir` as s.pov).
const ImageMap& image_map_of(const test::ScratchDir& dir, const std::string& scene,
                             SceneDescription& holder) {
    test::write_file(dir.file("s.pov"), scene);
    holder = parse_scene_file(dir.file("s.pov"));
    return *holder.objects.at(0).appearance.texture->pigment.pattern->image;
}

// One 2 x 1 image (values 0.2 and 0.6 in every channel) in several formats.
TEST(Images, EachFormatDecodesWithPovRaysGamma) {
    test::ScratchDir dir;
    const std::vector<float> grey{0.2f, 0.2f, 0.2f, 0.6f, 0.6f, 0.6f};
    test::write_image(dir.file("a.png"), 2, 1, 3, grey);
    test::write_image(dir.file("a.ppm"), 2, 1, 3, grey);
    test::write_image(dir.file("a.tga"), 2, 1, 3, grey);
    test::write_image(dir.file("a.exr"), 2, 1, 3, grey, true);
    const double v8 = std::round(0.6 * 255) / 255;  // the 8-bit number written
    struct Case {
        const char* image;
        double linear;  // the second pixel's linear value
    };
    const Case cases[] = {{"png \"a.png\"", srgb_to_linear(v8)},
                          {"tga \"a.tga\"", srgb_to_linear(v8)},
                          {"ppm \"a.ppm\"", v8},
                          {"exr \"a.exr\"", double(0.6f)},
                          {"png \"a.png\" gamma 2.2", std::pow(v8, 2.2)},
                          {"ppm \"a.ppm\" gamma srgb", srgb_to_linear(v8)}};
    for (const Case& c : cases) {
        SceneDescription scene;
        const ImageMap& image = image_map_of(
            dir,
            std::string("global_settings { assumed_gamma 1 } plane { z, 0 pigment { image_map { ") +
                c.image + " } } }",
            scene);
        Colour colour;
        ASSERT_TRUE(image_map_colour(image, {0.75, 0.5, 0}, colour)) << c.image;
        EXPECT_NEAR(colour.red, c.linear, 1e-6) << c.image;
        EXPECT_NEAR(colour.blue, c.linear, 1e-6) << c.image;
        EXPECT_EQ(colour.transmit, 0) << c.image;
    }
    // Under another assumed_gamma the colours are that gamma's numbers for the same light.
    SceneDescription scene;
    const ImageMap& encoded =
        image_map_of(dir,
                     "global_settings { assumed_gamma 2.2 } plane { z, 0 pigment { image_map { "
                     "ppm \"a.ppm\" } } }",
                     scene);
    Colour colour;
    ASSERT_TRUE(image_map_colour(encoded, {0.75, 0.5, 0}, colour));
    EXPECT_NEAR(colour.red, std::pow(v8, 1 / 2.2), 1e-6);
}

// Alpha is transmit, `transmit all` and `filter all` apply to every pixel; `once` leaves the
// rest clear.
TEST(Images, AlphaFilterTransmitAndOnce) {
    test::ScratchDir dir;
    test::write_image(dir.file("rgba.png"), 1, 1, 4, {1, 0, 0, 0.4f});
    test::write_image(dir.file("rgb.png"), 1, 1, 3, {0, 1, 0});
    SceneDescription a, b;
    Colour colour;
    ASSERT_TRUE(image_map_colour(
        image_map_of(dir, "plane { z, 0 pigment { image_map { png \"rgba.png\" } } }", a),
        {0.5, 0.5, 0}, colour));
    EXPECT_NEAR(colour.transmit, 1 - std::round(0.4 * 255) / 255, 1e-6);
    const ImageMap& all = image_map_of(
        dir,
        "plane { z, 0 pigment { image_map { png \"rgb.png\" filter all 0.3 transmit all 0.2 "
        "once } } }",
        b);
    ASSERT_TRUE(image_map_colour(all, {0.5, 0.5, 0}, colour));
    EXPECT_DOUBLE_EQ(colour.filter, 0.3);
    EXPECT_DOUBLE_EQ(colour.transmit, 0.2);
    ASSERT_TRUE(image_map_colour(all, {1.5, 0.5, 0}, colour));
    EXPECT_DOUBLE_EQ(colour.transmit, 1);
}

// Heights: the image's bottom row at z = 0; grey numbers over their maximum, an 8-bit colour's
// red and green as the high and low bytes of 16 bits.
TEST(Images, HeightFieldHeightsFollowPovRaysRules) {
    test::ScratchDir dir;
    test::write_image(dir.file("g.pgm"), 3, 2, 1, {0, 0.2f, 0.4f, 0.6f, 0.8f, 1});
    test::write_image(dir.file("c.png"), 2, 2, 3,
                      {100 / 255.0f, 200 / 255.0f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
    test::write_file(dir.file("s.pov"),
                     "height_field { pgm \"g.pgm\" } height_field { png \"c.png\" }");
    const SceneDescription scene = parse_scene_file(dir.file("s.pov"));
    const HeightGrid& grey = *std::get<HeightFieldShape>(scene.objects.at(0).shape).grid;
    ASSERT_EQ(grey.columns, 3);
    ASSERT_EQ(grey.rows, 2);
    EXPECT_NEAR(grey.at(0, 0), 0.6, 1e-6);  // bottom row first
    EXPECT_NEAR(grey.at(2, 1), 0.4, 1e-6);
    const HeightGrid& colour = *std::get<HeightFieldShape>(scene.objects.at(1).shape).grid;
    EXPECT_NEAR(colour.at(0, 1), (100 * 256 + 200) / 65535.0, 1e-9);
}

TEST(Images, BadFilesAreClearErrors) {
    test::ScratchDir dir;
    auto error = [&](const std::string& scene) {
        test::write_file(dir.file("s.pov"), scene);
        return error_of_file(dir.file("s.pov"));
    };
    const std::string missing = error("plane { z, 0 pigment { image_map { png \"gone.png\" } } }");
    EXPECT_NE(missing.find("image file \"gone.png\" not found"), std::string::npos) << missing;
    EXPECT_NE(missing.find("s.pov:1:40"), std::string::npos) << missing;

    test::write_file(dir.file("text.png"), "not an image at all");
    const std::string garbage = error("plane { z, 0 pigment { image_map { png \"text.png\" } } }");
    EXPECT_NE(garbage.find("cannot read the image"), std::string::npos) << garbage;
    EXPECT_NE(garbage.find("text.png"), std::string::npos) << garbage;
    EXPECT_NE(garbage.find("(PNG, JPEG, GIF, TGA, BMP, TIFF, PPM/PGM, HDR and EXR are read)"),
              std::string::npos)
        << garbage;
    EXPECT_NE(garbage.find("s.pov:1:40"), std::string::npos) << garbage;

    std::vector<float> pixels(64 * 64 * 3, 0.5f);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = float((i * 37) % 255) / 255;
    test::write_image(dir.file("whole.png"), 64, 64, 3, pixels);
    const std::string bytes = test::read_file(dir.file("whole.png"));
    test::write_file(dir.file("cut.png"), bytes.substr(0, bytes.size() / 2));
    const std::string cut = error("height_field { png \"cut.png\" }");
    EXPECT_NE(cut.find("cut.png"), std::string::npos) << cut;
    EXPECT_NE(cut.find("s.pov:1:20"), std::string::npos) << cut;

    // Types not read (iff, pot, sys) are read as the scene, without pixels: the renderer
    // refuses them (render_images_test.cpp).
    test::write_file(dir.file("a.pot"), "GIF87a");
    test::write_file(dir.file("s.pov"), "height_field { pot \"a.pot\" }");
    const SceneDescription pot = parse_scene_file(dir.file("s.pov"));
    EXPECT_FALSE(std::get<HeightFieldShape>(pot.objects.at(0).shape).grid);
}

}  // namespace
}  // namespace rayset::tracer
