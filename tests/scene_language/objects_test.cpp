// Tests of the objects grammar: every shape read into the values its text gives (worked out by
// hand) with POV-Ray's defaults, CSG trees and the flattening of unions, the object modifiers,
// light sources and light groups, the errors with their file:line:column, and the parse-time
// geometry (min_extent, max_extent, inside, trace). Values marked "povray" were read from
// POV-Ray 3.7.0.10 itself (#debug of the same expressions, or renders where the grammar leaves
// no number to print).
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "scene_language/scene_test_support.h"
#include "support/image_writing.h"
#include "support/test_support.h"
#include "tracer/scene_language/functions.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/scene_language/text_outline.h"

namespace rayset::tracer {
namespace {

using namespace scene_test;

namespace fs = std::filesystem;

template <typename T>
T only_shape(const SceneDescription& s) {
    EXPECT_EQ(s.objects.size(), 1u);
    return std::get<T>(s.objects.at(0).shape);
}

// An expression evaluated through the camera location, after `declarations`.
Vec3 eval(const std::string& expression, const std::string& declarations) {
    return parse(declarations + "\ncamera { location (" + expression + ") }").camera.location;
}

// min_extent and max_extent of `object` against POV-Ray's, printed to 4 decimals.
void expect_extent(const std::string& object, Vec3 minimum, Vec3 maximum,
                   double tolerance = 1.5e-4) {
    SCOPED_TRACE(object);
    const std::string declaration = "#declare O = " + object + "\n";
    expect_vec(eval("min_extent(O)", declaration), minimum, tolerance);
    expect_vec(eval("max_extent(O)", declaration), maximum, tolerance);
}

double inside(const std::string& object, const std::string& point) {
    return eval("inside(O, " + point + ")", "#declare O = " + object + "\n").x;
}

// trace(O, origin, direction, N): the hit and the normal.
std::pair<Vec3, Vec3> trace(const std::string& object, const std::string& origin,
                            const std::string& direction) {
    const std::string declarations = "#declare O = " + object +
                                     "\n#declare N = <9, 9, 9>;\n#declare H = trace(O, " + origin +
                                     ", " + direction + ", N);\n";
    return {eval("H", declarations), eval("N", declarations)};
}

// ---------------------------------------------------------------- basic shapes

TEST(ObjectsShapes, SolidsWithTheirParametersAndDefaults) {
    const auto& cylinder =
        only_shape<CylinderShape>(parse("cylinder { <1,2,3>, <4,5,6>, 0.5 open }"));
    expect_vec(cylinder.base, {1, 2, 3});
    expect_vec(cylinder.cap, {4, 5, 6});
    EXPECT_DOUBLE_EQ(cylinder.radius, 0.5);
    EXPECT_TRUE(cylinder.open);
    EXPECT_FALSE(only_shape<CylinderShape>(parse("cylinder { 0, y, 1 }")).open);

    const auto& cone = only_shape<ConeShape>(parse("cone { 0, 1, 2*y, 0.5 }"));
    expect_vec(cone.cap, {0, 2, 0});
    EXPECT_DOUBLE_EQ(cone.base_radius, 1);
    EXPECT_DOUBLE_EQ(cone.cap_radius, 0.5);
    EXPECT_FALSE(cone.open);

    const auto& torus = only_shape<TorusShape>(parse("torus { 2, 0.5 sturm }"));
    EXPECT_DOUBLE_EQ(torus.major_radius, 2);
    EXPECT_DOUBLE_EQ(torus.minor_radius, 0.5);
    EXPECT_TRUE(torus.sturm);
    EXPECT_FALSE(only_shape<TorusShape>(parse("torus { 2, 0.5 sturm sturm off }")).sturm);

    const auto& ovus = only_shape<OvusShape>(parse("ovus { 1, 0.5 }"));
    EXPECT_DOUBLE_EQ(ovus.bottom_radius, 1);
    EXPECT_DOUBLE_EQ(ovus.top_radius, 0.5);

    const auto& super = only_shape<SuperellipsoidShape>(parse("superellipsoid { <0.25, 0.5> }"));
    EXPECT_DOUBLE_EQ(super.east_west, 0.25);
    EXPECT_DOUBLE_EQ(super.north_south, 0.5);

    // POV-Ray takes a sphere of radius 0 or negative (povray).
    EXPECT_DOUBLE_EQ(only_shape<SphereShape>(parse("sphere { 0, -2 }")).radius, -2);
}

TEST(ObjectsShapes, PatchesAndPolynomials) {
    const auto& disc = only_shape<DiscShape>(parse("disc { <1,2,3>, <0,2,0>, 2, 1 }"));
    expect_vec(disc.normal, {0, 1, 0});  // normalised
    EXPECT_DOUBLE_EQ(disc.radius, 2);
    EXPECT_DOUBLE_EQ(disc.hole_radius, 1);
    EXPECT_DOUBLE_EQ(only_shape<DiscShape>(parse("disc { 0, y, 2 }")).hole_radius, 0);

    const auto& smooth =
        only_shape<SmoothTriangleShape>(parse("smooth_triangle { 0, y, x, <0,1,1>, z, <1,1,0> }"));
    expect_vec(smooth.b, {1, 0, 0});
    expect_vec(smooth.normal_b, {0, 1, 1});
    expect_vec(smooth.normal_c, {1, 1, 0});

    const auto& quadric =
        only_shape<QuadricShape>(parse("quadric { <1,2,3>, <4,5,6>, <7,8,9>, 10 }"));
    expect_vec(quadric.squares, {1, 2, 3});
    expect_vec(quadric.mixed, {4, 5, 6});
    expect_vec(quadric.linear, {7, 8, 9});
    EXPECT_DOUBLE_EQ(quadric.constant, 10);

    // The manual's torus of major radius sqrt(40), minor sqrt(12), written both ways: the
    // polynomial syntax puts each xyz term where the quartic's term order has it.
    const SceneDescription both = parse(R"(
        quartic { < 1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0,
                    0, 0, 1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784 > sturm }
        polynomial { 4, xyz(4,0,0):1, xyz(2,2,0):2, xyz(2,0,2):2, xyz(2,0,0):-104,
                     xyz(0,4,0):1, xyz(0,2,2):2, xyz(0,2,0):56, xyz(0,0,4):1, xyz(0,0,2):-104,
                     xyz(0,0,0):784 })");
    const auto& quartic = std::get<PolynomialShape>(both.objects[0].shape);
    const auto& polynomial = std::get<PolynomialShape>(both.objects[1].shape);
    EXPECT_EQ(quartic.order, 4);
    EXPECT_TRUE(quartic.sturm);
    ASSERT_EQ(quartic.coefficients.size(), 35u);
    EXPECT_EQ(polynomial.coefficients, quartic.coefficients);

    // Order 2: x^2 xy xz x y^2 yz y z^2 z 1.
    const auto& poly =
        only_shape<PolynomialShape>(parse("polynomial { 2, xyz(1,0,1):3, xyz(0,1,0):-2 }"));
    EXPECT_EQ(poly.coefficients, (std::vector<double>{0, 0, 3, 0, 0, 0, -2, 0, 0, 0}));
    EXPECT_EQ(only_shape<PolynomialShape>(
                  parse("cubic { <1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20> }"))
                  .coefficients.size(),
              20u);
    EXPECT_EQ(error_of("poly { 2, <1, 2, 3> }"),
              "'poly' takes 10 coefficients here, found 3 at test.pov:1:19");
    EXPECT_EQ(error_of("poly { 36, <1> }"),
              "the order of 'poly' must lie in 2..35, found 36 at test.pov:1:8");
    EXPECT_EQ(error_of("polynomial { 2, xyz(2,1,0):1 }"),
              "xyz(2,1,0) is not a term of a polynomial of order 2 at test.pov:1:17");
}

TEST(ObjectsShapes, DegenerateEndsAndPlanesAreErrors) {
    // povray: "Degenerate cylinder, base point = apex point", "Degenerate cone/cylinder".
    EXPECT_EQ(error_of("cylinder { 1, 1, 2 }"),
              "degenerate cylinder: its base and cap are the same point at test.pov:1:1");
    EXPECT_EQ(error_of("\n  cone { x, 1, x, 0.5 }"),
              "degenerate cone: its base and cap are the same point at test.pov:2:3");
    EXPECT_EQ(error_of("plane { 0, 1 }"), "degenerate plane normal (zero length) at test.pov:1:9");
    // `open` comes right after the parameters (povray refuses it after a modifier).
    EXPECT_EQ(error_of("cylinder { 0, y, 1 translate x open }"),
              "expected an object modifier or '}' to close 'cylinder' opened at test.pov:1:10, "
              "found 'open' at "
              "test.pov:1:32");
}

// ---------------------------------------------------------------- curves

TEST(ObjectsCurves, LathePrismSorSweepPolygon) {
    const auto& lathe = only_shape<LatheShape>(
        parse("lathe { bezier_spline 4, <1,0>, <2,1>, <3,2>, <0.5,3> sturm }"));
    EXPECT_EQ(lathe.spline, SplineKind::bezier);
    ASSERT_EQ(lathe.points.size(), 4u);
    EXPECT_DOUBLE_EQ(lathe.points[3].x, 0.5);
    EXPECT_DOUBLE_EQ(lathe.points[3].y, 3);
    EXPECT_TRUE(lathe.sturm);
    EXPECT_EQ(only_shape<LatheShape>(parse("lathe { 2, <1,0>, <1,1> }")).spline,
              SplineKind::linear);

    const auto& prism =
        only_shape<PrismShape>(parse("prism { conic_sweep cubic_spline 0.5, 1, 6, <-1,-1>, <0,0>, "
                                     "<1,0>, <0,1>, <0,0>, <3,3> open }"));
    EXPECT_EQ(prism.spline, SplineKind::cubic);
    EXPECT_TRUE(prism.conic_sweep);
    EXPECT_DOUBLE_EQ(prism.height1, 0.5);
    EXPECT_DOUBLE_EQ(prism.height2, 1);
    EXPECT_EQ(prism.points.size(), 6u);
    EXPECT_TRUE(prism.open);

    // A linear prism's last sub-prism closes itself, with a warning (povray: "Linear prism not
    // closed. Closing it."); a closed one is left alone.
    const std::string open_prism =
        "prism { 0, 1, 7, <0,0>, <2,0>, <0,2>, <0,0>, <1,1>, <1,1.5>, <1.5,1> }";
    const auto& closed = only_shape<PrismShape>(parse(open_prism));
    ASSERT_EQ(closed.points.size(), 8u);
    EXPECT_DOUBLE_EQ(closed.points[7].x, 1);
    EXPECT_DOUBLE_EQ(closed.points[7].y, 1);
    EXPECT_EQ(
        warnings_of(open_prism),
        std::vector<std::string>{
            "test.pov:1:15: warning: linear prism not closed: closing it, as POV-Ray does\n"});
    EXPECT_TRUE(warnings_of("prism { 0, 1, 4, <0,0>, <1,0>, <0,1>, <0,0> }").empty());

    const auto& sor = only_shape<SorShape>(parse("sor { 4, <0,0>, <1,0>, <1,1>, <1,1> open }"));
    EXPECT_EQ(sor.points.size(), 4u);
    EXPECT_TRUE(sor.open);

    const auto& sweep = only_shape<SphereSweepShape>(parse(
        "sphere_sweep { b_spline 4, 0, 1, x, 0.5, <0,3,0>, 0.2, <1,1,1>, 1 tolerance 1e-4 }"));
    EXPECT_EQ(sweep.kind, SphereSweepShape::Kind::b_spline);
    ASSERT_EQ(sweep.spheres.size(), 4u);
    expect_vec(sweep.spheres[2].centre, {0, 3, 0});
    EXPECT_DOUBLE_EQ(sweep.spheres[2].radius, 0.2);
    EXPECT_DOUBLE_EQ(sweep.tolerance, 1e-4);
    EXPECT_DOUBLE_EQ(
        only_shape<SphereSweepShape>(parse("sphere_sweep { linear_spline 2, 0, 1, x, 1 }"))
            .tolerance,
        1e-6);

    // 2-D points have z = 0; the last sub-polygon closes itself with a warning (povray).
    const std::string square = "polygon { 4, <0,0>, <1,0>, <1,1>, <0,1> }";
    const auto& polygon = only_shape<PolygonShape>(parse(square));
    ASSERT_EQ(polygon.points.size(), 5u);
    expect_vec(polygon.points[2], {1, 1, 0});
    expect_vec(polygon.points[4], {0, 0, 0});
    EXPECT_EQ(warnings_of(square).size(), 1u);
}

TEST(ObjectsCurves, PointCountsAndHeightsAsPovRayChecksThem) {
    // povray's own checks: the counts each spline needs, rising sor heights.
    EXPECT_EQ(error_of("lathe { 1, <1,0> }"),
              "lathe with linear splines must have at least 2 points, found 1 at test.pov:1:9");
    EXPECT_EQ(error_of("lathe { cubic_spline 3, <1,0>, <1,1>, <1,2> }"),
              "lathe with cubic splines must have at least 4 points, found 3 at test.pov:1:22");
    EXPECT_EQ(error_of("lathe { bezier_spline 5, <1,0>, <1,1>, <1,2>, <1,3>, <1,4> }"),
              "lathe with Bezier splines must have four points per segment, found 5 points at "
              "test.pov:1:23");
    EXPECT_EQ(error_of("prism { quadratic_spline 0, 1, 3, <0,0>, <1,0>, <1,1> }"),
              "prism with quadratic splines must have at least 5 points, found 3 at test.pov:1:32");
    EXPECT_EQ(error_of("prism { 0, 1, 2, <0,0>, <1,0> }"),
              "prism with linear splines must have at least 3 points, found 2 at test.pov:1:15");
    EXPECT_EQ(error_of("sor { 3, <0,0>, <1,1>, <1,2> }"),
              "a surface of revolution must have at least four points, found 3 at test.pov:1:7");
    EXPECT_NO_THROW(
        parse("sor { 4, <0,1>, <1,1>, <1,2>, <1,2> }"));  // equal ends: povray takes them
    EXPECT_EQ(error_of("sor { 4, <0,0>, <1,1>, <1,1>, <1,2> }"),
              "incorrect point in surface of revolution: height 1 of point 3 does not rise above 1 "
              "of point 2 at "
              "test.pov:1:7");
    EXPECT_EQ(error_of("sor { 4, <0,1>, <1,0>, <1,1>, <1,2> }"),
              "incorrect point in surface of revolution: height 0 of point 2 does not rise above 1 "
              "of point 1 at "
              "test.pov:1:7");
    EXPECT_EQ(error_of("sphere_sweep { cubic_spline 3, 0, 1, x, 1, y, 1 }"),
              "too few spheres for the interpolation: cubic_spline needs at least 4, found 3 at "
              "test.pov:1:29");
    EXPECT_EQ(error_of("sphere_sweep { 2, 0, 1, x, 1 }"),
              "expected linear_spline, b_spline or cubic_spline in 'sphere_sweep', found number 2 "
              "at test.pov:1:16");
    EXPECT_EQ(error_of("polygon { 2, <0,0>, <1,0> }"),
              "a polygon needs at least three points, found 2 at test.pov:1:11");
    EXPECT_EQ(error_of("lathe { 2, <1,0,3>, <1,1> }"),
              "expected a 2-D vector as point 1 of lathe points, found 3 terms at test.pov:1:12");
}

TEST(ObjectsCurves, HugeCountsFailBeforeAnythingIsStored) {
    ParseOptions options;
    options.max_array_elements = 1000;
    EXPECT_EQ(error_of("prism { 0, 1, 1000000000, <0,0> }", options),
              "1000000000 prism points: more than the limit of 1000 "
              "(ParseOptions::max_array_elements) at "
              "test.pov:1:15");
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 2000, <0,0,0> } }", options),
              "2000 entries of 'vertex_vectors': more than the limit of 1000 "
              "(ParseOptions::max_array_elements) at "
              "test.pov:1:26");
    EXPECT_EQ(error_of("height_field { function 100, 100 { x } }", options),
              "a height_field of 100 x 100 samples is more than the limit of 1000 "
              "(ParseOptions::max_array_elements) at "
              "test.pov:1:25");
    // A count with too few entries after it stops at the first thing that is not one.
    EXPECT_EQ(error_of("lathe { 100, <1,0>, <1,1> }"),
              "expected a numeric expression, found '}' at test.pov:1:27");
}

