// Parse-time geometry of objects, for the language's min_extent, max_extent, inside and trace.
//
// Bounding boxes follow POV-Ray 3.7 as its min_extent/max_extent report them (checked with
// povray on transformed shapes, unions, intersections, differences, clipped and bounded
// objects): a sphere, box, cylinder, cone, torus, disc, triangle, superellipsoid, isosurface
// (its container), bicubic_patch (its control points), blob of sphere components, linear
// sphere_sweep, and lathe or prism of linear or Bezier splines carries its own box through all
// its transforms at once (a cylinder, cone or disc in the frame that turns +z onto its axis
// by the shortest rotation); a mesh or a CSG transforms the box it has, one transform
// at a time, so boxes grow under rotations; a union's box holds its children's, an
// intersection's is the overlap of its non-inverted children's, cut by axis-aligned planes
// among them (a difference's children after the first count inverted), and is unbounded
// (+-1e10) when any side is; planes and lights are unbounded. At the end of an object's
// modifiers the box becomes its clipped_by objects' or its bounded_by objects' box when that
// is smaller in volume.
//
// inside and trace cover spheres, boxes, cylinders, cones, tori, planes, discs, triangles,
// meshes (inside with an inside_vector; trace of flat triangles), quadrics, polynomials and
// linear prisms (inside only), and CSG of those with transforms, inverse and clipped_by.
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.h"
#include "tracer/scene_language/object_grammar.h"

namespace rayset::tracer {
namespace {

constexpr double kUnbounded = 1e10;  // POV-Ray's coordinate for an unbounded side

struct Box {
    Vec3 lo, hi;
};

// The inverse of a node's transform; false when it is singular.
bool inverse_of(const Matrix4& m, Matrix4& inverse) {
    try {
        inverse = m.inverse();
    } catch (const Error&) {
        return false;
    }
    return true;
}

// A normal carried by the transform whose inverse is `inverse` (its inverse transpose).
Vec3 normal_through(const Matrix4& inverse, Vec3 n) {
    return {inverse(0, 0) * n.x + inverse(1, 0) * n.y + inverse(2, 0) * n.z,
            inverse(0, 1) * n.x + inverse(1, 1) * n.y + inverse(2, 1) * n.z,
            inverse(0, 2) * n.x + inverse(1, 2) * n.y + inverse(2, 2) * n.z};
}

Box empty_box() { return {{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}}; }

void add_point(Box& box, Vec3 p) {
    box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y), std::min(box.lo.z, p.z)};
    box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y), std::max(box.hi.z, p.z)};
}

Box transformed(const Box& box, const Matrix4& m) {
    Box out = empty_box();
    for (int i = 0; i < 8; ++i)
        add_point(out, m.point({i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                                i & 4 ? box.hi.z : box.lo.z}));
    return out;
}

// The rotation taking +z onto the unit vector `d` by the shortest way (about z x d); half a
// turn about x when d is -z.
Matrix4 z_onto(Vec3 d) {
    Matrix4 r;
    if (d.z < -1 + 1e-12) {
        r(1, 1) = r(2, 2) = -1;
        return r;
    }
    const double f = 1 / (1 + d.z);
    r(0, 0) = 1 - f * d.x * d.x, r(0, 1) = -f * d.x * d.y, r(0, 2) = d.x;
    r(1, 0) = -f * d.x * d.y, r(1, 1) = 1 - f * d.y * d.y, r(1, 2) = d.y;
    r(2, 0) = -d.x, r(2, 1) = -d.y, r(2, 2) = d.z;
    return r;
}

// The frame of a cylinder or cone: +z along base -> cap, scaled to `radius` across and to the
// length along.
Matrix4 axis_frame(Vec3 base, Vec3 cap, double radius) {
    const Vec3 axis = cap - base;
    const double len = length(axis);
    return translation(base) * z_onto((1 / len) * axis) * scaling({radius, radius, len});
}

// Whether a transform only turns, moves and scales evenly (its columns orthogonal, of one length).
bool is_similarity(const Matrix4& m) {
    const Vec3 c[3] = {m.vector({1, 0, 0}), m.vector({0, 1, 0}), m.vector({0, 0, 1})};
    const double scale = dot(c[0], c[0]), tolerance = 1e-12 * scale;
    return std::abs(dot(c[1], c[1]) - scale) <= tolerance &&
           std::abs(dot(c[2], c[2]) - scale) <= tolerance &&
           std::abs(dot(c[0], c[1])) <= tolerance && std::abs(dot(c[0], c[2])) <= tolerance &&
           std::abs(dot(c[1], c[2])) <= tolerance;
}

