// Tests of the scene-language front end: every construct of the subset, every error class with
// its message and file:line:column, transform composition against hand-computed matrices, and
// the POV-Ray distribution's radiosity/cornell.pov (copied, CC BY 3.0) with values worked out by
// hand from its text.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scene_language/scene_test_support.h"
#include "support/test_support.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

using namespace scene_test;

namespace fs = std::filesystem;

// Evaluates an expression through the camera location (a vector parameter; floats promote).
Vec3 eval(const std::string& expression, const std::string& declarations = "") {
    return parse(declarations + "\ncamera { location (" + expression + ") }").camera.location;
}

std::string scenes_dir() {
    return (fs::path(__FILE__).parent_path().parent_path() / "tracer" / "scenes").string();
}

// ---------------------------------------------------------------- cornell.pov

TEST(SceneLanguageCornell, ParsesWithTheValuesItsTextGives) {
    const SceneDescription s = parse_scene_file(scenes_dir() + "/cornell.pov");
    EXPECT_DOUBLE_EQ(s.version, 3.7);
    EXPECT_DOUBLE_EQ(s.global.assumed_gamma, 1.0);
    ASSERT_TRUE(s.global.radiosity);
    EXPECT_EQ(s.global.radiosity->count, 200);
    EXPECT_DOUBLE_EQ(s.global.radiosity->error_bound, 0.5);

    // Camera: angle 39.5 rescales the unit direction to |right| / tan(39.5/2 deg) / 2.
    ASSERT_TRUE(s.has_camera);
    expect_vec(s.camera.location, {27.8, 27.3, -80.0});
    expect_vec(s.camera.direction, {0, 0, 0.5 / std::tan(39.5 / 2 * kPi / 180)});
    expect_vec(s.camera.right, {-1, 0, 0});
    expect_vec(s.camera.up, {0, 1, 0});

    // 3 x 3 sub-patches of the declared area light, translated by <i*DX-(13-DX)/2, 0,
    // j*DZ-(10.5-DZ)/2>.
    ASSERT_EQ(s.lights.size(), 9u);
    const double dx = 13.0 / 3, dz = 10.5 / 3;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const LightSource& l = s.lights[3 * i + j];
            const Vec3 offset{i * dx - (13 - dx) / 2, 0, j * dz - (10.5 - dz) / 2};
            expect_vec(l.position, Vec3{27.8, 54.88, 27.95} + offset, 1e-12);
            expect_vec(l.point_at, Vec3{27.8, 0, 27.95} + offset, 1e-12);
        }
    const LightSource& l = s.lights[0];
    EXPECT_DOUBLE_EQ(l.colour.red, 7.0);
    EXPECT_FLOAT_EQ(l.colour.green, 0.67 * 7);
    EXPECT_FLOAT_EQ(l.colour.blue, 0.21 * 7);
    EXPECT_TRUE(l.area_light);
    expect_vec(l.axis1, {dx, 0, 0});
    expect_vec(l.axis2, {0, 0, dz});
    EXPECT_EQ(l.size1, 4);
    EXPECT_EQ(l.size2, 4);
    EXPECT_TRUE(l.jitter);
    EXPECT_EQ(l.adaptive, 0);
    EXPECT_TRUE(l.spotlight);
    EXPECT_DOUBLE_EQ(l.radius, -90);
    EXPECT_DOUBLE_EQ(l.falloff, 90);
    EXPECT_DOUBLE_EQ(l.tightness, 1);
    EXPECT_DOUBLE_EQ(l.fade_power, 2);
    EXPECT_DOUBLE_EQ(l.fade_distance, (dx + dz) / 2);

    // The light patch box, then 6 + 2 + 2 + 10 + 10 triangles.
    ASSERT_EQ(s.objects.size(), 31u);
    const ObjectInstance& patch = s.objects[0];
    const auto& box = std::get<BoxShape>(patch.shape);
    expect_vec(box.minimum, {21.3, 54.87, 22.7});
    expect_vec(box.maximum, {34.3, 54.88, 33.2});
    EXPECT_TRUE(patch.no_shadow);
    ASSERT_TRUE(patch.appearance.texture);
    EXPECT_FLOAT_EQ(patch.appearance.texture->finish->ambient.red, 0.78);
    EXPECT_DOUBLE_EQ(patch.appearance.texture->finish->diffuse, 0);
    EXPECT_DOUBLE_EQ(patch.appearance.texture->pigment.colour.green, 1);

    // Red wall (objects 9, 10): texture Red = pigment <0.57,0.025,0.025>, finish diffuse 0.75
    // ambient 0.
    const ObjectInstance& red = s.objects[9];
    EXPECT_FLOAT_EQ(red.appearance.texture->pigment.colour.red, 0.57);
    EXPECT_FLOAT_EQ(red.appearance.texture->pigment.colour.green, 0.025);
    EXPECT_DOUBLE_EQ(red.appearance.texture->finish->diffuse, 0.75);
    EXPECT_DOUBLE_EQ(red.appearance.texture->finish->ambient.red, 0);
    EXPECT_FALSE(red.no_shadow);

    // The tall block's second triangle writes "<47.20 33.00 40.60>" without commas.
    const auto& t = std::get<TriangleShape>(s.objects[22].shape);
    expect_vec(t.c, {47.2, 33.0, 40.6});
    const auto& u = std::get<TriangleShape>(s.objects[26].shape);
    expect_vec(u.c, {31.4, 0.0, 45.6});
    for (const ObjectInstance& o : s.objects) EXPECT_EQ(o.object_to_world.m, Matrix4{}.m);
}