TEST(ObjectsCurves, BicubicPatchAndText) {
    const SceneDescription s = parse(R"(
        bicubic_patch { type 1 flatness 0.1 u_steps 3 v_steps 4, uv_vectors <0,0> <2,0>, <2,3> <0,3>
          <0,0,2>, <1,0,0>, <2,0,0>, <3,0,-2>, <0,1,0>, <1,1,0>, <2,1,0>, <3,1,0>,
          <0,2,0>, <1,2,0>, <2,2,0>, <3,2,0>, <0,3,2>, <1,3,0>, <2,3,0>, <3,3,-2> })");
    const auto& patch = only_shape<BicubicPatchShape>(s);
    EXPECT_EQ(patch.type, 1);
    EXPECT_DOUBLE_EQ(patch.flatness, 0.1);
    EXPECT_EQ(patch.u_steps, 3);
    EXPECT_EQ(patch.v_steps, 4);
    expect_vec(patch.points[0], {0, 0, 2});
    expect_vec(patch.points[15], {3, 3, -2});
    EXPECT_DOUBLE_EQ(patch.corner_uvs[1].x, 2);
    EXPECT_DOUBLE_EQ(patch.corner_uvs[2].y, 3);
    const auto& defaults =
        only_shape<BicubicPatchShape>(parse("bicubic_patch { type 0 " + std::string(16 * 4, ' ') +
                                            "<0,0,0> <1,0,0> <2,0,0> <3,0,0> <0,1,0> <1,1,0> "
                                            "<2,1,0> <3,1,0> <0,2,0> <1,2,0> <2,2,0> <3,2,0> "
                                            "<0,3,0> <1,3,0> <2,3,0> <3,3,0> }"));
    EXPECT_DOUBLE_EQ(defaults.flatness, 0);
    EXPECT_EQ(defaults.u_steps, 0);
    EXPECT_DOUBLE_EQ(defaults.corner_uvs[2].x, 1);  // the unit square's corners
    EXPECT_DOUBLE_EQ(defaults.corner_uvs[3].y, 1);
    // povray: "Undefined bicubic patch type".
    EXPECT_EQ(error_of("bicubic_patch { <0,0,0> }"),
              "bicubic_patch needs 'type' (0 or 1) before its points at test.pov:1:17");
    EXPECT_EQ(error_of("bicubic_patch { type 1 <0,0,0> }"),
              "a bicubic_patch needs 16 points, found 1 at test.pov:1:32");

    test::ScratchDir dir;
    fs::copy_file("/usr/share/povray-3.7/include/timrom.ttf", dir.file("font.ttf"));
    test::write_file(dir.file("scene.pov"),
                     "text { ttf \"font\" \"Hi\" 0.5, <0.1, 0> }\n"
                     "text { internal 1 concat(\"a\", \"b\") 1, 0 }\n");
    const SceneDescription t = parse_scene_file(dir.file("scene.pov"));
    ASSERT_EQ(t.objects.size(), 2u);
    const auto& text = std::get<TextShape>(t.objects[0].shape);
    EXPECT_EQ(
        text.font_path,
        fs::weakly_canonical(dir.file("font.ttf")).string());  // ".ttf" added, as POV-Ray does
    EXPECT_EQ(text.internal_font, -1);
    EXPECT_EQ(text.text, "Hi");
    EXPECT_DOUBLE_EQ(text.thickness, 0.5);
    expect_vec(text.offset, {0.1, 0, 0});
    ASSERT_TRUE(text.outline);  // the glyphs' outlines, read while parsing
    EXPECT_FALSE(text.outline->pieces.empty());
    // Along y = 0.3 from the left: outside, then the H's left stem within its first 0.2.
    EXPECT_FALSE(text.outline->inside(-0.01, 0.3));
    bool stem = false;
    for (double x = 0; x < 0.2; x += 0.005) stem = stem || text.outline->inside(x, 0.3);
    EXPECT_TRUE(stem);
    const auto& internal = std::get<TextShape>(t.objects[1].shape);
    EXPECT_EQ(internal.internal_font, 1);  // povray 3.7 takes `internal` fonts
    EXPECT_TRUE(internal.font_path.empty());
    EXPECT_EQ(internal.text, "ab");
    expect_vec(internal.offset, {0, 0, 0});
    // A file that is no font: an error naming it and the text statement.
    test::write_file(dir.file("bad.ttf"), "no font");
    test::write_file(dir.file("bad.pov"), "text { ttf \"bad\" \"Hi\" 0.5, 0 }\n");
    try {
        parse_scene_file(dir.file("bad.pov"));
        ADD_FAILURE() << "a file that is no font was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot read the font"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("bad.pov:1:1"), std::string::npos) << e.what();
    }
}

// ---------------------------------------------------------------- fields and functions

