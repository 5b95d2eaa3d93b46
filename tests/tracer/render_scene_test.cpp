// Tests of the Embree scene: every shape's intersections and normals against hand-computed
// geometry (ellipsoids from scaled spheres, rotated boxes, planes, triangles, instanced meshes,
// OBJ files), the object modifiers (no_shadow, no_image) and the camera's POV-Ray frame.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/test_support.h"
#include "tracer/render/camera.h"
#include "tracer/render/parametric_mesh.h"
#include "tracer/render/povray_lights.h"
#include "tracer/render/render_scene.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Scene {
    explicit Scene(const std::string& text) : scene(parse_scene_text(text, "test.pov")) {}
    SurfaceHit hit(Vec3 o, Vec3 d, RayKind kind = RayKind::indirect) const {
        SurfaceHit h;
        h.object = -2;
        if (!scene.intersect(o, normalized(d), 0, kInf, kind, h)) h.object = -1;
        return h;
    }
    RenderScene scene;
};

void expect_vec(Vec3 a, Vec3 b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(RenderScene, NonUniformlyScaledSphereIsAnEllipsoid) {
    const Scene s("sphere { <0,0,0>, 1 scale <2, 1, 0.5> translate <0, 0, 10> }");
    SurfaceHit h = s.hit({-10, 0, 10}, {1, 0, 0});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 8, 1e-5);  // semi-axis 2 along x
    expect_vec(h.normal, {-1, 0, 0}, 1e-9);
    h = s.hit({0, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(h.t, 9.5, 1e-5);  // semi-axis 0.5 along z
    // A generic point: the normal of x^2/4 + y^2 + z'^2/0.25 = 1 is (x/4, y, 4 z').
    const Vec3 target{1, 0.5, 10 - 0.5 * std::sqrt(1 - 0.25 - 0.25)};  // on the near side
    h = s.hit({0, 0, 0}, target);
    ASSERT_EQ(h.object, 0);
    expect_vec(h.point, target, 1e-5);
    expect_vec(h.normal, normalized({target.x / 4, target.y, 4 * (target.z - 10)}), 1e-5);
}

TEST(RenderScene, RotatedBoxHasOutwardNormals) {
    // A unit cube turned 45 degrees about y: its corner points to -z; POV-Ray's rotate 45*y
    // maps +x to (cos45, 0, -sin45).
    const Scene s("box { <-1,-1,-1>, <1,1,1> rotate 45*y translate <0,0,10> }");
    const SurfaceHit h = s.hit({0, 0, 0}, {0, 0, 1});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 10 - std::sqrt(2.0), 1e-5);
    const SurfaceHit side = s.hit({-10, 0.3, 10}, {1, 0, 0});
    EXPECT_NEAR(side.t, 10 - std::sqrt(2.0), 1e-5);
    EXPECT_LT(side.normal.x, 0);                  // outward, toward the ray's origin
    for (double a : {0.3, 1.1, 2.0, 3.7, 5.0}) {  // rays from far outside, all around
        const Vec3 o{20 * std::cos(a), 0.2, 10 + 20 * std::sin(a)};
        const SurfaceHit g = s.hit(o, Vec3{0, 0, 10} - o);
        ASSERT_EQ(g.object, 0);
        EXPECT_LT(dot(g.normal, Vec3{0, 0, 10} - o), 0) << "angle " << a;
    }
}

// Cylinder, cone, disc and torus against their closed forms: distances and outward normals,
// through transforms, caps and holes.
TEST(RenderScene, AnalyticShapesHitWhereTheClosedFormsSay) {
    const Scene cylinder("cylinder { <0, 0, 0>, <0, 2, 0>, 1 translate 10*z }");
    SurfaceHit h = cylinder.hit({-5, 1, 10}, {1, 0, 0});  // the side
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 4, 1e-5);
    EXPECT_NEAR(h.normal.x, -1, 1e-6);
    h = cylinder.hit({0.5, 5, 10}, {0, -1, 0});  // the top cap
    EXPECT_NEAR(h.t, 3, 1e-5);
    EXPECT_NEAR(h.normal.y, 1, 1e-6);
    const Scene open("cylinder { <0, 0, 0>, <0, 2, 0>, 1 open }");
    EXPECT_EQ(open.hit({0.5, 5, 0}, {0, -1, 0}).object, -1);  // no caps: down the inside, nothing
    // A cone from radius 2 at y = 0 to 0 at y = 2: at height 1 its radius is 1, its outward
    // normal leans up by 45 degrees.
    const Scene cone("cone { 0, 2, 2*y, 0 }");
    h = cone.hit({-5, 1, 0}, {1, 0, 0});
    EXPECT_NEAR(h.t, 4, 1e-5);
    EXPECT_NEAR(h.normal.x, -std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(h.normal.y, std::sqrt(0.5), 1e-6);
    // A disc of radius 2 with a hole of radius 1, facing +z after a scale of 3 along z.
    const Scene disc("disc { 0, z, 2, 1 scale <1, 1, 3> translate 4*z }");
    EXPECT_EQ(disc.hit({0.5, 0, 0}, {0, 0, 1}).object, -1);  // the hole
    h = disc.hit({1.5, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(h.t, 4, 1e-5);
    EXPECT_NEAR(std::abs(h.normal.z), 1, 1e-6);
    // A torus (R 2, r 0.5) in the x-z plane, turned to stand in the x-y plane: a ray along z
    // through (2, 0) meets the tube 0.5 before its middle; through the centre it meets nothing.
    const Scene torus("torus { 2, 0.5 rotate 90*x translate 10*z }");
    h = torus.hit({2, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(h.t, 9.5, 1e-5);
    EXPECT_NEAR(h.normal.z, -1, 1e-6);
    EXPECT_EQ(torus.hit({0, 0, 0}, {0, 0, 1}).object, -1);
    h = torus.hit({-5, 0, 10}, {1, 0, 0});  // along the x axis: the outer rim at x = -2.5
    EXPECT_NEAR(h.t, 2.5, 1e-5);
    EXPECT_NEAR(h.normal.x, -1, 1e-6);
}

// Superellipsoids of closed form: <1, 1> is the unit sphere, <2, 2> the octahedron
// |x| + |y| + |z| = 1, <e, 1> about z a sphere's profile; distances to 1e-9 (the bisection
// goes to the last bit) and outward normals.
TEST(RenderScene, SuperellipsoidsHitWhereTheClosedFormsSay) {
    const Scene sphere("superellipsoid { <1, 1> translate 10*z }");
    SurfaceHit h = sphere.hit({0.6, 0, 0}, {0, 0, 1});
    ASSERT_EQ(sphere.hit({0.6, 0, 0}, {0, 0, 1}).object, 0);
    EXPECT_NEAR(h.t, 10 - 0.8, 1e-5);
    expect_vec(h.normal, {0.6, 0, -0.8}, 1e-6);
    const Scene octahedron("superellipsoid { <2, 2> scale 2 }");
    h = octahedron.hit({-10, 0.5, 0.5}, {1, 0, 0});  // |x| = 2 - 0.5 - 0.5 = 1
    EXPECT_NEAR(h.t, 9, 1e-5);
    expect_vec(h.normal, normalized({-1, 1, 1}), 1e-6);
    const Vec3 diagonal = normalized({1, 1, 1});
    h = octahedron.hit(-10 * diagonal, diagonal);  // the face's middle, 2 / sqrt(3) out
    EXPECT_NEAR(h.t, 10 - 2 / std::sqrt(3.0), 1e-5);
    expect_vec(h.normal, -1 * diagonal, 1e-6);
    EXPECT_EQ(octahedron.hit({-10, 1.1, 1.1}, {1, 0, 0}).object, -1);  // past an edge
}

// Isosurfaces: the unit sphere x^2 + y^2 + z^2 = 1 where its container holds it; a cylinder
// of radius 0.8 cut by its box -1..1, capped where the box cuts it (the box's normal) unless
// open; a threshold moves the surface.
TEST(RenderScene, IsosurfacesHitWhereTheClosedFormsSay) {
    const Scene sphere(
        "isosurface { function { x*x + y*y + z*z - 1 } max_gradient 4 "
        "contained_by { box { -2, 2 } } translate 10*z }");
    SurfaceHit h = sphere.hit({0.6, 0, 0}, {0, 0, 1});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 10 - 0.8, 1e-5);
    expect_vec(h.normal, {0.6, 0, -0.8}, 1e-5);
    const Scene bigger(
        "isosurface { function { x*x + y*y + z*z - 1 } threshold 0.44 "
        "contained_by { sphere { 0, 2 } } }");
    EXPECT_NEAR(bigger.hit({0, 0, -5}, {0, 0, 1}).t, 5 - 1.2, 1e-5);
    const std::string cylinder = "isosurface { function { sqrt(x*x + z*z) - 0.8 } ";
    const Scene capped(cylinder + "}");
    h = capped.hit({0.3, 5, 0.2}, {0, -1, 0});  // down the axis: the box's top cuts it
    EXPECT_NEAR(h.t, 4, 1e-5);
    expect_vec(h.normal, {0, 1, 0}, 1e-12);
    h = capped.hit({-5, 0.5, 0}, {1, 0, 0});  // from the side: the cylinder's wall
    EXPECT_NEAR(h.t, 5 - 0.8, 1e-5);
    expect_vec(h.normal, {-1, 0, 0}, 1e-5);
    const Scene open(cylinder + "open }");
    h = open.hit({0.3, 5, 0.2}, {0, -1, 0});  // down the axis of the open tube: nothing
    EXPECT_EQ(h.object, -1);
}

// Blobs: one sphere component of strength s and radius r at threshold t is the sphere of
// radius r sqrt(1 - sqrt(t / s)); a cylinder component's the capsule of that radius about its
// segment; a negative component carves the field.
TEST(RenderScene, BlobsHitWhereTheClosedFormsSay) {
    const Scene sphere("blob { threshold 0.36 sphere { 0, 2, 1 } translate 10*z }");
    const double radius = 2 * std::sqrt(1 - 0.6);
    SurfaceHit h = sphere.hit({0, 0, 0}, {0, 0, 1});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 10 - radius, 1e-5);
    expect_vec(h.normal, {0, 0, -1}, 1e-5);
    const Scene capsule("blob { threshold 0.36 cylinder { <-1, 0, 0>, <1, 0, 0>, 2, 1 } }");
    h = capsule.hit({0.5, 5, 0}, {0, -1, 0});  // onto the side, above the segment
    EXPECT_NEAR(h.t, 5 - radius, 1e-5);
    h = capsule.hit({5, 0, 0}, {-1, 0, 0});  // onto the rounded end
    EXPECT_NEAR(h.t, 5 - 1 - radius, 1e-5);
    // A negative component of the same size at the centre leaves nothing there.
    const Scene carved("blob { threshold 0.36 sphere { 0, 2, 1 } sphere { 0, 2, -1 } }");
    EXPECT_EQ(carved.hit({0, 0, -5}, {0, 0, 1}).object, -1);
}

// Linear prisms: a square outline with a square hole swept from y = 0 to 2 (caps on top and
// bottom, walls facing out of the solid, into the hole too), and the same square swept
// conically from y = 1 to 2 (the outline scaled by the height).
TEST(RenderScene, PrismsHitWhereTheClosedFormsSay) {
    const Scene framed(
        "prism { 0, 2, 10, <-2, -2>, <2, -2>, <2, 2>, <-2, 2>, <-2, -2>, "
        "<-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> }");
    SurfaceHit h = framed.hit({1.5, 5, 0}, {0, -1, 0});  // the top cap of the frame
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 3, 1e-5);
    expect_vec(h.normal, {0, 1, 0}, 1e-12);
    EXPECT_EQ(framed.hit({0, 5, 0}, {0, -1, 0}).object, -1);  // down the hole
    h = framed.hit({-5, 1, 0}, {1, 0, 0});                    // the outer wall
    EXPECT_NEAR(h.t, 3, 1e-5);
    expect_vec(h.normal, {-1, 0, 0}, 1e-12);
    h = framed.hit({0, 1, 0}, {1, 0, 0});  // from the hole: its wall faces into the hole
    EXPECT_NEAR(h.t, 1, 1e-5);
    expect_vec(h.normal, {-1, 0, 0}, 1e-12);
    const Scene conic(
        "prism { conic_sweep 1, 2, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> }");
    h = conic.hit({-5, 1.5, 0}, {1, 0, 0});  // at y = 1.5 the square's half-width is 1.5
    EXPECT_NEAR(h.t, 5 - 1.5, 1e-5);
    expect_vec(h.normal, normalized({-1, -1, 0}), 1e-6);  // the wall widens upward
    h = conic.hit({1.9, 5, 0}, {0, -1, 0});  // the top cap (half-width 2) just inside its edge
    EXPECT_NEAR(h.t, 3, 1e-5);
}

// Lathes: a linear profile from radius 2 at y = 0 to 1 at y = 2 is a cone's frustum (radius
// 1.5 at y = 1, its side leaning out by atan(1/2)); a cubic profile passes through its inner
// points (radius 1 at y = 1); a closed profile with a hole is a ring a line down the middle
// misses.
TEST(RenderScene, LathesHitWhereTheClosedFormsSay) {
    const Scene cone("lathe { linear_spline 4, <0, 0>, <2, 0>, <1, 2>, <0, 2> }");
    SurfaceHit h = cone.hit({-5, 1, 0}, {1, 0, 0});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 5 - 1.5, 1e-5);
    expect_vec(h.normal, normalized({-2, 1, 0}), 1e-6);
    h = cone.hit({0.5, 5, 0.3}, {0, -1, 0});  // the flat top
    EXPECT_NEAR(h.t, 3, 1e-5);
    expect_vec(h.normal, {0, 1, 0}, 1e-6);
    const Scene cubic("lathe { cubic_spline 5, <0.5, -1>, <1.5, 0>, <1, 1>, <1.5, 2>, <0.5, 3> }");
    EXPECT_NEAR(cubic.hit({0, 1, -5}, {0, 0, 1}).t, 5 - 1, 1e-5);
    EXPECT_NEAR(cubic.hit({0, 0, -5}, {0, 0, 1}).t, 5 - 1.5, 1e-5);
    const Scene ring("lathe { linear_spline 5, <1, 0>, <2, 0>, <2, 1>, <1, 1>, <1, 0> }");
    EXPECT_EQ(ring.hit({0, 5, 0}, {0, -1, 0}).object, -1);
    h = ring.hit({0, 0.5, 0}, {1, 0, 0});  // from the hole: the inner wall faces it
    EXPECT_NEAR(h.t, 1, 1e-5);
    expect_vec(h.normal, {-1, 0, 0}, 1e-6);
}

// Surfaces of revolution: four points of one radius make a cylinder between the inner two
// heights (r^2 has slope 0 there), capped unless open; inside it a box's top is kept by an
// intersection. A polygon of two loops is a square frame: a ray down the hole misses.
TEST(RenderScene, SorsAndPolygonsHitWhereTheClosedFormsSay) {
    const std::string cylinder = "sor { 4, <1, -1>, <1, 0>, <1, 2>, <1, 3> ";
    const Scene capped(cylinder + "}");
    SurfaceHit h = capped.hit({-5, 1, 0}, {1, 0, 0});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 4, 1e-9);
    expect_vec(h.normal, {-1, 0, 0}, 1e-9);
    h = capped.hit({0.3, 5, 0.2}, {0, -1, 0});  // the top cap at y = 2
    EXPECT_NEAR(h.t, 3, 1e-9);
    expect_vec(h.normal, {0, 1, 0}, 1e-9);
    EXPECT_EQ(capped.hit({1.5, 5, 0}, {0, -1, 0}).object, -1);  // beside it
    const Scene open(cylinder + "open }");
    h = open.hit({0.3, 5, 0.2}, {0, -1, 0});  // down the open tube: nothing
    EXPECT_EQ(h.object, -1);
    const Scene cut("intersection { " + cylinder + "} box { <-2, 0.5, -2>, <2, 1.5, 2> } }");
    h = cut.hit({0.3, 5, 0.2}, {0, -1, 0});  // the box's top, inside the cylinder
    EXPECT_NEAR(h.t, 3.5, 1e-9);
    expect_vec(h.normal, {0, 1, 0}, 1e-9);
    EXPECT_EQ(cut.hit({1.5, 5, 0}, {0, -1, 0}).object, -1);  // the box's top, outside it

    const Scene frame(
        "polygon { 10, <-2, -2>, <2, -2>, <2, 2>, <-2, 2>, <-2, -2>, "
        "<-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> translate 3*z }");
    h = frame.hit({1.5, 0.2, 0}, {0, 0, 1});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 3, 1e-9);
    EXPECT_NEAR(std::abs(h.normal.z), 1, 1e-9);
    EXPECT_EQ(frame.hit({0.2, 0.3, 0}, {0, 0, 1}).object, -1);  // through the hole
    EXPECT_EQ(frame.hit({2.5, 0, 0}, {0, 0, 1}).object, -1);    // beside it
}

