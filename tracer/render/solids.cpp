#include "tracer/render/solids.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/scene_language/text_outline.h"

namespace rayset::tracer {

namespace {

struct Bounds {
    bool bounded = true;
    Vec3 lower{1e300, 1e300, 1e300}, upper{-1e300, -1e300, -1e300};
    void add(Vec3 p) {
        lower = {std::min(lower.x, p.x), std::min(lower.y, p.y), std::min(lower.z, p.z)};
        upper = {std::max(upper.x, p.x), std::max(upper.y, p.y), std::max(upper.z, p.z)};
    }
    static Bounds unbounded() {
        Bounds b;
        b.bounded = false;
        return b;
    }
    // The common part (unbounded on one side: the other).
    Bounds overlap(const Bounds& other) const {
        if (!bounded) return other;
        if (!other.bounded) return *this;
        Bounds b;
        b.lower = {std::max(lower.x, other.lower.x), std::max(lower.y, other.lower.y),
                   std::max(lower.z, other.lower.z)};
        b.upper = {std::min(upper.x, other.upper.x), std::min(upper.y, other.upper.y),
                   std::min(upper.z, other.upper.z)};
        return b;
    }
    Bounds hull(const Bounds& other) const {
        if (!bounded || !other.bounded) return unbounded();
        Bounds b = *this;
        b.add(other.lower), b.add(other.upper);
        return b;
    }
};

[[noreturn]] void refuse(const std::string& feature, const SourceLocation& where) {
    throw Error(fmt::format("not supported: {} at {}", feature, where.str()));
}

// A part's shape must be one the tree intersects and tells the inside of.
void check_covered(const ObjectInstance& part) {
    std::vector<ShapeHit> hits;
    bool in = false;
    if (!shape_hits(part.shape, {0, 0, 0}, {0, 0, 1}, hits) ||
        !shape_inside(part.shape, {0, 0, 0}, in))
        refuse(fmt::format("{} in CSG, clipped_by or inverse", shape_keyword(part.shape)),
               part.location);
}

class SolidBuilder {
public:
    // Adds `o` and what it holds; returns its node and sets its world bounds. The shapes of a
    // part of the whole (not of a clip or bound) are recorded as parts.
    int add(const ObjectInstance& o, Bounds& bounds, bool part_of_whole) {
        if (o.cutaway_textures) refuse("cutaway_textures", o.location);
        int index = 0;
        if (const auto* csg = std::get_if<CsgShape>(&o.shape)) {
            index = tree_.add_csg(csg->operation, o.inverse);
            bounds = csg_bounds(*csg, index, part_of_whole);
        } else {
            check_covered(o);
            index = tree_.add_shape(o.shape, o.object_to_world.inverse(), o.inverse);
            parts_.resize(size_t(index) + 1, nullptr);
            if (part_of_whole) parts_[size_t(index)] = &o;
            bounds = shape_bounds(o);
        }
        // An inverted solid reaches everywhere its original does not.
        if (o.inverse) bounds = Bounds::unbounded();
        for (const ObjectInstance& clip : o.clipped_by) {
            Bounds clip_bounds;
            tree_.add_clip(index, add(clip, clip_bounds, false));
            bounds = bounds.overlap(clip_bounds);
        }
        return index;
    }

    // The union of `parts` (bounding objects) as the root; returns its bounds.
    Bounds add_union(const std::vector<ObjectInstance>& parts) {
        const int root = tree_.add_csg(CsgShape::Operation::union_of, false);
        Bounds bounds;
        for (size_t i = 0; i < parts.size(); ++i) {
            Bounds part;
            tree_.add_child(root, add(parts[i], part, false));
            bounds = i == 0 ? part : bounds.hull(part);
        }
        return bounds;
    }

    SolidTree take() { return std::move(tree_); }
    std::vector<const ObjectInstance*> take_parts() { return std::move(parts_); }

private:
    Bounds csg_bounds(const CsgShape& csg, int index, bool part_of_whole) {
        Bounds bounds;
        for (size_t i = 0; i < csg.children.size(); ++i) {
            Bounds child;
            tree_.add_child(index, add(csg.children[i], child, part_of_whole));
            switch (csg.operation) {
                case CsgShape::Operation::union_of:
                case CsgShape::Operation::merge:
                    bounds = i == 0 ? child : bounds.hull(child);
                    break;
                case CsgShape::Operation::intersection:
                    bounds = i == 0 ? child : bounds.overlap(child);
                    break;
                case CsgShape::Operation::difference:
                    if (i == 0) bounds = child;
                    break;
            }
        }
        return bounds;
    }

    static Bounds shape_bounds(const ObjectInstance& o) {
        Vec3 lower, upper;
        if (!local_box(o.shape, lower, upper)) return Bounds::unbounded();
        Bounds bounds;
        for (int i = 0; i < 8; ++i)
            bounds.add(o.object_to_world.point(
                {i & 1 ? upper.x : lower.x, i & 2 ? upper.y : lower.y, i & 4 ? upper.z : lower.z}));
        return bounds;
    }