TEST(ObjectsFields, BlobWithItsComponents) {
    const SceneDescription s = parse(R"(
        blob { threshold 0.6
          sphere { <1,0,0>, 2, strength 3 pigment { rgb <1,0,0> } translate y }
          cylinder { 0, x, 1, -2 }
          component 1, 2, <0,0,1>
          hierarchy off sturm })");
    const auto& blob = only_shape<BlobShape>(s);
    EXPECT_DOUBLE_EQ(blob.threshold, 0.6);
    EXPECT_FALSE(blob.hierarchy);
    EXPECT_TRUE(blob.sturm);
    ASSERT_EQ(blob.components.size(), 3u);
    const BlobComponent& sphere = blob.components[0];
    EXPECT_EQ(sphere.kind, BlobComponent::Kind::sphere);
    EXPECT_DOUBLE_EQ(sphere.radius, 2);
    EXPECT_DOUBLE_EQ(sphere.strength, 3);
    expect_vec(sphere.transform.point(sphere.centre), {1, 1, 0});
    ASSERT_TRUE(sphere.appearance.texture);
    EXPECT_DOUBLE_EQ(sphere.appearance.texture->pigment.colour.red, 1);
    EXPECT_EQ(sphere.location.str(), "test.pov:3:11");
    const BlobComponent& cylinder = blob.components[1];
    EXPECT_EQ(cylinder.kind, BlobComponent::Kind::cylinder);
    expect_vec(cylinder.end, {1, 0, 0});
    EXPECT_DOUBLE_EQ(cylinder.strength, -2);
    EXPECT_FALSE(cylinder.appearance.texture);
    const BlobComponent& component = blob.components[2];  // component STRENGTH, RADIUS, CENTRE
    EXPECT_DOUBLE_EQ(component.strength, 1);
    EXPECT_DOUBLE_EQ(component.radius, 2);
    expect_vec(component.centre, {0, 0, 1});

    const auto& defaults = only_shape<BlobShape>(parse("blob { sphere { 0, 1, 1 } }"));
    EXPECT_DOUBLE_EQ(defaults.threshold, 1);
    EXPECT_TRUE(defaults.hierarchy);
    EXPECT_FALSE(defaults.sturm);
    // povray: "Need at least one component in a blob"; threshold goes before the modifiers.
    EXPECT_EQ(error_of("blob { threshold 1 }"),
              "a blob needs at least one component (sphere, cylinder) at test.pov:1:20");
    EXPECT_EQ(error_of("blob { sphere { 0, 1, 1 } translate x threshold 0.5 }"),
              "expected an object modifier or '}' to close 'blob' opened at test.pov:1:6, found "
              "'threshold' at "
              "test.pov:1:39");
    EXPECT_EQ(error_of("blob { sphere { 0, 1, 1 interior { ior 1.5 } } }"),
              "a blob component takes no interior (give the blob one) at test.pov:1:25");
}

TEST(ObjectsFields, HeightFieldFromAnImageOrAFunction) {
    test::ScratchDir dir;
    test::write_image(dir.file("hf.png"), 2, 2, 1, {0, 0.5f, 0.25f, 1});
    test::write_image(dir.file("hf.exr"), 2, 2, 1, {0, 0.5f, 0.25f, 1}, true);
    test::write_file(dir.file("scene.pov"),
                     "height_field { png \"hf.png\" gamma 2.2 smooth water_level 0.2 }\n"
                     "height_field { \"hf.png\" gamma srgb premultiplied hierarchy off }\n"
                     "height_field { exr \"hf.exr\" }\n"
                     "height_field { function 8, 4 { x * y } }\n");
    const SceneDescription s = parse_scene_file(dir.file("scene.pov"));
    ASSERT_EQ(s.objects.size(), 4u);
    const auto& png = std::get<HeightFieldShape>(s.objects[0].shape);
    EXPECT_EQ(png.image_type, "png");
    EXPECT_EQ(png.image_path, fs::weakly_canonical(dir.file("hf.png")).string());
    EXPECT_DOUBLE_EQ(png.image_gamma, 2.2);
    EXPECT_TRUE(png.smooth);
    EXPECT_DOUBLE_EQ(png.water_level, 0.2);
    EXPECT_TRUE(png.hierarchy);
    const auto& untyped = std::get<HeightFieldShape>(s.objects[1].shape);
    EXPECT_EQ(untyped.image_type, "");
    EXPECT_TRUE(untyped.image_srgb);
    EXPECT_TRUE(untyped.premultiplied);
    EXPECT_FALSE(untyped.hierarchy);
    EXPECT_FALSE(untyped.smooth);
    EXPECT_DOUBLE_EQ(untyped.water_level, 0);
    EXPECT_EQ(std::get<HeightFieldShape>(s.objects[2].shape).image_type, "exr");
    const auto& function = std::get<HeightFieldShape>(s.objects[3].shape);
    EXPECT_EQ(function.function_width, 8);
    EXPECT_EQ(function.function_height, 4);
    ASSERT_TRUE(function.function);
    EXPECT_TRUE(function.image_path.empty());
}

TEST(ObjectsFields, IsosurfaceParametricJulia) {
    const auto& iso = only_shape<IsosurfaceShape>(
        parse("isosurface { function { x*x + y*y + z*z - 1 } contained_by { sphere { x, 2 } } "
              "threshold 0.1 "
              "accuracy 0.01 max_gradient 3 evaluate 1, 2, 0.5 open max_trace 3 }"));
    ASSERT_TRUE(iso.function);
    EXPECT_EQ(iso.contained_by.kind, ContainedBy::Kind::sphere);
    expect_vec(iso.contained_by.centre, {1, 0, 0});
    EXPECT_DOUBLE_EQ(iso.contained_by.radius, 2);
    EXPECT_DOUBLE_EQ(iso.threshold, 0.1);
    EXPECT_DOUBLE_EQ(iso.accuracy, 0.01);
    EXPECT_DOUBLE_EQ(iso.max_gradient, 3);
    EXPECT_TRUE(iso.evaluate);
    EXPECT_EQ(iso.evaluate_values, (std::array<double, 3>{1, 2, 0.5}));
    EXPECT_TRUE(iso.open);
    EXPECT_EQ(iso.max_trace, 3);
    EXPECT_FALSE(iso.all_intersections);
    const double at[3] = {1, 2, 2};
    EXPECT_DOUBLE_EQ(iso.function->evaluate_float(at), 8);

    const auto& plain =
        only_shape<IsosurfaceShape>(parse("isosurface { function { x } all_intersections }"));
    EXPECT_EQ(plain.contained_by.kind, ContainedBy::Kind::box);  // POV-Ray's default box { -1, 1 }
    expect_vec(plain.contained_by.minimum, {-1, -1, -1});
    expect_vec(plain.contained_by.maximum, {1, 1, 1});
    EXPECT_DOUBLE_EQ(plain.threshold, 0);
    EXPECT_DOUBLE_EQ(plain.accuracy, 0.001);
    EXPECT_DOUBLE_EQ(plain.max_gradient, 1.1);
    EXPECT_TRUE(plain.all_intersections);
    // povray: the function first ("Expected 'function'").
    EXPECT_EQ(error_of("isosurface { threshold 1 function { x } }"),
              "expected 'function' first in 'isosurface', found 'threshold' at test.pov:1:14");

    const auto& parametric = only_shape<ParametricShape>(
        parse("parametric { function { u } function { v } function { u * v } <0,0>, <1,2> "
              "contained_by { box { 2, -2 } } max_gradient 2 accuracy 0.01 precompute 10 x, z }"));
    const double uv[3] = {3, 4, 0};
    EXPECT_DOUBLE_EQ(parametric.functions[2]->evaluate_float(uv), 12);
    EXPECT_DOUBLE_EQ(parametric.uv_maximum.y, 2);
    expect_vec(parametric.contained_by.minimum, {-2, -2, -2});
    EXPECT_DOUBLE_EQ(parametric.max_gradient, 2);
    EXPECT_DOUBLE_EQ(parametric.accuracy, 0.01);
    EXPECT_EQ(parametric.precompute_depth, 10);
    EXPECT_EQ(parametric.precompute_axes, (std::array<bool, 3>{true, false, true}));
    EXPECT_EQ(error_of("parametric { function { u } function { v } function { 0 } <0,0>, <1,1> "
                       "precompute 21 x }"),
              "precompute depth 21 is more than POV-Ray's 20 at test.pov:1:83");

    const auto& julia =
        only_shape<JuliaFractalShape>(parse("julia_fractal { <-0.083, 0, -0.83, -0.025> "
                                            "hypercomplex pwr(2, 1) max_iteration 8 precision 15 "
                                            "slice <0,0,1,1>, 0.5 }"));
    EXPECT_EQ(julia.parameter, (std::array<double, 4>{-0.083, 0, -0.83, -0.025}));
    EXPECT_EQ(julia.algebra, JuliaFractalShape::Algebra::hypercomplex);
    EXPECT_EQ(julia.function, JuliaFractalShape::Function::pwr);
    EXPECT_DOUBLE_EQ(julia.power.x, 2);
    EXPECT_DOUBLE_EQ(julia.power.y, 1);
    EXPECT_EQ(julia.max_iteration, 8);
    EXPECT_DOUBLE_EQ(julia.precision, 15);
    EXPECT_EQ(julia.slice_normal, (std::array<double, 4>{0, 0, 1, 1}));
    EXPECT_DOUBLE_EQ(julia.slice_distance, 0.5);
    const auto& standard =
        only_shape<JuliaFractalShape>(parse("julia_fractal { <1, 0, 0, 0> cube }"));
    EXPECT_EQ(standard.algebra, JuliaFractalShape::Algebra::quaternion);
    EXPECT_EQ(standard.function, JuliaFractalShape::Function::cube);
    EXPECT_EQ(standard.max_iteration, 20);
    EXPECT_DOUBLE_EQ(standard.precision, 20);
    EXPECT_EQ(standard.slice_normal, (std::array<double, 4>{0, 0, 0, 1}));
    // povray: "Illegal function: quaternion only supports sqr and cube", "Slice t component is
    // zero".
    EXPECT_EQ(error_of("julia_fractal { <1,2,3,4> quaternion exp }"),
              "illegal function 'exp': a quaternion julia_fractal takes only sqr and cube at "
              "test.pov:1:1");
    EXPECT_EQ(error_of("julia_fractal { <1,2,3,4> slice <1,0,0,0>, 2 }"),
              "the slice normal's fourth (t) component must not be 0 at test.pov:1:33");
}

// ---------------------------------------------------------------- meshes