// Sphere sweeps: the union of the spheres along the spline. Embree keeps distances and normals
// in single precision (the double-precision hits are checked against POV-Ray's trace at 1e-9 in
// ObjectsGeometry.TraceAsPovRayAnswers).
constexpr double kSingle = 1e-6;

// Two equal spheres make a capsule; two of radii 1 and 0.5 four apart are joined by the cone
// tangent to both (its surface line sin(a) x + cos(a) y = 1 with sin(a) = (1 - 0.5) / 4).
TEST(RenderScene, LinearSphereSweepsHitWhereTheClosedFormsSay) {
    const Scene capsule("sphere_sweep { linear_spline 2, <-1, 0, 0>, 0.5, <1, 0, 0>, 0.5 }");
    SurfaceHit h = capsule.hit({0.3, 5, 0}, {0, -1, 0});  // the tube
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 4.5, kSingle);
    expect_vec(normalized(h.normal), {0, 1, 0}, kSingle);
    h = capsule.hit({-5, 0, 0}, {1, 0, 0});  // the end sphere, along the axis
    EXPECT_NEAR(h.t, 3.5, kSingle);
    expect_vec(normalized(h.normal), {-1, 0, 0}, kSingle);
    h = capsule.hit({1.3, 5, 0}, {0, -1, 0});  // the end sphere at y = 0.4
    EXPECT_NEAR(h.t, 4.6, kSingle);
    expect_vec(normalized(h.normal), {0.6, 0.8, 0}, kSingle);
    const double z = std::sqrt(0.25 - 0.04);
    h = capsule.hit({0.5, 0.2, -5}, {0, 0, 1});
    EXPECT_NEAR(h.t, 5 - z, kSingle);
    expect_vec(normalized(h.normal), {0, 0.4, -2 * z}, kSingle);
    EXPECT_EQ(capsule.hit({1.6, 5, 0}, {0, -1, 0}).object, -1);   // beyond the end
    EXPECT_EQ(capsule.hit({0, 5, 0.51}, {0, -1, 0}).object, -1);  // beside the tube

    const Scene cone("sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <4, 0, 0>, 0.5 }");
    const double sine = 0.125, cosine = std::sqrt(1 - sine * sine);
    h = cone.hit({2, 5, 0}, {0, -1, 0});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 5 - (1 - 2 * sine) / cosine, kSingle);
    expect_vec(normalized(h.normal), {sine, cosine, 0}, kSingle);
    h = cone.hit({-5, 0, 0}, {1, 0, 0});  // the larger sphere's far side
    EXPECT_NEAR(h.t, 4, kSingle);
    h = cone.hit({9, 0, 0}, {-1, 0, 0});  // the smaller's
    EXPECT_NEAR(h.t, 4.5, kSingle);
    expect_vec(normalized(h.normal), {1, 0, 0}, kSingle);
    h = cone.hit({0, 0, 0}, {0, 0, 1});  // from inside: out through the larger sphere
    EXPECT_NEAR(h.t, 1, kSingle);
}

