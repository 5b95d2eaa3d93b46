// Tests of the appearance grammar: pigments, patterns and their modifiers, maps and lists,
// normals, finishes, textures (plain, patterned, layered), interiors and media, material,
// #default, and the parse-time evaluation of patterns and pigments. Values are worked out by
// hand from the text; where POV-Ray's behaviour is not in its manual, the comment says it was
// checked with POV-Ray 3.7.0 (function { pigment { ... } } and #debug, or a rendered pixel).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "scene_language/scene_test_support.h"
#include "support/image_writing.h"
#include "support/test_support.h"
#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

using namespace scene_test;

// The appearance of `sphere { 0, 1 MODIFIERS }` after `declarations`.
ObjectAppearance appearance_of(const std::string& modifiers, const std::string& declarations = "") {
    const SceneDescription s = parse(declarations + "\nsphere { 0, 1 " + modifiers + " }");
    return s.objects.at(0).appearance;
}

// A copy: the appearance it comes from is a temporary.
Texture texture_of(const ObjectAppearance& a) { return *a.texture; }

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

std::string arguments(Vec3 p) {
    return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")";
}

// The colour `function { pigment { BODY } }` gives at a point, through the scene language.
Colour pigment_at(const std::string& body, Vec3 p, const std::string& declarations = "") {
    const std::string call = "F" + arguments(p);
    const SceneDescription s =
        parse(declarations + "\n#declare F = function { pigment { " + body + " } }\n" +
              "camera { location <" + call + ".red, " + call + ".green, " + call + ".blue> " +
              "sky <" + call + ".filter, " + call + ".transmit, 1> }");
    return {s.camera.location.x, s.camera.location.y, s.camera.location.z, s.camera.sky.x,
            s.camera.sky.y};
}

// The value `function { pattern { BODY } }` gives at a point.
double pattern_at(const std::string& body, Vec3 p) {
    const SceneDescription s = parse("#declare F = function { pattern { " + body +
                                     " } }\ncamera { location F" + arguments(p) + " }");
    return s.camera.location.x;
}

void expect_colour(const Colour& c, double r, double g, double b, double tolerance = 1e-9) {
    EXPECT_NEAR(c.red, r, tolerance);
    EXPECT_NEAR(c.green, g, tolerance);
    EXPECT_NEAR(c.blue, b, tolerance);
}

// ---------------------------------------------------------------- pigments

TEST(CopyOnWrite, CopiesShareTheirValueUntilOneIsEdited) {
    const CopyOnWrite<Finish> a;
    CopyOnWrite<Finish> b = a;
    EXPECT_EQ(&*a, &*b);                      // one default value for both
    EXPECT_EQ(&*a, &*CopyOnWrite<Finish>());  // and for every other default
    b.edit().diffuse = 0.9;
    EXPECT_NE(&*a, &*b);
    EXPECT_DOUBLE_EQ(a->diffuse, 0.6);  // POV-Ray's default, unchanged
    EXPECT_DOUBLE_EQ(b->diffuse, 0.9);
    const Finish* own = &*b;
    b.edit().phong = 1;
    EXPECT_EQ(&*b, own);  // once its own, edited in place
}

TEST(AppearancePigments, SolidColourAndDefaults) {
    const Texture t =
        texture_of(appearance_of("pigment { rgbf <1, 0.5, 0.25, 0.1> quick_color rgb 1 }"));
    EXPECT_EQ(t.kind, Texture::Kind::plain);
    EXPECT_EQ(t.pigment.pattern->kind, PatternKind::plain);
    expect_colour(t.pigment.colour, 1, 0.5, 0.25);
    EXPECT_FLOAT_EQ(t.pigment.colour.filter, 0.1);
    EXPECT_TRUE(t.pigment.quick_colour_given);
    EXPECT_DOUBLE_EQ(t.pigment.quick_colour.green, 1);
    EXPECT_EQ(t.pigment.location.line, 2);
    EXPECT_FALSE(t.normal);
    // POV-Ray's default finish.
    EXPECT_DOUBLE_EQ(t.finish->ambient.red, 0.1);
    EXPECT_DOUBLE_EQ(t.finish->diffuse, 0.6);
    EXPECT_DOUBLE_EQ(t.finish->phong_size, 40);
    EXPECT_DOUBLE_EQ(t.finish->roughness, 0.05);
    // An empty pigment is POV-Ray's default: black.
    expect_colour(texture_of(appearance_of("pigment { }")).pigment.colour, 0, 0, 0);
}

TEST(AppearancePigments, PatternWithColourMapOldAndNewEntries) {
    const Pigment p =
        texture_of(
            appearance_of("pigment { gradient <0, 2, 0> color_map { [0.1 rgb 1] [0.3, color red 1]"
                          " [0.5 0.7 color rgb 0.2 color rgb 0.4] } }"))
            .pigment;
    EXPECT_EQ(p.pattern->kind, PatternKind::gradient);
    expect_vec(p.pattern->gradient, {0, 2, 0});
    EXPECT_EQ(p.pattern->location.line, 2);
    EXPECT_EQ(p.pattern->location.column, 25);
    ASSERT_TRUE(p.map);
    EXPECT_EQ(p.map->kind, BlendMapKind::colour);
    ASSERT_EQ(p.map->entries.size(), 4u);  // the old two-value entry is two entries
    EXPECT_DOUBLE_EQ(p.map->entries[0].value, 0.1);
    EXPECT_DOUBLE_EQ(p.map->entries[0].colour.blue, 1);
    EXPECT_DOUBLE_EQ(p.map->entries[0].colour.transmit, 0);  // rgb: three terms
    EXPECT_DOUBLE_EQ(p.map->entries[1].colour.red, 1);
    EXPECT_DOUBLE_EQ(p.map->entries[2].value, 0.5);
    EXPECT_FLOAT_EQ(p.map->entries[2].colour.red, 0.2);
    EXPECT_FLOAT_EQ(p.map->entries[3].value, 0.7);
    EXPECT_FLOAT_EQ(p.map->entries[3].colour.red, 0.4);
    EXPECT_EQ(p.pattern->waveform, Waveform::ramp);
}

TEST(AppearancePigments, BlockPatternListsTakeBuiltInItemsForMissingOnes) {
    // checker rgb <1,0,0>: the second item is POV-Ray's own green (checked with POV-Ray 3.7).
    const Pigment p = texture_of(appearance_of("pigment { checker rgb <1, 0, 0> }")).pigment;
    ASSERT_TRUE(p.map);
    ASSERT_EQ(p.map->entries.size(), 2u);
    EXPECT_DOUBLE_EQ(p.map->entries[0].colour.red, 1);
    EXPECT_DOUBLE_EQ(p.map->entries[1].value, 1);
    EXPECT_DOUBLE_EQ(p.map->entries[1].colour.green, 1);
    // Pigments in a list; no list: the built-in one, null.
    const Pigment q =
        texture_of(appearance_of("pigment { hexagon pigment { rgb 1 }, pigment { gradient x } }"))
            .pigment;
    ASSERT_EQ(q.map->entries.size(), 3u);
    EXPECT_EQ(q.map->kind, BlendMapKind::pigment);
    EXPECT_EQ(q.map->entries[1].pigment->pattern->kind, PatternKind::gradient);
    EXPECT_DOUBLE_EQ(q.map->entries[2].pigment->colour.red, 1);  // hexagon's built-in third: red
    EXPECT_FALSE(texture_of(appearance_of("pigment { brick }")).pigment.map);
    EXPECT_DOUBLE_EQ(builtin_colour_map(PatternKind::brick).entries[1].colour.green, 0.15);
    // A new block pattern drops an identifier's list (checked with POV-Ray 3.7).
    EXPECT_FALSE(texture_of(appearance_of("pigment { P hexagon }",
                                          "#declare P = pigment { checker rgb 1, rgb 0 }"))
                     .pigment.map);
    // The object pattern takes its list inside its braces.
    const Pigment o = texture_of(appearance_of("pigment { object { S rgb 1, rgb <0, 1, 0> } }",
                                               "#declare S = sphere { 0, 1 }"))
                          .pigment;
    EXPECT_EQ(o.pattern->kind, PatternKind::object);
    ASSERT_TRUE(o.pattern->object);
    EXPECT_DOUBLE_EQ(o.map->entries[1].colour.green, 1);
}