// A blob's box in its own coordinates: its positive sphere components' boxes (POV-Ray leaves
// out negative components and the threshold). A component moved only by a similarity keeps a
// tight box; otherwise POV-Ray widens its radius by the transform's largest row sum. False
// with a positive cylinder component, whose box is not computed here.
bool blob_box(const BlobShape& blob, Box& box) {
    box = empty_box();
    for (const BlobComponent& component : blob.components) {
        if (component.strength <= 0) continue;
        if (component.kind == BlobComponent::Kind::cylinder) return false;
        const Matrix4& m = component.transform;
        double scale = length(m.vector({1, 0, 0}));
        if (!is_similarity(m)) {
            scale = 0;
            for (int row = 0; row < 3; ++row)
                scale = std::max(scale,
                                 std::abs(m(row, 0)) + std::abs(m(row, 1)) + std::abs(m(row, 2)));
        }
        const Vec3 c = m.point(component.centre);
        const double r = std::abs(component.radius) * scale;
        add_point(box, {c.x - r, c.y - r, c.z - r});
        add_point(box, {c.x + r, c.y + r, c.z + r});
    }
    if (box.lo.x > box.hi.x) box = {};  // no positive component
    return true;
}

// Lathes and prisms of linear or Bezier splines: the box of their points (a Bezier curve lies
// in its points' hull, and POV-Ray takes that hull); the other splines' curves reach past
// their points in ways not computed here.
bool spline_box(SplineKind spline, const std::vector<Vec2>& points, Vec2& lo, Vec2& hi) {
    if (spline != SplineKind::linear && spline != SplineKind::bezier) return false;
    lo = {1e300, 1e300}, hi = {-1e300, -1e300};
    for (const Vec2& p : points) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    return true;
}

bool lathe_box(const LatheShape& lathe, Box& box) {
    Vec2 lo, hi;
    if (!spline_box(lathe.spline, lathe.points, lo, hi)) return false;
    const double r = std::max(std::abs(lo.x), std::abs(hi.x));
    box = {{-r, lo.y, -r}, {r, hi.y, r}};
    return true;
}

// A conic prism's outline scales with the height, from height1 to height2.
bool prism_box(const PrismShape& prism, Box& box) {
    Vec2 lo, hi;
    if (!spline_box(prism.spline, prism.points, lo, hi)) return false;
    const double y0 = std::min(prism.height1, prism.height2),
                 y1 = std::max(prism.height1, prism.height2);
    box = {{lo.x, y0, lo.y}, {hi.x, y1, hi.y}};
    if (prism.conic_sweep) {
        box.lo.x = box.lo.z = 1e300, box.hi.x = box.hi.z = -1e300;
        for (double h : {prism.height1, prism.height2})
            for (double x : {lo.x * h, hi.x * h})
                for (double z : {lo.y * h, hi.y * h}) add_point(box, {x, y0, z});
    }
    return true;
}

// The shapes whose box is their own and moves with their transforms as a whole.
bool own_box(const Shape& shape, Box& box) {
    if (const auto* blob = std::get_if<BlobShape>(&shape)) return blob_box(*blob, box);
    if (const auto* lathe = std::get_if<LatheShape>(&shape)) return lathe_box(*lathe, box);
    if (const auto* prism = std::get_if<PrismShape>(&shape)) return prism_box(*prism, box);
    if (std::holds_alternative<SuperellipsoidShape>(shape)) {
        constexpr double kMargin =
            1e-4;  // POV-Ray's box of a superellipsoid, 1.0001 wide of the origin
        box = {{-1 - kMargin, -1 - kMargin, -1 - kMargin}, {1 + kMargin, 1 + kMargin, 1 + kMargin}};
    } else if (const auto* iso = std::get_if<IsosurfaceShape>(&shape)) {
        const ContainedBy& c = iso->contained_by;
        const double r = std::abs(c.radius);
        box = c.kind == ContainedBy::Kind::box
                  ? Box{c.minimum, c.maximum}
                  : Box{c.centre - Vec3{r, r, r}, c.centre + Vec3{r, r, r}};
    } else if (const auto* sweep = std::get_if<SphereSweepShape>(&shape)) {
        if (sweep->kind != SphereSweepShape::Kind::linear_spline) return false;
        box = empty_box();
        for (const auto& sphere : sweep->spheres) {
            const double r = std::abs(sphere.radius);
            add_point(box, sphere.centre - Vec3{r, r, r});
            add_point(box, sphere.centre + Vec3{r, r, r});
        }
    } else if (const auto* patch = std::get_if<BicubicPatchShape>(&shape)) {
        box = empty_box();
        for (const Vec3& p : patch->points) add_point(box, p);
    } else {
        return false;
    }
    return true;
}