TEST(ObjectsMeshes, MeshTrianglesSmoothUvAndTextures) {
    const SceneDescription s = parse(R"(
        #declare Red = texture { pigment { rgb <1,0,0> } }
        #declare Blue = texture { pigment { rgb <0,0,1> } }
        mesh {
          smooth_triangle { 0, y, x, y, z, y uv_vectors <0,0>, <1,0>, <0,1> texture { Red } }
          triangle { 0, x, 2*x }
          triangle { 0, z, y texture_list { Red Blue Red } }
          inside_vector z
          hierarchy off
        })");
    const MeshShape& shape = only_shape<MeshShape>(s);
    EXPECT_FALSE(shape.hierarchy);
    const TriangleMesh& mesh = *shape.mesh;
    ASSERT_EQ(mesh.faces.size(), 2u);  // the degenerate triangle is dropped, as POV-Ray drops it
    ASSERT_EQ(mesh.vertices.size(), 6u);
    expect_vec(mesh.vertices[mesh.faces[1][1]], {0, 0, 1});
    // Smooth and flat in one mesh: the flat face has no normals.
    ASSERT_EQ(mesh.normal_faces.size(), 2u);
    expect_vec(mesh.normals[mesh.normal_faces[0][2]], {0, 1, 0});
    EXPECT_EQ(mesh.normal_faces[1], (std::array<int, 3>{-1, -1, -1}));
    ASSERT_EQ(mesh.uv_faces.size(), 2u);
    EXPECT_DOUBLE_EQ(mesh.uvs[mesh.uv_faces[0][2]].y, 1);
    EXPECT_EQ(mesh.uv_faces[1], (std::array<int, 3>{-1, -1, -1}));
    ASSERT_EQ(mesh.textures.size(), 2u);
    EXPECT_EQ(mesh.face_textures[0], (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(mesh.face_textures[1], (std::array<int, 3>{0, 1, 0}));
    EXPECT_DOUBLE_EQ(mesh.textures[1]->pigment.colour.blue, 1);
    EXPECT_TRUE(mesh.has_inside_vector);
    expect_vec(mesh.inside_vector, {0, 0, 1});

    const SceneDescription plain_scene = parse("mesh { triangle { 0, x, y } }");
    const TriangleMesh& plain = *only_shape<MeshShape>(plain_scene).mesh;
    EXPECT_TRUE(plain.normal_faces.empty());
    EXPECT_TRUE(plain.uv_faces.empty());
    EXPECT_TRUE(plain.face_textures.empty());
    EXPECT_FALSE(plain.has_inside_vector);

    // povray: "No triangles in triangle mesh"; a triangle takes a texture identifier only;
    // inside_vector comes before the other modifiers.
    EXPECT_EQ(error_of("mesh { triangle { 0, x, 2*x } }"),
              "no triangles in the mesh (POV-Ray drops degenerate ones) at test.pov:1:31");
    EXPECT_EQ(error_of("mesh { triangle { 0, x, y texture { pigment { rgb 1 } } } }"),
              "expected a texture identifier (a mesh triangle takes no texture definition), found "
              "'pigment' at "
              "test.pov:1:37");
    EXPECT_EQ(error_of("mesh { triangle { 0, x, y } translate x inside_vector z }"),
              "expected an object modifier or '}' to close 'mesh' opened at test.pov:1:6, found "
              "'inside_vector' at "
              "test.pov:1:41");
}

TEST(ObjectsMeshes, Mesh2ListsIndicesAndTheirChecks) {
    const SceneDescription s = parse(R"(
        mesh2 {
          vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0> }
          normal_vectors { 1, <0,0,-1> }
          uv_vectors { 4, <0,0>, <1,0>, <0,1>, <1,1> }
          texture_list { 2, texture { pigment { rgb 1 } }, texture { pigment { rgb 0.5 } } }
          face_indices { 3, <0,1,2>, 1, <1,3,2>, 0, 1, 1, <0,2,3> }
          normal_indices { 1, <0,0,0> }
          inside_vector y
        })");
    const TriangleMesh& mesh = *only_shape<MeshShape>(s).mesh;
    ASSERT_EQ(mesh.faces.size(), 3u);
    EXPECT_EQ(mesh.face_textures[0], (std::array<int, 3>{1, 1, 1}));
    EXPECT_EQ(mesh.face_textures[1], (std::array<int, 3>{0, 1, 1}));
    EXPECT_EQ(mesh.face_textures[2], (std::array<int, 3>{-1, -1, -1}));
    // Fewer normal_indices than faces: the rest are flat (POV-Ray's way to mix them).
    ASSERT_EQ(mesh.normal_faces.size(), 3u);
    EXPECT_EQ(mesh.normal_faces[0], (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(mesh.normal_faces[2], (std::array<int, 3>{-1, -1, -1}));
    EXPECT_EQ(mesh.uvs.size(), 4u);
    EXPECT_TRUE(mesh.uv_faces.empty());  // uvs follow the vertices
    EXPECT_DOUBLE_EQ(mesh.textures[1]->pigment.colour.green, 0.5);
    EXPECT_TRUE(mesh.has_inside_vector);

    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0,1,3> } }"),
              "vertex index 3 out of range: there are 3 vertex_vectors at test.pov:1:57");
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0,1,2>, 2 } }"),
              "texture index 2 out of range: texture_list has 0 at test.pov:1:66");
    EXPECT_EQ(error_of("mesh2 { face_indices { 1, <0,1,2> } vertex_vectors { 3, 0, x, y } }"),
              "'vertex_vectors' after the indices in mesh2: its sections come in the order "
              "vectors, texture_list, "
              "indices at test.pov:1:37");
    EXPECT_EQ(
        error_of(
            "mesh2 { vertex_vectors { 3, 0, x, y } uv_vectors { 1, 0 } face_indices { 1, <0,1,2> } "
            "uv_indices { 2, <0,0,0>, <0,0,0> } }"),
        "uv_indices has 2 entries, face_indices 1 at test.pov:1:87");
    EXPECT_EQ(
        error_of("mesh2 { vertex_vectors { 3, 0, x, y } normal_vectors { 2, y, y } face_indices { "
                 "1, <0,1,2> } }"),
        "without normal_indices, normal_vectors (2) must match vertex_vectors (3) at test.pov:1:1");
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 2, 0, x } face_indices { 1, <0,1,1> } }"),
              "no error");
}

// ---------------------------------------------------------------- CSG and flattening

TEST(ObjectsCsg, UnionsSplitOtherCsgStaysATree) {
    const SceneDescription s = parse(R"(
        union {
          sphere { 0, 1 }
          difference {
            box { -1, 1 }
            sphere { 0, 1.2 texture { pigment { rgb <0,1,0> } } }
            cylinder { -2*x, 2*x, 0.5 }
            light_source { <0, 5, 0>, 1 }
            translate y
          }
          texture { pigment { rgb <1,0,0> } }
          translate 10*x
        })");
    ASSERT_EQ(s.objects.size(), 2u);  // the union is split; the difference is one instance
    ASSERT_EQ(s.lights.size(), 1u);   // its light is the scene's, placed by both transforms
    expect_vec(s.lights[0].position, {10, 6, 0});
    EXPECT_TRUE(std::holds_alternative<SphereShape>(s.objects[0].shape));
    const ObjectInstance& difference = s.objects[1];
    const auto& csg = std::get<CsgShape>(difference.shape);
    EXPECT_EQ(csg.operation, CsgShape::Operation::difference);
    EXPECT_STREQ(shape_keyword(difference.shape), "difference");
    expect_vec(difference.object_to_world.point({0, 0, 0}), {10, 1, 0});
    ASSERT_EQ(csg.children.size(), 3u);
    // Children in world coordinates, each with what it inherits.
    expect_vec(csg.children[2].object_to_world.point({2, 0, 0}), {12, 1, 0});
    EXPECT_DOUBLE_EQ(csg.children[0].appearance.texture->pigment.colour.red, 1);    // the union's
    EXPECT_DOUBLE_EQ(csg.children[1].appearance.texture->pigment.colour.green, 1);  // its own
    EXPECT_DOUBLE_EQ(difference.appearance.texture->pigment.colour.red, 1);
    EXPECT_EQ(csg.children[1].location.str(), "test.pov:6:13");

    for (const auto& [text, operation] : {std::pair{"merge", CsgShape::Operation::merge},
                                          {"intersection", CsgShape::Operation::intersection}}) {
        const SceneDescription one =
            parse(std::string(text) + " { sphere { 0, 1 } sphere { x, 1 } }");
        EXPECT_EQ(only_shape<CsgShape>(one).operation, operation);
    }
    // A union with clipped_by, bounded_by or inverse is not split (POV-Ray does not split it).
    for (const char* modifier :
         {"clipped_by { plane { y, 0 } }", "bounded_by { sphere { 0, 3 } }", "inverse"}) {
        const SceneDescription kept =
            parse(std::string("union { sphere { 0, 1 } sphere { x, 1 } ") + modifier + " }");
        EXPECT_EQ(only_shape<CsgShape>(kept).operation, CsgShape::Operation::union_of) << modifier;
        EXPECT_EQ(only_shape<CsgShape>(kept).children.size(), 2u);
    }
    // composite is POV-Ray's old name for union.
    EXPECT_EQ(parse("composite { sphere { 0, 1 } sphere { x, 1 } }").objects.size(), 2u);
    EXPECT_FALSE(only_shape<CsgShape>(
                     parse("union { sphere { 0, 1 } box { 0, 1 } split_union off inverse }"))
                     .split_union);
}

TEST(ObjectsCsg, ObjectsComeBeforeTheModifiers) {
    // povray: "No matching } in 'union', sphere found instead".
    EXPECT_EQ(error_of("union { sphere { 0, 1 } translate x sphere { 0, 1 } }"),
              "an object after the modifiers of 'union' opened at test.pov:1:7 (its objects come "
              "first) at "
              "test.pov:1:37");
    EXPECT_EQ(
        warnings_of("union { sphere { 0, 1 } }"),
        std::vector<std::string>{"test.pov:1:1: warning: 'union' with fewer than 2 objects\n"});
    EXPECT_NO_THROW(parse("union { }"));  // povray takes an empty union
}