TEST(AppearancePigments, PigmentMapEntriesAndTheirTransforms) {
    const Pigment p =
        texture_of(
            appearance_of(
                "pigment { gradient x translate x pigment_map { [0 P] [0.5, checker rgb 1, rgb 0 "
                "scale 2] [1 rgb <0, 0, 1>] } }",
                "#declare P = pigment { wood }"))
            .pigment;
    ASSERT_EQ(p.map->entries.size(), 3u);
    EXPECT_EQ(p.map->kind, BlendMapKind::pigment);
    EXPECT_EQ(p.map->entries[0].pigment->pattern->kind, PatternKind::wood);
    EXPECT_EQ(p.map->entries[0].pigment->pattern->waveform, Waveform::triangle);  // wood's own
    // The translate written before the map moves every entry too (checked with POV-Ray 3.7).
    const std::vector<Warp>& warps = p.map->entries[1].pigment->pattern->warps;
    ASSERT_EQ(warps.size(), 1u);  // scale 2 then the translate: one transform
    expect_vec(warps[0].transform.point({1, 1, 1}), {3, 2, 2});
    ASSERT_EQ(p.map->entries[2].pigment->pattern->warps.size(), 1u);
    ASSERT_EQ(p.pattern->warps.size(), 1u);
    expect_vec(p.pattern->warps[0].transform.point({0, 0, 0}), {1, 0, 0});
}

TEST(AppearancePigments, ImageMapAndItsModifiers) {
    test::ScratchDir dir;
    test::write_image(dir.file("a.png"), 1, 1, 3, {0.5f, 0.5f, 0.5f});
    const std::string text =
        "sphere { 0, 1 pigment { image_map { png \"a.png\" gamma srgb premultiplied on map_type 1 "
        "once interpolate 2 filter 3, 0.5 transmit all 0.25 } rotate x } }";
    test::write_file(dir.file("s.pov"), text);
    const SceneDescription s = parse_scene_file(dir.file("s.pov"));
    const Pigment& p = s.objects.at(0).appearance.texture->pigment;
    EXPECT_EQ(p.pattern->kind, PatternKind::image_map);
    const ImageMap& image = *p.pattern->image;
    EXPECT_EQ(image.file_type, "png");
    EXPECT_EQ(image.path, std::filesystem::canonical(dir.file("a.png")).string());
    EXPECT_TRUE(image.gamma_given && image.gamma_srgb);
    EXPECT_TRUE(image.premultiplied_given && image.premultiplied);
    EXPECT_EQ(image.map_type, 1);
    EXPECT_TRUE(image.once);
    EXPECT_EQ(image.interpolate, 2);
    ASSERT_EQ(image.filter.size(), 1u);
    EXPECT_EQ(image.filter[0].index, 3);
    EXPECT_DOUBLE_EQ(image.filter[0].amount, 0.5);
    ASSERT_EQ(image.transmit.size(), 1u);
    EXPECT_EQ(image.transmit[0].index, -1);  // all
    EXPECT_EQ(p.pattern->warps.size(), 1u);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { image_map { png \"missing.png\" } } }")
                  .find("image file \"missing.png\" "
                        "not found"),
              std::string::npos);
}

// ---------------------------------------------------------------- patterns and modifiers

TEST(AppearancePatterns, ParametersOfEachKind) {
    auto pattern = [](const std::string& body, const std::string& declarations = "") {
        return *texture_of(appearance_of("pigment { " + body + " }", declarations)).pigment.pattern;
    };
    Pattern p = pattern("brick brick_size <2, 1, 3> mortar 0.2");
    expect_vec(p.brick_size, {2, 1, 3});
    EXPECT_DOUBLE_EQ(p.mortar, 0.2);
    p = pattern("crackle form <1, 0, 0> metric 3 offset 0.5 solid");
    expect_vec(p.crackle.form, {1, 0, 0});
    EXPECT_DOUBLE_EQ(p.crackle.metric, 3);
    EXPECT_DOUBLE_EQ(p.crackle.offset, 0.5);
    EXPECT_TRUE(p.crackle.solid);
    p = pattern("julia <0.353, 0.288>, 30 exponent 3 interior 1, 0.5 exterior 2, 2");
    EXPECT_EQ(p.kind, PatternKind::julia);
    EXPECT_DOUBLE_EQ(p.fractal.julia_real, 0.353);
    EXPECT_DOUBLE_EQ(p.fractal.julia_imaginary, 0.288);
    EXPECT_EQ(p.fractal.iterations, 30);
    EXPECT_EQ(p.fractal.exponent, 3);
    EXPECT_EQ(p.fractal.interior_type, 1);
    EXPECT_DOUBLE_EQ(p.fractal.interior_factor, 0.5);
    EXPECT_EQ(p.fractal.exterior_type, 2);
    p = pattern("magnet 2 mandel 12");
    EXPECT_EQ(p.kind, PatternKind::mandel);
    EXPECT_EQ(p.fractal.magnet, 2);
    EXPECT_EQ(p.fractal.iterations, 12);
    EXPECT_EQ(p.fractal.exterior_type, 1);  // POV-Ray's defaults: exterior 1, interior 0
    EXPECT_EQ(p.fractal.interior_type, 0);
    p = pattern("slope { <0, -1, 0>, 0, 0.5 altitude y, -3, 2 }");
    expect_vec(p.slope.direction, {0, -1, 0});
    EXPECT_DOUBLE_EQ(p.slope.high_slope, 0.5);
    EXPECT_TRUE(p.slope.altitude_given);
    EXPECT_DOUBLE_EQ(p.slope.low_altitude, -3);
    p = pattern("slope -z");  // the older form without braces, which POV-Ray 3.7 reads
    expect_vec(p.slope.direction, {0, 0, -1});
    EXPECT_FALSE(p.slope.altitude_given);
    p = pattern("slope { point_at <1, 2, 3> }");
    EXPECT_TRUE(p.slope.point_at);
    EXPECT_DOUBLE_EQ(p.slope.high_slope, 1);
    p = pattern("spiral1 5");
    EXPECT_EQ(p.spiral_arms, 5);
    EXPECT_EQ(p.waveform, Waveform::triangle);  // spiral1's default (reference 3.4.7.1.25)
    EXPECT_EQ(pattern("tiling 27").tiling, 27);
    p = pattern(
        "pavement number_of_sides 4 number_of_tiles 5 pattern 3 exterior 1 interior 2 form 3");
    EXPECT_EQ(p.pavement.sides, 4);
    EXPECT_EQ(p.pavement.tiles, 5);
    EXPECT_EQ(p.pavement.pattern, 3);
    EXPECT_EQ(p.pavement.exterior, 1);
    EXPECT_EQ(p.pavement.interior, 2);
    EXPECT_EQ(p.pavement.form, 3);
    p = pattern("quilted control0 0.2 control1 0.7");
    EXPECT_DOUBLE_EQ(p.quilted_control0, 0.2);
    EXPECT_DOUBLE_EQ(p.quilted_control1, 0.7);
    EXPECT_DOUBLE_EQ(pattern("agate agate_turb 0.3").agate_turbulence, 0.3);
    EXPECT_TRUE(pattern("function { x + y }").function);
    p = pattern("pigment_pattern { checker rgb 1, rgb 0 scale 2 }");
    ASSERT_TRUE(p.pigment);
    EXPECT_EQ(p.pigment->pattern->kind, PatternKind::checker);
    EXPECT_EQ(pattern("uv_mapping spiral2 8").uv_mapping, true);
}