// ---------------------------------------------------------------- transforms

TEST(SceneLanguageTransforms, RotateFollowsPovRayLeftHandedConvention) {
    // POV-Ray: rotate about y by +90 turns +x to -z and +z to +x (left-hand rule, thumb on +y);
    // about x: +y to +z; about z: +x to +y.
    const Matrix4 ry = pov_rotation({0, 90, 0});
    expect_vec(ry.vector({1, 0, 0}), {0, 0, -1}, 1e-15);
    expect_vec(ry.vector({0, 0, 1}), {1, 0, 0}, 1e-15);
    expect_vec(pov_rotation({90, 0, 0}).vector({0, 1, 0}), {0, 0, 1}, 1e-15);
    expect_vec(pov_rotation({0, 0, 90}).vector({1, 0, 0}), {0, 1, 0}, 1e-15);
    // rotate <90, 90, 0> is x first, then y: +y -> +z -> +x.
    expect_vec(pov_rotation({90, 90, 0}).vector({0, 1, 0}), {1, 0, 0}, 1e-15);
    // A general angle against the hand-written matrix of rotate 30*y.
    const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
    const Matrix4 r = pov_rotation({0, 30, 0});
    const double expected[16] = {c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0, 0, 0, 0, 1};
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(r.m[i], expected[i], 1e-15) << i;
}

TEST(SceneLanguageTransforms, StatementsComposeInWritingOrder) {
    const SceneDescription s = parse(R"(
        sphere { <0,0,0>, 1 translate <1,0,0> scale 2 }
        sphere { <0,0,0>, 1 scale 2 translate <1,0,0> }
        sphere { <0,0,0>, 1 rotate 90*y translate <0,0,5> }
        sphere { <0,0,0>, 1 matrix <1,0,0, 1,1,0, 0,0,1, 5,6,7> }
        sphere { <0,0,0>, 1 scale <1,2,3> rotate <0,0,90> }
    )");
    ASSERT_EQ(s.objects.size(), 5u);
    expect_vec(s.objects[0].object_to_world.point({0, 0, 0}), {2, 0, 0});
    expect_vec(s.objects[1].object_to_world.point({0, 0, 0}), {1, 0, 0});
    expect_vec(s.objects[1].object_to_world.point({1, 0, 0}), {3, 0, 0});
    expect_vec(s.objects[2].object_to_world.point({1, 0, 0}), {0, 0, 4}, 1e-15);
    // matrix: x' = m00 x + m10 y + m20 z + m30 (row-vector convention): a shear plus translation.
    expect_vec(s.objects[3].object_to_world.point({0, 1, 0}), {6, 7, 7});
    expect_vec(s.objects[3].object_to_world.point({1, 0, 0}), {6, 6, 7});
    // scale then rotate: (0,1,0) -> (0,2,0) -> rotate 90 about z -> (-2,0,0).
    expect_vec(s.objects[4].object_to_world.point({0, 1, 0}), {-2, 0, 0}, 1e-15);
    const double expected[16] = {0, -2, 0, 0, 1, 0, 0, 0, 0, 0, 3, 0, 0, 0, 0, 1};
    for (int i = 0; i < 16; ++i)
        EXPECT_NEAR(s.objects[4].object_to_world.m[i], expected[i], 1e-15) << i;
}