// A b_spline or cubic_spline of collinear spheres of one radius is a capsule from the spline's
// start to its end; a cubic sweep of varied radii hits where POV-Ray's trace() says (printed to
// 10 decimals).
TEST(RenderScene, CurvedSphereSweepsHitWhereTheClosedFormsSay) {
    SurfaceHit h;
    // The B-spline of -3, -1, 1, 3 runs from (-3 + 4 (-1) + 1) / 6 = -1 to 1; Catmull-Rom's of
    // -2, -1, 1, 2 from -1 to 1 (monotone between).
    for (const std::string tube :
         {"sphere_sweep { b_spline 4, <-3, 0, 0>, 0.5, <-1, 0, 0>, 0.5, <1, 0, 0>, 0.5, "
          "<3, 0, 0>, 0.5 rotate 90*y }",
          "sphere_sweep { cubic_spline 4, <-2, 0, 0>, 0.5, <-1, 0, 0>, 0.5, <1, 0, 0>, 0.5, "
          "<2, 0, 0>, 0.5 rotate 90*y }"}) {
        SCOPED_TRACE(tube);
        const Scene s(tube);  // along z after the turn
        h = s.hit({0.1, 5, 0.3}, {0, -1, 0});
        ASSERT_EQ(h.object, 0);
        const double y = std::sqrt(0.25 - 0.01);
        EXPECT_NEAR(h.t, 5 - y, kSingle);
        expect_vec(normalized(h.normal), {0.2, 2 * y, 0}, kSingle);
        h = s.hit({0, 0, -5}, {0, 0, 1});
        EXPECT_NEAR(h.t, 3.5, kSingle);
        expect_vec(normalized(h.normal), {0, 0, -1}, kSingle);
        EXPECT_EQ(s.hit({0, 5, 1.55}, {0, -1, 0}).object, -1);
    }

    const Scene cubic(
        "sphere_sweep { cubic_spline 4, <0, 0, 0>, 0.2, <1, 0, 0>, 0.5, <3, 0, 0>, 1, "
        "<6, 0, 0>, 0.3 }");
    h = cubic.hit({1.4, 5, 0}, {0, -1, 0});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 5 - 0.6884538080, kSingle);
    expect_vec(normalized(h.normal), {-0.3711251951, 0.9285828394, 0}, kSingle);
}