TEST(AppearancePatterns, ModifiersWarpsAndTheirOrder) {
    const Pattern p =
        *texture_of(
             appearance_of(
                 "pigment { wood turbulence <0.5, 0.2, 0.1> octaves 3 omega 0.3 lambda 1.5 "
                 "translate x scale 2 warp { repeat 2*x offset z flip <1, 1, 0> } rotate 90*y "
                 "warp { black_hole <1, 1, 1>, 0.5 strength 2 falloff 3 inverse type 1 "
                 "repeat <2, 2, 2> turbulence 0.1 } warp { turbulence 0.4 octaves 2 } "
                 "warp { toroidal orientation y dist_exp 1 major_radius 2 } warp { planar y, 2 } "
                 "warp { cubic } frequency 2 phase 0.25 poly_wave 3 noise_generator 3 }"))
             .pigment.pattern;
    expect_vec(p.turbulence.amount, {0.5, 0.2, 0.1});
    EXPECT_EQ(p.turbulence.octaves, 3);
    EXPECT_DOUBLE_EQ(p.turbulence.omega, 0.3);
    EXPECT_DOUBLE_EQ(p.turbulence.lambda, 1.5);
    ASSERT_EQ(p.warps.size(), 8u);
    EXPECT_EQ(p.warps[0].kind, Warp::Kind::transform);  // translate x scale 2: one transform
    expect_vec(p.warps[0].transform.point({0, 0, 0}), {2, 0, 0});
    EXPECT_EQ(p.warps[1].kind, Warp::Kind::repeat);
    expect_vec(p.warps[1].repeat, {2, 0, 0});
    expect_vec(p.warps[1].offset, {0, 0, 1});
    expect_vec(p.warps[1].flip, {1, 1, 0});
    EXPECT_EQ(p.warps[2].kind, Warp::Kind::transform);
    expect_vec(p.warps[2].transform.point({1, 0, 0}), {0, 0, -1}, 1e-12);
    const Warp& hole = p.warps[3];
    EXPECT_EQ(hole.kind, Warp::Kind::black_hole);
    expect_vec(hole.centre, {1, 1, 1});
    EXPECT_DOUBLE_EQ(hole.radius, 0.5);
    EXPECT_DOUBLE_EQ(hole.strength, 2);
    EXPECT_DOUBLE_EQ(hole.falloff, 3);
    EXPECT_TRUE(hole.inverse);
    EXPECT_EQ(hole.black_hole_type, 1);
    expect_vec(hole.black_hole_repeat, {2, 2, 2});
    expect_vec(hole.black_hole_turbulence, {0.1, 0.1, 0.1});
    EXPECT_EQ(p.warps[4].kind, Warp::Kind::turbulence);
    EXPECT_EQ(p.warps[4].turbulence.octaves, 2);
    EXPECT_DOUBLE_EQ(p.warps[4].turbulence.omega, 0.5);  // the default
    EXPECT_EQ(p.warps[5].kind, Warp::Kind::toroidal);
    expect_vec(p.warps[5].orientation, {0, 1, 0});
    EXPECT_DOUBLE_EQ(p.warps[5].distance_exponent, 1);
    EXPECT_DOUBLE_EQ(p.warps[5].major_radius, 2);
    EXPECT_EQ(p.warps[6].kind, Warp::Kind::planar);
    EXPECT_DOUBLE_EQ(p.warps[6].plane_distance, 2);
    EXPECT_EQ(p.warps[7].kind, Warp::Kind::cubic);
    EXPECT_DOUBLE_EQ(p.frequency, 2);
    EXPECT_TRUE(p.frequency_written);
    EXPECT_DOUBLE_EQ(p.phase, 0.25);
    EXPECT_EQ(p.waveform, Waveform::poly);
    EXPECT_DOUBLE_EQ(p.poly_exponent, 3);
    EXPECT_EQ(p.noise_generator, 3);
    // A cylindrical warp keeps its defaults.
    const Warp w = texture_of(appearance_of("pigment { checker warp { cylindrical } }"))
                       .pigment.pattern->warps.at(0);
    expect_vec(w.orientation, {0, 0, 1});
    EXPECT_DOUBLE_EQ(w.distance_exponent, 0);
}

TEST(AppearancePatterns, ErrorsNameTheRule) {
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { gradient x mortar 0.2 } }"),
              "'mortar' can only be used with brick, found with gradient at test.pov:1:36");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { checker color_map { [0 rgb 1] } } }"),
              "'color_map' cannot be used with the checker pattern (POV-Ray's rule: it takes a "
              "list or its image) at "
              "test.pov:1:33");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { scale 2 gradient x } }"),
              "the pigment type ('gradient') must come first in 'pigment' opened at test.pov:1:23, "
              "before its "
              "modifiers (POV-Ray's rule) at test.pov:1:33");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { tiling 28 } }"),
              "the tiling number must be between 1 and 27, found 28 at test.pov:1:32");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { magnet 3 mandel 10 } }"),
              "the magnet type must be 1 or 2, found 3 at test.pov:1:32");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { facets } }"),
              "'facets' can only be used in a normal, found in a pigment at test.pov:1:25");
    EXPECT_EQ(
        error_of("sphere { 0, 1 pigment { gradient x warp { repeat <1, 1, 0> } } }"),
        "a repeat warp repeats along one axis only (two components must be 0) at test.pov:1:43");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { gradient x noise_generator 4 } }"),
              "noise_generator must be 0, 1, 2 or 3, found 4 at test.pov:1:52");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { mandel 10 interior 7, 1 } }"),
              "the fractal interior type must be 0 to 6, found 7 at test.pov:1:44");
    // Pattern functions in POV-Ray 3.7 take no square, triangular, tiling, pavement, slope, aoi
    // or average (checked with POV-Ray 3.7).
    EXPECT_EQ(error_of("#declare F = function { pattern { square } }"),
              "'square' can only be used in a pigment, normal, texture or density (not a pattern "
              "function, in POV-Ray "
              "3.7), found in a pattern at test.pov:1:35");
    EXPECT_EQ(error_of("#declare F = function { pattern { gradient x color_map { [0 rgb 1] } } }"),
              "expected a pattern modifier or '}' to close 'pattern' opened at test.pov:1:33, "
              "found 'color_map' at "
              "test.pov:1:46");
}

// ---------------------------------------------------------------- maps