TEST(SceneLanguageTransforms, UnionsAndObjectCopiesStackTransforms) {
    const SceneDescription s = parse(R"(
        #declare Ball = sphere { <0,0,0>, 1 translate y }
        #declare Pair = union { object { Ball } object { Ball translate x } translate z }
        object { Pair scale 2 }
        #declare T = transform { rotate 90*y translate <1,2,3> }
        object { Ball transform T }
        object { Ball transform { T inverse } }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    expect_vec(s.objects[0].object_to_world.point({0, 0, 0}), {0, 2, 2});
    expect_vec(s.objects[1].object_to_world.point({0, 0, 0}), {2, 2, 2});
    // Ball at (0,1,0), rotate 90*y leaves it, then translate.
    expect_vec(s.objects[2].object_to_world.point({0, 0, 0}), {1, 3, 3}, 1e-15);
    // The inverse of T takes (1,2,3) + rotation back: (0,1,0) -> (-1,-1,-3) -> rotate -90*y.
    const Vec3 p = s.objects[3].object_to_world.point({0, 0, 0});
    expect_vec(pov_rotation({0, 90, 0}).point(p) + Vec3{1, 2, 3}, {0, 1, 0}, 1e-14);
}

// ---------------------------------------------------------------- expressions

TEST(SceneLanguageExpressions, PrecedenceAndUnaryMinus) {
    expect_vec(eval("1 + 2 * 3"), {7, 7, 7});
    expect_vec(eval("(1 + 2) * 3"), {9, 9, 9});
    expect_vec(eval("-2 * -3 - 1"), {5, 5, 5});
    expect_vec(eval("10 / 4 / 5"), {0.5, 0.5, 0.5});
    expect_vec(eval("1 + 2 < 4"), {1, 1, 1});          // comparison below + -
    expect_vec(eval("1 < 2 & 3 > 4 | 1"), {1, 1, 1});  // (((1<2) & (3>4)) | 1)
    expect_vec(eval("2 = 2"), {1, 1, 1});
    expect_vec(eval("2 != 2"), {0, 0, 0});
    expect_vec(eval("3 >= 3"), {1, 1, 1});
    expect_vec(eval("!0"), {1, 1, 1});
    expect_vec(eval("0 ? 5 : 6"), {6, 6, 6});
    expect_vec(eval("true + yes + on - false - no - off"), {3, 3, 3});
}

TEST(SceneLanguageExpressions, VectorsAndPromotion) {
    expect_vec(eval("<1,2,3> * 2"), {2, 4, 6});
    expect_vec(eval("<1,2,3> + 1"), {2, 3, 4});  // a float promotes to <1,1,1>
    expect_vec(eval("<1,2,3> * <2,3,4>"), {2, 6, 12});
    expect_vec(eval("x + 2*y - z"), {1, 2, -1});
    expect_vec(eval("<1,2>"), {1, 2, 0});      // a 2-vector pads with 0
    expect_vec(eval("<1 -2 3>"), {-1, 3, 0});  // as in POV-Ray: 1-2, then 3
    expect_vec(eval("<5,6,7>.y"), {6, 6, 6});
    expect_vec(eval("V.z + V.x", "#declare V = <1,2,3>;"), {4, 4, 4});
    expect_vec(eval("<(1 < 2), 0, 0>"), {1, 0, 0});
    expect_vec(eval("-<1,2,3>"), {-1, -2, -3});
}

TEST(SceneLanguageExpressions, Functions) {
    const double pi = kPi;
    EXPECT_NEAR(eval("sin(pi/6)").x, 0.5, 1e-15);
    EXPECT_NEAR(eval("cos(0) + tan(0)").x, 1, 1e-15);
    EXPECT_NEAR(eval("asin(1)").x, pi / 2, 1e-15);
    EXPECT_NEAR(eval("acos(-1)").x, pi, 1e-15);
    EXPECT_NEAR(eval("atan(1)").x, pi / 4, 1e-15);
    EXPECT_NEAR(eval("atan2(1, -1)").x, 3 * pi / 4, 1e-15);
    EXPECT_DOUBLE_EQ(eval("sqrt(16) + pow(2, 10)").x, 1028);
    EXPECT_NEAR(eval("exp(1)").x, std::exp(1.0), 1e-15);
    EXPECT_DOUBLE_EQ(eval("log(1000)").x, 3);  // POV-Ray's log is base 10
    EXPECT_NEAR(eval("ln(exp(2))").x, 2, 1e-15);
    EXPECT_DOUBLE_EQ(eval("abs(-3) + min(4, 2, 8) + max(1, 5)").x, 10);
    EXPECT_DOUBLE_EQ(eval("floor(-2.5) + ceil(-2.5)").x, -5);
    EXPECT_DOUBLE_EQ(eval("mod(7, 3) + int(-2.5)").x, -1);  // int truncates toward zero
    EXPECT_NEAR(eval("radians(180) + degrees(pi)").x, pi + 180, 1e-12);
    EXPECT_DOUBLE_EQ(eval("vlength(<3,4,0>)").x, 5);
    expect_vec(eval("vnormalize(<0,0,2>)"), {0, 0, 1});
    EXPECT_DOUBLE_EQ(eval("vdot(<1,2,3>, <4,5,6>)").x, 32);
    expect_vec(eval("vcross(x, y)"), {0, 0, 1});
    expect_vec(eval("vrotate(x, <0,90,0>)"), {0, 0, -1}, 1e-15);
}

TEST(SceneLanguageExpressions, Colours) {
    auto background = [](const std::string& colour) {
        return parse("background { " + colour + " }").background;
    };
    Colour c = background("rgb <1, 0.5, 0.25>");
    EXPECT_EQ((std::array<double, 5>{c.red, c.green, c.blue, c.filter, c.transmit}),
              (std::array<double, 5>{1, 0.5, 0.25, 0, 0}));
    c = background("rgb 0.5");  // rgb promotes to three terms only
    EXPECT_EQ((std::array<double, 5>{c.red, c.green, c.blue, c.filter, c.transmit}),
              (std::array<double, 5>{0.5, 0.5, 0.5, 0, 0}));
    c = background("color 0.5");  // a bare float fills all five terms, as POV-Ray does
    EXPECT_EQ((std::array<double, 5>{c.red, c.green, c.blue, c.filter, c.transmit}),
              (std::array<double, 5>{0.5, 0.5, 0.5, 0.5, 0.5}));
    c = background("rgbt <1, 0, 0, 0.3>");
    EXPECT_FLOAT_EQ(c.transmit, 0.3);
    EXPECT_DOUBLE_EQ(c.filter, 0);
    c = background("rgbf <0, 1, 0, 0.4>");
    EXPECT_FLOAT_EQ(c.filter, 0.4);
    c = background("rgbft <0, 0, 1, 0.1, 0.2>");
    EXPECT_FLOAT_EQ(c.filter, 0.1);
    EXPECT_FLOAT_EQ(c.transmit, 0.2);
    c = background("colour red 1 green 0.5 blue 0.25 transmit 0.5");
    EXPECT_EQ((std::array<double, 5>{c.red, c.green, c.blue, c.filter, c.transmit}),
              (std::array<double, 5>{1, 0.5, 0.25, 0, 0.5}));
    c = parse("#declare C = rgb <0.2, 0.4, 0.6>;\nbackground { C * 2 green 0 }").background;
    EXPECT_FLOAT_EQ(c.red, 0.4);
    EXPECT_FLOAT_EQ(c.green, 0);
    EXPECT_FLOAT_EQ(c.blue, 1.2);
    EXPECT_FLOAT_EQ(eval("C.blue", "#declare C = rgb <0.2, 0.4, 0.6>;").x, 0.6);
}

// ---------------------------------------------------------------- directives

TEST(SceneLanguageDirectives, ConditionalsAndLoops) {
    const SceneDescription s = parse(R"(
        #version 3.6;
        #declare N = 4;
        #declare I = 0;
        #while (I < N)
            #if (mod(I, 2) = 0)
                sphere { <I, 0, 0>, 1 }
            #elseif (I = 1)
                box { <I, 0, 0>, <I + 1, 1, 1> }
            #else
                #if (0) plane { y, 0 } #else triangle { 0, x, y } #end
            #end
            #declare I = I + 1;
        #end
        #ifdef (N) sphere { 0, 5 } #end
        #ifndef (N) sphere { 0, 6 } #else sphere { 0, 7 } #end
        #undef N
        #ifdef (N) sphere { 0, 8 } #end
        #declare J = 0; #while (J < 2) #declare J = J + 1; #end
        sphere { 0, J }
    )");
    EXPECT_DOUBLE_EQ(s.version, 3.6);
    ASSERT_EQ(s.objects.size(), 7u);
    EXPECT_TRUE(std::holds_alternative<SphereShape>(s.objects[0].shape));
    EXPECT_TRUE(std::holds_alternative<BoxShape>(s.objects[1].shape));
    EXPECT_DOUBLE_EQ(std::get<SphereShape>(s.objects[2].shape).centre.x, 2);
    EXPECT_TRUE(std::holds_alternative<TriangleShape>(s.objects[3].shape));
    EXPECT_DOUBLE_EQ(std::get<SphereShape>(s.objects[4].shape).radius, 5);
    EXPECT_DOUBLE_EQ(std::get<SphereShape>(s.objects[5].shape).radius, 7);
    EXPECT_DOUBLE_EQ(std::get<SphereShape>(s.objects[6].shape).radius, 2);
}

TEST(SceneLanguageDirectives, DeclaresEveryKindOfValue) {
    const SceneDescription s = parse(R"(
        #declare F = finish { diffuse 0.5 specular 0.25 roughness 0.01 phong 0.5 phong_size 20
                              brilliance 2 reflection { 0.1, 0.9 fresnel on metallic 0.5 }
                              emission 0.2 ambient rgb <0,0.1,0> }
        #declare P = pigment { rgb <1, 0, 0> filter 0.5 }
        #declare T = texture { pigment { P } finish { F } }
        #declare I = interior { ior 1.5 }
        #declare S = "unused";
        #declare O = sphere { 0, 1 texture { T } interior { I } }
        object { O }
        #declare L = light_source { <1, 2, 3> color rgb <1, 1, 1> }
        light_source { L translate x }
        #declare Cam = camera { location <0, 0, -5> }
        camera { Cam translate y }
    )");
    ASSERT_EQ(s.objects.size(), 1u);
    const ObjectInstance& o = s.objects[0];
    EXPECT_DOUBLE_EQ(o.appearance.texture->pigment.colour.red, 1);
    EXPECT_DOUBLE_EQ(o.appearance.texture->pigment.colour.filter, 0.5);
    const Finish& f = *o.appearance.texture->finish;
    EXPECT_DOUBLE_EQ(f.diffuse, 0.5);
    EXPECT_DOUBLE_EQ(f.specular, 0.25);
    EXPECT_DOUBLE_EQ(f.roughness, 0.01);
    EXPECT_DOUBLE_EQ(f.phong, 0.5);
    EXPECT_DOUBLE_EQ(f.phong_size, 20);
    EXPECT_DOUBLE_EQ(f.brilliance, 2);
    EXPECT_FLOAT_EQ(f.reflection_min.red, 0.1);
    EXPECT_FLOAT_EQ(f.reflection_max.blue, 0.9);
    EXPECT_TRUE(f.reflection_fresnel);
    EXPECT_DOUBLE_EQ(f.reflection_metallic, 0.5);  // reflection's own, not the highlights'
    EXPECT_DOUBLE_EQ(f.metallic, 0);
    EXPECT_FLOAT_EQ(f.emission.green, 0.2);
    EXPECT_FLOAT_EQ(f.ambient.green, 0.1);
    EXPECT_DOUBLE_EQ(f.ambient.red, 0);
    ASSERT_TRUE(o.appearance.interior);
    EXPECT_DOUBLE_EQ(o.appearance.interior->ior, 1.5);
    ASSERT_EQ(s.lights.size(), 1u);
    expect_vec(s.lights[0].position, {2, 2, 3});
    expect_vec(s.camera.location, {0, 1, -5});
}