// The box POV-Ray gives a shape in the coordinates `to_parent` maps from; false for the
// shapes not covered (and spheres, planes and meshes, handled apart).
bool exact_box(const Shape& shape, const Matrix4& to_parent, Box& box) {
    Box own;
    if (own_box(shape, own)) {
        box = transformed(own, to_parent);
        return true;
    }
    if (const auto* b = std::get_if<BoxShape>(&shape)) {
        box = transformed({b->minimum, b->maximum}, to_parent);
    } else if (const auto* c = std::get_if<CylinderShape>(&shape)) {
        box = transformed({{-1, -1, 0}, {1, 1, 1}},
                          to_parent * axis_frame(c->base, c->cap, std::abs(c->radius)));
    } else if (const auto* c = std::get_if<ConeShape>(&shape)) {
        const double r = std::max(std::abs(c->base_radius), std::abs(c->cap_radius));
        box = transformed({{-1, -1, 0}, {1, 1, 1}}, to_parent * axis_frame(c->base, c->cap, r));
    } else if (const auto* t = std::get_if<TorusShape>(&shape)) {
        const double outer = std::abs(t->major_radius) + std::abs(t->minor_radius),
                     r = std::abs(t->minor_radius);
        box = transformed({{-outer, -r, -outer}, {outer, r, outer}}, to_parent);
    } else if (const auto* d = std::get_if<DiscShape>(&shape)) {
        // POV-Ray's disc box is 0.001 thick whatever its size.
        const double r = std::abs(d->radius);
        const Vec3 n = length(d->normal) > 0 ? d->normal : Vec3{0, 0, 1};
        box = transformed({{-r, -r, -1e-3}, {r, r, 1e-3}},
                          to_parent * translation(d->centre) * z_onto(n));
    } else if (const auto* t = std::get_if<TriangleShape>(&shape)) {
        box = empty_box();
        for (Vec3 p : {t->a, t->b, t->c}) add_point(box, to_parent.point(p));
    } else if (const auto* t = std::get_if<SmoothTriangleShape>(&shape)) {
        box = empty_box();
        for (Vec3 p : {t->a, t->b, t->c}) add_point(box, to_parent.point(p));
    } else {
        return false;
    }
    return true;
}

void set_box(ParseBounds& bounds, const Box& box) {
    bounds.known = true;
    bounds.infinite = false;
    bounds.minimum = box.lo;
    bounds.maximum = box.hi;
}

void set_unbounded(ParseBounds& bounds) {
    bounds.known = bounds.infinite = true;
    bounds.minimum = {-kUnbounded, -kUnbounded, -kUnbounded};
    bounds.maximum = {kUnbounded, kUnbounded, kUnbounded};
}

Box box_of(const ParseBounds& bounds) { return {bounds.minimum, bounds.maximum}; }

void set_sphere_box(ParseBounds& bounds) {
    const double r = bounds.sphere_radius;
    const Vec3 c = bounds.sphere_centre;
    const Box own{{c.x - r, c.y - r, c.z - r}, {c.x + r, c.y + r, c.z + r}};
    set_box(bounds, bounds.sphere_transformed ? transformed(own, bounds.sphere_transform) : own);
}

// An intersection's box cut by a plane child whose normal (in the intersection's
// coordinates, turned over when the child counts inverted) lies along an axis.
void cut_by_plane(Box& box, const ObjectNode& child, bool inverted) {
    const auto& plane = std::get<PlaneShape>(child.shape);
    Matrix4 inverse;
    if (!inverse_of(child.transform, inverse)) return;
    Vec3 n = normal_through(inverse, plane.normal);
    const double len = length(n);
    n = (1 / len) * n;
    double d = dot(n, child.transform.point(plane.distance * plane.normal));
    if (inverted) n = -n, d = -d;
    const double along[3] = {n.x, n.y, n.z};
    double* lo[3] = {&box.lo.x, &box.lo.y, &box.lo.z};
    double* hi[3] = {&box.hi.x, &box.hi.y, &box.hi.z};
    for (int axis = 0; axis < 3; ++axis) {
        const double rest = std::abs(along[(axis + 1) % 3]) + std::abs(along[(axis + 2) % 3]);
        if (rest > 1e-10) continue;
        // inside: n . p <= d
        if (along[axis] > 0)
            *hi[axis] = std::min(*hi[axis], d / along[axis]);
        else
            *lo[axis] = std::max(*lo[axis], d / along[axis]);
    }
}

bool touches_unbounded(const Box& box) {
    for (double v : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z})
        if (std::abs(v) >= kUnbounded) return true;
    return box.lo.x > box.hi.x || box.lo.y > box.hi.y || box.lo.z > box.hi.z;
}

void intersection_bounds(ObjectNode& node, bool difference) {
    Box box{{-kUnbounded, -kUnbounded, -kUnbounded}, {kUnbounded, kUnbounded, kUnbounded}};
    for (size_t i = 0; i < node.children.size(); ++i) {
        const ObjectNode& child = *node.children[i];
        const bool inverted = child.inverse != (difference && i > 0);
        if (child.kind == ObjectNode::Kind::shape &&
            std::holds_alternative<PlaneShape>(child.shape)) {
            cut_by_plane(box, child, inverted);
            continue;
        }
        if (inverted) continue;
        if (!child.bounds.known) {
            node.bounds.known = false;
            return;
        }
        if (child.bounds.infinite) continue;
        box.lo = {std::max(box.lo.x, child.bounds.minimum.x),
                  std::max(box.lo.y, child.bounds.minimum.y),
                  std::max(box.lo.z, child.bounds.minimum.z)};
        box.hi = {std::min(box.hi.x, child.bounds.maximum.x),
                  std::min(box.hi.y, child.bounds.maximum.y),
                  std::min(box.hi.z, child.bounds.maximum.z)};
    }
    if (touches_unbounded(box))
        set_unbounded(node.bounds);
    else
        set_box(node.bounds, box);
}