TEST(AppearanceMaps, DeclaredMapsLimitsAndEntries) {
    const SceneDescription s = parse(R"(
        #declare C = color_map { [0 rgb 0] [1 rgb 1] }
        #declare T1 = texture { pigment { rgb 0 } }
        #declare T = texture_map { [0 pigment { rgb 1 }] [1 T1] }
        #declare D = density_map { [0 rgb 0] [1 spherical] }
        sphere { 0, 1 texture { gradient y texture_map { T } } hollow
                 interior { media { density { gradient x density_map { D } }
                                    density { bozo color_map { C } } } } }
    )");
    const ObjectAppearance& a = s.objects.at(0).appearance;
    ASSERT_EQ(a.texture->map->entries.size(), 2u);
    EXPECT_EQ(a.texture->map->kind, BlendMapKind::texture);
    EXPECT_DOUBLE_EQ(a.texture->map->entries[0].texture->pigment.colour.red, 1);
    const Media& m = *a.interior->media.at(0);
    EXPECT_EQ(m.densities.at(0).item->map->kind, BlendMapKind::density);
    EXPECT_EQ(m.densities.at(0).item->map->entries[1].pigment->pattern->kind,
              PatternKind::spherical);
    EXPECT_EQ(m.densities.at(1).item->map->kind, BlendMapKind::colour);
    EXPECT_EQ(error_of("#declare M = color_map { }"),
              "expected at least one '[' entry in 'color_map' (POV-Ray's rule), found '}' at "
              "test.pov:1:26");
    std::string many = "#declare M = color_map {";
    for (int i = 0; i <= 256; ++i) many += " [0 rgb 1]";
    EXPECT_EQ(error_of(many + " }"),
              "'color_map' has more than 256 entries (POV-Ray's limit) at test.pov:1:2586");
    const Normal n =
        *texture_of(appearance_of("normal { gradient x slope_map { S } }",
                                  "#declare S = slope_map { [0 <0, 1>] [0.5, <1, -1>] }"))
             .normal;
    ASSERT_EQ(n.map->kind, BlendMapKind::slope);
    EXPECT_DOUBLE_EQ(n.map->entries[1].value, 0.5);
    EXPECT_DOUBLE_EQ(n.map->entries[1].height, 1);
    EXPECT_DOUBLE_EQ(n.map->entries[1].slope, -1);
    // average: weights may be left out (1) in its own map only (checked with POV-Ray 3.7).
    const Pigment average =
        texture_of(appearance_of("pigment { average pigment_map { [gradient x] [2 bumps] } }"))
            .pigment;
    EXPECT_DOUBLE_EQ(average.map->entries[0].value, 1);
    EXPECT_DOUBLE_EQ(average.map->entries[1].value, 2);
    EXPECT_EQ(error_of("#declare M = pigment_map { [gradient x] }"),
              "expected a numeric expression, found 'gradient' at test.pov:1:29");
    EXPECT_EQ(error_of("#declare M = color_map { [0 rgb 1] }\nsphere { 0, 1 pigment { gradient x "
                       "pigment_map { M } } }"),
              "wrong type: 'M' is a color_map, expected a pigment_map identifier or '[' entries at "
              "test.pov:2:50");
}

// ---------------------------------------------------------------- normals

TEST(AppearanceNormals, AmountMapsAndModifiers) {
    auto normal = [](const std::string& body) {
        return *texture_of(appearance_of("normal { " + body + " }")).normal;
    };
    EXPECT_DOUBLE_EQ(normal("bumps").amount, 0.5);  // POV-Ray's default
    EXPECT_DOUBLE_EQ(normal("bumps 0.3 scale 0.2").amount, 0.3);
    Normal n = normal("gradient x, -0.5 accuracy 0.01 no_bump_scale");
    EXPECT_DOUBLE_EQ(n.amount, -0.5);
    EXPECT_DOUBLE_EQ(n.accuracy, 0.01);
    EXPECT_TRUE(n.no_bump_scale);
    n = normal("spiral1 3, 0.7 bump_size 2");
    EXPECT_EQ(n.pattern->spiral_arms, 3);
    EXPECT_DOUBLE_EQ(n.amount, 2);
    n = normal("checker 0.4 normal { gradient x scale 0.2 }, normal { bumps }");
    EXPECT_DOUBLE_EQ(n.amount, 0.4);
    ASSERT_EQ(n.map->kind, BlendMapKind::normal);
    EXPECT_EQ(n.map->entries[1].normal->pattern->kind, PatternKind::bumps);
    n = normal("gradient y normal_map { [0.3 bumps scale 2] [0.9 marble turbulence 1] }");
    ASSERT_EQ(n.map->entries.size(), 2u);
    EXPECT_DOUBLE_EQ(n.map->entries[1].normal->pattern->turbulence.amount.x, 1);
    n = normal("facets coords 0.5");
    EXPECT_DOUBLE_EQ(n.pattern->facets_coords, 0.5);
    EXPECT_EQ(error_of("sphere { 0, 1 normal { checker slope_map { [0 <0, 1>] } } }"),
              "'slope_map' cannot be used with the checker pattern (POV-Ray's rule: it takes a "
              "list or its image) at "
              "test.pov:1:32");
}

// ---------------------------------------------------------------- finish

TEST(AppearanceFinish, EveryKeyword) {
    std::string warnings;
    ParseOptions options;
    options.on_message = [&](MessageStream, const std::string& text) { warnings += text; };
    const SceneDescription s = parse(
        "sphere { 0, 1 finish { ambient rgb <0.1, 0.2, 0.3> emission 0.5 diffuse albedo 0.7, 0.2 "
        "brilliance 3 "
        "crand 0.05 phong albedo 0.9 phong_size 60 specular 0.4 roughness 0.02 metallic "
        "conserve_energy "
        "reflection { 0.03, 1 fresnel on falloff 2 exponent 0.8 metallic 0.4 } irid { 0.35 "
        "thickness 0.5 "
        "turbulence 0.2 } subsurface { translucency <1, 0.5, 0.25> } ior 1.4 } }",
        options);
    const Finish& f = *s.objects.at(0).appearance.texture->finish;
    EXPECT_FLOAT_EQ(f.ambient.blue, 0.3);
    EXPECT_DOUBLE_EQ(f.emission.green, 0.5);
    EXPECT_DOUBLE_EQ(f.diffuse, 0.7);
    EXPECT_TRUE(f.diffuse_albedo);
    EXPECT_DOUBLE_EQ(f.diffuse_back, 0.2);
    EXPECT_DOUBLE_EQ(f.brilliance, 3);
    EXPECT_DOUBLE_EQ(f.crand, 0.05);
    EXPECT_DOUBLE_EQ(f.phong, 0.9);
    EXPECT_TRUE(f.phong_albedo);
    EXPECT_DOUBLE_EQ(f.phong_size, 60);
    EXPECT_DOUBLE_EQ(f.specular, 0.4);
    EXPECT_FALSE(f.specular_albedo);
    EXPECT_DOUBLE_EQ(f.roughness, 0.02);
    EXPECT_DOUBLE_EQ(f.metallic, 1);  // metallic without a value
    EXPECT_TRUE(f.conserve_energy);
    EXPECT_FLOAT_EQ(f.reflection_min.red, 0.03);
    EXPECT_DOUBLE_EQ(f.reflection_max.red, 1);
    EXPECT_TRUE(f.reflection_fresnel);
    EXPECT_DOUBLE_EQ(f.reflection_falloff, 2);
    EXPECT_DOUBLE_EQ(f.reflection_exponent, 0.8);
    EXPECT_DOUBLE_EQ(f.reflection_metallic, 0.4);
    EXPECT_DOUBLE_EQ(f.irid_amount, 0.35);
    EXPECT_DOUBLE_EQ(f.irid_thickness, 0.5);
    EXPECT_DOUBLE_EQ(f.irid_turbulence, 0.2);
    EXPECT_TRUE(f.subsurface);
    EXPECT_DOUBLE_EQ(f.translucency.blue, 0.25);
    EXPECT_DOUBLE_EQ(f.legacy_ior, 1.4);  // POV-Ray reads it with a warning
    EXPECT_NE(warnings.find("'ior' belongs in interior { }"), std::string::npos);
    const Finish g =
        *texture_of(appearance_of("finish { reflection 0.4 reflection_exponent 2 }")).finish;
    EXPECT_FLOAT_EQ(g.reflection_min.green, 0.4);
    EXPECT_FLOAT_EQ(g.reflection_max.green, 0.4);
    EXPECT_DOUBLE_EQ(g.reflection_exponent, 2);
    EXPECT_EQ(error_of("sphere { 0, 1 finish { fade_distance 2 } }"),
              "expected a finish keyword or '}' to close 'finish' opened at test.pov:1:22, found "
              "'fade_distance' at "
              "test.pov:1:24");
}