TEST(SceneLanguageDirectives, IncludesResolveRelativeThenSearchPathWithLocalScopes) {
    test::ScratchDir dir;
    fs::create_directories(dir.path() / "scene" / "parts");
    fs::create_directories(dir.path() / "library");
    test::write_file(dir.file("scene/main.pov"),
                     "#include \"parts/a.inc\"\n#include \"lib.inc\"\nsphere { 0, R + Q }\n"
                     "#ifdef (Hidden) sphere { 0, 100 } #end\n");
    test::write_file(dir.file("scene/parts/a.inc"),
                     "#include \"b.inc\"\n#local Hidden = 1;\n#declare Q = Hidden + 1;\n");
    test::write_file(dir.file("scene/parts/b.inc"), "#declare R = 10;\n");
    test::write_file(dir.file("library/lib.inc"), "box { 0, 1 }\n");
    ParseOptions options;
    options.include_paths = {dir.file("library")};
    const SceneDescription s = parse_scene_file(dir.file("scene/main.pov"), options);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<BoxShape>(s.objects[0].shape));
    EXPECT_DOUBLE_EQ(std::get<SphereShape>(s.objects[1].shape).radius, 12);  // #local did not leak
    ASSERT_EQ(s.files.size(), 4u);
}

TEST(SceneLanguageDirectives, Comments) {
    const SceneDescription s = parse(R"(
        // sphere { 0, 1 }
        /* outer /* nested */ still a comment sphere { 0, 2 } */
        /* a line comment inside hides the closer: // */ sphere { 0, 3 }
        */
        sphere { 0, 4 } // trailing
    )");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_DOUBLE_EQ(std::get<SphereShape>(s.objects[0].shape).radius, 4);
}