TEST(ObjectsCsg, InheritedFlagsHollowImportanceAndPhotons) {
    const SceneDescription s = parse(R"(
        union {
          sphere { -x, 1 hollow off }
          sphere { x, 1 no_reflection radiosity { importance 0.5 }
                   photons { target 0.5 refraction on } }
          hollow
          no_image
          radiosity { importance 0.25 }
          double_illuminate
        }
        sphere { 0, 1 no_shadow }
        sphere { 0, 1 no_shadow photons { pass_through off } })");
    ASSERT_EQ(s.objects.size(), 4u);
    const ObjectInstance& first = s.objects[0];
    const ObjectInstance& second = s.objects[1];
    EXPECT_FALSE(first.hollow);  // its own off beats the union's on (the manual's example)
    EXPECT_TRUE(second.hollow);
    EXPECT_TRUE(first.no_image);
    EXPECT_TRUE(second.no_image);
    EXPECT_FALSE(first.no_reflection);
    EXPECT_TRUE(second.no_reflection);
    EXPECT_TRUE(first.double_illuminate);
    EXPECT_DOUBLE_EQ(first.radiosity_importance, 0.25);
    EXPECT_DOUBLE_EQ(second.radiosity_importance, 0.5);
    EXPECT_DOUBLE_EQ(s.objects[2].radiosity_importance, 1);
    EXPECT_FALSE(first.photons.target);
    EXPECT_TRUE(second.photons.target);
    EXPECT_DOUBLE_EQ(second.photons.spacing_multiplier, 0.5);
    EXPECT_TRUE(second.photons.refraction);
    EXPECT_FALSE(second.photons.reflection);
    EXPECT_TRUE(second.photons.collect);
    // no_shadow makes photons pass through, until photons { pass_through off } (the manual).
    EXPECT_TRUE(s.objects[2].photons.pass_through);
    EXPECT_FALSE(s.objects[3].photons.pass_through);
    EXPECT_TRUE(s.objects[3].no_shadow);

    // `no_shadow` and `inverse` take no value (povray: "float function 'off' found instead").
    EXPECT_EQ(error_of("sphere { 0, 1 no_shadow off }"),
              "expected an object modifier or '}' to close 'sphere' opened at test.pov:1:8, found "
              "'off' at "
              "test.pov:1:25");
    EXPECT_EQ(error_of("sphere { 0, 1 radiosity { importance 0 } }"),
              "radiosity importance must lie in (0, 1], found 0 at test.pov:1:38");
}

TEST(ObjectsCsg, RestrictedModifiers) {
    // povray: "Keyword 'sturm' cannot be used with this object", likewise hierarchy;
    // "cutaway_textures can only be used with intersection and difference".
    EXPECT_EQ(error_of("sphere { 0, 1 sturm }"),
              "'sturm' cannot be used with sphere (only with blob, cubic, lathe, ovus, poly, "
              "polynomial, prism, "
              "quartic, sor and torus) at test.pov:1:15");
    EXPECT_EQ(error_of("union { torus { 1, 0.5 } sphere { 0, 1 } sturm }"),
              "'sturm' cannot be used with this object (only with blob, cubic, lathe, ovus, poly, "
              "polynomial, prism, "
              "quartic, sor and torus) at test.pov:1:42");
    EXPECT_EQ(error_of("torus { 1, 0.5 hierarchy }"),
              "'hierarchy' cannot be used with torus (only with blob, height_field, mesh and "
              "mesh2) at test.pov:1:16");
    EXPECT_EQ(error_of("merge { sphere { 0, 1 } sphere { 0, 1 } split_union off }"),
              "'split_union' cannot be used with this object (only with union) at test.pov:1:41");
    EXPECT_EQ(
        error_of("sphere { 0, 1 cutaway_textures }"),
        "'cutaway_textures' cannot be used with sphere (only with intersection and difference) at "
        "test.pov:1:15");
    EXPECT_TRUE(parse("difference { sphere { 0, 1 } sphere { x, 1 } cutaway_textures }")
                    .objects.at(0)
                    .cutaway_textures);
    // On a copy of a shape that takes it, sturm is the copy's (povray: `object { T sturm off }`).
    const SceneDescription copy =
        parse("#declare T = torus { 1, 0.5 sturm }\nobject { T sturm off }\nobject { T }");
    EXPECT_FALSE(std::get<TorusShape>(copy.objects[0].shape).sturm);
    EXPECT_TRUE(std::get<TorusShape>(copy.objects[1].shape).sturm);
}

TEST(ObjectsCsg, ClippedByAndBoundedByTakeTheTransformsAfterThem) {
    const SceneDescription s = parse(R"(
        sphere { 0, 1
          translate x
          clipped_by { plane { y, 0 } box { -1, 1 } }
          bounded_by { clipped_by }
          translate z
        })");
    const ObjectInstance& o = s.objects.at(0);
    ASSERT_EQ(o.clipped_by.size(), 2u);
    ASSERT_EQ(o.bounded_by.size(), 2u);
    // The clip came after `translate x`: only `translate z` moves it.
    expect_vec(o.clipped_by[1].object_to_world.point({0, 0, 0}), {0, 0, 1});
    expect_vec(o.bounded_by[1].object_to_world.point({0, 0, 0}), {0, 0, 1});
    expect_vec(o.object_to_world.point({0, 0, 0}), {1, 0, 1});
    EXPECT_TRUE(std::holds_alternative<PlaneShape>(o.clipped_by[0].shape));

    // Untextured solid objects only (povray: "Illegal texture or patch in clip, bound or object
    // pattern").
    EXPECT_EQ(error_of("sphere { 0, 1 clipped_by { sphere { 0, 1 pigment { rgb 1 } } } }"),
              "'clipped_by' takes untextured solid objects: it has a texture at test.pov:1:28");
    EXPECT_EQ(
        error_of("sphere { 0, 1 bounded_by { triangle { 0, x, y } } }"),
        "'bounded_by' takes untextured solid objects: a triangle has no inside at test.pov:1:28");
    EXPECT_EQ(error_of("sphere { 0, 1 clipped_by { mesh { triangle { 0, x, y } } } }"),
              "'clipped_by' takes untextured solid objects: a mesh without inside_vector has no "
              "inside at "
              "test.pov:1:28");
    EXPECT_EQ(error_of("sphere { 0, 1 clipped_by { light_source { 0, 1 } } }"),
              "'clipped_by' takes untextured solid objects: a light_source is not an object with "
              "an inside at "
              "test.pov:1:28");
    EXPECT_EQ(error_of("sphere { 0, 1 clipped_by { } }"),
              "expected an object in 'clipped_by', found '}' at test.pov:1:28");
    EXPECT_EQ(error_of("sphere { 0, 1 clipped_by { bounded_by } }"),
              "'clipped_by { bounded_by }' without a bounded_by before it at test.pov:1:28");
    EXPECT_NO_THROW(
        parse("sphere { 0, 1 clipped_by { disc { 0, y, 1 } polygon { 3, 0, x, y } } }"));
}

TEST(ObjectsCsg, ObjectCopiesKeepTheirShapeAndTakeNewModifiers) {
    const SceneDescription s = parse(R"(
        #declare D = difference { box { -1, 1 } sphere { 0, 1.2 } }
        object { D translate 5*x no_shadow }
        object { D })");
    ASSERT_EQ(s.objects.size(), 2u);
    expect_vec(s.objects[0].object_to_world.point({0, 0, 0}), {5, 0, 0});
    EXPECT_TRUE(s.objects[0].no_shadow);
    EXPECT_FALSE(s.objects[1].no_shadow);
    expect_vec(std::get<CsgShape>(s.objects[0].shape).children[1].object_to_world.point({0, 0, 0}),
               {5, 0, 0});
}

TEST(ObjectsMeshes, MeshOfADeclaredMeshIsThatMeshMoved) {
    // POV-Ray accepts mesh { MESH_ID modifiers } (checked with povray 3.7); the mesh is shared.
    const SceneDescription s = parse(R"(
        #declare M = mesh { triangle { 0, x, y } }
        mesh { M translate 2*x }
        object { M })");
    ASSERT_EQ(s.objects.size(), 2u);
    expect_vec(s.objects[0].object_to_world.point({0, 0, 0}), {2, 0, 0});
    EXPECT_EQ(std::get<MeshShape>(s.objects[0].shape).mesh,
              std::get<MeshShape>(s.objects[1].shape).mesh);
    EXPECT_EQ(
        error_of("#declare B = box { 0, 1 }\nmesh { B }"),
        "wrong type: 'B' is not a mesh, expected a mesh identifier or triangles at test.pov:2:8");
}

// ---------------------------------------------------------------- lights

TEST(ObjectsLights, TypesAndTheirDefaults) {
    const SceneDescription s = parse(R"(
        light_source { <1,2,3>, rgb <1,0.5,0.25> }
        light_source { 0, 1 spotlight }
        light_source { 0, 1 cylinder point_at x }
        light_source { 0, 1 spotlight radius 0.3 falloff 0.4 tightness 2 cylinder }
        light_source { 0, 1 cylinder radius 0.3 spotlight }
        light_source { 0, 1 spotlight shadowless }
        light_source { 0, 1 shadowless spotlight }
        light_source { 0, 1 parallel point_at <0,-1,0> }
        light_source { 0 })");
    ASSERT_EQ(s.lights.size(), 9u);
    const LightSource& point = s.lights[0];
    expect_vec(point.position, {1, 2, 3});
    EXPECT_DOUBLE_EQ(point.colour.green, 0.5);
    EXPECT_FALSE(point.spotlight || point.cylinder || point.shadowless || point.parallel);
    expect_vec(point.point_at,
               {0, 0, 1});  // povray renders: 3.7's default is <0,0,1>, not the manual's <0,0,0>
    EXPECT_TRUE(point.media_interaction);
    EXPECT_FALSE(point.media_attenuation);
    EXPECT_TRUE(point.photons_reflection);
    EXPECT_TRUE(point.photons_refraction);
    EXPECT_FALSE(point.photons_area_light);
    EXPECT_FALSE(point.area_illumination);
    EXPECT_EQ(point.location.str(), "test.pov:2:9");
    // The last type keyword decides and resets the spot parameters to its defaults (povray
    // renders: a spotlight after a cylinder's radius lights as a 30-degree spot).
    EXPECT_TRUE(s.lights[1].spotlight);
    EXPECT_DOUBLE_EQ(s.lights[1].radius, 30);
    EXPECT_DOUBLE_EQ(s.lights[1].falloff, 45);
    const LightSource& cylinder = s.lights[2];
    EXPECT_TRUE(cylinder.cylinder);
    EXPECT_FALSE(cylinder.spotlight);
    EXPECT_DOUBLE_EQ(cylinder.radius, 0.75);
    EXPECT_DOUBLE_EQ(cylinder.falloff, 1);
    EXPECT_DOUBLE_EQ(cylinder.tightness, 0);
    expect_vec(cylinder.point_at, {1, 0, 0});
    EXPECT_TRUE(s.lights[3].cylinder);
    EXPECT_DOUBLE_EQ(s.lights[3].radius, 0.75);
    EXPECT_DOUBLE_EQ(s.lights[3].tightness, 0);
    EXPECT_TRUE(s.lights[4].spotlight);
    EXPECT_DOUBLE_EQ(s.lights[4].radius, 30);
    // shadowless is a type too (povray renders: `spotlight ... shadowless` lights every
    // direction, `shadowless spotlight` casts shadows).
    EXPECT_TRUE(s.lights[5].shadowless);
    EXPECT_FALSE(s.lights[5].spotlight);
    EXPECT_TRUE(s.lights[6].spotlight);
    EXPECT_FALSE(s.lights[6].shadowless);
    EXPECT_TRUE(s.lights[7].parallel);
    expect_vec(s.lights[7].point_at, {0, -1, 0});
    // No colour: black (povray renders nothing lit by it).
    EXPECT_DOUBLE_EQ(s.lights[8].colour.red + s.lights[8].colour.green + s.lights[8].colour.blue,
                     0);
}