// ---------------------------------------------------------------- textures

TEST(AppearanceTextures, TransformsMoveOnlyThePartsWrittenBefore) {
    const Texture t = texture_of(
        appearance_of("texture { pigment { checker } scale 2 normal { bumps } translate x "
                      "finish { phong 1 } }"));
    ASSERT_EQ(t.pigment.pattern->warps.size(), 1u);
    expect_vec(t.pigment.pattern->warps[0].transform.point({1, 1, 1}), {3, 2, 2});
    ASSERT_EQ(t.normal->pattern->warps.size(), 1u);
    expect_vec(t.normal->pattern->warps[0].transform.point({1, 1, 1}), {2, 1, 1});
    EXPECT_DOUBLE_EQ(t.finish->phong, 1);
}

TEST(AppearanceTextures, IdentifiersAndPartIdentifiers) {
    const std::string declarations =
        "#declare T = texture { pigment { rgb 1 } finish { phong 0.5 } }\n"
        "#declare P = pigment { rgb <0, 1, 0> }\n#declare F = finish { diffuse 0.9 }";
    const Texture t =
        texture_of(appearance_of("texture { T P F finish { ambient 0 } }", declarations));
    EXPECT_DOUBLE_EQ(t.pigment.colour.green, 1);
    EXPECT_DOUBLE_EQ(t.pigment.colour.red, 0);
    EXPECT_DOUBLE_EQ(t.finish->diffuse, 0.9);  // F replaces the finish, then ambient modifies it
    EXPECT_DOUBLE_EQ(t.finish->phong, 0);
    EXPECT_DOUBLE_EQ(t.finish->ambient.red, 0);
    // A pigment block in a texture modifies the texture's pigment: a pattern keeps its map;
    // a colour is a new colour, from black (checked with POV-Ray 3.7: `pigment { P filter 0.5 }`
    // is rgbf <0, 0, 0, 0.5>).
    const Texture u =
        texture_of(appearance_of("texture { T pigment { filter 0.5 } }", declarations));
    EXPECT_DOUBLE_EQ(u.pigment.colour.red, 0);
    EXPECT_DOUBLE_EQ(u.pigment.colour.filter, 0.5);
    // Array elements stand for identifiers.
    const Texture w =
        texture_of(appearance_of("texture { A[1] pigment { Q[0] } }",
                                 "#declare A = array[2] { texture { pigment { rgb 1 } }, texture { "
                                 "finish { phong 0.25 } } }\n"
                                 "#declare Q = array[1] { pigment { rgb <0, 0, 1> } }"));
    EXPECT_DOUBLE_EQ(w.finish->phong, 0.25);
    EXPECT_DOUBLE_EQ(w.pigment.colour.blue, 1);
    EXPECT_EQ(error_of("#declare A = array[1] { texture { } }\nsphere { 0, 1 pigment { A[0] } }"),
              "wrong type: 'A' is an array, expected a colour, a pattern or a pigment modifier or "
              "'}' to close "
              "'pigment' opened at test.pov:2:23 at test.pov:2:25");
    const Texture v = texture_of(
        appearance_of("texture { G pigment { marble } }",
                      "#declare C = color_map { [0 rgb 1] [1 rgb 0] }\n"
                      "#declare G = texture { pigment { gradient x color_map { C } } }"));
    EXPECT_EQ(v.pigment.pattern->kind, PatternKind::marble);
    EXPECT_TRUE(v.pigment.map);
}

TEST(AppearanceTextures, PatternedTexturesTilesAndMaterialMaps) {
    const Texture t =
        texture_of(appearance_of("texture { checker texture { pigment { rgb 1 } } texture { T } "
                                 "scale 20 }",
                                 "#declare T = texture { pigment { rgb 0 } }"));
    EXPECT_EQ(t.kind, Texture::Kind::patterned);
    EXPECT_EQ(t.pattern->kind, PatternKind::checker);
    ASSERT_EQ(t.map->entries.size(), 2u);
    EXPECT_EQ(t.map->kind, BlendMapKind::texture);
    // The scale moves the pattern and the textures in the list.
    ASSERT_EQ(t.map->entries[0].texture->pigment.pattern->warps.size(), 1u);
    const Texture m = texture_of(
        appearance_of("texture { gradient x texture_map { [0 pigment { rgb 1 }] [1 T] } }",
                      "#declare T = texture { pigment { rgb 0 } }"));
    ASSERT_EQ(m.map->entries.size(), 2u);
    EXPECT_DOUBLE_EQ(m.map->entries[0].texture->pigment.colour.red, 1);
    // tiles: a checker over two textures, the first one layered.
    const Texture tiles =
        texture_of(appearance_of("texture { tiles { texture { pigment { rgb 1 } } texture { "
                                 "pigment { rgbt 0.5 } } tile2 texture { pigment { rgb 0 } } } "
                                 "rotate y }"));
    EXPECT_EQ(tiles.pattern->kind, PatternKind::checker);
    EXPECT_EQ(tiles.map->entries[0].texture->kind, Texture::Kind::layered);
    EXPECT_EQ(tiles.map->entries[1].texture->kind, Texture::Kind::plain);
    // material_map: the textures are the list.
    test::ScratchDir dir;
    test::write_image(dir.file("m.png"), 1, 1, 3, {0, 0, 0});
    test::write_file(
        dir.file("s.pov"),
        "sphere { 0, 1 texture { material_map { png \"m.png\" map_type 2 texture { "
        "pigment { rgb 1 } } texture { pigment { rgb 0 } } texture { finish { phong 1 } } "
        "} scale 30 } }");
    const Texture mm = *parse_scene_file(dir.file("s.pov")).objects.at(0).appearance.texture;
    EXPECT_EQ(mm.pattern->kind, PatternKind::material_map);
    EXPECT_EQ(mm.pattern->image->map_type, 2);
    ASSERT_EQ(mm.map->entries.size(), 3u);
    EXPECT_DOUBLE_EQ(mm.map->entries[2].value, 2);
    EXPECT_EQ(
        error_of("sphere { 0, 1 texture { checker texture { } texture { } finish { phong 1 } } }"),
        "a patterned texture takes no 'finish': give it to the textures in its map or list "
        "(POV-Ray's rule) at "
        "test.pov:1:57");
}

