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
// inside and trace cover the shapes shape_geometry.h covers (sphere_sweep of every spline kind
// among them; its header lists them) and CSG of those with transforms, inverse and clipped_by.
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/bounds.h"
#include "core/error.h"
#include "tracer/scene_language/object_grammar.h"
#include "tracer/scene_language/shape_geometry.h"
#include "tracer/scene_language/text_outline.h"

namespace rayset::tracer {
namespace {

constexpr double kUnbounded = 1e10;  // POV-Ray's coordinate for an unbounded side

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

Bounds3 transformed(const Bounds3& box, const Matrix4& m) {
    Bounds3 out;
    for (int i = 0; i < 8; ++i)
        out.add(m.point({i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
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
bool blob_box(const BlobShape& blob, Bounds3& box) {
    box = Bounds3{};
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
        box.add({c.x - r, c.y - r, c.z - r});
        box.add({c.x + r, c.y + r, c.z + r});
    }
    if (box.empty()) box = Bounds3{Vec3{}, Vec3{}};  // no positive component: a point
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

bool lathe_box(const LatheShape& lathe, Bounds3& box) {
    Vec2 lo, hi;
    if (!spline_box(lathe.spline, lathe.points, lo, hi)) return false;
    const double r = std::max(std::abs(lo.x), std::abs(hi.x));
    box = {{-r, lo.y, -r}, {r, hi.y, r}};
    return true;
}

// A conic prism's outline scales with the height, from height1 to height2.
bool prism_box(const PrismShape& prism, Bounds3& box) {
    Vec2 lo, hi;
    if (!spline_box(prism.spline, prism.points, lo, hi)) return false;
    const double y0 = std::min(prism.height1, prism.height2),
                 y1 = std::max(prism.height1, prism.height2);
    box = {{lo.x, y0, lo.y}, {hi.x, y1, hi.y}};
    if (prism.conic_sweep) {
        box.lo.x = box.lo.z = 1e300, box.hi.x = box.hi.z = -1e300;
        for (double h : {prism.height1, prism.height2})
            for (double x : {lo.x * h, hi.x * h})
                for (double z : {lo.y * h, hi.y * h}) box.add({x, y0, z});
    }
    return true;
}

// The shapes whose box is their own and moves with their transforms as a whole.
bool own_box(const Shape& shape, Bounds3& box) {
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
                  ? Bounds3{c.minimum, c.maximum}
                  : Bounds3{c.centre - Vec3{r, r, r}, c.centre + Vec3{r, r, r}};
    } else if (const auto* sweep = std::get_if<SphereSweepShape>(&shape)) {
        if (sweep->kind != SphereSweepShape::Kind::linear_spline) return false;
        box = Bounds3{};
        for (const auto& sphere : sweep->spheres) {
            const double r = std::abs(sphere.radius);
            box.add(sphere.centre - Vec3{r, r, r});
            box.add(sphere.centre + Vec3{r, r, r});
        }
    } else if (const auto* patch = std::get_if<BicubicPatchShape>(&shape)) {
        box = Bounds3{};
        for (const Vec3& p : patch->points) box.add(p);
    } else if (const auto* text = std::get_if<TextShape>(&shape)) {
        if (!text->outline) return false;
        const TextOutline& o = *text->outline;
        box = {{std::min(0.0, o.min_x), o.min_y, std::min(0.0, text->thickness)},
               {o.max_x, o.max_y, std::max(0.0, text->thickness)}};
    } else {
        return false;
    }
    return true;
}

// The box POV-Ray gives a shape in the coordinates `to_parent` maps from; false for the
// shapes not covered (and spheres, planes and meshes, handled apart).
bool exact_box(const Shape& shape, const Matrix4& to_parent, Bounds3& box) {
    Bounds3 own;
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
        box = Bounds3{};
        for (Vec3 p : {t->a, t->b, t->c}) box.add(to_parent.point(p));
    } else if (const auto* t = std::get_if<SmoothTriangleShape>(&shape)) {
        box = Bounds3{};
        for (Vec3 p : {t->a, t->b, t->c}) box.add(to_parent.point(p));
    } else {
        return false;
    }
    return true;
}

void set_box(ParseBounds& bounds, const Bounds3& box) {
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

Bounds3 box_of(const ParseBounds& bounds) { return {bounds.minimum, bounds.maximum}; }

void set_sphere_box(ParseBounds& bounds) {
    const double r = bounds.sphere_radius;
    const Vec3 c = bounds.sphere_centre;
    const Bounds3 own{{c.x - r, c.y - r, c.z - r}, {c.x + r, c.y + r, c.z + r}};
    set_box(bounds, bounds.sphere_transformed ? transformed(own, bounds.sphere_transform) : own);
}

// An intersection's box cut by a plane child whose normal (in the intersection's
// coordinates, turned over when the child counts inverted) lies along an axis.
void cut_by_plane(Bounds3& box, const ObjectNode& child, bool inverted) {
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

bool touches_unbounded(const Bounds3& box) {
    for (double v : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z})
        if (std::abs(v) >= kUnbounded) return true;
    return box.lo.x > box.hi.x || box.lo.y > box.hi.y || box.lo.z > box.hi.z;
}

void intersection_bounds(ObjectNode& node, bool difference) {
    Bounds3 box{{-kUnbounded, -kUnbounded, -kUnbounded}, {kUnbounded, kUnbounded, kUnbounded}};
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
std::optional<Bounds3> overlap_of(const std::vector<ObjectRef>& objects) {
    Bounds3 box{{-kUnbounded, -kUnbounded, -kUnbounded}, {kUnbounded, kUnbounded, kUnbounded}};
    for (const ObjectRef& object : objects) {
        if (!object->bounds.known) return std::nullopt;
        if (object->bounds.infinite) continue;
        const Bounds3 b = box_of(object->bounds);
        box.lo = {std::max(box.lo.x, b.lo.x), std::max(box.lo.y, b.lo.y),
                  std::max(box.lo.z, b.lo.z)};
        box.hi = {std::min(box.hi.x, b.hi.x), std::min(box.hi.y, b.hi.y),
                  std::min(box.hi.z, b.hi.z)};
    }
    return box;
}

double volume(const Bounds3& b) {
    return std::max(0.0, b.hi.x - b.lo.x) * std::max(0.0, b.hi.y - b.lo.y) *
           std::max(0.0, b.hi.z - b.lo.z);
}

}  // namespace

void compute_shape_bounds(ObjectNode& node) {
    ParseBounds& bounds = node.bounds;
    bounds = ParseBounds{};
    const Shape& shape = node.shape;
    Bounds3 box;
    if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
        bounds.sphere_centre = node.transform.point(sphere->centre);
        bounds.sphere_radius = std::abs(sphere->radius);
        set_sphere_box(bounds);
    } else if (std::holds_alternative<PlaneShape>(shape)) {
        set_unbounded(bounds);
    } else if (const auto* mesh = std::get_if<MeshShape>(&shape)) {
        box = Bounds3{};
        for (const Vec3& v : mesh->mesh->vertices) box.add(v);
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
    Bounds3 box;
    for (const ObjectRef& child : node.children) {
        if (!child->bounds.known) {
            node.bounds.known = false;
            return;
        }
        if (child->bounds.infinite) return set_unbounded(node.bounds);
        box.add(child->bounds.minimum);
        box.add(child->bounds.maximum);
    }
    if (node.children.empty())
        box = Bounds3{Vec3{}, Vec3{}};  // an empty union: POV-Ray's box is a point
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
    Bounds3 box;
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
        const std::optional<Bounds3> box = overlap_of(*objects);
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

// ---------------------------------------------------------------- inside and trace

namespace {

// The node, in the coordinates of its parent taken to the solid's frame by `parent_to_frame`,
// added to `tree` as `index`; false for lights and for transforms that cannot be inverted.
bool add_to_solid(const ObjectNode& node, const Matrix4& parent_to_frame, SolidTree& tree,
                  int& index) {
    if (node.kind == ObjectNode::Kind::light || node.kind == ObjectNode::Kind::light_group)
        return false;
    const Matrix4 to_frame = parent_to_frame * node.transform;
    Matrix4 to_local;
    if (!inverse_of(to_frame, to_local)) return false;
    if (node.kind == ObjectNode::Kind::shape) {
        index = tree.add_shape(node.shape, to_local, node.inverse);
    } else {
        index = tree.add_csg(std::get<CsgShape>(node.shape).operation, node.inverse);
        for (const ObjectRef& child : node.children) {
            int c = 0;
            if (!add_to_solid(*child, to_frame, tree, c)) return false;
            tree.add_child(index, c);
        }
    }
    for (const ObjectRef& clip : node.clipped_by) {
        int k = 0;
        if (!add_to_solid(*clip, parent_to_frame, tree, k)) return false;
        tree.add_clip(index, k);
    }
    return true;
}

}  // namespace

bool object_inside(const ObjectNode& object, Vec3 point, bool& inside) {
    SolidTree tree;
    int root = 0;
    return add_to_solid(object, Matrix4{}, tree, root) && tree.inside(point, inside);
}

bool object_trace(const ObjectNode& object, Vec3 origin, Vec3 direction, Vec3& hit, Vec3& normal,
                  bool& found) {
    found = false;
    const double len = length(direction);
    if (!(len > 0)) return true;
    const Vec3 d = (1 / len) * direction;
    std::vector<ShapeHit> hits;
    SolidTree tree;
    int root = 0;
    if (!add_to_solid(object, Matrix4{}, tree, root) || !tree.hits(origin, d, hits)) return false;
    constexpr double kMinimumDistance =
        1e-6;  // a hit closer than this to the origin is the origin's own surface
    const ShapeHit* nearest = nullptr;
    for (const ShapeHit& h : hits)
        if (h.t > kMinimumDistance && (!nearest || h.t < nearest->t)) nearest = &h;
    if (!nearest) return true;
    found = true;
    hit = origin + nearest->t * d;
    const double n = length(nearest->normal);
    normal = n > 0 ? (1 / n) * nearest->normal : nearest->normal;
    return true;
}

}  // namespace rayset::tracer