// The overlap of the boxes of `objects` (clipped_by, bounded_by), if all are known.
std::optional<Box> overlap_of(const std::vector<ObjectRef>& objects) {
    Box box{{-kUnbounded, -kUnbounded, -kUnbounded}, {kUnbounded, kUnbounded, kUnbounded}};
    for (const ObjectRef& object : objects) {
        if (!object->bounds.known) return std::nullopt;
        if (object->bounds.infinite) continue;
        const Box b = box_of(object->bounds);
        box.lo = {std::max(box.lo.x, b.lo.x), std::max(box.lo.y, b.lo.y),
                  std::max(box.lo.z, b.lo.z)};
        box.hi = {std::min(box.hi.x, b.hi.x), std::min(box.hi.y, b.hi.y),
                  std::min(box.hi.z, b.hi.z)};
    }
    return box;
}

double volume(const Box& b) {
    return std::max(0.0, b.hi.x - b.lo.x) * std::max(0.0, b.hi.y - b.lo.y) *
           std::max(0.0, b.hi.z - b.lo.z);
}

}  // namespace

void compute_shape_bounds(ObjectNode& node) {
    ParseBounds& bounds = node.bounds;
    bounds = ParseBounds{};
    const Shape& shape = node.shape;
    Box box;
    if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
        bounds.sphere_centre = node.transform.point(sphere->centre);
        bounds.sphere_radius = std::abs(sphere->radius);
        set_sphere_box(bounds);
    } else if (std::holds_alternative<PlaneShape>(shape)) {
        set_unbounded(bounds);
    } else if (const auto* mesh = std::get_if<MeshShape>(&shape)) {
        box = empty_box();
        for (const Vec3& v : mesh->mesh->vertices) add_point(box, v);
        set_box(bounds, transformed(box, node.transform));
    } else if (exact_box(shape, node.transform, box)) {
        set_box(bounds, box);
    }
}

void compute_csg_bounds(ObjectNode& node) {
    const CsgShape& csg = std::get<CsgShape>(node.shape);
    if (node.kind == ObjectNode::Kind::csg && csg.operation == CsgShape::Operation::intersection)
        return intersection_bounds(node, false);
    if (node.kind == ObjectNode::Kind::csg && csg.operation == CsgShape::Operation::difference)
        return intersection_bounds(node, true);
    Box box = empty_box();
    for (const ObjectRef& child : node.children) {
        if (!child->bounds.known) {
            node.bounds.known = false;
            return;
        }
        if (child->bounds.infinite) return set_unbounded(node.bounds);
        add_point(box, child->bounds.minimum);
        add_point(box, child->bounds.maximum);
    }
    if (node.children.empty()) box = {};  // an empty union: POV-Ray's box is then a point
    set_box(node.bounds, box);
}

void transform_bounds(ObjectNode& node, const Matrix4& step, bool similarity) {
    ParseBounds& bounds = node.bounds;
    if (!bounds.known || bounds.infinite) return;
    if (node.kind == ObjectNode::Kind::shape && std::holds_alternative<SphereShape>(node.shape)) {
        if (!bounds.sphere_transformed && similarity) {
            bounds.sphere_centre = step.point(bounds.sphere_centre);
            bounds.sphere_radius *= length(step.vector({1, 0, 0}));
        } else {
            bounds.sphere_transformed = true;
            bounds.sphere_transform = step * bounds.sphere_transform;
        }
        return set_sphere_box(bounds);
    }
    Box box;
    if (node.kind == ObjectNode::Kind::shape && exact_box(node.shape, node.transform, box))
        return set_box(bounds, box);
    set_box(bounds, transformed(box_of(bounds), step));
}

void apply_bounding_rules(ObjectNode& node) {
    if (node.clipped_by.empty() && node.bounded_by.empty()) return;
    ParseBounds& bounds = node.bounds;
    if (!bounds.known) return;
    double best = bounds.infinite ? HUGE_VAL : volume(box_of(bounds));
    for (const std::vector<ObjectRef>* objects : {&node.clipped_by, &node.bounded_by}) {
        if (objects->empty()) continue;
        const std::optional<Box> box = overlap_of(*objects);
        if (!box) {
            bounds.known = false;
            return;
        }
        if (touches_unbounded(*box)) continue;
        if (volume(*box) < best) {
            best = volume(*box);
            set_box(bounds, *box);
        }
    }
}