// ---------------------------------------------------------------- objects, camera, extensions

TEST(SceneLanguageObjects, ShapesMeshesAndSharedInstances) {
    test::ScratchDir dir;
    test::write_file(dir.file("part.obj"), "v 0 0 0\n");
    const std::string text = R"(
        plane { <0, 2, 0>, 3 }
        #declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> }
                            triangle { <0,0,0> <0,1,0> <0,0,1> } }
        object { M }
        object { M translate x }
        mesh2 {
            vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <0,0,1> }
            normal_vectors { 1, <0,0,-1> }
            face_indices { 2, <0,1,2>, <0,2,3> }
            normal_indices { 2, <0,0,0>, <0,0,0> }
        }
        mesh_file { "part.obj" scale 2 }
    )";
    const SceneDescription s = parse_scene_text(text, dir.file("scene.pov"));
    ASSERT_EQ(s.objects.size(), 5u);
    const auto& plane = std::get<PlaneShape>(s.objects[0].shape);
    expect_vec(plane.normal, {0, 1, 0});  // POV-Ray normalises the normal, keeps the distance
    EXPECT_DOUBLE_EQ(plane.distance, 3);
    const auto& m1 = std::get<MeshShape>(s.objects[1].shape);
    const auto& m2 = std::get<MeshShape>(s.objects[2].shape);
    EXPECT_EQ(m1.mesh, m2.mesh);  // one mesh, two instances
    ASSERT_EQ(m1.mesh->faces.size(), 2u);
    expect_vec(m1.mesh->vertices[5], {0, 0, 1});
    expect_vec(s.objects[2].object_to_world.point({0, 0, 0}), {1, 0, 0});
    const auto& m3 = std::get<MeshShape>(s.objects[3].shape);
    EXPECT_EQ(m3.mesh->faces[1], (std::array<int, 3>{0, 2, 3}));
    EXPECT_EQ(m3.mesh->normal_faces.size(), 2u);
    const auto& file = std::get<MeshFileShape>(s.objects[4].shape);
    EXPECT_EQ(file.path, fs::weakly_canonical(dir.file("part.obj")).string());
    EXPECT_EQ(file.format, "obj");
}