TEST(ObjectsLights, AreaFadeMediaPhotons) {
    const LightSource l = parse(R"(
        light_source { <0,5,0>, 1
          area_light <2,0,0>, <0,0,1>, 3.7, 2 adaptive 1 jitter circular orient area_illumination
          fade_distance 2 fade_power 1 media_interaction off media_attenuation
          photons { reflection off area_light }
        })")
                              .lights.at(0);
    EXPECT_TRUE(l.area_light);
    expect_vec(l.axis1, {2, 0, 0});
    EXPECT_EQ(l.size1, 3);  // truncated, as POV-Ray does
    EXPECT_EQ(l.size2, 2);
    EXPECT_EQ(l.adaptive, 1);
    EXPECT_TRUE(l.jitter && l.circular && l.orient && l.area_illumination);
    EXPECT_DOUBLE_EQ(l.fade_distance, 2);
    EXPECT_DOUBLE_EQ(l.fade_power, 1);
    EXPECT_FALSE(l.media_interaction);
    EXPECT_TRUE(l.media_attenuation);
    EXPECT_FALSE(l.photons_reflection);
    EXPECT_TRUE(l.photons_refraction);
    EXPECT_TRUE(l.photons_area_light);
    // povray takes a negative adaptive as 0.
    EXPECT_EQ(parse("light_source { 0, 1 adaptive -1 }").lights[0].adaptive, 0);

    // povray's corrections of orient, with its warnings: circular, the first axis's length.
    const std::string oriented = "light_source { 0, 1 area_light x, 2*y, 3, 2 orient }";
    const LightSource o = parse(oriented).lights.at(0);
    EXPECT_TRUE(o.circular);
    expect_vec(o.axis2, {0, 1, 0});
    EXPECT_EQ(warnings_of(oriented).size(), 3u);
    EXPECT_TRUE(warnings_of("light_source { 0, 1 area_light x, y, 3, 3 circular orient }").empty());
}

TEST(ObjectsLights, WhatPovRayRefuses) {
    // povray: "Keyword 'radius' cannot be used with standard light source" and likewise.
    EXPECT_EQ(error_of("light_source { 0, 1 radius 10 spotlight }"),
              "'radius' cannot be used with a point light (write spotlight or cylinder before it) "
              "at test.pov:1:21");
    EXPECT_EQ(error_of("light_source { 0, 1 point_at x parallel }"),
              "'point_at' cannot be used with a point light (write spotlight or cylinder, or "
              "parallel, before it) at "
              "test.pov:1:21");
    EXPECT_EQ(error_of("light_source { 0, 1 spotlight shadowless falloff 5 }"),
              "'falloff' cannot be used with a shadowless light (write spotlight or cylinder "
              "before it) at "
              "test.pov:1:42");
    EXPECT_EQ(error_of("light_source { 0, 1 area_light x, y, 0, 2 }"),
              "expected an integer >= 1 as the first area_light size, found 0 at test.pov:1:38");
    // No colour after the first, nothing but transforms after a light identifier (povray).
    EXPECT_EQ(error_of("light_source { 0, 1 rgb 0.5 }"),
              "expected a light_source modifier or '}' to close 'light_source' opened at "
              "test.pov:1:14, found 'rgb' at "
              "test.pov:1:21");
    EXPECT_EQ(error_of("#declare L = light_source { 0, 1 spotlight }\nlight_source { L radius 3 }"),
              "expected a transform or '}' to close 'light_source' opened at test.pov:2:14 (a "
              "declared light takes "
              "no other modifier), found 'radius' at test.pov:2:18");
    EXPECT_EQ(error_of("#declare S = sphere { 0, 1 }\nlight_source { S }"),
              "wrong type: 'S' is an object, expected a light_source identifier at test.pov:2:16");
    const SceneDescription moved =
        parse("#declare L = light_source { x, 1 }\nlight_source { L translate y }");
    expect_vec(moved.lights.at(0).position, {1, 1, 0});
}

TEST(ObjectsLights, LooksLikeMovesToTheLightProjectedThroughStays) {
    // Checked against povray renders: the object is moved to where the light is when looks_like
    // is read, then the block's own modifiers apply, then the light's later transforms.
    const SceneDescription s = parse(R"(
        #declare Shape = sphere { <0,1,0>, 0.5 }
        light_source { <2,0,0>, 1 looks_like { Shape scale 2 } }
        light_source { <2,0,0>, 1 translate y looks_like { sphere { 0, 0.5 } } }
        light_source { <0,1,0>, 1 looks_like { sphere { 0, 0.5 } } scale 0.5
                       projected_through { box { -1, 1 } } translate 3*x })");
    ASSERT_EQ(s.lights.size(), 3u);
    ASSERT_EQ(s.objects.size(), 3u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(s.objects[k].looks_like_of, k);
        EXPECT_TRUE(s.objects[k].no_shadow);  // POV-Ray's implied no_shadow
    }
    expect_vec(s.objects[0].object_to_world.point(std::get<SphereShape>(s.objects[0].shape).centre),
               {4, 2, 0});
    expect_vec(s.objects[1].object_to_world.point({0, 0, 0}), {2, 1, 0});
    expect_vec(s.objects[2].object_to_world.point({0, 0, 0}), {3, 0.5, 0});
    expect_vec(s.lights[2].position, {3, 0.5, 0});
    ASSERT_EQ(s.lights[2].projected_through.size(), 1u);
    expect_vec(s.lights[2].projected_through[0].object_to_world.point({0, 0, 0}),
               {3, 0, 0});  // not scaled
    EXPECT_EQ(error_of("light_source { 0, 1 looks_like { 3 } }"),
              "expected an object or an object identifier in 'looks_like', found number 3 at "
              "test.pov:1:34");
}

TEST(ObjectsLights, LightGroups) {
    const SceneDescription s = parse(R"(
        #declare Inner = light_group { light_source { y, 1 } sphere { 0, 1 } global_lights }
        light_source { 10*y, 1 }
        light_group {
          light_source { x, 1 }
          box { 0, 1 }
          light_group { Inner }
          translate z
        })");
    ASSERT_EQ(s.lights.size(), 3u);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_FALSE(s.lights[0].light_group);
    const auto& outer = s.lights[1].light_group;
    ASSERT_TRUE(outer);
    EXPECT_FALSE(outer->global_lights);
    EXPECT_FALSE(outer->parent);
    EXPECT_EQ(outer->location.str(), "test.pov:4:9");
    expect_vec(s.lights[1].position, {1, 0, 1});
    EXPECT_EQ(s.objects[0].light_group, outer);
    // Inner, nested in a group of its own (light_group { Inner }) inside the outer one.
    const auto& inner = s.lights[2].light_group;
    ASSERT_TRUE(inner);
    EXPECT_TRUE(inner->global_lights);
    ASSERT_TRUE(inner->parent);
    EXPECT_FALSE(inner->parent->global_lights);
    EXPECT_EQ(inner->parent->parent, outer);
    EXPECT_EQ(s.objects[1].light_group, inner);
    expect_vec(s.lights[2].position, {0, 1, 1});
    // In a CSG kept whole, a light group's objects and lights share one group.
    const SceneDescription csg = parse(
        "difference { box { -1, 1 } light_group { sphere { 0, 0.5 } light_source { 5, 1 } } }");
    ASSERT_EQ(csg.lights.size(), 1u);
    ASSERT_TRUE(csg.lights[0].light_group);
    const ObjectInstance& members = std::get<CsgShape>(csg.objects.at(0).shape).children.at(1);
    EXPECT_EQ(std::get<CsgShape>(members.shape).children.at(0).light_group,
              csg.lights[0].light_group);
    // povray: objects and lights first, then only transforms and global_lights.
    EXPECT_EQ(error_of("light_group { sphere { 0, 1 } no_shadow }"),
              "expected a transform, global_lights or '}' to close 'light_group' opened at "
              "test.pov:1:13, found "
              "'no_shadow' at test.pov:1:31");
    EXPECT_EQ(error_of("light_group { translate x sphere { 0, 1 } }"),
              "an object after the modifiers of 'light_group' opened at test.pov:1:13 (its objects "
              "and lights come "
              "first) at test.pov:1:27");
}

// ---------------------------------------------------------------- min_extent, max_extent