bool object_bounding_box(const ObjectNode& object, Vec3& minimum, Vec3& maximum) {
    if (!object.bounds.known) return false;
    minimum = object.bounds.minimum;
    maximum = object.bounds.maximum;
    return true;
}

// ---------------------------------------------------------------- inside

namespace {

// POV-Ray's term order of a polynomial (x^order first): see grammar_shapes.cpp.
double polynomial_value(const PolynomialShape& poly, Vec3 p) {
    double sum = 0;
    size_t term = 0;
    for (int i = poly.order; i >= 0; --i)
        for (int j = poly.order - i; j >= 0; --j)
            for (int k = poly.order - i - j; k >= 0; --k)
                sum += poly.coefficients[term++] * std::pow(p.x, i) * std::pow(p.y, j) *
                       std::pow(p.z, k);
    return sum;
}

struct Hit {
    double t;
    Vec3 normal;  // not normalised
};

void mesh_hits(const TriangleMesh& mesh, Vec3 o, Vec3 d, std::vector<Hit>& hits);

// Whether (x, z) is inside the closed outlines of a linear prism (each sub-outline closes
// where its first point repeats): an odd number of edge crossings, so that where an even
// number of outlines overlap there is a hole, as POV-Ray has it.
bool inside_outlines(const std::vector<Vec2>& points, double x, double z) {
    bool inside = false;
    size_t start = 0;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const Vec2 a = points[i], b = points[i + 1];
        if ((a.y > z) != (b.y > z) && x < a.x + (z - a.y) * (b.x - a.x) / (b.y - a.y))
            inside = !inside;
        if (b.x == points[start].x && b.y == points[start].y) start = i + 2, ++i;
    }
    return inside;
}

// A prism of linear spline between its heights; a conic one's outline scales with the height.
bool prism_inside(const PrismShape& prism, Vec3 p, bool& inside) {
    if (prism.spline != SplineKind::linear) return false;
    const double low = std::min(prism.height1, prism.height2);
    const double high = std::max(prism.height1, prism.height2);
    inside = p.y >= low && p.y <= high;
    if (!inside) return true;
    if (!prism.conic_sweep) {
        inside = inside_outlines(prism.points, p.x, p.z);
    } else {
        inside = p.y != 0 && inside_outlines(prism.points, p.x / p.y, p.z / p.y);
    }
    return true;
}

bool shape_inside(const Shape& shape, Vec3 p, bool& inside) {
    if (const auto* prism = std::get_if<PrismShape>(&shape)) return prism_inside(*prism, p, inside);
    if (const auto* s = std::get_if<SphereShape>(&shape)) {
        const Vec3 q = p - s->centre;
        inside = dot(q, q) < s->radius * s->radius;
    } else if (const auto* b = std::get_if<BoxShape>(&shape)) {
        inside = p.x >= b->minimum.x && p.x <= b->maximum.x && p.y >= b->minimum.y &&
                 p.y <= b->maximum.y && p.z >= b->minimum.z && p.z <= b->maximum.z;
    } else if (const auto* c = std::get_if<CylinderShape>(&shape)) {
        const Vec3 axis = c->cap - c->base, q = p - c->base;
        const double s = dot(q, axis) / dot(axis, axis);
        const Vec3 radial = q - s * axis;
        inside = s >= 0 && s <= 1 && dot(radial, radial) < c->radius * c->radius;
    } else if (const auto* c = std::get_if<ConeShape>(&shape)) {
        const Vec3 axis = c->cap - c->base, q = p - c->base;
        const double s = dot(q, axis) / dot(axis, axis);
        const double r = c->base_radius + s * (c->cap_radius - c->base_radius);
        const Vec3 radial = q - s * axis;
        inside = s >= 0 && s <= 1 && dot(radial, radial) < r * r;
    } else if (const auto* t = std::get_if<TorusShape>(&shape)) {
        const double ring = std::hypot(p.x, p.z) - t->major_radius;
        inside = ring * ring + p.y * p.y < t->minor_radius * t->minor_radius;
    } else if (const auto* plane = std::get_if<PlaneShape>(&shape)) {
        inside = dot(plane->normal, p) < plane->distance;
    } else if (const auto* disc = std::get_if<DiscShape>(&shape)) {
        inside =
            dot(disc->normal, p - disc->centre) < 0;  // its plane's inside, whatever the radius
    } else if (const auto* q = std::get_if<QuadricShape>(&shape)) {
        const double value = q->squares.x * p.x * p.x + q->squares.y * p.y * p.y +
                             q->squares.z * p.z * p.z + q->mixed.x * p.x * p.y +
                             q->mixed.y * p.x * p.z + q->mixed.z * p.y * p.z + dot(q->linear, p) +
                             q->constant;
        inside = value < 0;
    } else if (const auto* poly = std::get_if<PolynomialShape>(&shape)) {
        inside = polynomial_value(*poly, p) < 0;
    } else if (const auto* mesh = std::get_if<MeshShape>(&shape)) {
        // POV-Ray counts the crossings of a ray along inside_vector: odd is inside.
        if (!mesh->mesh->has_inside_vector) return false;
        std::vector<Hit> hits;
        mesh_hits(*mesh->mesh, p, mesh->mesh->inside_vector, hits);
        inside = hits.size() % 2 == 1;
    } else {
        return false;
    }
    return true;
}