// Inside for CSG: a capsule cut by a box, and a box less a capsule.
TEST(RenderScene, SphereSweepsAreSolidsInCsg) {
    const Scene cut(
        "intersection { sphere_sweep { linear_spline 2, <-1, 0, 0>, 0.5, "
        "<1, 0, 0>, 0.5 } box { <-3, -3, -3>, <0.5, 0.3, 3> } }");
    SurfaceHit h = cut.hit({0, 5, 0}, {0, -1, 0});  // the box's top, inside the capsule
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 4.7, kSingle);
    expect_vec(normalized(h.normal), {0, 1, 0}, kSingle);
    // At z = 0.45 the capsule reaches up to y = sqrt(0.0475), below the box's top: the tube.
    h = cut.hit({0, 5, 0.45}, {0, -1, 0});
    EXPECT_NEAR(h.t, 5 - std::sqrt(0.0475), kSingle);
    expect_vec(normalized(h.normal), {0, 2 * std::sqrt(0.0475), 0.9}, kSingle);
    h = cut.hit({5, 0, 0}, {-1, 0, 0});  // the box's side x = 0.5
    EXPECT_NEAR(h.t, 4.5, kSingle);
    const Scene groove(
        "difference { box { <-2, -1, -1>, <2, 1, 1> } sphere_sweep { "
        "linear_spline 2, <-3, 1, 0>, 0.5, <3, 1, 0>, 0.5 } }");
    h = groove.hit({0, 5, 0.3}, {0, -1, 0});  // the groove's floor
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 4 + std::sqrt(0.25 - 0.09), kSingle);
    expect_vec(normalized(h.normal), {0, 0.8, -0.6}, kSingle);
}