TEST(AppearanceTextures, LayersAsPovRayLaysThem) {
    // Object textures layer; an object pigment modifies the top layer (checked with POV-Ray 3.7:
    // the last texture written is the top one).
    const ObjectAppearance a = appearance_of(
        "texture { pigment { rgb <1, 0, 0> } } texture { pigment { rgbt "
        "<0, 0, 1, 0.5> } } pigment { rgbt <0, 1, 0, 0.5> }");
    ASSERT_EQ(a.texture->kind, Texture::Kind::layered);
    ASSERT_EQ(a.texture->layers.size(), 2u);
    EXPECT_DOUBLE_EQ(a.texture->layers[0]->pigment.colour.red, 1);
    EXPECT_DOUBLE_EQ(a.texture->layers[1]->pigment.colour.green, 1);
    EXPECT_DOUBLE_EQ(a.texture->layers[1]->pigment.colour.blue, 0);
    // A material's textures layer too; an object pigment then modifies the material's top one.
    const ObjectAppearance b = appearance_of(
        "material { texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } } } "
        "pigment { rgb 0.5 }");
    ASSERT_EQ(b.texture->layers.size(), 2u);
    EXPECT_DOUBLE_EQ(b.texture->layers[0]->pigment.colour.red, 1);
    EXPECT_DOUBLE_EQ(b.texture->layers[1]->pigment.colour.red, 0.5);
    EXPECT_EQ(error_of("sphere { 0, 1 texture { pigment { rgb 1 } } texture { checker texture { } "
                       "texture { } } }"),
              "cannot layer a patterned texture over another (POV-Ray: \"Cannot layer a patterned "
              "texture over "
              "another\") at test.pov:1:45");
    EXPECT_EQ(
        error_of("sphere { 0, 1 texture { checker texture { } texture { } } pigment { rgb 1 } }"),
        "'pigment' cannot modify a patterned texture (POV-Ray: \"Cannot layer over a patterned "
        "texture\") at "
        "test.pov:1:59");
    EXPECT_EQ(
        error_of(
            "#declare T = texture { checker texture { } texture { } }\nsphere { 0, 1 texture { T "
            "pigment { rgb 1 } } }"),
        "a patterned texture takes no 'pigment': give it to the textures in its map or list "
        "(POV-Ray's rule) "
        "at test.pov:2:27");
    // interior_texture is layered the same way and kept apart.
    const ObjectAppearance c =
        appearance_of("texture { pigment { rgb 1 } } interior_texture { pigment { rgb 0 } }");
    ASSERT_TRUE(c.interior_texture);
    EXPECT_DOUBLE_EQ(c.interior_texture->pigment.colour.red, 0);
}

// What `#declare T = texture { A } texture { B } texture { C }` makes (the rvalue reader calls
// layer_textures for each texture after the first): one stack, bottom first.
TEST(AppearanceTextures, LayerTexturesStacksBottomFirst) {
    Parser parser{ParseOptions{}};
    auto a = std::make_shared<Texture>(), b = std::make_shared<Texture>(),
         c = std::make_shared<Texture>();
    const TextureRef ab = layer_textures(parser, Token{}, a, b);
    const TextureRef abc = layer_textures(parser, Token{}, ab, c);
    ASSERT_EQ(abc->kind, Texture::Kind::layered);
    ASSERT_EQ(abc->layers.size(), 3u);
    EXPECT_EQ(abc->layers[0], a);
    EXPECT_EQ(abc->layers[2], c);
}

TEST(AppearanceTextures, TransformsReachEveryLayer) {
    auto below = std::make_shared<Texture>();
    auto above = std::make_shared<Texture>();
    Texture layered;
    layered.kind = Texture::Kind::layered;
    layered.layers = {below, above};
    transform_texture(layered, scaling({2, 2, 2}));
    EXPECT_EQ(layered.layers[0]->pigment.pattern->warps.size(), 1u);
    EXPECT_EQ(layered.layers[1]->pigment.pattern->warps.size(), 1u);
    EXPECT_TRUE(below->pigment.pattern->warps.empty());  // shared items are copied, not changed
}

// ---------------------------------------------------------------- interior, media, material

TEST(AppearanceInterior, DefaultsKeysAndMediaAddingUp) {
    const ObjectAppearance a = appearance_of(
        "hollow interior { ior 1.5 caustics 0.5 dispersion 1.05 "
        "dispersion_samples 20 fade_distance 2 fade_power 1001 fade_color rgb <1, 0, 0> "
        "media { emission 0.5 } } interior { media { absorption <0, 1, 0> } }");
    const Interior& i = *a.interior;
    EXPECT_DOUBLE_EQ(i.ior, 1.5);
    EXPECT_DOUBLE_EQ(i.caustics, 0.5);
    EXPECT_DOUBLE_EQ(i.dispersion, 1.05);
    EXPECT_EQ(i.dispersion_samples, 20);
    EXPECT_DOUBLE_EQ(i.fade_distance, 2);
    EXPECT_DOUBLE_EQ(i.fade_power, 1001);
    EXPECT_DOUBLE_EQ(i.fade_colour.red, 1);
    // A second interior on the object modifies the first (checked with POV-Ray 3.7: the media add
    // up).
    ASSERT_EQ(i.media.size(), 2u);
    EXPECT_DOUBLE_EQ(i.media[1]->absorption.green, 1);
    const Interior defaults;
    EXPECT_DOUBLE_EQ(defaults.dispersion, 1.0);
    EXPECT_EQ(defaults.dispersion_samples, 7);
    EXPECT_EQ(
        error_of("sphere { 0, 1 interior { dispersion_samples 1 } }"),
        "'dispersion_samples' must be at least 2, found 1 at test.pov:1:45");  // POV-Ray's rule too
}

TEST(AppearanceInterior, MediaKeysDensitiesAndTheirTransforms) {
    const ObjectAppearance a = appearance_of(
        "hollow interior { media { method 2 intervals 3 samples 4, 8 confidence 0.95 variance 0.01 "
        "ratio 0.8 "
        "jitter 0.5 aa_level 5 aa_threshold 0.2 absorption 0.1 emission <0.2, 0.3, 0.4> "
        "scattering { 5, rgb 0.03 eccentricity 0.6 extinction 0.5 } density { spherical } scale 2 "
        "density { checker density { rgb 1 }, density { granite } } } }");
    const Media& m = *a.interior->media.at(0);
    EXPECT_EQ(m.method, 2);
    EXPECT_EQ(m.intervals, 3);
    EXPECT_EQ(m.samples_min, 4);
    EXPECT_EQ(m.samples_max, 8);
    EXPECT_DOUBLE_EQ(m.confidence, 0.95);
    EXPECT_DOUBLE_EQ(m.variance, 0.01);
    EXPECT_DOUBLE_EQ(m.ratio, 0.8);
    EXPECT_DOUBLE_EQ(m.jitter, 0.5);
    EXPECT_EQ(m.aa_level, 5);
    EXPECT_DOUBLE_EQ(m.aa_threshold, 0.2);
    EXPECT_FLOAT_EQ(m.absorption.red, 0.1);
    EXPECT_FLOAT_EQ(m.emission.blue, 0.4);
    EXPECT_EQ(m.scattering_type, 5);
    EXPECT_FLOAT_EQ(m.scattering.green, 0.03);
    EXPECT_DOUBLE_EQ(m.eccentricity, 0.6);
    EXPECT_DOUBLE_EQ(m.extinction, 0.5);
    ASSERT_EQ(m.densities.size(), 2u);
    // The scale moves the density written before it only (reference 3.4.8).
    EXPECT_EQ(m.densities[0].item->pattern->warps.size(), 1u);
    EXPECT_TRUE(m.densities[1].item->pattern->warps.empty());
    EXPECT_EQ(m.densities[1].item->map->kind, BlendMapKind::density);
    // A density starts black, not as the default pigment (checked with POV-Ray 3.7).
    const ObjectAppearance b = appearance_of("hollow interior { media { density { } } }",
                                             "#default { pigment { rgb 1 } }");
    EXPECT_DOUBLE_EQ(b.interior->media.at(0)->densities.at(0).item->colour.red, 0);
    const Media defaults;
    EXPECT_EQ(defaults.samples_min, 1);
    EXPECT_DOUBLE_EQ(defaults.variance, 1.0 / 128);
    EXPECT_EQ(error_of("#declare M = media { samples 4, 2 }"),
              "the maximum number of media samples (2) is below the minimum (4) at test.pov:1:33");
}