// Whether `p` (in the coordinates of the node's parent) is inside the node; false when that
// cannot be answered here.
bool node_inside(const ObjectNode& node, Vec3 p, bool& inside) {
    Matrix4 to_local;
    if (!inverse_of(node.transform, to_local)) return false;
    const Vec3 local = to_local.point(p);
    if (node.kind == ObjectNode::Kind::light || node.kind == ObjectNode::Kind::light_group)
        return false;
    if (node.kind == ObjectNode::Kind::shape) {
        if (!shape_inside(node.shape, local, inside)) return false;
    } else {
        const auto operation = std::get<CsgShape>(node.shape).operation;
        const bool any =
            operation == CsgShape::Operation::union_of || operation == CsgShape::Operation::merge;
        inside = !any;
        for (size_t i = 0; i < node.children.size(); ++i) {
            bool in = false;
            if (!node_inside(*node.children[i], local, in)) return false;
            if (operation == CsgShape::Operation::difference && i > 0) in = !in;
            inside = any ? inside || in : inside && in;
        }
    }
    if (node.inverse) inside = !inside;
    for (const ObjectRef& clip : node.clipped_by) {
        bool in = false;
        if (!node_inside(*clip, p, in)) return false;
        inside = inside && in;
    }
    return true;
}

// ---------------------------------------------------------------- ray hits

// The real roots of c[0] + c[1] t + ... + c[n] t^n in [lo, hi]: each monotone piece between the
// roots of the derivative is bisected.
std::vector<double> roots_between(std::vector<double> c, double lo, double hi) {
    while (c.size() > 1 && c.back() == 0) c.pop_back();
    std::vector<double> roots;
    if (c.size() < 2) return roots;
    auto value = [&](double t) {
        double v = 0;
        for (size_t i = c.size(); i-- > 0;) v = v * t + c[i];
        return v;
    };
    std::vector<double> derivative;
    for (size_t i = 1; i < c.size(); ++i) derivative.push_back(double(i) * c[i]);
    std::vector<double> ends{lo};
    for (double t : roots_between(derivative, lo, hi)) ends.push_back(t);
    ends.push_back(hi);
    for (size_t k = 0; k + 1 < ends.size(); ++k) {
        double a = ends[k], b = ends[k + 1];
        double fa = value(a), fb = value(b);
        if (fa == 0) {
            if (roots.empty() || roots.back() != a) roots.push_back(a);
            continue;
        }
        if ((fa < 0) == (fb < 0)) continue;
        for (int iteration = 0; iteration < 200 && b - a > 1e-15 * std::max(1.0, std::abs(a));
             ++iteration) {
            const double m = 0.5 * (a + b), fm = value(m);
            if ((fm < 0) == (fa < 0))
                a = m, fa = fm;
            else
                b = m;
        }
        roots.push_back(0.5 * (a + b));
    }
    return roots;
}

// The roots of a t^2 + b t + c.
std::vector<double> quadratic_roots(double a, double b, double c) {
    if (a == 0) return b == 0 ? std::vector<double>{} : std::vector<double>{-c / b};
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return {};
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    std::vector<double> roots{q / a};
    if (q != 0) roots.push_back(c / q);
    std::sort(roots.begin(), roots.end());
    return roots;
}

// A triangle's hit by Moller-Trumbore; its normal is POV-Ray's, (c - a) x (b - a).
void triangle_hit(Vec3 a, Vec3 b, Vec3 c, Vec3 o, Vec3 d, std::vector<Hit>& hits) {
    const Vec3 e1 = b - a, e2 = c - a, pv = cross(d, e2);
    const double det = dot(e1, pv);
    if (det == 0) return;
    const Vec3 tv = o - a;
    const double u = dot(tv, pv) / det;
    if (u < 0 || u > 1) return;
    const Vec3 qv = cross(tv, e1);
    const double v = dot(d, qv) / det;
    if (v < 0 || u + v > 1) return;
    hits.push_back({dot(e2, qv) / det, cross(e2, e1)});
}

void mesh_hits(const TriangleMesh& mesh, Vec3 o, Vec3 d, std::vector<Hit>& hits) {
    std::vector<Hit> all;
    for (const auto& f : mesh.faces)
        triangle_hit(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]], o, d, all);
    for (const Hit& hit : all)
        if (hit.t > 0) hits.push_back(hit);
}