// Parametric surfaces: triangles within kParametricTolerance of the size of the surface's part
// inside its container (hits within that of the closed forms, plus Embree's float); normals
// cross(dP/du, dP/dv) at the hit's (u, v) (shading) and the triangle's (geometric), as POV-Ray
// orients them (inward for this sphere and cylinder, whichever side the ray comes from); only
// the uv rectangle is drawn, and only inside the container (the box -1..1 by default).
TEST(RenderScene, ParametricsHitWhereTheClosedFormsSay) {
    auto surface = [](const std::string& xyz, const std::string& rest) {
        return "parametric { " + xyz + " " + rest + " }";
    };
    const std::string sphere =
        "function { R*cos(v)*cos(u) } function { R*sin(v) } function { R*cos(v)*sin(u) } "
        "<0, -pi/2>, <2*pi, pi/2>";
    // The largest side of the sphere's box within its container is 2.
    const double tolerance = 2 * kParametricTolerance + 1e-5;
    const Scene unit("#declare R = 1;\n" + surface(sphere, "contained_by { box { -2, 2 } }"));
    for (const Vec3 direction : {Vec3{1, 0, 0}, normalized({1, 2, -2}), normalized({-3, -1, 1})}) {
        SurfaceHit h = unit.hit(-5 * direction, direction);
        ASSERT_EQ(h.object, 0);
        EXPECT_NEAR(h.t, 4, tolerance);
        expect_vec(h.shading_normal, direction, tolerance);  // inward
        EXPECT_GT(dot(h.normal, direction), 0.999);
        h = unit.hit({0, 0, 0}, direction);  // from inside: inward still
        EXPECT_NEAR(h.t, 1, tolerance);
        expect_vec(h.shading_normal, -1 * direction, tolerance);
    }

    // A cylinder of radius 1 for v from 0 to 1: cross(dP/du, dP/dv) = (-cos u, 0, -sin u).
    const Scene cylinder(surface("function { cos(u) } function { v } function { sin(u) }",
                                 "<0, 0>, <2*pi, 1> contained_by { box { -2, 2 } }"));
    SurfaceHit h = cylinder.hit({-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 4, tolerance);
    expect_vec(h.shading_normal, {1, 0, 0}, 1e-3);
    h = cylinder.hit({0, 0.25, 0}, {0, 0, -1});
    EXPECT_NEAR(h.t, 1, tolerance);
    expect_vec(h.shading_normal, {0, 0, 1}, 1e-3);
    EXPECT_EQ(cylinder.hit({-5, 1.5, 0}, {1, 0, 0}).object, -1);   // above v = 1
    EXPECT_EQ(cylinder.hit({-5, -0.5, 0}, {1, 0, 0}).object, -1);  // below v = 0

    // A tilted plane patch is its triangles exactly: z = u/2 + v/4, normal (-1/2, -1/4, 1);
    // corners given in either order are the same rectangle.
    for (const std::string corners : {"<-0.5, -1>, <0.5, 1>", "<0.5, 1>, <-0.5, -1>"}) {
        const Scene patch(surface("function { u } function { v } function { u/2 + v/4 }",
                                  corners + " scale 2 translate <0, 0, 3>"));
        h = patch.hit({0.4, 0.8, -5}, {0, 0, 1});  // (u, v) = (0.2, 0.4): z = 0.2 (x2, +3)
        ASSERT_EQ(h.object, 0);
        EXPECT_NEAR(h.t, 8.4, 1e-5);
        expect_vec(h.normal, normalized({-0.5, -0.25, 1}), 1e-6);
        expect_vec(h.shading_normal, normalized({-0.5, -0.25, 1}), 1e-6);
        h = patch.hit({0.4, 0.8, 10}, {0, 0, -1});  // from behind: the same normal
        EXPECT_NEAR(h.t, 6.6, 1e-5);
        expect_vec(h.shading_normal, normalized({-0.5, -0.25, 1}), 1e-6);
        EXPECT_EQ(patch.hit({1.2, 0, -5}, {0, 0, 1}).object, -1);  // u = 0.6: beyond u2
    }

    // Mirrored, both normals keep POV-Ray's side: (1/2, -1/4, 1) through the inverse transpose.
    const Scene mirrored(surface("function { u } function { v } function { u/2 + v/4 }",
                                 "<-0.5, -1>, <0.5, 1> scale <-1, 1, 1>"));
    h = mirrored.hit({-0.2, 0.4, -5}, {0, 0, 1});  // (u, v) = (0.2, 0.4): z = 0.2
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 5.2, 1e-5);
    expect_vec(h.normal, normalized({0.5, -0.25, 1}), 1e-6);
    expect_vec(h.shading_normal, normalized({0.5, -0.25, 1}), 1e-6);

    // A sphere of radius 1.2 in the default container (box -1..1): its caps beyond the box are
    // cut away; in a sphere container only what the sphere holds is left.
    const Scene boxed("#declare R = 1.2;\n" + surface(sphere, ""));
    EXPECT_EQ(boxed.hit({0, 0, -5}, {0, 0, 1}).object, -1);  // z = -1.2 and 1.2: outside
    EXPECT_EQ(boxed.hit({0, 0, 0}, {0, 0, 1}).object, -1);
    h = boxed.hit({0.8, 0, -5}, {0, 0, 1});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 5 - std::sqrt(1.44 - 0.64), tolerance);
    const Scene in_sphere("#declare R = 1.2;\n" +
                          surface(sphere, "contained_by { sphere { <0.5, 0, 0>, 1 } }"));
    EXPECT_EQ(in_sphere.hit({0.2, 0, -5}, {0, 0, 1}).object, -1);  // |p - centre| = 1.22
    h = in_sphere.hit({0.8, 0, -5}, {0, 0, 1});
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 5 - std::sqrt(1.44 - 0.64), tolerance);
    // Radius 2 without a container: nothing is left of it.
    const Scene gone("#declare R = 2;\n" + surface(sphere, ""));
    EXPECT_EQ(gone.hit({0, 0, -5}, {0, 0, 1}).object, -1);
    EXPECT_EQ(gone.hit({0, 0, 0}, {1, 0, 0}).object, -1);
}

// The triangles' bound, checked away from the samples the grid was refined at: random points
// of every triangle of a unit sphere lie within the tolerance of radius 1, and of a torus
// within it of the surface at the same (u, v). The sphere's size is 2 (the largest side of its
// box), the torus's 2.7.
TEST(RenderScene, ParametricTrianglesFollowTheSurfaceWithinTheirTolerance) {
    const SceneDescription d = parse_scene_text(
        "parametric { function { cos(v)*cos(u) } function { sin(v) } function { cos(v)*sin(u) } "
        "<0, -pi/2>, <2*pi, pi/2> contained_by { box { -2, 2 } } }\n"
        "parametric { function { (1 + 0.35*cos(v))*cos(u) } function { 0.35*sin(v) } "
        "function { (1 + 0.35*cos(v))*sin(u) } <0, 0>, <2*pi, 2*pi> "
        "contained_by { box { -2, 2 } } }",
        "test.pov");
    std::mt19937 random(1);
    std::uniform_real_distribution<double> unit(0, 1);
    const double sizes[2] = {2, 2.7};
    for (size_t k = 0; k < 2; ++k) {
        const auto& shape = std::get<ParametricShape>(d.objects[k].shape);
        const ParametricMesh mesh = tessellate_parametric(shape, "test.pov");
        EXPECT_NEAR(mesh.tolerance, kParametricTolerance * sizes[k], 1e-12);
        double worst = 0;
        for (const auto& t : mesh.triangles)
            for (int sample = 0; sample < 4; ++sample) {
                double a = unit(random), b = unit(random);
                if (a + b > 1) a = 1 - a, b = 1 - b;
                const double c = 1 - a - b;
                const Vec3 p =
                    c * mesh.points[t[0]] + a * mesh.points[t[1]] + b * mesh.points[t[2]];
                const double u = c * mesh.uvs[t[0]].x + a * mesh.uvs[t[1]].x + b * mesh.uvs[t[2]].x;
                const double v = c * mesh.uvs[t[0]].y + a * mesh.uvs[t[1]].y + b * mesh.uvs[t[2]].y;
                worst = std::max(worst, k == 0 ? std::abs(length(p) - 1)
                                               : length(p - parametric_point(shape, u, v)));
            }
        std::printf("parametric %zu: %zu triangles, worst distance %.3g of tolerance %.3g\n", k,
                    mesh.triangles.size(), worst, mesh.tolerance);
        EXPECT_LE(worst, mesh.tolerance);
    }
}