    SolidTree tree_;
    std::vector<const ObjectInstance*> parts_;
};

}  // namespace

bool is_solid(const ObjectInstance& object) {
    // Polynomial shapes are unbounded in general: one primitive with a plane's bounds.
    return std::holds_alternative<CsgShape>(object.shape) ||
           std::holds_alternative<PolynomialShape>(object.shape) ||
           std::holds_alternative<QuadricShape>(object.shape) || !object.clipped_by.empty() ||
           !object.bounded_by.empty() || object.inverse;
}

bool local_box(const Shape& shape, Vec3& lower, Vec3& upper) {
    Bounds b;
    auto around = [&](Vec3 a, Vec3 c, double r) {
        r = std::abs(r);
        b.add({std::min(a.x, c.x) - r, std::min(a.y, c.y) - r, std::min(a.z, c.z) - r});
        b.add({std::max(a.x, c.x) + r, std::max(a.y, c.y) + r, std::max(a.z, c.z) + r});
    };
    if (const auto* s = std::get_if<SphereShape>(&shape)) {
        around(s->centre, s->centre, s->radius);
    } else if (const auto* box = std::get_if<BoxShape>(&shape)) {
        b.add(box->minimum), b.add(box->maximum);
    } else if (const auto* c = std::get_if<CylinderShape>(&shape)) {
        around(c->base, c->cap, c->radius);
    } else if (const auto* c = std::get_if<ConeShape>(&shape)) {
        around(c->base, c->cap, std::max(std::abs(c->base_radius), std::abs(c->cap_radius)));
    } else if (const auto* d = std::get_if<DiscShape>(&shape)) {
        around(d->centre, d->centre, d->radius);
    } else if (const auto* t = std::get_if<TorusShape>(&shape)) {
        const double outer = std::abs(t->major_radius) + std::abs(t->minor_radius);
        const double r = std::abs(t->minor_radius);
        b.add({-outer, -r, -outer}), b.add({outer, r, outer});
    } else if (std::holds_alternative<SuperellipsoidShape>(shape)) {
        b.add({-1, -1, -1}), b.add({1, 1, 1});
    } else if (const auto* prism = std::get_if<PrismShape>(&shape)) {
        // A conic sweep's outline scales with the height: the hull of its outlines at both.
        for (const double h : {prism->height1, prism->height2}) {
            const double scale = prism->conic_sweep ? h : 1.0;
            for (const Vec2& p : prism->points) b.add({scale * p.x, h, scale * p.y});
        }
    } else if (const auto* lathe = std::get_if<LatheShape>(&shape)) {
        Vec3 lo, hi;
        lathe_bounds(*lathe, lo, hi);
        b.add(lo), b.add(hi);
    } else if (const auto* sor = std::get_if<SorShape>(&shape)) {
        Vec3 lo, hi;
        sor_bounds(*sor, lo, hi);
        b.add(lo), b.add(hi);
    } else if (const auto* sweep = std::get_if<SphereSweepShape>(&shape)) {
        Vec3 lo, hi;
        sphere_sweep_bounds(*sweep, lo, hi);
        b.add(lo), b.add(hi);
    } else if (std::holds_alternative<JuliaFractalShape>(shape)) {
        b.add({-2, -2, -2}), b.add({2, 2, 2});
    } else if (const auto* polygon = std::get_if<PolygonShape>(&shape)) {
        for (const Vec3& p : polygon->points) b.add(p);
    } else if (const auto* blob = std::get_if<BlobShape>(&shape)) {
        Vec3 lo, hi;
        if (!blob_bounds(*blob, lo, hi)) return false;
        b.add(lo), b.add(hi);
    } else if (std::holds_alternative<IsosurfaceShape>(shape) ||
               std::holds_alternative<ParametricShape>(shape)) {
        // Nothing outside the container is seen.
        const auto* iso = std::get_if<IsosurfaceShape>(&shape);
        const ContainedBy& c =
            iso ? iso->contained_by : std::get<ParametricShape>(shape).contained_by;
        if (c.kind == ContainedBy::Kind::sphere) {
            around(c.centre, c.centre, c.radius);
        } else {
            b.add(c.minimum), b.add(c.maximum);
        }
    } else if (const auto* t = std::get_if<TriangleShape>(&shape)) {
        b.add(t->a), b.add(t->b), b.add(t->c);
    } else if (const auto* m = std::get_if<MeshShape>(&shape)) {
        for (const Vec3& v : m->mesh->vertices) b.add(v);
    } else if (const auto* field = std::get_if<HeightFieldShape>(&shape)) {
        if (!field->grid) return false;
        double lowest = 0, highest = 0;
        height_field_range(*field->grid, lowest, highest);
        b.add({0, std::min(0.0, lowest), 0}), b.add({1, std::max(1.0, highest), 1});
    } else if (const auto* t = std::get_if<TextShape>(&shape)) {
        if (!t->outline) return false;
        b.add({t->outline->min_x, t->outline->min_y, std::min(0.0, t->thickness)});
        b.add({t->outline->max_x, t->outline->max_y, std::max(0.0, t->thickness)});
    } else {
        return false;
    }
    lower = b.lower, upper = b.upper;
    return true;
}

Solid solid_of(const ObjectInstance& object) {
    SolidBuilder builder;
    Bounds bounds;
    builder.add(object, bounds, true);
    Solid solid;
    solid.tree = builder.take();
    solid.parts = builder.take_parts();
    if (!object.bounded_by.empty() && !bounds.bounded) {
        SolidBuilder bound;
        bounds = bound.add_union(object.bounded_by);
        solid.bound = bound.take();
    }
    solid.bounded = bounds.bounded;
    // An empty overlap (nothing left of an intersection) is a point: found by no ray.
    solid.lower = bounds.lower;
    solid.upper = {std::max(bounds.lower.x, bounds.upper.x),
                   std::max(bounds.lower.y, bounds.upper.y),
                   std::max(bounds.lower.z, bounds.upper.z)};
    return solid;
}

}  // namespace rayset::tracer