TEST(ObjectsGeometry, BoundingBoxesOfShapesAsPovRayComputesThem) {
    // All values: povray's min_extent/max_extent of the same objects.
    expect_extent("box { <1,2,3>, <-1,-2,-3> rotate 45*y }", {-2.8284, -2, -2.8284},
                  {2.8284, 2, 2.8284});
    expect_extent("cylinder { 0, 2*y, 1 }", {-1, 0, -1}, {1, 2, 1});
    // A tilted cylinder or cone: its box turned by the shortest rotation of +z onto its axis.
    expect_extent("cylinder { 0, <1,2,0>, 1 }", {-1.2, -0.6, -1.3416}, {2.2, 2.6, 1.3416});
    expect_extent("cylinder { 0, <1,1,1>, 1 }", {-1, -1, -1.1547}, {2, 2, 2.1547});
    expect_extent("cylinder { 0, -z, 1 }", {-1, -1, -1}, {1, 1, 0});
    expect_extent("cone { 0, 1, <1,1,1>, 2 }", {-2, -2, -2.3094}, {3, 3, 3.3094});
    expect_extent("cone { 0, 1, y, 0.5 scale <2,1,1> rotate 30*x }", {-2, -0.5, -0.8660},
                  {2, 1.3660, 1.3660});
    expect_extent("cylinder { 0, y, 1 scale <1,3,1> rotate 30*x translate <1,2,3> }",
                  {0, 1.5, 2.1340}, {2, 5.0981, 5.3660});
    expect_extent("torus { 2, 0.5 }", {-2.5, -0.5, -2.5}, {2.5, 0.5, 2.5});
    expect_extent("torus { 2, 0.5 scale <1,3,1> rotate 30*x translate <1,2,3> }",
                  {-1.5, -0.5490, 0.0849}, {3.5, 4.5490, 5.9151});
    // A disc's box is 0.001 thick.
    expect_extent("disc { <1,0,0>, y, 2 }", {-1, -0.001, -2}, {3, 0.001, 2});
    expect_extent("disc { <1,2,3>, <1,1,0>, 2 }", {-1.0007, -0.0007, 0.1716},
                  {3.0007, 4.0007, 5.8284});
    expect_extent("triangle { 0, x, <0,1,2> }", {0, 0, 0}, {1, 1, 2});
    expect_extent("plane { y, 1 }", {-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10});
    // A sphere keeps a tight box through translate, rotate and even scale; other transforms
    // carry the box of the sphere as it was.
    expect_extent("sphere { x, 1 rotate 45*z }", {-0.2929, -0.2929, -1}, {1.7071, 1.7071, 1});
    expect_extent("sphere { x, 1 scale 2 rotate 45*z translate y }", {-0.5858, 0.4142, -2},
                  {3.4142, 4.4142, 2});
    expect_extent("sphere { x, 1 scale <1,2,1> rotate 45*z }", {-1.4142, -1.4142, -1},
                  {2.8284, 2.8284, 1});
    expect_extent("sphere { x, 1 rotate 45*z scale <1,2,1> }", {-0.2929, -0.5858, -1},
                  {1.7071, 3.4142, 1});
    expect_extent("sphere { x, 1 transform { rotate 45*z } }", {-0.7071, -0.7071, -1},
                  {2.1213, 2.1213, 1});
    expect_extent("sphere { <1,0,0>, 1 scale <1,2,3> rotate 30*z }", {-1, -1.7321, -3},
                  {2.7321, 2.7321, 3});
    expect_extent("object { sphere { x, 1 } rotate 45*z }", {-0.2929, -0.2929, -1},
                  {1.7071, 1.7071, 1});
    // Shapes with their own box.
    expect_extent("blob { threshold 0.6 sphere { <1,2,3>, 2, 5 } sphere { -x, 1, 1 } }",
                  {-2, -1, -1}, {3, 4, 5});
    expect_extent("blob { sphere { 0, 2, -1 } sphere { x, 1, 1 } }", {0, -1, -1}, {2, 1, 1});
    expect_extent("blob { sphere { x, 2, 1 rotate 45*z } }", {-1.2929, -1.2929, -2},
                  {2.7071, 2.7071, 2});
    expect_extent("blob { sphere { 0, 2, 1 scale <1,2,3> rotate 30*x } }",
                  {-7.1962, -7.1962, -7.1962}, {7.1962, 7.1962, 7.1962});
    expect_extent("blob { sphere { 0, 2, 1 } rotate 45*z }", {-2.8284, -2.8284, -2},
                  {2.8284, 2.8284, 2});
    expect_extent("lathe { linear_spline 3, <-1,0>, <2,1>, <0.5,3> }", {-2, 0, -2}, {2, 3, 2});
    expect_extent("lathe { bezier_spline 4, <1,0>, <2,1>, <3,2>, <0.5,3> }", {-3, 0, -3},
                  {3, 3, 3});
    expect_extent("prism { 2, 0, 4, <0,0>, <1,0>, <0,1>, <0,0> }", {0, 0, 0}, {1, 2, 1});
    expect_extent("prism { conic_sweep 1, 0.5, 4, <-1,-2>, <1,0>, <0,1>, <-1,-2> }", {-1, 0.5, -2},
                  {1, 1, 1});
    expect_extent("superellipsoid { <0.5, 0.5> }", {-1.0001, -1.0001, -1.0001},
                  {1.0001, 1.0001, 1.0001}, 1e-9);
    expect_extent("isosurface { function { x } contained_by { sphere { x, 2 } } }", {-1, -2, -2},
                  {3, 2, 2});
    expect_extent("sphere_sweep { linear_spline 3, 0, 1, x, 0.5, <0,3,0>, 0.2 }", {-1, -1, -1},
                  {1.5, 3.2, 1});
    expect_extent(
        "bicubic_patch { type 1 <0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>,<0,1,0>,<1,1,1>,<2,1,0>,<3,1,0>,"
        "<0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>,<0,3,0>,<1,3,0>,<2,3,0>,<3,3,0> }",
        {0, 0, 0}, {3, 3, 1});
}

TEST(ObjectsGeometry, BoundingBoxesOfCsgClipsAndBounds) {
    // povray again. A CSG or a mesh transforms the box it has, one transform at a time.
    expect_extent("union { sphere { 0, 1 } box { 0, 2 } translate x }", {0, -1, -1}, {3, 2, 2});
    expect_extent("union { box { -1, 1 } rotate 45*y rotate -45*y }", {-2, -1, -2}, {2, 1, 2});
    expect_extent("mesh { triangle { 0, x, y } rotate 45*y rotate -45*y }", {0, 0, -0.5},
                  {1, 1, 0.5});
    expect_extent("merge { sphere { 0, 1 } sphere { x, 1 } rotate 45*y }", {-1.4142, -1, -2.1213},
                  {2.1213, 1, 1.4142});
    expect_extent("intersection { sphere { 0, 1 } box { 0, 2 } }", {0, 0, 0}, {1, 1, 1});
    expect_extent("difference { sphere { 0, 1 } box { 0, 2 } }", {-1, -1, -1}, {1, 1, 1});
    expect_extent("intersection { sphere { 0, 1 } sphere { 0, 0.5 inverse } }", {-1, -1, -1},
                  {1, 1, 1});
    // Axis-aligned planes cut an intersection's box (inverted ones from the other side).
    expect_extent("intersection { sphere { 0, 1 } plane { y, 0 } }", {-1, -1, -1}, {1, 0, 1});
    expect_extent("intersection { sphere { 0, 1 } plane { -y, 0 } }", {-1, 0, -1}, {1, 1, 1});
    expect_extent("intersection { sphere { 0, 1 } plane { x, 0.5 rotate 90*z } }", {-1, -1, -1},
                  {1, 0.5, 1});
    expect_extent("intersection { sphere { 0, 1 } plane { y, 0.5 inverse } }", {-1, 0.5, -1},
                  {1, 1, 1});
    expect_extent("intersection { sphere { 0, 1 } plane { <0,1,0.001>, 0 } }", {-1, -1, -1},
                  {1, 1, 1});
    expect_extent("difference { sphere { 0, 1 } plane { y, 0 } }", {-1, 0, -1}, {1, 1, 1});
    expect_extent("intersection { sphere { 0, 1 } plane { y, 0 } rotate 45*x rotate -45*x }",
                  {-1, -2, -1.5}, {1, 1, 1.5});
    expect_extent(
        "intersection { plane { x, 1 } plane { -x, 1 } plane { y, 1 } plane { -y, 1 } plane { z, 1 "
        "} "
        "plane { -z, 1 } }",
        {-1, -1, -1}, {1, 1, 1});
    // Unbounded on any side, or empty: unbounded everywhere.
    const Vec3 far{1e10, 1e10, 1e10};
    expect_extent("intersection { plane { y, 0 } plane { x, 1 } plane { -x, 1 } }", -far, far);
    expect_extent("intersection { sphere { 0, 1 } plane { y, -2 } }", -far, far);
    expect_extent("union { sphere { 0, 1 } plane { y, 0 } }", -far, far);
    expect_extent("union { light_source { 5, 1 } sphere { 0, 1 } }", -far, far);
    expect_extent("sphere { 0, 1 inverse }", {-1, -1, -1}, {1, 1, 1});
    // clipped_by and bounded_by boxes replace the object's own when smaller in volume.
    expect_extent("sphere { 0, 1 bounded_by { box { -0.5, 0.5 } } }", {-0.5, -0.5, -0.5},
                  {0.5, 0.5, 0.5});
    expect_extent("sphere { 0, 1 bounded_by { box { -3, 3 } } }", {-1, -1, -1}, {1, 1, 1});
    expect_extent("sphere { 0, 1 bounded_by { box { <-0.5,-0.5,-10>, <0.5,0.5,10> } } }",
                  {-1, -1, -1}, {1, 1, 1});
    expect_extent("sphere { 0, 1 clipped_by { box { 0, 0.5 } } }", {0, 0, 0}, {0.5, 0.5, 0.5});
    expect_extent("sphere { 0, 1 bounded_by { box { 0, 0.5 } } translate x }", {1, 0, 0},
                  {1.5, 0.5, 0.5});
    expect_extent("sphere { 0, 1 translate x bounded_by { box { 0, 0.5 } } }", {0, 0, 0},
                  {0.5, 0.5, 0.5});
    expect_extent("plane { y, 0 clipped_by { box { 0, 0.5 } } bounded_by { box { -1, 1 } } }",
                  {0, 0, 0}, {0.5, 0.5, 0.5});
    expect_extent("plane { y, 0 clipped_by { box { 0, 0.5 } box { -1, 0.25 } } }", {0, 0, 0},
                  {0.25, 0.25, 0.25});
    expect_extent(
        "union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { 0, 0.5 } } rotate 45*y rotate "
        "-45*y }",
        {0, 0, 0}, {0.5, 0.5, 0.5});
}

TEST(ObjectsGeometry, ShapesWithoutAComputedBoxAreNotSupported) {
    EXPECT_EQ(error_of("#declare O = ovus { 1, 0.5 }\ncamera { location min_extent(O) }"),
              "not supported: 'min_extent' of this kind of object at test.pov:2:19");
    EXPECT_EQ(error_of("#declare O = union { sphere { 0, 1 } julia_fractal { <1,0,0,0> } }\n"
                       "camera { location max_extent(O) }"),
              "not supported: 'max_extent' of this kind of object at test.pov:2:19");
}

// ---------------------------------------------------------------- inside and trace