// Julia fractals of c = 0: under z -> z^2 a point stays within radius 2 for the 7 steps of
// max_iteration 8 where |z|^128 <= 2: a ball of radius 2^(1/128), in every direction for the
// quaternions; along x (both complex planes alike) for the hypercomplex numbers.
TEST(RenderScene, JuliaFractalsOfZeroAreBalls) {
    const double radius = std::pow(2.0, 1.0 / 128);
    const Scene quaternion("julia_fractal { <0, 0, 0, 0> quaternion sqr max_iteration 8 }");
    for (const Vec3 direction : {Vec3{1, 0, 0}, normalized({1, 2, -2})}) {
        const SurfaceHit h = quaternion.hit(-5 * direction, direction);
        ASSERT_EQ(h.object, 0);
        EXPECT_NEAR(h.t, 5 - radius, 1e-5);  // Embree keeps distances in single precision
        expect_vec(h.normal, -1 * direction, 1e-4);
    }
    const Scene hypercomplex("julia_fractal { <0, 0, 0, 0> hypercomplex sqr max_iteration 8 }");
    EXPECT_NEAR(hypercomplex.hit({-5, 0, 0}, {1, 0, 0}).t, 5 - radius, 1e-5);
}

// Text: the glyph outline extruded along z from 0 to the thickness, its first glyph's left edge
// at x = 0. Times Roman's "I" is a stem with serifs: its caps face -z and +z, its stem's walls
// +-x; "O" has a hole where a ray along z passes through.
TEST(RenderScene, TextIsTheOutlineExtruded) {
    const Scene text("text { ttf \"timrom.ttf\" \"IO\" 0.5, 0 translate 10*z }");
    SurfaceHit h = text.hit({0.15, 0.3, 0}, {0, 0, 1});  // the front cap through the stem
    ASSERT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 10, 1e-5);
    EXPECT_NEAR(h.normal.z, -1, 1e-6);
    h = text.hit({0.15, 0.3, 20}, {0, 0, -1});  // the back cap
    EXPECT_NEAR(h.t, 9.5, 1e-5);
    EXPECT_NEAR(h.normal.z, 1, 1e-6);
    h = text.hit({-5, 0.3, 10.25}, {1, 0, 0});  // the stem's left wall, between the serifs
    ASSERT_EQ(h.object, 0);
    EXPECT_GT(h.t, 5);  // inside the serifs' span, which starts at x = 0
    EXPECT_NEAR(h.normal.x, -1, 1e-3);
    EXPECT_EQ(text.hit({0.342 + 0.36, 0.33, 0}, {0, 0, 1}).object, -1);  // the O's hole
    EXPECT_EQ(text.hit({0.342 + 0.05, 0.33, 0}, {0, 0, 1}).object, 0);   // its left side
}

TEST(RenderScene, PlaneIsInfiniteUserGeometry) {
    const Scene s("plane { <0, 1, 1>, 2 }  sphere { <0,0,0>, 0.001 translate <1000,1000,1000> }");
    // Points with dot(n, p) = 2 with n = (0, 1, 1)/sqrt 2.
    const SurfaceHit h = s.hit({5000, -3000, 0}, {0, 1, 0});
    ASSERT_EQ(h.object, 0);
    // Embree keeps the hit distance in float: t ~ 3003 is exact to 2^-24 t = 1.8e-4.
    EXPECT_NEAR(h.point.y, 2 * std::sqrt(2.0), 3003 * std::ldexp(1.0, -24));
    expect_vec(h.normal, normalized({0, 1, 1}), 1e-12);
}

TEST(RenderScene, ClearWithinSaysNoOnlyWhereASurfaceOrMediumMayBe) {
    // What lets a ray source end shadow rays at its body's box: "clear" must never be said of a
    // box a surface passes through. Planes and triangles count by their planes (a box beside a
    // room's face, inside the face's bounding box, is clear), other shapes by their bounds.
    auto clear = [](const std::string& text, Vec3 low, Vec3 high) {
        return Scene(text).scene.clear_within({low, high});
    };
    const std::string room = "box { <-1000, 0, -1000>, <1000, 2000, 1000> }";  // 12 triangles
    EXPECT_TRUE(clear(room, {-50, 1998, -50}, {50, 1999.8, 50}));              // under the ceiling
    EXPECT_FALSE(clear(room, {-50, 1998, -50}, {50, 2000.1, 50}));
    EXPECT_FALSE(clear(room, {999, 10, 10}, {1001, 20, 20}));  // across a wall
    EXPECT_FALSE(clear(room, {-10, -10, -10}, {10, 10, 10}));  // across the floor at y = 0

    const std::string plane = "plane { <0, 1, 1>, 2 }";     // dot(n, p) = 2, n = (0, 1, 1) / sqrt 2
    EXPECT_TRUE(clear(plane, {-5, 0, 0}, {5, 1, 1}));       // below: dot(n, corner) <= 1.42
    EXPECT_FALSE(clear(plane, {-5, 0, 0}, {5, 1.5, 1.5}));  // (0, 1.5, 1.5): 2.12 > 2

    const std::string sphere = "sphere { <0, 0, 0>, 1 }";
    EXPECT_TRUE(clear(sphere, {1.01, -1, -1}, {3, 1, 1}));
    EXPECT_FALSE(clear(sphere, {0.99, -1, -1}, {3, 1, 1}));

    const std::string mesh = R"(
        #declare M = mesh { triangle { <-1,-1,0>, <1,-1,0>, <0,1,0> } }
        object { M translate <0,0,5> })";
    EXPECT_TRUE(clear(mesh, {-0.5, -0.5, 5.01}, {0.5, 0.5, 6}));
    EXPECT_FALSE(clear(mesh, {-0.5, -0.5, 4.9}, {0.5, 0.5, 6}));
    EXPECT_TRUE(clear("triangle { <0,0,0>, <1,0,0>, <0,1,0> }", {0, 0, -1}, {1, 1, -0.01}));
    EXPECT_FALSE(clear("triangle { <0,0,0>, <1,0,0>, <0,1,0> }", {0.2, 0.2, -1}, {0.3, 0.3, 1}));

    // An unbounded solid may be anywhere; fog and media change what a ray carries anywhere.
    EXPECT_FALSE(
        clear("difference { plane { y, 0 } sphere { <0, -5, 0>, 1 } }", {5, 5, 5}, {6, 6, 6}));
    EXPECT_TRUE(clear(sphere, {5, 5, 5}, {6, 6, 6}));
    EXPECT_FALSE(clear(sphere + " fog { distance 100 color rgb 1 }", {5, 5, 5}, {6, 6, 6}));
    EXPECT_FALSE(
        clear("sphere { <0, 0, 0>, 1 pigment { rgbf 1 } hollow "
              "interior { media { absorption 1 } } }",
              {5, 5, 5}, {6, 6, 6}));
}