void plane_hit(Vec3 n, double distance, Vec3 o, Vec3 d, std::vector<Hit>& hits) {
    const double along = dot(n, d);
    if (along != 0) hits.push_back({(distance - dot(n, o)) / along, n});
}

void box_hits(const BoxShape& box, Vec3 o, Vec3 d, std::vector<Hit>& hits) {
    const double lo[3] = {box.minimum.x, box.minimum.y, box.minimum.z};
    const double hi[3] = {box.maximum.x, box.maximum.y, box.maximum.z};
    const double origin[3] = {o.x, o.y, o.z}, dir[3] = {d.x, d.y, d.z};
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0) continue;
        for (int side = 0; side < 2; ++side) {
            const double t = ((side ? hi : lo)[axis] - origin[axis]) / dir[axis];
            const Vec3 p = o + t * d;
            const double q[3] = {p.x, p.y, p.z};
            bool on_face = true;
            for (int other = 0; other < 3; ++other)
                if (other != axis && (q[other] < lo[other] || q[other] > hi[other]))
                    on_face = false;
            if (!on_face) continue;
            Vec3 n;
            (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = side ? 1 : -1;
            hits.push_back({t, n});
        }
    }
}

// A cylinder (equal radii) or cone about base -> cap, with its caps unless open.
void cone_hits(Vec3 base, Vec3 cap, double r0, double r1, bool open, Vec3 o, Vec3 d,
               std::vector<Hit>& hits) {
    const Vec3 axis = cap - base;
    const double len = length(axis);
    const Vec3 u = (1 / len) * axis;
    const double slope = (r1 - r0) / len;
    const Vec3 w = o - base;
    const double wu = dot(w, u), du = dot(d, u);
    const Vec3 wr = w - wu * u, dr = d - du * u;
    const double rw = r0 + slope * wu;
    for (double t : quadratic_roots(dot(dr, dr) - slope * slope * du * du,
                                    2 * (dot(wr, dr) - slope * rw * du), dot(wr, wr) - rw * rw)) {
        const double s = wu + t * du;
        if (s < 0 || s > len) continue;
        const Vec3 radial = wr + t * dr;
        const double rl = length(radial);
        if (rl == 0) continue;
        hits.push_back({t, (1 / rl) * radial - slope * u});
    }
    if (open || du == 0) return;
    for (int end = 0; end < 2; ++end) {
        const double t = ((end ? len : 0) - wu) / du, r = end ? r1 : r0;
        const Vec3 radial = wr + t * dr;
        if (dot(radial, radial) <= r * r) hits.push_back({t, end ? u : -u});
    }
}

void torus_hits(const TorusShape& torus, Vec3 o, Vec3 d, std::vector<Hit>& hits) {
    const double big = torus.major_radius * torus.major_radius,
                 small = torus.minor_radius * torus.minor_radius;
    const double outer = std::abs(torus.major_radius) + std::abs(torus.minor_radius);
    const std::vector<double> span =
        quadratic_roots(dot(d, d), 2 * dot(o, d), dot(o, o) - outer * outer);
    if (span.size() < 2) return;
    // (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) along p = o + t d.
    const double a = dot(d, d), b = 2 * dot(o, d), c = dot(o, o) + big - small;
    const double dxz = d.x * d.x + d.z * d.z, odxz = o.x * d.x + o.z * d.z,
                 oxz = o.x * o.x + o.z * o.z;
    const std::vector<double> coefficients{c * c - 4 * big * oxz, 2 * b * c - 8 * big * odxz,
                                           b * b + 2 * a * c - 4 * big * dxz, 2 * a * b, a * a};
    const double margin = 1e-9 * (span[1] - span[0]);
    for (double t : roots_between(coefficients, span[0] - margin, span[1] + margin)) {
        const Vec3 p = o + t * d;
        const double ring = std::hypot(p.x, p.z);
        const Vec3 centre =
            ring > 0 ? Vec3{torus.major_radius * p.x / ring, 0, torus.major_radius * p.z / ring}
                     : Vec3{};
        hits.push_back({t, p - centre});
    }
}

void disc_hit(const DiscShape& disc, Vec3 o, Vec3 d, std::vector<Hit>& hits) {
    const double along = dot(disc.normal, d);
    if (along == 0) return;
    const double t = dot(disc.normal, disc.centre - o) / along;
    const Vec3 q = o + t * d - disc.centre;
    const double r2 = dot(q, q);
    if (r2 <= disc.radius * disc.radius && r2 >= disc.hole_radius * disc.hole_radius)
        hits.push_back({t, disc.normal});
}