TEST(SceneLanguageObjects, TexturesInheritThroughUnionsAndFlagsPropagate) {
    const SceneDescription s = parse(R"(
        union {
            sphere { 0, 1 }
            sphere { 0, 2 pigment { rgb <0, 1, 0> } }
            light_source { <0, 1, 0>, 1 }
            pigment { rgb <1, 0, 0> }
            finish { diffuse 0.9 }
            no_shadow
            translate <0, 0, 10>
        }
        sphere { 0, 3 hollow off }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_DOUBLE_EQ(s.objects[0].appearance.texture->pigment.colour.red, 1);
    EXPECT_DOUBLE_EQ(s.objects[0].appearance.texture->finish->diffuse, 0.9);
    EXPECT_DOUBLE_EQ(s.objects[1].appearance.texture->pigment.colour.green,
                     1);  // its own texture wins
    EXPECT_DOUBLE_EQ(s.objects[1].appearance.texture->finish->diffuse,
                     0.6);  // with POV-Ray's default finish
    EXPECT_TRUE(s.objects[0].no_shadow);
    EXPECT_TRUE(s.objects[1].no_shadow);
    // No texture anywhere: POV-Ray's default texture (black) is attached when it is added.
    ASSERT_TRUE(s.objects[2].appearance.texture);
    EXPECT_EQ(s.objects[2].appearance.texture->pigment.colour.red, 0);
    EXPECT_DOUBLE_EQ(s.objects[2].appearance.texture->finish->diffuse, 0.6);
    EXPECT_FALSE(s.objects[2].hollow);
    ASSERT_EQ(s.lights.size(), 1u);
    expect_vec(s.lights[0].position, {0, 1, 10});  // a light in a union moves with it
    EXPECT_DOUBLE_EQ(s.lights[0].colour.blue, 1);
}

TEST(SceneLanguageCamera, AngleLookAtAndSkyAsPovRay) {
    // Default right <1.33,0,0>; angle 90 gives |direction| = 1.33 / tan(45 deg) / 2.
    Camera c = parse("camera { location <0,0,-10> angle 90 look_at <0,0,0> }").camera;
    expect_vec(c.direction, {0, 0, 0.665}, 1e-15);
    expect_vec(c.right, {1.33, 0, 0}, 1e-15);
    expect_vec(c.up, {0, 1, 0}, 1e-15);
    EXPECT_DOUBLE_EQ(c.angle, 90);
    // From +x looking at the origin: direction -x, right = sky x direction = y x (-x) = +z.
    c = parse("camera { location <10,0,0> look_at <0,0,0> right x up y }").camera;
    expect_vec(c.direction, {-1, 0, 0}, 1e-15);
    expect_vec(c.right, {0, 0, 1}, 1e-15);
    expect_vec(c.up, {0, 1, 0}, 1e-15);
    // A right-handed-style right vector (-x) keeps its sign through look_at (Handedness < 0).
    c = parse("camera { location <0,0,-10> right -x look_at <0,0,0> }").camera;
    expect_vec(c.right, {-1, 0, 0}, 1e-15);
    // sky z, looking along +x: right = z x x = +y, up = x x y = +z.
    c = parse("camera { sky z location 0 look_at <5,0,0> }").camera;
    expect_vec(c.right, {0, 1.33, 0}, 1e-15);
    expect_vec(c.up, {0, 0, 1}, 1e-15);
    // Transforms come last, whatever their place in the block.
    c = parse("camera { translate <1,2,3> location <0,0,-1> }").camera;
    expect_vec(c.location, {1, 2, 2});
}

TEST(SceneLanguageExtensions, GlobalSettingsRaySourceAndReceiver) {
    test::ScratchDir dir;
    test::write_file(dir.file("led.tm25ray"), "x");
    const std::string text = R"(
        global_settings { assumed_gamma 2.2 ambient_light 0 max_trace_level 7 length_unit "m"
                          integrator "bidirectional" passes 16 time_limit 60 }
        ray_source { "led.tm25ray" rotate 90*x translate <0, 1, 0> }
        illuminance_receiver { <0, 0, 0>, <2, 0, 0>, <0, 0, 1> resolution <20, 10> name "floor"
                               translate y }
        illuminance_receiver { <0, 0, 0>, x, z resolution <1, 1> }
    )";
    const SceneDescription s = parse_scene_text(text, dir.file("scene.pov"));
    EXPECT_DOUBLE_EQ(s.global.assumed_gamma, 2.2);
    EXPECT_DOUBLE_EQ(s.global.ambient_light.green, 0);
    EXPECT_EQ(s.global.max_trace_level, 7);
    EXPECT_EQ(s.global.length_unit, "m");
    EXPECT_DOUBLE_EQ(s.global.millimetres_per_unit, 1000);
    EXPECT_EQ(s.global.integrator, "bidirectional");
    EXPECT_EQ(s.global.passes, 16);
    EXPECT_DOUBLE_EQ(s.global.time_limit, 60);
    ASSERT_EQ(s.ray_sources.size(), 1u);
    EXPECT_EQ(s.ray_sources[0].path, fs::weakly_canonical(dir.file("led.tm25ray")).string());
    // rotate 90*x takes +z to -y (y' = y cos - z sin), then translate <0,1,0> brings it to the
    // origin.
    expect_vec(s.ray_sources[0].source_to_world.point({0, 0, 1}), {0, 0, 0}, 1e-15);
    ASSERT_EQ(s.receivers.size(), 2u);
    EXPECT_EQ(s.receivers[0].name, "floor");
    EXPECT_EQ(s.receivers[0].nx, 20);
    EXPECT_EQ(s.receivers[0].ny, 10);
    expect_vec(s.receivers[0].corner, {0, 1, 0});
    expect_vec(s.receivers[0].edge1, {2, 0, 0});
    EXPECT_EQ(s.receivers[1].name, "receiver2");
}

// ---------------------------------------------------------------- errors

TEST(SceneLanguageErrors, UnknownIdentifierWrongTypeAndNotSupported) {
    EXPECT_EQ(error_of("sphere { 0, Radius }"),
              "unknown identifier 'Radius' (expected a numeric expression) at test.pov:1:13");
    EXPECT_EQ(error_of("#declare T = texture { pigment { rgb 1 } }\nsphere { 0, 1 pigment { T } }"),
              "wrong type: 'T' is a texture, expected a colour, a pattern or a pigment modifier or "
              "'}' to close "
              "'pigment' opened at test.pov:2:23 at test.pov:2:25");
    EXPECT_EQ(error_of("#declare V = <1,2,3>;\nsphere { 0, V }"),
              "expected a float as the sphere radius, found a vector at test.pov:2:13");
    EXPECT_EQ(error_of("sphere { 0, 1 normal { bumps } foo }"),
              "unknown identifier 'foo' (expected an object modifier or '}' to close 'sphere' "
              "opened at test.pov:1:8) "
              "at test.pov:1:32");
    EXPECT_EQ(error_of("camera { location 0 orthographic }"),
              "the camera type 'orthographic' must come first in the camera at test.pov:1:21");
    EXPECT_EQ(error_of("#declare sphere = 1;"),
              "cannot #declare 'sphere': it is a reserved word at test.pov:1:10");
    EXPECT_EQ(error_of("global_settings { integrator \"photon\" }"),
              "unknown integrator \"photon\" (expected \"path\", \"bidirectional\" or \"vcm\") "
              "at test.pov:1:30");
}