TEST(RenderScene, MeshInstancesShareOnePrototype) {
    const Scene s(R"(
        #declare M = mesh { triangle { <-1,-1,0>, <1,-1,0>, <0,1,0> } }
        object { M translate <0,0,5> }
        object { M scale 2 rotate 90*y translate <10,0,0> }
    )");
    const SurfaceHit a = s.hit({0, 0, 0}, {0, 0, 1});
    EXPECT_EQ(a.object, 0);
    EXPECT_NEAR(a.t, 5, 1e-5);
    // rotate 90*y maps +z to +x: the second copy is the plane x = 10, twice as large.
    const SurfaceHit b = s.hit({0, 1.5, 0}, {1, 0, 0});
    EXPECT_EQ(b.object, 1);
    EXPECT_NEAR(b.t, 10, 1e-5);
    expect_vec(b.normal, {std::copysign(1.0, b.normal.x), 0, 0}, 1e-6);
    const auto& d = s.scene.description();
    EXPECT_EQ(std::get<MeshShape>(d.objects[0].shape).mesh,
              std::get<MeshShape>(d.objects[1].shape).mesh);
}

TEST(RenderScene, Mesh2NormalsAreInterpolated) {
    const Scene s(R"(
        mesh2 { vertex_vectors { 3, <-1,-1,5>, <1,-1,5>, <0,1,5> }
                normal_vectors { 3, <-1,0,-1>, <1,0,-1>, <0,0,-1> }
                face_indices { 1, <0,1,2> } }
    )");
    const SurfaceHit h = s.hit({-0.5, -0.5, 0}, {0, 0, 1});
    ASSERT_EQ(h.object, 0);
    // (-0.5, -0.5) = a + u (b - a) + v (c - a) with u = 1/8, v = 1/4: weights 5/8, 1/8, 1/4
    // -> (-0.5, 0, -1).
    expect_vec(h.shading_normal, normalized({-0.5, 0, -1}), 1e-5);
    expect_vec(h.normal, {0, 0, std::copysign(1.0, h.normal.z)}, 1e-9);
}