bool shape_hits(const Shape& shape, Vec3 o, Vec3 d, std::vector<Hit>& hits) {
    if (const auto* s = std::get_if<SphereShape>(&shape)) {
        const Vec3 w = o - s->centre;
        for (double t :
             quadratic_roots(dot(d, d), 2 * dot(w, d), dot(w, w) - s->radius * s->radius))
            hits.push_back({t, w + t * d});
    } else if (const auto* b = std::get_if<BoxShape>(&shape)) {
        box_hits(*b, o, d, hits);
    } else if (const auto* c = std::get_if<CylinderShape>(&shape)) {
        cone_hits(c->base, c->cap, c->radius, c->radius, c->open, o, d, hits);
    } else if (const auto* c = std::get_if<ConeShape>(&shape)) {
        cone_hits(c->base, c->cap, c->base_radius, c->cap_radius, c->open, o, d, hits);
    } else if (const auto* t = std::get_if<TorusShape>(&shape)) {
        torus_hits(*t, o, d, hits);
    } else if (const auto* plane = std::get_if<PlaneShape>(&shape)) {
        plane_hit(plane->normal, plane->distance, o, d, hits);
    } else if (const auto* disc = std::get_if<DiscShape>(&shape)) {
        disc_hit(*disc, o, d, hits);
    } else if (const auto* t = std::get_if<TriangleShape>(&shape)) {
        triangle_hit(t->a, t->b, t->c, o, d, hits);
    } else if (const auto* mesh = std::get_if<MeshShape>(&shape)) {
        if (!mesh->mesh->normals.empty()) return false;  // smooth triangles' normals: not here
        std::vector<Hit> all;
        for (const auto& f : mesh->mesh->faces)
            triangle_hit(mesh->mesh->vertices[f[0]], mesh->mesh->vertices[f[1]],
                         mesh->mesh->vertices[f[2]], o, d, all);
        hits.insert(hits.end(), all.begin(), all.end());
    } else {
        return false;
    }
    return true;
}

// Every hit of the ray o + t d (the node's parent's coordinates) with the node's surface as
// CSG keeps it, normals in the parent's coordinates; false when that cannot be answered here.
bool node_hits(const ObjectNode& node, Vec3 o, Vec3 d, std::vector<Hit>& hits) {
    Matrix4 to_local;
    if (!inverse_of(node.transform, to_local)) return false;
    const Vec3 lo = to_local.point(o), ld = to_local.vector(d);
    std::vector<Hit> local;
    if (node.kind == ObjectNode::Kind::light || node.kind == ObjectNode::Kind::light_group)
        return false;
    if (node.kind == ObjectNode::Kind::shape) {
        if (!shape_hits(node.shape, lo, ld, local)) return false;
    } else {
        const auto operation = std::get<CsgShape>(node.shape).operation;
        for (size_t i = 0; i < node.children.size(); ++i) {
            std::vector<Hit> child_hits;
            if (!node_hits(*node.children[i], lo, ld, child_hits)) return false;
            const bool subtracted = operation == CsgShape::Operation::difference && i > 0;
            for (Hit& hit : child_hits) {
                const Vec3 p = lo + hit.t * ld;
                bool keep = true;
                for (size_t j = 0; j < node.children.size() && keep; ++j) {
                    if (j == i) continue;
                    bool in = false;
                    if (!node_inside(*node.children[j], p, in)) return false;
                    switch (operation) {
                        case CsgShape::Operation::union_of: break;
                        case CsgShape::Operation::merge: keep = !in; break;
                        case CsgShape::Operation::intersection: keep = in; break;
                        case CsgShape::Operation::difference: keep = j == 0 ? in : !in; break;
                    }
                }
                if (!keep) continue;
                if (subtracted) hit.normal = -hit.normal;
                local.push_back(hit);
            }
        }
    }
    for (Hit& hit : local) {
        if (node.inverse) hit.normal = -hit.normal;
        hit.normal = normal_through(to_local, hit.normal);
        bool keep = true;
        for (const ObjectRef& clip : node.clipped_by) {
            bool in = false;
            if (!node_inside(*clip, o + hit.t * d, in)) return false;
            keep = keep && in;
        }
        if (keep) hits.push_back(hit);
    }
    return true;
}

}  // namespace

bool object_inside(const ObjectNode& object, Vec3 point, bool& inside) {
    return node_inside(object, point, inside);
}

bool object_trace(const ObjectNode& object, Vec3 origin, Vec3 direction, Vec3& hit, Vec3& normal,
                  bool& found) {
    found = false;
    const double len = length(direction);
    if (!(len > 0)) return true;
    const Vec3 d = (1 / len) * direction;
    std::vector<Hit> hits;
    if (!node_hits(object, origin, d, hits)) return false;
    constexpr double kMinimumDistance =
        1e-6;  // a hit closer than this to the origin is the origin's own surface
    const Hit* nearest = nullptr;
    for (const Hit& h : hits)
        if (h.t > kMinimumDistance && (!nearest || h.t < nearest->t)) nearest = &h;
    if (!nearest) return true;
    found = true;
    hit = origin + nearest->t * d;
    const double n = length(nearest->normal);
    normal = n > 0 ? (1 / n) * nearest->normal : nearest->normal;
    return true;
}

}  // namespace rayset::tracer