TEST(AppearanceMaterial, TextureLayersOverInteriorReplacesTransformsWhatItHolds) {
    const ObjectAppearance a =
        appearance_of("texture { pigment { rgb 1 } } interior { ior 1.2 } material { M }",
                      "#declare M = material { texture { pigment { checker } } scale 4 interior { "
                      "ior 1.5 } translate x }");
    ASSERT_EQ(a.texture->kind, Texture::Kind::layered);
    const Texture& top = *a.texture->layers.at(1);
    ASSERT_EQ(top.pigment.pattern->warps.size(), 1u);  // scale 4 then translate x
    expect_vec(top.pigment.pattern->warps[0].transform.point({1, 1, 1}), {5, 4, 4});
    EXPECT_DOUBLE_EQ(a.interior->ior, 1.5);
}

// ---------------------------------------------------------------- #default

TEST(AppearanceDefault, OneDefaultTextureAsPovRayKeepsIt) {
    // #default pigment and finish change the one default texture; texture { } and pigment { }
    // start from it; a later #default texture replaces it whole (checked with POV-Ray 3.7).
    const SceneDescription s = parse(R"(
        #default { finish { ambient 1 diffuse 0 } pigment { rgb <1, 0, 0> } }
        sphere { 0, 1 texture { } }
        sphere { 0, 1 finish { phong 1 } }
        #default { texture { pigment { rgb <0, 1, 0> } } }
        #default { finish { ambient 0.5 } }
        sphere { 0, 1 pigment { checker } }
    )");
    const Texture& first = *s.objects.at(0).appearance.texture;
    EXPECT_DOUBLE_EQ(first.pigment.colour.red, 1);
    EXPECT_DOUBLE_EQ(first.finish->ambient.red, 1);
    const Texture& second = *s.objects.at(1).appearance.texture;
    EXPECT_DOUBLE_EQ(second.finish->diffuse, 0);
    EXPECT_DOUBLE_EQ(second.finish->phong, 1);
    const Texture& third = *s.objects.at(2).appearance.texture;
    EXPECT_EQ(third.pigment.pattern->kind, PatternKind::checker);
    EXPECT_DOUBLE_EQ(third.finish->ambient.red, 0.5);
    EXPECT_DOUBLE_EQ(third.finish->diffuse, 0);  // from the texture the default was made from
    EXPECT_EQ(error_of("#default { texture { checker texture { } texture { } } }"),
              "the default texture cannot be patterned, tiles or a material_map (POV-Ray's rule) "
              "at test.pov:1:12");
    EXPECT_EQ(error_of("#default { sphere { 0, 1 } }"),
              "expected texture, pigment, normal, finish or '}' to close 'default' opened at "
              "test.pov:1:10, found "
              "'sphere' at test.pov:1:12");
}

TEST(AppearanceDefault, SceneDefaultAppearanceIsTheDefaultOfTheMoment) {
    Parser parser{ParseOptions{}};
    ObjectAppearance a = scene_default_appearance(parser);
    ASSERT_TRUE(a.texture);
    EXPECT_DOUBLE_EQ(a.texture->finish->diffuse, 0.6);  // POV-Ray's own default texture
    EXPECT_FALSE(a.interior);
    auto texture = std::make_shared<Texture>();
    texture->pigment.colour.red = 1;
    parser.default_texture = texture;
    a = scene_default_appearance(parser);
    EXPECT_DOUBLE_EQ(a.texture->pigment.colour.red, 1);
}

// ---------------------------------------------------------------- transforms of appearances

TEST(AppearanceTransforms, ObjectTransformsMoveTexturesAndMedia) {
    ObjectAppearance a = appearance_of(
        "texture { pigment { gradient x } normal { bumps } } "
        "interior_texture { pigment { checker } } hollow interior { media { density "
        "{ spherical } } }");
    const TextureRef before = a.texture;
    transform_appearance(a, translation({1, 0, 0}));
    expect_vec(a.texture->pigment.pattern->warps.at(0).transform.point({0, 0, 0}), {1, 0, 0});
    expect_vec(a.texture->normal->pattern->warps.at(0).transform.point({0, 0, 0}), {1, 0, 0});
    EXPECT_EQ(a.interior_texture->pigment.pattern->warps.size(), 1u);
    EXPECT_EQ(a.interior->media.at(0)->densities.at(0).item->pattern->warps.size(), 1u);
    EXPECT_TRUE(before->pigment.pattern->warps.empty());  // copies: the parsed texture is unchanged
    // inherit_appearance fills only what the inner object lacks.
    ObjectAppearance inner;
    inner.interior = a.interior;
    inherit_appearance(inner, a);
    EXPECT_EQ(inner.texture, a.texture);
    EXPECT_EQ(inner.interior_texture, a.interior_texture);
}

// ---------------------------------------------------------------- evaluation

TEST(AppearanceEvaluation, BlockPatternsAndTheirLists) {
    // Indices and built-in lists as POV-Ray 3.7 gives them at these points.
    expect_colour(pigment_at("checker", {0.5, 0.5, 0.5}), 0, 0, 1);
    expect_colour(pigment_at("checker", {1.5, 0.5, 0.5}), 0, 1, 0);
    expect_colour(pigment_at("checker", {-1e-9, 0.5, 0.5}), 0, 1, 0);
    expect_colour(pigment_at("hexagon", {0, 0, 0}), 0, 0, 1);
    expect_colour(pigment_at("hexagon", {0, 0, 1.5}), 0, 1, 0);
    expect_colour(pigment_at("hexagon", {1.5, 0, 0}), 1, 0, 0);
    expect_colour(pigment_at("hexagon", {1.5, 0, -0.866}), 0, 1, 0);
    expect_colour(pigment_at("brick", {4, 0, 2}), 0.5, 0.5, 0.5);  // mortar
    expect_colour(pigment_at("brick", {0.1, 0.1, 0.1}), 0.6, 0.15, 0.15);
    expect_colour(pigment_at("brick", {-0.25, 1.5, 1}), 0.5, 0.5, 0.5);
    expect_colour(pigment_at("brick", {3.75, 4.5, 1}), 0.5, 0.5, 0.5);  // odd rows shift along x
    expect_colour(pigment_at("brick brick_size <2, 1, 3> mortar 0.2", {1.9, 0.5, 0.5}), 0.5, 0.5,
                  0.5);
    expect_colour(pigment_at("square", {1.5, 0, 0.5}), 1, 1, 0);
    expect_colour(pigment_at("square", {0.5, 0, 1.5}), 0, 1, 0);
    expect_colour(pigment_at("square", {1.5, 0, 1.5}), 0, 0, 1);
    expect_colour(pigment_at("triangular", {1, 0, 0.2}), 1, 1, 0);
    expect_colour(pigment_at("triangular", {1.5, 0, 0.2}), 0, 1, 1);
    expect_colour(pigment_at("triangular", {2.5, 0, 0.2}), 0, 0, 1);
    expect_colour(pigment_at("triangular", {0.5, 0, -0.2}), 1, 0, 1);
    expect_colour(pigment_at("cubic", {0, -2, 0}), 0, 1, 1);
    expect_colour(pigment_at("checker rgb <1, 1, 0>, rgb 0.5 scale 2", {1.5, 0.5, 0.5}), 1, 1, 0);
    // frequency and phase reach a list only when frequency is written (checked with POV-Ray 3.7).
    expect_colour(pigment_at("brick frequency 1e-9 phase 0.7", {4, 1, 2}), 0.57, 0.255, 0.255,
                  1e-6);
    EXPECT_DOUBLE_EQ(pattern_at("hexagon phase 0.3", {1.5, 0, 0}), 2);
    EXPECT_NEAR(pattern_at("hexagon frequency 1", {1.5, 0, 0}), 0.99999, 1e-12);
}