TEST(RenderScene, ObjMeshFileLoads) {
    test::ScratchDir dir;
    test::write_file(dir.file("quad.obj"), "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    test::write_file(dir.file("scene.pov"), "mesh_file { \"quad.obj\" translate <0, 0, 3> }\n");
    const RenderScene scene(parse_scene_file(dir.file("scene.pov")));
    SurfaceHit h;
    ASSERT_TRUE(
        scene.intersect({0.9, 0.9, 0}, {0, 0, 1}, 0, kInf, RayKind::camera, h));  // second triangle
    EXPECT_NEAR(h.t, 3, 1e-6);
    ASSERT_TRUE(scene.intersect({-0.9, -0.9, 0}, {0, 0, 1}, 0, kInf, RayKind::camera, h));
    EXPECT_FALSE(scene.intersect({1.1, 0, 0}, {0, 0, 1}, 0, kInf, RayKind::camera, h));
}

TEST(RenderScene, ModifiersHideObjectsFromTheirRays) {
    const Scene s(R"(
        sphere { <0,0,5>, 1 no_shadow }
        sphere { <0,0,10>, 1 no_image }
        sphere { <0,0,15>, 1 }
    )");
    EXPECT_EQ(s.hit({0, 0, 0}, {0, 0, 1}, RayKind::camera).object, 0);
    EXPECT_EQ(s.hit({0, 0, 0}, {0, 0, 1}, RayKind::shadow).object, 1);
    EXPECT_EQ(s.hit({0, 0, 7}, {0, 0, 1}, RayKind::camera).object, 2);
    EXPECT_FALSE(
        s.scene.occluded({0, 0, 0}, {0, 0, 1}, 0, 8.5));  // only the no_shadow sphere before 8.5
    EXPECT_TRUE(s.scene.occluded({0, 0, 0}, {0, 0, 1}, 0, 9.5));
}

TEST(RenderCamera, PovRayFrameAndMirroredRight) {
    Camera c;  // POV-Ray's default camera: at the origin looking along +z, right <1.33,0,0>
    SceneCamera camera(c, 100, 50);
    expect_vec(camera.ray(50, 25).direction, {0, 0, 1}, 1e-12);
    // Image left edge, top row: direction + (-0.5) right + 0.5 up.
    expect_vec(camera.ray(0, 0).direction, normalized({-0.665, 0.5, 1}), 1e-12);
    c.right = {-1, 0, 0};  // cornell.pov's right <-1,0,0>: the image's left is +x
    expect_vec(SceneCamera(c, 100, 50).ray(0, 25).direction, normalized({0.5, 0, 1}), 1e-12);
}

// The message of the error a scene gives the renderer, or "no error".
std::string render_error(const std::string& text) {
    try {
        RenderScene scene(parse_scene_text(text, "test.pov"));
    } catch (const rayset::Error& e) {
        return e.what();
    }
    return "no error";
}

// What the renderer renders as POV-Ray does rather than physically, or leaves to its own
// physics, it says in a note: shadowless lights, fake caustics.
TEST(RenderScene, NotesWhatItRendersItsOwnWay) {
    const RenderScene plain(parse_scene_text("sphere { 0, 1 interior { ior 1.5 } }", "test.pov"));
    EXPECT_TRUE(plain.notes().empty());
    const RenderScene glass(
        parse_scene_text("sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 caustics 1 } }\n"
                         "sphere { 2, 1 pigment { rgbf 1 } interior { ior 1.5 caustics 0.5 } }\n"
                         "light_source { <0, 9, 0> color 1 shadowless }",
                         "test.pov"));
    ASSERT_EQ(glass.notes().size(), 2u);
    EXPECT_NE(glass.notes()[0].find("shadowless light_source at test.pov:3:1"), std::string::npos);
    EXPECT_NE(glass.notes()[1].find("interior caustics at test.pov:1:34"), std::string::npos);
}

TEST(RenderLights, UnsupportedFadeAndShadowlessAreaLightsAreErrors) {
    EXPECT_EQ(
        render_error("light_source { <0,0,0> color 1 fade_distance 2 fade_power 1 }"),
        "not supported: fade_power 1 (only 2, read as the inverse-square law) at test.pov:1:1");
    EXPECT_EQ(render_error("light_source { <0,0,0> color 1 area_light x, y, 2, 2 shadowless }"),
              "not supported: shadowless area_light at test.pov:1:1");
    EXPECT_EQ(render_error("light_source { <0,0,0> color 1 shadowless }"), "no error");
}

// What the renderer does not render is refused with its place in the file; POV-Ray's hints
// (radiosity, photons, max_trace_level ...) and ambient_light are accepted (README.md).
TEST(RenderScene, RefusesSceneItemsItDoesNotRender) {
    EXPECT_EQ(render_error("#declare C = camera { location -5*z aperture 0.4 }\ncamera { C }"),
              "not supported: focal blur (camera aperture 0.4) at test.pov:1:37");
    EXPECT_EQ(render_error("camera { location -5*z aperture 0.4 blur_samples 9 }"),
              "not supported: focal blur (camera aperture 0.4) at test.pov:1:24");
    EXPECT_EQ(render_error("rainbow { direction z angle 42 width 5 }"),
              "not supported: rainbow at test.pov:1:1");
    EXPECT_EQ(render_error("sky_sphere { pigment { rgb 1 } }"), "no error");
    EXPECT_EQ(render_error("sky_sphere {\n pigment { spiral2 3 } }"),
              "not supported: pigment pattern 'spiral2' in sky_sphere at test.pov:2:12");
    EXPECT_EQ(render_error(
                  "global_settings { assumed_gamma 1 ambient_light 0.3 adc_bailout 0.1\n"
                  "  max_trace_level 3 max_intersections 10 number_of_waves 3 noise_generator 1\n"
                  "  charset utf8 irid_wavelength 0.5 mm_per_unit 1 radiosity { count 50 }\n"
                  "  photons { count 1000 } subsurface { } }\n"
                  "camera { perspective location -5*z angle 60 }"),
              "no error");
}

TEST(RenderScene, LightAndSkyColoursDecodedFromTheAssumedGamma) {
    const SceneDescription d = parse_scene_text(
        "global_settings { assumed_gamma 2.2 }\n"
        "light_source { <0, 5, 0> rgb <0.5, 1, 2> }\n"
        "background { rgb <0.5, 0, 0> }\n"
        "sky_sphere { pigment { rgbt <1, 0.5, 0.25, 0.5> } }",
        "test.pov");
    const PovrayLights lights =
        read_povray_lights(d.lights, SceneUnits{}, ColourDecoding(d.global));
    ASSERT_EQ(lights.points.size(), 1u);
    EXPECT_DOUBLE_EQ(lights.points[0].intensity.red, std::pow(0.5, 2.2));
    EXPECT_DOUBLE_EQ(lights.points[0].intensity.green, 1);
    EXPECT_DOUBLE_EQ(lights.points[0].intensity.blue, std::pow(2, 2.2));
    // Half the sky's decoded colour over half the decoded background (transmit 0.5 is kept).
    const Rgb sky = Sky(d, 1.0).radiance({0, 1, 0});
    EXPECT_DOUBLE_EQ(sky.red, 0.5 + 0.5 * std::pow(0.5, 2.2));
    EXPECT_DOUBLE_EQ(sky.green, 0.5 * std::pow(0.5, 2.2));
    EXPECT_DOUBLE_EQ(sky.blue, 0.5 * std::pow(0.25, 2.2));
}

TEST(RenderScene, RefusesWhatItDoesNotRender) {
    auto refused = [](const std::string& feature, const std::string& at) {
        return "not supported: " + feature + " at test.pov:" + at;
    };
    EXPECT_EQ(render_error("sphere { 0, 1 }\n  ovus { 1, 0.5 }"), refused("ovus", "2:3"));
    EXPECT_EQ(render_error("blob { sphere { 0, 1, 1 }\n sphere { x, 1, 1 pigment { rgb 1 } } }"),
              refused("blob components with textures of their own (at test.pov:2:2)", "1:1"));
    // CSG, clipped_by and inverse render (RenderShapes); parts the solid cannot take do not.
    EXPECT_EQ(render_error("difference { box { -1, 1 }\n sphere { 0, 2 } cutaway_textures }"),
              refused("cutaway_textures", "1:1"));
    EXPECT_EQ(render_error("intersection { box { -1, 1 }\n triangle { 0, x, y } }"),
              refused("triangle in CSG, clipped_by or inverse", "2:2"));
    EXPECT_EQ(render_error("sphere { 0, 1 clipped_by {\n polygon { 4, 0, x, y, 0 } } }"),
              refused("polygon in CSG, clipped_by or inverse", "2:2"));
    // A parametric surface is no solid (POV-Ray's inside() refuses it): not in CSG or clips.
    const std::string parametric =
        "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> }";
    EXPECT_EQ(render_error("difference { box { -1, 1 }\n " + parametric + " }"),
              refused("parametric in CSG, clipped_by or inverse", "2:2"));
    EXPECT_EQ(render_error(parametric.substr(0, parametric.size() - 1) +
                           "clipped_by { sphere { 0, 1 } } }"),
              refused("parametric in CSG, clipped_by or inverse", "1:1"));
    EXPECT_EQ(render_error("union { sphere { 0, 1 } " + parametric + " }"), "no error");
    EXPECT_EQ(render_error("parametric { function { sqrt(u) } function { v } function { 0 } "
                           "<-1, 0>, <1, 1> }"),
              refused("parametric whose functions are not finite at <-1, 0>", "1:1"));
    EXPECT_EQ(render_error("sphere { 0, 1 double_illuminate }"),
              refused("double_illuminate", "1:1"));
    EXPECT_EQ(render_error("sphere { 0, 1 no_radiosity }"), refused("no_radiosity", "1:1"));
    EXPECT_EQ(render_error("sphere { 0, 1 uv_mapping }"), refused("uv_mapping", "1:1"));
    EXPECT_EQ(render_error("sphere { 0, 0 }"),
              refused("sphere of radius 0 (only positive radii)", "1:1"));
    EXPECT_EQ(render_error("light_group { box { 0, 1 } }"),
              refused("light_group (at test.pov:1:1)", "1:15"));
    EXPECT_EQ(render_error("#declare T = texture { pigment { rgb 1 } }\n"
                           "mesh { triangle { 0, x, y texture { T } } }"),
              refused("mesh triangle textures", "2:1"));
    EXPECT_EQ(render_error("mesh { smooth_triangle { 0, y, x, y, z, y } triangle { 0, x, -z } }"),
              refused("mesh mixing smooth and flat triangles", "1:1"));
    EXPECT_EQ(render_error("light_source { 0, 1 cylinder }"),
              refused("cylinder light_source", "1:1"));
    EXPECT_EQ(render_error("light_source { 0, 1 parallel point_at -y }"),
              refused("parallel light_source", "1:1"));
    EXPECT_EQ(render_error("light_source { 0, 1 projected_through { sphere { 0, 1 } } }"),
              refused("projected_through", "1:1"));
    EXPECT_EQ(render_error("light_group { light_source { 0, 1 } }"),
              refused("light_group (at test.pov:1:1)", "1:15"));
    // Photon and radiosity hints change nothing a path tracer computes; a looks_like object is
    // an object without shadow.
    EXPECT_EQ(
        render_error("sphere { 0, 1 photons { target } radiosity { importance 0.5 } hollow }"),
        "no error");
    EXPECT_EQ(render_error("light_source { 0, 1 looks_like { sphere { 0, 0.1 } } }"), "no error");
}

}  // namespace
}  // namespace rayset::tracer
