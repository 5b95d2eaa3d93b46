// The grid is a product of u and v breakpoints: a u interval is halved across the whole
// rectangle when any cell over it strays from its triangles along u (at its edges' middles),
// a v interval likewise, and both where only the centre or a triangle's centroid strays. Every
// cell is then two triangles split along the diagonal from (u, v) to (u + du, v + dv); the
// grid has no T-junctions, so no cracks. Cells whose box (grown by its diagonal) misses the
// container's box are neither refined nor drawn.
#include "tracer/render/parametric_mesh.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/bounds.h"
#include "core/error.h"
#include "tracer/scene_language/functions.h"

namespace rayset::tracer {

namespace {

constexpr int kInitialCells = 16;          // per side of the rectangle
constexpr int kSizeSamples = 64;           // per side, to measure the surface's size
constexpr size_t kMaxTriangles = 1 << 20;  // beyond this, refused

Bounds3 container_box(const ContainedBy& c) {
    Bounds3 b;
    if (c.kind == ContainedBy::Kind::sphere) {
        const double r = std::abs(c.radius);
        b.add(c.centre - Vec3{r, r, r}), b.add(c.centre + Vec3{r, r, r});
    } else {
        b.add(c.minimum), b.add(c.maximum);
    }
    return b;
}

bool finite(Vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

std::vector<double> evenly(double from, double to, int intervals) {
    std::vector<double> at(size_t(intervals) + 1);
    for (int i = 0; i <= intervals; ++i) at[size_t(i)] = from + (to - from) * i / intervals;
    at.back() = to;
    return at;
}

// The breakpoints with the marked intervals halved.
std::vector<double> halved(const std::vector<double>& at, const std::vector<char>& split) {
    std::vector<double> out;
    for (size_t i = 0; i + 1 < at.size(); ++i) {
        out.push_back(at[i]);
        if (split[i]) out.push_back(0.5 * (at[i] + at[i + 1]));
    }
    out.push_back(at.back());
    return out;
}

class Tessellator {
public:
    Tessellator(const ParametricShape& shape, const std::string& where)
        : shape_(shape), where_(where), container_(container_box(shape.contained_by)) {
        u0_ = std::min(shape.uv_minimum.x, shape.uv_maximum.x);
        u1_ = std::max(shape.uv_minimum.x, shape.uv_maximum.x);
        v0_ = std::min(shape.uv_minimum.y, shape.uv_maximum.y);
        v1_ = std::max(shape.uv_minimum.y, shape.uv_maximum.y);
    }

    ParametricMesh run() {
        ParametricMesh mesh;
        if (!(u1_ > u0_) || !(v1_ > v0_)) return mesh;  // no area: nothing to see
        tolerance_ = kParametricTolerance * size();
        mesh.tolerance = tolerance_;
        us_ = evenly(u0_, u1_, kInitialCells);
        vs_ = evenly(v0_, v1_, kInitialCells);
        for (;;) {
            evaluate_grid();
            std::vector<char> split_u(us_.size() - 1, 0), split_v(vs_.size() - 1, 0);
            bool any = false;
            for (size_t j = 0; j + 1 < vs_.size(); ++j)
                for (size_t i = 0; i + 1 < us_.size(); ++i)
                    if (near_container(i, j)) any |= check_cell(i, j, split_u[i], split_v[j]);
            if (!any) break;
            us_ = halved(us_, split_u);
            vs_ = halved(vs_, split_v);
            if (2 * (us_.size() - 1) * (vs_.size() - 1) > kMaxTriangles)
                refuse(fmt::format(
                    "parametric whose surface {} triangles do not follow within {} of its size "
                    "(a function with a jump?)",
                    kMaxTriangles, kParametricTolerance));
        }
        build(mesh);
        return mesh;
    }

private:
    [[noreturn]] void refuse(const std::string& what) const {
        throw Error(fmt::format("not supported: {} at {}", what, where_));
    }

    Vec3 at(double u, double v) const {
        const Vec3 p = parametric_point(shape_, u, v);
        if (!finite(p))
            refuse(fmt::format("parametric whose functions are not finite at <{}, {}>", u, v));
        return p;
    }

    // The largest side of the box around the surface's samples, cut to the container's box
    // (the container's box when the samples stay out of it).
    double size() const {
        const std::vector<double> us = evenly(u0_, u1_, kSizeSamples);
        const std::vector<double> vs = evenly(v0_, v1_, kSizeSamples);
        Bounds3 samples;
        for (double v : vs)
            for (double u : us) samples.add(at(u, v));
        const double cut = samples.overlap(container_).largest_side();
        const double size = samples.overlaps(container_) && cut > 0
                                ? cut
                                : std::min(container_.largest_side(), samples.largest_side());
        return size > 0 ? size : 1;
    }

    Vec3& point(size_t i, size_t j) { return grid_[j * us_.size() + i]; }

    void evaluate_grid() {
        grid_.resize(us_.size() * vs_.size());
        for (size_t j = 0; j < vs_.size(); ++j)
            for (size_t i = 0; i < us_.size(); ++i) point(i, j) = at(us_[i], vs_[j]);
    }

    Bounds3 cell_box(size_t i, size_t j) {
        Bounds3 b;
        for (Vec3 p : {point(i, j), point(i + 1, j), point(i, j + 1), point(i + 1, j + 1)})
            b.add(p);
        return b;
    }

    // Whether the cell may reach into the container: its corners' box grown by its diagonal.
    bool near_container(size_t i, size_t j) {
        const Bounds3 b = cell_box(i, j);
        return b.grown(length(b.hi - b.lo) + tolerance_).overlaps(container_);
    }

    bool strays(double u, double v, Vec3 on_triangle) const {
        return length(at(u, v) - on_triangle) > tolerance_;
    }

    // Marks the cell's intervals whose halving it needs; true if it needs any.
    bool check_cell(size_t i, size_t j, char& split_u, char& split_v) {
        const double ua = us_[i], ub = us_[i + 1], va = vs_[j], vb = vs_[j + 1];
        const double um = 0.5 * (ua + ub), vm = 0.5 * (va + vb);
        const Vec3 p00 = point(i, j), p10 = point(i + 1, j), p01 = point(i, j + 1),
                   p11 = point(i + 1, j + 1);
        bool along_u = strays(um, va, 0.5 * (p00 + p10)) || strays(um, vb, 0.5 * (p01 + p11));
        bool along_v = strays(ua, vm, 0.5 * (p00 + p01)) || strays(ub, vm, 0.5 * (p10 + p11));
        const double third = 1.0 / 3;
        const bool inside =
            strays(um, vm, 0.5 * (p00 + p11)) ||
            strays(ua + 2 * third * (ub - ua), va + third * (vb - va), third * (p00 + p10 + p11)) ||
            strays(ua + third * (ub - ua), va + 2 * third * (vb - va), third * (p00 + p11 + p01));
        if (inside && !along_u && !along_v) along_u = along_v = true;
        if (along_u) split_u = 1;
        if (along_v) split_v = 1;
        return along_u || along_v;
    }

    void build(ParametricMesh& mesh) {
        const size_t nu = us_.size();
        mesh.points = grid_;
        mesh.uvs.resize(grid_.size());
        for (size_t j = 0; j < vs_.size(); ++j)
            for (size_t i = 0; i < nu; ++i) mesh.uvs[j * nu + i] = {us_[i], vs_[j]};
        const ContainedBy& c = shape_.contained_by;
        auto add = [&](unsigned a, unsigned b, unsigned d) {
            Bounds3 box;
            for (unsigned k : {a, b, d}) box.add(grid_[k]);
            if (!box.grown(tolerance_).overlaps(container_)) return;
            mesh.triangles.push_back({a, b, d});
            mesh.straddles.push_back(!container_holds(c, grid_[a]) ||
                                     !container_holds(c, grid_[b]) ||
                                     !container_holds(c, grid_[d]));
        };
        for (size_t j = 0; j + 1 < vs_.size(); ++j)
            for (size_t i = 0; i + 1 < nu; ++i) {
                const auto k00 = unsigned(j * nu + i), k10 = k00 + 1, k01 = unsigned(k00 + nu),
                           k11 = k01 + 1;
                add(k00, k10, k11);
                add(k00, k11, k01);
            }
    }

    const ParametricShape& shape_;
    const std::string& where_;
    const Bounds3 container_;
    double u0_ = 0, u1_ = 0, v0_ = 0, v1_ = 0;
    double tolerance_ = 0;
    std::vector<double> us_, vs_;
    std::vector<Vec3> grid_;
};

}  // namespace

Vec3 parametric_point(const ParametricShape& shape, double u, double v) {
    const double arguments[3] = {u, v, 0};
    return {shape.functions[0]->evaluate_float(arguments),
            shape.functions[1]->evaluate_float(arguments),
            shape.functions[2]->evaluate_float(arguments)};
}

Vec3 parametric_normal(const ParametricShape& shape, double u, double v) {
    const double hu = 1e-6 * std::max(std::abs(shape.uv_maximum.x - shape.uv_minimum.x), 1e-3);
    const double hv = 1e-6 * std::max(std::abs(shape.uv_maximum.y - shape.uv_minimum.y), 1e-3);
    const Vec3 du = parametric_point(shape, u + hu, v) - parametric_point(shape, u - hu, v);
    const Vec3 dv = parametric_point(shape, u, v + hv) - parametric_point(shape, u, v - hv);
    return (1 / (4 * hu * hv)) * cross(du, dv);
}

bool container_holds(const ContainedBy& c, Vec3 p) {
    if (c.kind == ContainedBy::Kind::sphere) {
        const Vec3 q = p - c.centre;
        return dot(q, q) <= c.radius * c.radius;
    }
    return p.x >= c.minimum.x && p.x <= c.maximum.x && p.y >= c.minimum.y && p.y <= c.maximum.y &&
           p.z >= c.minimum.z && p.z <= c.maximum.z;
}

ParametricMesh tessellate_parametric(const ParametricShape& shape, const std::string& where) {
    return Tessellator(shape, where).run();
}

}  // namespace rayset::tracer