TEST(ObjectsGeometry, InsideAsPovRayAnswers) {
    // povray's inside() of the same objects and points.
    const std::string closed =
        "mesh { triangle { <-1,-1,-1>, <1,-1,-1>, <0,1,-1> } "
        "triangle { <-1,-1,1>, <1,-1,1>, <0,1,1> } inside_vector ";
    EXPECT_EQ(inside(closed + "z }", "0"), 1);
    EXPECT_EQ(inside(closed + "z }", "<0,0,2>"), 0);
    EXPECT_EQ(inside(closed + "x }", "0"), 0);
    EXPECT_EQ(inside("disc { 0, y, 1 }", "<5,-1,0>"), 1);  // the disc's plane, whatever the radius
    EXPECT_EQ(inside("disc { 0, y, 1 }", "<5,1,0>"), 0);
    EXPECT_EQ(inside("sphere { 0, 1 clipped_by { plane { x, 0 } } }", "<0.5,0,0>"), 0);
    EXPECT_EQ(inside("sphere { 0, 1 clipped_by { plane { x, 0 } } }", "<-0.5,0,0>"), 1);
    EXPECT_EQ(inside("sphere { 0, 1 inverse }", "0"), 0);
    EXPECT_EQ(inside("difference { sphere { 0, 1 } sphere { 0, 0.5 } }", "0"), 0);
    EXPECT_EQ(inside("difference { sphere { 0, 1 } sphere { 0, 0.5 } }", "0.75*x"), 1);
    EXPECT_EQ(inside("cylinder { 0, y, 1 open }", "0.5*y"), 1);
    EXPECT_EQ(inside("cone { 0, 1, y, 0 open }", "0.25*y"), 1);
    EXPECT_EQ(inside("merge { sphere { 0, 1 } sphere { x, 1 } }", "0.5*x"), 1);
    EXPECT_EQ(inside("merge { sphere { 0, 1 } sphere { x, 1 } }", "3*x"), 0);
    EXPECT_EQ(inside("intersection { sphere { 0, 1 } sphere { x, 1 } }", "-0.5*x"), 0);
    EXPECT_EQ(inside("intersection { sphere { 0, 1 } sphere { x, 1 } inverse }", "-0.5*x"), 1);
    EXPECT_EQ(inside("torus { 2, 0.5 rotate 90*x }", "<0,2,0>"), 1);
    EXPECT_EQ(inside("torus { 2, 0.5 rotate 90*x }", "0"), 0);
    EXPECT_EQ(inside("box { -1, 1 rotate 45*z }", "<1.2,0,0>"), 1);
    EXPECT_EQ(inside("box { -1, 1 rotate 45*z }", "<0.8,0.8,0>"), 0);
    EXPECT_EQ(inside("plane { y, 1 translate y }", "<0,1.5,0>"), 1);
    EXPECT_EQ(inside("quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 scale 2 }", "<1.5,0,0>"), 1);
    EXPECT_EQ(inside("poly { 2, <1,0,0,0,1,0,0,1,0,-1> }", "<0,0,1.5>"), 0);
    EXPECT_EQ(inside("poly { 2, <1,0,0,0,1,0,0,1,0,-1> }", "<0,0,0.5>"), 1);
    // 3xz - 2y: the term order as POV-Ray evaluates it.
    EXPECT_EQ(inside("polynomial { 2, xyz(1,0,1):3, xyz(0,1,0):-2 }", "<1,1,0.5>"), 1);
    EXPECT_EQ(inside("polynomial { 2, xyz(1,0,1):3, xyz(0,1,0):-2 }", "<1,0.5,1>"), 0);
    // A linear prism, even-odd over its outlines (a frame: the middle is a hole), conic too.
    const std::string frame =
        "prism { 0, 1, 10, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1> }";
    EXPECT_EQ(inside(frame, "<3,0.5,4>"), 0);
    EXPECT_EQ(inside(frame, "<0.5,0.5,4>"), 1);
    EXPECT_EQ(inside(frame, "<0.5,1.5,4>"), 0);
    const std::string conic = "prism { conic_sweep 0.5, 1, 4, <-1,-1>, <1,-1>, <0,1>, <-1,-1> }";
    EXPECT_EQ(inside(conic, "<0,0.75,0>"), 1);
    EXPECT_EQ(inside(conic, "<0.9,0.75,0>"), 0);
    EXPECT_EQ(inside(conic, "<0.7,0.75,-0.7>"), 1);
    EXPECT_EQ(inside(conic, "<0,0.25,0>"), 0);
    EXPECT_EQ(inside("prism { 1, 0, 3, <-1,-1>, <1,-1>, <0,1> }", "<0,0.5,0>"), 1);
    // Sphere sweeps: the union of their spheres (a b_spline's end at 19/6 + 0.8 on its axis).
    const std::string line = "sphere_sweep { linear_spline 3, 0, 1, 2*x, 1, 4*x, 1 }";
    EXPECT_EQ(inside(line, "<1,0.9,0>"), 1);
    EXPECT_EQ(inside(line, "<1,1.1,0>"), 0);
    EXPECT_EQ(inside(line, "<4.99,0,0>"), 1);
    EXPECT_EQ(inside(line, "<5.01,0,0>"), 0);
    const std::string spheres = "4, 0, 0.2, x, 0.5, 3*x, 1, 6*x, 0.3 }";
    EXPECT_EQ(inside("sphere_sweep { b_spline " + spheres, "<3.96,0,0>"), 1);
    EXPECT_EQ(inside("sphere_sweep { b_spline " + spheres, "<3.97,0,0>"), 0);
    EXPECT_EQ(inside("sphere_sweep { b_spline " + spheres, "<2,0.73,0>"), 1);
    EXPECT_EQ(inside("sphere_sweep { b_spline " + spheres, "<2,0.735,0>"), 0);
    EXPECT_EQ(inside("sphere_sweep { cubic_spline " + spheres, "<1.4,0.688,0>"), 1);
    EXPECT_EQ(inside("sphere_sweep { cubic_spline " + spheres, "<1.4,0.689,0>"), 0);
    EXPECT_EQ(error_of("#declare O = triangle { 0, x, y }\ncamera { location inside(O, 0) }"),
              "not supported: 'inside' of this kind of object at test.pov:2:19");
}

TEST(ObjectsGeometry, TraceAsPovRayAnswers) {
    // povray's trace() of the same objects and rays: the nearest hit and the object's normal
    // there (turned over on inverted objects).
    auto expect_trace = [](const std::string& object, const std::string& origin,
                           const std::string& direction, Vec3 hit, Vec3 normal) {
        SCOPED_TRACE(object + " from " + origin);
        const auto [h, n] = trace(object, origin, direction);
        expect_vec(h, hit, 1e-9);
        expect_vec(n, normal, 1e-3);
    };
    expect_trace("sphere { 0, 1 }", "-5*z", "z", {0, 0, -1}, {0, 0, -1});
    expect_trace("sphere { 0, 1 }", "0", "2*z", {0, 0, 1}, {0, 0, 1});
    expect_trace("sphere { 0, 1 }", "-5*z", "x", {0, 0, 0}, {0, 0, 0});  // no hit
    expect_trace("sphere { 0, 1 inverse }", "-5*z", "z", {0, 0, -1}, {0, 0, 1});
    expect_trace("box { -1, 1 rotate 45*y }", "<0.2,0,-5>", "z",
                 {0.2, 0, (0.2 * std::sqrt(0.5) - 1) / std::sqrt(0.5)}, {0.7071, 0, -0.7071});
    expect_trace("difference { sphere { 0, 1 } sphere { 0, 0.5 } }", "<0.2,0,0>", "z",
                 {0.2, 0, std::sqrt(0.25 - 0.04)}, {-0.4, 0, -0.9165});
    expect_trace("cylinder { 0, 2*y, 1 }", "5*y", "-y", {0, 2, 0}, {0, 1, 0});
    expect_trace("cylinder { 0, 2*y, 1 }", "<0,1,-5>", "z", {0, 1, -1}, {0, 0, -1});
    expect_trace("cylinder { 0, 2*y, 1 open }", "5*y", "-y", {0, 0, 0}, {0, 0, 0});
    expect_trace("cone { 0, 1, 2*y, 0.5 }", "<0,1,-5>", "z", {0, 1, -0.75}, {0, 0.2425, -0.9701});
    expect_trace("torus { 2, 0.5 }", "-5*x", "x", {-2.5, 0, 0}, {-1, 0, 0});
    expect_trace("torus { 2, 0.5 }", "<0,5,2>", "-y", {0, 0.5, 2}, {0, 1, 0});
    expect_trace("plane { y, 1 }", "5*y", "-y", {0, 1, 0}, {0, 1, 0});
    expect_trace("disc { 0, y, 1, 0.5 }", "5*y", "-y", {0, 0, 0}, {0, 0, 0});  // through the hole
    expect_trace("disc { 0, y, 1, 0.5 }", "<0.7,5,0>", "-y", {0.7, 0, 0}, {0, 1, 0});
    // A triangle's normal is (c - a) x (b - a) whichever side the ray comes from.
    expect_trace("triangle { <-1,-1,0>, <1,-1,0>, <0,1,0> }", "5*z", "-z", {0, 0, 0}, {0, 0, -1});
    expect_trace("mesh { triangle { <-1,-1,0>, <1,-1,0>, <0,1,0> } }", "-5*z", "z", {0, 0, 0},
                 {0, 0, -1});
    expect_trace("sphere { 0, 1 clipped_by { plane { z, 0 } } }", "-5*z", "z", {0, 0, -1},
                 {0, 0, -1});
    expect_trace("sphere { 0, 1 scale <1,2,1> translate x }", "<1,-5,0>", "y", {1, -2, 0},
                 {0, -1, 0});
    // Sphere sweeps, POV-Ray's hits printed to 10 decimals: from inside a straight one out
    // through its far end (no surface between its segments), a bent one of varied radii, and
    // b_spline and cubic_spline sweeps, turned and scaled.
    expect_trace("sphere_sweep { linear_spline 3, 0, 1, 2*x, 1, 4*x, 1 }", "-0.5*x", "x", {5, 0, 0},
                 {1, 0, 0});
    const std::string bent =
        "sphere_sweep { linear_spline 4, 0, 1, 2*x, 0.5, <2,2,0>, 1, -x, 0.7 }";
    expect_trace(bent, "<1,0.1,0>", "x", {2.5422176685, 0.1, 0}, {0.9682458366, -0.25, 0});
    expect_trace(bent, "<1,0.1,0>", "y", {1, 2.4827420741, 0}, {-0.6220075146, 0.7830112718, 0});
    const std::string spheres =
        "6, <-2,0,0>, 0.3, <-1,1,0>, 0.4, <0,0,1>, 0.6, <1,-1,0>, 0.3, <2,0,0>, 0.5, <3,1,1>, "
        "0.2 rotate 30*y scale <1,2,1> }";
    expect_trace("sphere_sweep { cubic_spline " + spheres, "<0.3,-5,0.2>", "y",
                 {0.3, -1.5937607397, 0.2}, {-0.9771990637, -0.1982426868, -0.0760383266});
    expect_trace("sphere_sweep { cubic_spline " + spheres, "<-5,0.1,0.1>", "x", {0, 0, 0},
                 {0, 0, 0});
    expect_trace("sphere_sweep { b_spline " + spheres, "<0.3,-5,0.2>", "y",
                 {0.3, -1.4444625717, 0.2}, {-0.9083528586, -0.4129748806, -0.0659305109});
    expect_trace("sphere_sweep { b_spline " + spheres, "<-5,0.1,0.1>", "x",
                 {0.1420546342, 0.1, 0.1}, {-0.3675090098, 0.0463310268, -0.9288652021});
    EXPECT_EQ(error_of("#declare O = ovus { 1, 0.5 }\n"
                       "#declare H = trace(O, 0, x);"),
              "not supported: 'trace' of this kind of object at test.pov:2:14");
}

}  // namespace
}  // namespace rayset::tracer