TEST(SceneLanguageErrors, UnclosedBlocksAndExpectedTokens) {
    EXPECT_EQ(error_of("union {\n  sphere { 0, 1 }\n"),
              "expected an object, an object modifier or '}' to close 'union' opened at "
              "test.pov:1:7, found end of file "
              "at test.pov:3:1");
    EXPECT_EQ(error_of("box { 0, 1 \n"),
              "expected an object modifier or '}' to close 'box' opened at test.pov:1:5, found end "
              "of file at test.pov:2:1");
    EXPECT_EQ(error_of("sphere 0, 1 }"),
              "expected '{' after 'sphere', found number 0 at test.pov:1:8");
    EXPECT_EQ(error_of("sphere { <1, 2 0, 1 }"),
              "expected a vector component or '>' to close the vector opened at test.pov:1:10, "
              "found '}' at test.pov:1:21");
    EXPECT_EQ(error_of("/* never closed"),
              "unclosed comment: expected '*/' before end of file for the comment opened at "
              "test.pov:1:1");
    EXPECT_EQ(error_of("#declare S = \"abc\n"),
              "unterminated string: expected '\"' before end of file at test.pov:1:14");
    EXPECT_EQ(error_of("sphere { 0, 1/0 }"), "division by zero at test.pov:1:14");
    EXPECT_EQ(
        error_of("sphere { 0, sqrt(-1) }"),
        "'sqrt': negative argument (POV-Ray would compute a meaningless number) at test.pov:1:13");
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 2, 0, x } face_indices { 1, <0, 1, 2> } }"),
              "vertex index 2 out of range: there are 2 vertex_vectors at test.pov:1:54");
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 3, 0, x } face_indices { 1, <0, 1, 2> } }"),
              "'vertex_vectors' declares 3 entries, found '}' after 2 at test.pov:1:34");
    EXPECT_EQ(
        error_of("global_settings { length_unit \"furlong\" }"),
        "unknown length_unit \"furlong\" (expected um, mm, cm, m, in or ft) at test.pov:1:31");
    // A NUL in quoted text is shown as the escape that wrote it, so that the message, read as a
    // C string, still reaches the place.
    EXPECT_EQ(error_of("sphere { 0, 1 }\n\"a\\0b\""),
              "expected an object, a light_source, camera, global_settings, background, fog, "
              "rainbow, sky_sphere, media, ray_source or illuminance_receiver, found string "
              "\"a\\0b\" at test.pov:2:1");
}

TEST(SceneLanguageErrors, DirectiveStructure) {
    EXPECT_EQ(
        error_of("#if (1)\nsphere { 0, 1 }\n"),
        "unclosed #if opened at test.pov:1:1: expected #end before end of file at test.pov:3:1");
    EXPECT_EQ(
        error_of("#if (0)\nsphere { 0, 1 }\n"),
        "unclosed #if opened at test.pov:1:1: expected #end before end of file at test.pov:3:1");
    EXPECT_EQ(
        error_of("#while (1)\n"),
        "unclosed #while opened at test.pov:1:1: expected #end before end of file at test.pov:2:1");
    // A block must close in the file that opens it: an include that ends inside one is reported
    // there.
    test::ScratchDir dir;
    test::write_file(dir.file("cut.inc"), "#while (1)");
    test::write_file(dir.file("main.pov"), "#include \"cut.inc\"\nsphere { 0, 1 }\n");
    const std::string cut = fs::weakly_canonical(dir.file("cut.inc")).string();
    EXPECT_EQ(error_of_file(dir.file("main.pov")),
              "unclosed #while opened at " + cut + ":1:1: expected #end before end of file at " +
                  cut + ":1:11 (included from " + dir.file("main.pov") + ":1:1)");
    EXPECT_EQ(error_of("sphere { 0, 1 }\n#end"),
              "#end without an open #if, #ifdef, #ifndef, #switch, #while, #for or #macro here at "
              "test.pov:2:1");
    EXPECT_EQ(error_of("#else"), "#else without a matching #if, #ifdef or #ifndef at test.pov:1:1");
    ParseOptions options;
    options.max_loop_iterations = 100;
    EXPECT_EQ(error_of("#while (1) #end", options),
              "loop limit: more than 100 #while and #for iterations in total "
              "(ParseOptions::max_loop_iterations) at "
              "test.pov:1:1");
}