TEST(AppearanceEvaluation, ContinuousPatternsFrequencyPhaseAndWaveforms) {
    // Values POV-Ray 3.7 gives through function { pattern { ... } }.
    EXPECT_NEAR(pattern_at("gradient x", {1, 0, 0}), 1, 1e-12);
    EXPECT_NEAR(pattern_at("gradient x", {2, 0, 0}), 0, 1e-12);
    EXPECT_NEAR(pattern_at("gradient x", {-0.3, 0, 0}), 0.7, 1e-12);
    EXPECT_NEAR(pattern_at("gradient x", {2.50773, 0, 0}), 0.50773, 1e-9);
    EXPECT_NEAR(pattern_at("gradient x", {-1.583711, 0, 0}), 0.416299, 1e-6);
    EXPECT_NEAR(pattern_at("gradient <1, 1, 0>", {0.3, 0.4, 0}), 0.494975, 1e-6);
    EXPECT_NEAR(pattern_at("gradient x frequency 2", {0.3, 0, 0}), 0.6, 1e-12);
    EXPECT_NEAR(pattern_at("gradient x frequency 2 triangle_wave", {0.3, 0, 0}), 0.8, 1e-12);
    EXPECT_NEAR(pattern_at("boxed phase 0.5", {0, 0, 0}), 0.49999, 1e-12);
    EXPECT_NEAR(pattern_at("boxed frequency -1", {0.5, 0, 0}), 0.5, 1e-12);
    EXPECT_NEAR(pattern_at("boxed frequency 0 phase 0.25", {0.5, 0, 0}), 0.5, 1e-12);
    EXPECT_NEAR(pattern_at("marble", {0.25, 0, 0}), 0.5, 1e-12);
    EXPECT_NEAR(pattern_at("marble", {-1.5837115, 0, 0}), 0.832597, 1e-6);
    EXPECT_NEAR(pattern_at("onion", {1, 0, 0}), 0, 1e-12);
    EXPECT_NEAR(pattern_at("radial", {0, 0, -1}), 0.24999, 1e-12);
    EXPECT_NEAR(pattern_at("radial", {0, 0, 0}), 0.25, 1e-12);
    EXPECT_NEAR(pattern_at("radial", {-1, 0, 0}), 0.5, 1e-12);
    EXPECT_NEAR(pattern_at("radial", {0, 0, 1}), 0.75, 1e-12);
    EXPECT_NEAR(pattern_at("gradient x sine_wave", {0.1, 0, 0}), 0.793893, 1e-6);
    EXPECT_NEAR(pattern_at("gradient x scallop_wave", {0.6, 0, 0}), 0.951057, 1e-6);
    EXPECT_NEAR(pattern_at("gradient x cubic_wave", {0.3, 0, 0}), 0.216, 1e-12);
    EXPECT_NEAR(pattern_at("gradient x poly_wave 0.5", {0.6, 0, 0}), 0.774597, 1e-6);
    EXPECT_NEAR(pattern_at("hexagon cubic_wave", {1.5, 0, 0}), -4, 1e-12);
    EXPECT_NEAR(pattern_at("function { x * 1.5 }", {1, 0, 0}), 0.5, 1e-12);
    EXPECT_NEAR(pattern_at("pigment_pattern { rgbft <0.5, 1, 0.25, 0.5, 0.5> }", {0, 0, 0}),
                0.297 * 0.5 + 0.589 + 0.114 * 0.25, 1e-12);
    EXPECT_NEAR(pattern_at("pigment_pattern { rgb 2 }", {0, 0, 0}), 0.99999, 1e-12);
    EXPECT_NEAR(pattern_at("pigment_pattern { checker rgb 0.5, rgb 1 } scale 2", {0.5, 0.5, 0.5}),
                0.5, 1e-12);
    EXPECT_NEAR(pattern_at("gradient x scale 2 translate x", {2, 0, 0}), 0.5, 1e-12);
    EXPECT_NEAR(pattern_at("leopard", {1, 2, 3}),
                std::pow((std::sin(1.0) + std::sin(2.0) + std::sin(3.0)) / 3, 2), 1e-12);
}

TEST(AppearanceEvaluation, MapsAndPigmentMaps) {
    expect_colour(pigment_at("gradient x", {0.7, 0, 0}), 0.7, 0.7, 0.7);
    expect_colour(
        pigment_at("gradient x color_map { [0.2 rgb <1, 0, 0>] [0.6 rgb <0, 0, 1>] [0.6 rgb 1] }",
                   {0.3, 0, 0}),
        0.75, 0, 0.25);
    expect_colour(
        pigment_at("gradient x color_map { [0.2 rgb <1, 0, 0>] [0.6 rgb <0, 0, 1>] [0.6 rgb 1] }",
                   {0.6, 0, 0}),
        1, 1, 1);  // exactly at a repeated value: the later entry
    expect_colour(
        pigment_at("gradient x color_map { [0.2 rgb <1, 0, 0>] [0.6 rgb <0, 0, 1>] }", {0.1, 0, 0}),
        1, 0, 0);
    // An unsorted map as POV-Ray 3.7 reads it: past the last value first.
    expect_colour(pigment_at("gradient x color_map { [0.5 rgb 1] [0.2 rgb 0] }", {0.3, 0, 0}), 0, 0,
                  0);
    expect_colour(pigment_at("gradient x color_map { [0.5 rgb 1] [0.2 rgb 0] }", {0.1, 0, 0}), 1, 1,
                  1);
    expect_colour(pigment_at("average pigment_map { [1 gradient x] } translate 0.25*x", {0, 0, 0}),
                  0.75, 0.75, 0.75);
    expect_colour(pigment_at("average pigment_map { [1 rgb 1] [3 rgb 0] }", {0, 0, 0}), 0.25, 0.25,
                  0.25);
    expect_colour(
        pigment_at("gradient x pigment_map { [0 checker rgb 1, rgb 0] [1 rgb <1, 0, 0>] }",
                   {0.5, 0.5, 0.5}),
        1, 0.5, 0.5);
    expect_colour(pigment_at("radial frequency 1e-9 phase 0.333", {1, 0, 0}), 1, 1, 0, 1e-6);
    // An identifier's map survives a new continuous pattern, whose keyword sets its waveform
    // (checked with POV-Ray 3.7).
    expect_colour(pigment_at("P marble", {0.25, 0, 0},
                             "#declare P = pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 "
                             "rgb <0, 0, 1>] } }"),
                  0.5, 0, 0.5);
    // What cannot be evaluated (spiral2, a black hole warp): the caller says so.
    EXPECT_NE(
        error_of(
            "#declare F = function { pigment { spiral2 3 } }\ncamera { location F(0, 0, 0).red }")
            .find("not supported"),
        std::string::npos);
    EXPECT_NE(error_of("#declare F = function { pattern { gradient x warp { black_hole 0, 1 } } }\n"
                       "camera { location F(0, 0, 0) }")
                  .find("not supported"),
              std::string::npos);
}

}  // namespace
}  // namespace rayset::tracer