TEST(SceneLanguageErrors, IncludeNotFoundOutsideRootsAndRecursion) {
    test::ScratchDir dir;
    fs::create_directories(dir.path() / "scene");
    fs::create_directories(dir.path() / "elsewhere");
    test::write_file(dir.file("elsewhere/secret.inc"), "#declare X = 1;\n");
    test::write_file(dir.file("scene/missing.pov"), "\n  #include \"nothere.inc\"\n");
    const std::string scene_dir = fs::weakly_canonical(dir.file("scene")).string();
    std::string povray_folders;  // POV-Ray's include folder, searched and allowed when installed
    for (const std::string& folder : default_include_paths()) povray_folders += ", " + folder;
    EXPECT_EQ(error_of_file(dir.file("scene/missing.pov")),
              "include file \"nothere.inc\" not found (searched " + dir.file("scene") +
                  povray_folders + ") at " + dir.file("scene/missing.pov") + ":2:3");

    test::write_file(dir.file("scene/escape.pov"), "#include \"../elsewhere/secret.inc\"\n");
    const std::string secret = fs::weakly_canonical(dir.file("elsewhere/secret.inc")).string();
    EXPECT_EQ(error_of_file(dir.file("scene/escape.pov")),
              "include file \"../elsewhere/secret.inc\" resolves to " + secret +
                  ", outside the allowed roots (" + scene_dir + povray_folders + ") at " +
                  dir.file("scene/escape.pov") + ":1:1");
    ParseOptions allowed;
    allowed.allowed_roots = {dir.file("elsewhere")};
    EXPECT_NO_THROW(parse_scene_file(dir.file("scene/escape.pov"), allowed));

    test::write_file(dir.file("scene/self.inc"), "#include \"self.inc\"\n");
    test::write_file(dir.file("scene/loop.pov"), "#include \"self.inc\"\n");
    ParseOptions shallow;
    shallow.max_include_depth = 4;
    const std::string self = fs::weakly_canonical(dir.file("scene/self.inc")).string();
    EXPECT_EQ(error_of_file(dir.file("scene/loop.pov"), shallow),
              "include depth limit: more than 4 nested #include levels (recursive include of "
              "\"self.inc\"?) "
              "(ParseOptions::max_include_depth) at " +
                  self + ":1:1 (included from " + self + ":1:1) (included from " + self +
                  ":1:1) (included from " + dir.file("scene/loop.pov") + ":1:1)");

    // An error inside an included file names the file and the include chain.
    test::write_file(dir.file("scene/bad.inc"), "sphere { 0, Nope }\n");
    test::write_file(dir.file("scene/main.pov"), "// first line\n#include \"bad.inc\"\n");
    EXPECT_EQ(error_of_file(dir.file("scene/main.pov")),
              "unknown identifier 'Nope' (expected a numeric expression) at " +
                  fs::weakly_canonical(dir.file("scene/bad.inc")).string() +
                  ":1:13 (included from " + dir.file("scene/main.pov") + ":2:1)");
}

}  // namespace
}  // namespace rayset::tracer

namespace rayset::tracer {
namespace {

struct Messages {
    std::string debug, warnings;
    ParseOptions options() {
        ParseOptions o;
        o.on_message = [this](MessageStream stream, const std::string& text) {
            (stream == MessageStream::debug ? debug : warnings) += text;
        };
        return o;
    }
};

TEST(SceneLanguageMessages, DebugWarningErrorAndDeprecatedIdentifiers) {
    Messages m;
    parse_scene_text(
        "#debug \"one\\n\"\n#warning concat(\"two \", str(2, 0, 0))\n#render \"three\\n\"\n"
        "#declare deprecated once \"use New\" Old = 1;\n#declare A = Old + Old;\n"
        "#declare deprecated Older = 2;\n#declare B = Older;\n",
        "test.pov", m.options());
    EXPECT_EQ(m.debug, "one\nthree\n");
    EXPECT_EQ(m.warnings,
              "test.pov:2:1: warning: two 2\ntest.pov:5:14: warning: use New\n"
              "test.pov:7:14: warning: identifier Older was declared deprecated\n");
    EXPECT_EQ(error_of("#error concat(\"stop \", \"here\")"), "#error: stop here at test.pov:1:1");
}

TEST(SceneLanguageBuiltins, AnimationImageAndFileVariables) {
    ParseOptions options;
    options.animation.clock = 0.5;
    options.animation.clock_delta = 0.25;
    options.animation.clock_on = true;
    options.animation.frame_number = 3;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 5;
    options.animation.final_clock = 1;
    options.animation.image_width = 640;
    options.animation.image_height = 480;
    const Vec3 v =
        parse_scene_text(
            "camera { location <clock + clock_delta, frame_number * 10 + initial_frame + "
            "final_frame * 100, image_width / image_height + clock_on + final_clock> }",
            "test.pov", options)
            .camera.location;
    expect_vec(v, {0.75, 531, 640.0 / 480 + 2});
    EXPECT_DOUBLE_EQ(eval("version").x, 3.7);
    EXPECT_DOUBLE_EQ(eval("version", "#version 3.5;").x, 3.5);
    // input_file_name is the main file's name; now is days since 2000, so between 2020 and 2100.
    Messages m;
    parse_scene_text("#debug input_file_name", "some/folder/scene.pov", m.options());
    EXPECT_EQ(m.debug, "scene.pov");
    const double now = eval("now").x;
    EXPECT_GT(now, 20 * 365.25);
    EXPECT_LT(now, 100 * 365.25);
}

TEST(SceneLanguageBuiltins, TransformValuesComposeAndInvert) {
    // vtransform of transforms.inc is a macro; a transform applied to a point through a
    // function gives the same.
    const std::string declarations =
        "#declare T = transform { translate <1, 2, 3> rotate 90 * y scale 2 }\n"
        "#declare F = function { transform { T } }\n"
        "#declare G = function { transform { T inverse } }\n";
    // (1,0,0) + <1,2,3> = (2,2,3); 90 degrees about y: (3,2,-2); times 2.
    expect_vec(eval("F(1, 0, 0)", declarations), {6, 4, -4}, 1e-12);
    expect_vec(eval("G(6, 4, -4)", declarations), {1, 0, 0}, 1e-12);
    EXPECT_EQ(error_of("#declare T = transform { matrix <1,0,0, 0,1,0, 0,0,0, 0,0,0> inverse }"),
              "'inverse' of a singular transform at test.pov:1:24");
}

}  // namespace
}  // namespace rayset::tracer
