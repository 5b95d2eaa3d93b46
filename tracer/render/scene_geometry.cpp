// SceneDescription objects -> Embree geometry: triangles and boxes as world-space triangles,
// meshes as instances of one prototype per mesh (every `object { M }` of a mesh shares it),
// spheres, planes, cylinders, cones, tori and discs as user geometry (user_geometry.cpp), a
// parametric as its own triangles, clipped by its container (parametric_mesh.h).
#include "tracer/render/scene_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include <fmt/format.h>

#include "core/bounds.h"
#include "core/error.h"
#include "tracer/render/mesh_loader.h"
#include "tracer/render/solids.h"
#include "tracer/scene_language/functions.h"

namespace rayset::tracer {

namespace {

// What the renderer does not render is refused, never dropped or approximated: the shapes
// other than sphere, box, plane, triangle, mesh, cylinder, cone, torus, disc, text of a TrueType
// font, quadric, polynomials, superellipsoid, isosurface, blob, linear prism, lathe, sor,
// polygon, julia_fractal, bicubic_patch, height_field, sphere_sweep and parametric (solids.h
// refuses what it cannot take into CSG, clipped_by, bounded_by or inverse), and the modifiers
// that change what is seen. Photon and radiosity hints (photons { }, radiosity { importance }),
// hierarchy, sturm and hollow have nothing to change in a path tracer, which computes all light
// transport; they pass.
// An isosurface whose function the language cannot evaluate (an internal function or a
// pattern it does not have) is refused before rendering, where one evaluation tells.
template <class Refuse>
void refuse_unevaluable(const IsosurfaceShape& iso, Refuse&& refuse) {
    if (!iso.function || iso.function->result_terms() != 1 || iso.function->parameter_count() > 3)
        refuse("isosurface of this function");
    const ContainedBy& c = iso.contained_by;
    const Vec3 p = c.kind == ContainedBy::Kind::sphere ? c.centre : 0.5 * (c.minimum + c.maximum);
    const double arguments[3] = {p.x, p.y, p.z};
    try {
        iso.function->evaluate_float(arguments);
    } catch (const FunctionNotSupported& e) {
        refuse(fmt::format("isosurface function ({})", e.what()));
    }
}

// A parametric's functions likewise, at the middle of its rectangle.
template <class Refuse>
void refuse_unevaluable(const ParametricShape& parametric, Refuse&& refuse) {
    for (const FunctionRef& f : parametric.functions)
        if (!f || f->result_terms() != 1 || f->parameter_count() > 3)
            refuse("parametric of this function");
    try {
        parametric_point(parametric, 0.5 * (parametric.uv_minimum.x + parametric.uv_maximum.x),
                         0.5 * (parametric.uv_minimum.y + parametric.uv_maximum.y));
    } catch (const FunctionNotSupported& e) {
        refuse(fmt::format("parametric function ({})", e.what()));
    }
}

// Height fields are rendered from an image's heights as read (HeightFieldShape::grid).
template <class Refuse>
void refuse_unrendered(const HeightFieldShape& field, Refuse&& refuse) {
    if (field.function) refuse("height_field of a function");
    if (!image_type_is_read(field.image_type))
        refuse(fmt::format("{} images (convert it to PNG, TGA or EXR)", field.image_type));
    if (field.image_gamma != 0 || field.image_srgb)
        refuse("height_field image 'gamma' (POV-Ray's heights then follow no rule found)");
    if (!field.grid)
        refuse(
            "height_field of a palette image (its indices are not read: save it as a grey "
            "image) or of a single row or column of pixels");
}

void refuse_unrendered(const ObjectInstance& o) {
    const std::string where = o.location.str();
    auto refuse = [&](const std::string& feature) {
        throw Error(fmt::format("not supported: {} at {}", feature, where));
    };
    const Shape& s = o.shape;
    const bool rendered_shape =
        std::holds_alternative<SphereShape>(s) || std::holds_alternative<BoxShape>(s) ||
        std::holds_alternative<PlaneShape>(s) || std::holds_alternative<TriangleShape>(s) ||
        std::holds_alternative<MeshShape>(s) || std::holds_alternative<MeshFileShape>(s) ||
        std::holds_alternative<CylinderShape>(s) || std::holds_alternative<ConeShape>(s) ||
        std::holds_alternative<TorusShape>(s) || std::holds_alternative<DiscShape>(s) ||
        (std::holds_alternative<TextShape>(s) && std::get<TextShape>(s).outline) ||
        std::holds_alternative<CsgShape>(s) || std::holds_alternative<PolynomialShape>(s) ||
        std::holds_alternative<QuadricShape>(s) || std::holds_alternative<SuperellipsoidShape>(s) ||
        std::holds_alternative<IsosurfaceShape>(s) || std::holds_alternative<BlobShape>(s) ||
        std::holds_alternative<PrismShape>(s) || std::holds_alternative<LatheShape>(s) ||
        std::holds_alternative<SorShape>(s) || std::holds_alternative<PolygonShape>(s) ||
        std::holds_alternative<JuliaFractalShape>(s) ||
        std::holds_alternative<BicubicPatchShape>(s) ||
        std::holds_alternative<HeightFieldShape>(s) ||
        std::holds_alternative<SphereSweepShape>(s) || std::holds_alternative<ParametricShape>(s);
    if (!rendered_shape) refuse(shape_keyword(s));
    if (const auto* julia = std::get_if<JuliaFractalShape>(&s);
        julia && !julia_default_slice(*julia))
        refuse("julia_fractal sliced other than by w = distance (slice <0, 0, 0, 1>)");
    if (const auto* field = std::get_if<HeightFieldShape>(&s)) refuse_unrendered(*field, refuse);
    if (const auto* prism = std::get_if<PrismShape>(&s);
        prism && prism->spline != SplineKind::linear)
        refuse("prism of a quadratic, cubic or bezier spline (only linear_spline)");
    if (const auto* blob = std::get_if<BlobShape>(&s))
        for (const BlobComponent& c : blob->components)
            if (c.appearance.texture || c.appearance.interior)
                refuse(fmt::format("blob components with textures of their own (at {})",
                                   c.location.str()));
    if (const auto* iso = std::get_if<IsosurfaceShape>(&s)) refuse_unevaluable(*iso, refuse);
    if (const auto* parametric = std::get_if<ParametricShape>(&s))
        refuse_unevaluable(*parametric, refuse);
    if (const auto* sphere = std::get_if<SphereShape>(&o.shape); sphere && !(sphere->radius > 0))
        refuse(fmt::format("sphere of radius {} (only positive radii)", sphere->radius));
    if (const auto* mesh = std::get_if<MeshShape>(&o.shape)) {
        if (!mesh->mesh->face_textures.empty()) refuse("mesh triangle textures");
        for (const auto& corners : mesh->mesh->normal_faces)
            if (corners[0] < 0) refuse("mesh mixing smooth and flat triangles");
    }
    if (o.double_illuminate) refuse("double_illuminate");
    if (o.no_radiosity) refuse("no_radiosity");
    if (o.uv_mapping) refuse("uv_mapping");
    if (o.light_group) refuse(fmt::format("light_group (at {})", o.light_group->location.str()));
}

uint8_t flags_of(const ObjectInstance& o) {
    return uint8_t((o.no_shadow ? kNoShadow : 0) | (o.no_image ? kNoImage : 0) |
                   (o.no_reflection ? kNoReflection : 0));
}

// Rejects candidate hits on objects the ray skips (installed only on geometry holding such
// objects).
void skip_filter(const RTCFilterFunctionNArguments* args) {
    const auto* context = reinterpret_cast<const TraceContext*>(args->context);
    if (!context->skip) return;
    const auto* leaf = static_cast<const LeafTable*>(args->geometryUserPtr);
    const GeometryTables& tables = *leaf->tables;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned instance = RTCHitN_instID(args->hit, args->N, i, 0);
        const int object = instance != RTC_INVALID_GEOMETRY_ID
                               ? tables.instances[tables.instance_of_geometry[instance]].object
                               : leaf->prim_object[RTCHitN_primID(args->hit, args->N, i)];
        if (tables.object_flags[object] & context->skip) args->valid[i] = 0;
    }
}

// Skips as skip_filter does, and rejects hits on a parametric's triangles outside its container
// (the hit distance is the ray's tfar while the filter runs).
void parametric_filter(const RTCFilterFunctionNArguments* args) {
    const auto* context = reinterpret_cast<const TraceContext*>(args->context);
    const auto* leaf = static_cast<const LeafTable*>(args->geometryUserPtr);
    const bool skipped = (leaf->tables->object_flags[leaf->parametric_object] & context->skip) != 0;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        if (skipped) {
            args->valid[i] = 0;
            continue;
        }
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        if (!leaf->parametric_mesh->straddles[prim]) continue;
        RTCRayN* ray = args->ray;
        const unsigned n = args->N;
        const double t = RTCRayN_tfar(ray, n, i);
        const Vec3 p{RTCRayN_org_x(ray, n, i) + t * RTCRayN_dir_x(ray, n, i),
                     RTCRayN_org_y(ray, n, i) + t * RTCRayN_dir_y(ray, n, i),
                     RTCRayN_org_z(ray, n, i) + t * RTCRayN_dir_z(ray, n, i)};
        if (!container_holds(leaf->parametric->contained_by, leaf->world_to_object.point(p)))
            args->valid[i] = 0;
    }
}

Vec3 unit_or_up(Vec3 v) {
    const double l = length(v);
    return l > 0 ? (1 / l) * v : Vec3{0, 1, 0};
}

// The shapes intersected through the scene language's shape geometry (user_geometry.cpp).
bool analytic(const Shape& s) {
    return std::holds_alternative<CylinderShape>(s) || std::holds_alternative<ConeShape>(s) ||
           std::holds_alternative<TorusShape>(s) || std::holds_alternative<DiscShape>(s) ||
           std::holds_alternative<TextShape>(s) || std::holds_alternative<SuperellipsoidShape>(s) ||
           std::holds_alternative<IsosurfaceShape>(s) || std::holds_alternative<BlobShape>(s) ||
           std::holds_alternative<PrismShape>(s) || std::holds_alternative<LatheShape>(s) ||
           std::holds_alternative<SorShape>(s) || std::holds_alternative<PolygonShape>(s) ||
           std::holds_alternative<JuliaFractalShape>(s) ||
           std::holds_alternative<HeightFieldShape>(s) ||
           std::holds_alternative<SphereSweepShape>(s);
}

struct TriangleSoup {
    std::vector<float> vertices;
    std::vector<unsigned> indices;
    void add(Vec3 a, Vec3 b, Vec3 c) {
        const unsigned base = unsigned(vertices.size() / 3);
        for (Vec3 p : {a, b, c})
            vertices.insert(vertices.end(), {float(p.x), float(p.y), float(p.z)});
        indices.insert(indices.end(), {base, base + 1, base + 2});
    }
};

RTCGeometry triangle_geometry(RTCDevice device, const TriangleSoup& soup, LeafTable* leaf,
                              bool filtered) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const size_t nv = soup.vertices.size() / 3, nt = soup.indices.size() / 3;
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
    auto* i = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
    std::copy(soup.vertices.begin(), soup.vertices.end(), v);
    std::copy(soup.indices.begin(), soup.indices.end(), i);
    rtcSetGeometryUserData(geometry, leaf);
    if (filtered) {
        rtcSetGeometryIntersectFilterFunction(geometry, skip_filter);
        rtcSetGeometryOccludedFilterFunction(geometry, skip_filter);
    }
    rtcCommitGeometry(geometry);
    return geometry;
}

class GeometryBuilder {
public:
    GeometryBuilder(RTCDevice device, RTCScene scene, const SceneDescription& d)
        : device_(device),
          scene_(scene),
          description_(d),
          tables_(std::make_unique<GeometryTables>()) {}

    std::unique_ptr<GeometryTables> build() {
        for (const ObjectInstance& o : description_.objects) refuse_unrendered(o);
        for (const ObjectInstance& o : description_.objects)
            tables_->object_flags.push_back(flags_of(o));
        LeafTable& plain = new_leaf();
        LeafTable& flagged = new_leaf();
        LeafTable& user = new_leaf();
        TriangleSoup plain_soup, flagged_soup;
        for (int k = 0; k < int(description_.objects.size()); ++k) {
            const ObjectInstance& o = description_.objects[k];
            const bool is_flagged = tables_->object_flags[k] != 0;
            add_object(k, o, is_flagged ? flagged : plain, is_flagged ? flagged_soup : plain_soup,
                       user);
        }
        const double extent = std::max({bounds_.hi.x - bounds_.lo.x, bounds_.hi.y - bounds_.lo.y,
                                        bounds_.hi.z - bounds_.lo.z, 0.0});
        tables_->extent = extent > 0 && std::isfinite(extent) ? extent : 1;
        attach_triangles(plain, plain_soup, false);
        attach_triangles(flagged, flagged_soup, true);
        if (!user.user_prims.empty()) {
            // Planes reach 10^5 times beyond everything placed in the scene.
            Bounds3 placed = bounds_;
            placed.add(description_.camera.location);
            for (const LightSource& l : description_.lights) placed.add(l.position);
            for (const IlluminanceReceiver& r : description_.receivers)
                placed.add(r.corner), placed.add(r.corner + r.edge1 + r.edge2);
            const double reach =
                std::max({std::abs(placed.lo.x), std::abs(placed.lo.y), std::abs(placed.lo.z),
                          std::abs(placed.hi.x), std::abs(placed.hi.y), std::abs(placed.hi.z)});
            user.plane_extent =
                float(1e5 * std::max(tables_->extent, std::isfinite(reach) ? reach : 1.0));
            add_user_geometry(device_, scene_, *tables_, user);
        }
        attach_instances();
        return std::move(tables_);
    }

private:
    LeafTable& new_leaf() {
        tables_->leaves.push_back(std::make_unique<LeafTable>());
        tables_->leaves.back()->tables = tables_.get();
        return *tables_->leaves.back();
    }

    void add_triangle(int object, const Matrix4& m, const Matrix4& inverse, Vec3 a, Vec3 b, Vec3 c,
                      LeafTable& leaf, TriangleSoup& soup) {
        const Vec3 n = cross(b - a, c - a);  // object space; transformed as a normal
        const Vec3 world_n{inverse(0, 0) * n.x + inverse(1, 0) * n.y + inverse(2, 0) * n.z,
                           inverse(0, 1) * n.x + inverse(1, 1) * n.y + inverse(2, 1) * n.z,
                           inverse(0, 2) * n.x + inverse(1, 2) * n.y + inverse(2, 2) * n.z};
        const Vec3 wa = m.point(a), wb = m.point(b), wc = m.point(c);
        for (Vec3 p : {wa, wb, wc}) bounds_.add(p);
        soup.add(wa, wb, wc);
        leaf.prim_object.push_back(object);
        leaf.prim_normal.push_back(unit_or_up(world_n));
    }

    void add_box(int object, const BoxShape& box, const Matrix4& m, const Matrix4& inverse,
                 LeafTable& leaf, TriangleSoup& soup) {
        const Vec3 lo = box.minimum, hi = box.maximum;
        auto corner = [&](int i) {
            return Vec3{i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
        };
        // Faces as corner indices, counter-clockwise seen from outside in a right-handed reading
        // of the numbers, so cross(b - a, c - a) points out of the box.
        static const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                        {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
        for (const auto& f : faces) {
            add_triangle(object, m, inverse, corner(f[0]), corner(f[1]), corner(f[2]), leaf, soup);
            add_triangle(object, m, inverse, corner(f[0]), corner(f[2]), corner(f[3]), leaf, soup);
        }
    }

    // POV-Ray draws a bicubic patch as 2^u_steps x 2^v_steps quads of points on the Bezier
    // surface, each two triangles split along the diagonal from (u, v) to (u + 1, v + 1) (its
    // renders agree on 98.9% of the pixels of tests/tracer/scenes/patches.pov, 94.2% with the
    // other diagonal): so here, flat-shaded.
    void add_bicubic_patch(int object, const BicubicPatchShape& patch, const Matrix4& m,
                           const Matrix4& inverse, LeafTable& leaf, TriangleSoup& soup) {
        const int nu = 1 << std::clamp(patch.u_steps, 0, 10);
        const int nv = 1 << std::clamp(patch.v_steps, 0, 10);
        auto bernstein = [](double t, int i) {
            const double s = 1 - t;
            return i == 0 ? s * s * s : i == 1 ? 3 * t * s * s : i == 2 ? 3 * t * t * s : t * t * t;
        };
        auto at = [&](int i, int j) {
            const double u = double(i) / nu, v = double(j) / nv;
            Vec3 p{};
            for (int row = 0; row < 4; ++row)
                for (int column = 0; column < 4; ++column)
                    p = p + (bernstein(v, row) * bernstein(u, column)) *
                                patch.points[size_t(4 * row + column)];
            return p;
        };
        for (int j = 0; j < nv; ++j)
            for (int i = 0; i < nu; ++i) {
                const Vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
                add_triangle(object, m, inverse, a, b, c, leaf, soup);
                add_triangle(object, m, inverse, a, c, d, leaf, soup);
            }
    }

    // A parametric's triangles in world coordinates, one geometry of its own whose filter
    // clips them by the container; geometric normals are the triangles' (wound along
    // cross(dP/du, dP/dv)), shading normals the surface's at the hit's (u, v).
    void add_parametric(int object, const ParametricShape& parametric, const std::string& where,
                        const Matrix4& m, const Matrix4& inverse) {
        auto mesh =
            std::make_shared<const ParametricMesh>(tessellate_parametric(parametric, where));
        if (mesh->triangles.empty()) return;
        LeafTable& leaf = new_leaf();
        leaf.parametric = &parametric;
        leaf.parametric_mesh = mesh;
        leaf.parametric_object = object;
        leaf.world_to_object = inverse;
        std::vector<Vec3> world(mesh->points.size());
        for (size_t i = 0; i < world.size(); ++i) world[i] = m.point(mesh->points[i]);
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertex = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), world.size()));
        auto* index = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), mesh->triangles.size()));
        for (size_t i = 0; i < world.size(); ++i) {
            vertex[3 * i] = float(world[i].x);
            vertex[3 * i + 1] = float(world[i].y);
            vertex[3 * i + 2] = float(world[i].z);
        }
        leaf.prim_normal.reserve(mesh->triangles.size());
        for (size_t k = 0; k < mesh->triangles.size(); ++k) {
            const auto& t = mesh->triangles[k];
            for (size_t c = 0; c < 3; ++c) {
                index[3 * k + c] = t[c];
                bounds_.add(world[t[c]]);
            }
            // Through the inverse transpose, which keeps its side under a mirroring transform.
            const Vec3 a = mesh->points[t[0]], b = mesh->points[t[1]], c = mesh->points[t[2]];
            leaf.prim_normal.push_back(unit_or_up(inverse.transpose_vector(cross(b - a, c - a))));
        }
        rtcSetGeometryUserData(geometry, &leaf);
        rtcSetGeometryIntersectFilterFunction(geometry, parametric_filter);
        rtcSetGeometryOccludedFilterFunction(geometry, parametric_filter);
        rtcCommitGeometry(geometry);
        record(rtcAttachGeometry(scene_, geometry), &leaf, -1);
        rtcReleaseGeometry(geometry);
    }

    void add_object(int k, const ObjectInstance& o, LeafTable& leaf, TriangleSoup& soup,
                    LeafTable& user) {
        const Matrix4& m = o.object_to_world;
        const Matrix4 inverse = m.inverse();
        Vec3 lower, upper;
        if (is_solid(o)) {
            add_solid(k, o, user);
        } else if (const auto* sphere = std::get_if<SphereShape>(&o.shape)) {
            UserPrim prim;
            prim.object = k;
            const Matrix4 unit_to_world = m * translation(sphere->centre) *
                                          scaling({sphere->radius, sphere->radius, sphere->radius});
            prim.world_to_local = unit_to_world.inverse();
            add_user_prim(prim, unit_to_world, {-1, -1, -1}, {1, 1, 1}, user);
        } else if (const auto* plane = std::get_if<PlaneShape>(&o.shape)) {
            UserPrim prim;
            prim.kind = UserPrim::Kind::plane;
            prim.object = k;
            prim.normal = normalized(m.normal(plane->normal));
            prim.distance = dot(prim.normal, m.point(plane->distance * plane->normal));
            user.user_prims.push_back(prim);
        } else if (analytic(o.shape) && local_box(o.shape, lower, upper)) {
            UserPrim prim;
            prim.kind = UserPrim::Kind::shape;
            prim.object = k;
            prim.shape = &o.shape;
            prim.world_to_local = inverse;
            add_user_prim(prim, m, lower, upper, user);
        } else if (const auto* triangle = std::get_if<TriangleShape>(&o.shape)) {
            add_triangle(k, m, inverse, triangle->a, triangle->b, triangle->c, leaf, soup);
        } else if (const auto* box = std::get_if<BoxShape>(&o.shape)) {
            add_box(k, *box, m, inverse, leaf, soup);
        } else if (const auto* patch = std::get_if<BicubicPatchShape>(&o.shape)) {
            add_bicubic_patch(k, *patch, m, inverse, leaf, soup);
        } else if (const auto* parametric = std::get_if<ParametricShape>(&o.shape)) {
            add_parametric(k, *parametric, o.location.str(), m, inverse);
        } else if (const auto* mesh = std::get_if<MeshShape>(&o.shape)) {
            add_instance(k, mesh->mesh, m, inverse);
        } else if (const auto* file = std::get_if<MeshFileShape>(&o.shape)) {
            auto& cached = loaded_[file->path];
            if (!cached) cached = load_mesh_file(*file, o.location.str());
            add_instance(k, cached, m, inverse);
        }
    }

    void add_solid(int object, const ObjectInstance& o, LeafTable& user) {
        Solid solid = solid_of(o);
        tables_->solid_parts.emplace_back(object, std::move(solid.parts));
        tables_->solids.push_back(std::make_unique<SolidTree>(std::move(solid.tree)));
        UserPrim prim;
        prim.kind = UserPrim::Kind::solid;
        prim.object = object;
        prim.solid = tables_->solids.back().get();
        if (solid.bound) {
            tables_->solids.push_back(std::make_unique<SolidTree>(std::move(*solid.bound)));
            prim.bound = tables_->solids.back().get();
        }
        prim.unbounded = !solid.bounded;
        if (solid.bounded) {
            prim.lower = solid.lower, prim.upper = solid.upper;
            bounds_.add(solid.lower), bounds_.add(solid.upper);
        }
        user.user_prims.push_back(prim);
    }

    // A bounded user primitive whose own coordinates hold it in the box lower..upper.
    void add_user_prim(UserPrim prim, const Matrix4& local_to_world, Vec3 lower, Vec3 upper,
                       LeafTable& user) {
        Bounds3 box;
        for (int i = 0; i < 8; ++i)
            box.add(local_to_world.point(
                {i & 1 ? upper.x : lower.x, i & 2 ? upper.y : lower.y, i & 4 ? upper.z : lower.z}));
        prim.lower = box.lo, prim.upper = box.hi;
        bounds_.add(box.lo), bounds_.add(box.hi);
        user.user_prims.push_back(prim);
    }

    void add_instance(int object, const std::shared_ptr<const TriangleMesh>& mesh, const Matrix4& m,
                      const Matrix4& inverse) {
        for (const Vec3& v : mesh->vertices) bounds_.add(m.point(v));
        pending_.push_back({object, m, inverse, mesh});
    }

    void attach_triangles(LeafTable& leaf, const TriangleSoup& soup, bool filtered) {
        if (soup.indices.empty()) return;
        RTCGeometry geometry = triangle_geometry(device_, soup, &leaf, filtered);
        record(rtcAttachGeometry(scene_, geometry), &leaf, -1);
        rtcReleaseGeometry(geometry);
    }

    // One prototype scene per distinct mesh; a skip filter only where an instance needs it.
    void attach_instances() {
        std::map<const TriangleMesh*, std::pair<RTCScene, const LeafTable*>> prototypes;
        std::map<const TriangleMesh*, bool> any_flagged;
        for (const Pending& p : pending_)
            any_flagged[p.mesh.get()] |= tables_->object_flags[p.object] != 0;
        for (const Pending& p : pending_) {
            auto& proto = prototypes[p.mesh.get()];
            if (!proto.first) proto = build_prototype(p.mesh, any_flagged[p.mesh.get()]);
            RTCGeometry instance = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(instance, proto.first);
            float xfm[12];
            for (int col = 0; col < 4; ++col)
                for (int row = 0; row < 3; ++row) xfm[3 * col + row] = float(p.m(row, col));
            rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
            rtcCommitGeometry(instance);
            tables_->instances.push_back({p.object, p.m, p.inverse, proto.second});
            record(rtcAttachGeometry(scene_, instance), nullptr,
                   int(tables_->instances.size()) - 1);
            rtcReleaseGeometry(instance);
        }
    }

    std::pair<RTCScene, const LeafTable*> build_prototype(
        const std::shared_ptr<const TriangleMesh>& mesh, bool filtered) {
        LeafTable& leaf = new_leaf();
        leaf.mesh = mesh;
        TriangleSoup soup;
        for (const auto& f : mesh->faces) {
            const Vec3 a = mesh->vertices[f[0]], b = mesh->vertices[f[1]], c = mesh->vertices[f[2]];
            soup.add(a, b, c);
            leaf.prim_normal.push_back(unit_or_up(cross(b - a, c - a)));
        }
        RTCScene prototype = rtcNewScene(device_);
        RTCGeometry geometry = triangle_geometry(device_, soup, &leaf, filtered);
        rtcAttachGeometry(prototype, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(prototype);
        tables_->prototypes.push_back(prototype);
        return {prototype, &leaf};
    }

    void record(unsigned geometry_id, const LeafTable* leaf, int instance) {
        if (tables_->leaf_of_geometry.size() <= geometry_id) {
            tables_->leaf_of_geometry.resize(geometry_id + 1, nullptr);
            tables_->instance_of_geometry.resize(geometry_id + 1, -1);
        }
        tables_->leaf_of_geometry[geometry_id] = leaf;
        tables_->instance_of_geometry[geometry_id] = instance;
    }

    struct Pending {
        int object;
        Matrix4 m, inverse;
        std::shared_ptr<const TriangleMesh> mesh;
    };

    RTCDevice device_;
    RTCScene scene_;
    const SceneDescription& description_;
    std::unique_ptr<GeometryTables> tables_;
    Bounds3 bounds_;
    std::vector<Pending> pending_;
    std::map<std::string, std::shared_ptr<const TriangleMesh>> loaded_;
};

}  // namespace

std::unique_ptr<GeometryTables> build_geometry(RTCDevice device, RTCScene scene,
                                               const SceneDescription& description) {
    return GeometryBuilder(device, scene, description).build();
}

void resolve_hit(const GeometryTables& tables, const RTCHit& h, SurfaceHit& hit) {
    hit.part = -1;
    const unsigned instance_id = h.instID[0];
    if (instance_id != RTC_INVALID_GEOMETRY_ID) {
        const InstanceRecord& instance = tables.instances[tables.instance_of_geometry[instance_id]];
        const LeafTable& leaf = *instance.prototype;
        hit.object = instance.object;
        hit.normal =
            unit_or_up(instance.world_to_object.transpose_vector(leaf.prim_normal[h.primID]));
        hit.shading_normal = hit.normal;
        const TriangleMesh& mesh = *leaf.mesh;
        if (!mesh.normals.empty()) {
            const auto& corners =
                mesh.normal_faces.empty() ? mesh.faces[h.primID] : mesh.normal_faces[h.primID];
            const Vec3 n = (1 - h.u - h.v) * mesh.normals[corners[0]] +
                           double(h.u) * mesh.normals[corners[1]] +
                           double(h.v) * mesh.normals[corners[2]];
            hit.shading_normal = unit_or_up(instance.world_to_object.transpose_vector(n));
        }
        return;
    }
    const LeafTable& leaf = *tables.leaf_of_geometry[h.geomID];
    if (leaf.parametric) {
        hit.object = leaf.parametric_object;
        hit.normal = hit.shading_normal = leaf.prim_normal[h.primID];
        const ParametricMesh& mesh = *leaf.parametric_mesh;
        const auto& corners = mesh.triangles[h.primID];
        const double u = h.u, v = h.v;
        const Vec2 a = mesh.uvs[corners[0]], b = mesh.uvs[corners[1]], c = mesh.uvs[corners[2]];
        const Vec3 n = leaf.world_to_object.transpose_vector(
            parametric_normal(*leaf.parametric, (1 - u - v) * a.x + u * b.x + v * c.x,
                              (1 - u - v) * a.y + u * b.y + v * c.y));
        const double l = length(n);
        // Where the surface is degenerate (a pole), the triangle's normal.
        if (l > 0 && std::isfinite(l)) hit.shading_normal = (1 / l) * n;
        return;
    }
    if (leaf.user_prims.empty()) {
        hit.object = leaf.prim_object[h.primID];
        hit.normal = hit.shading_normal = leaf.prim_normal[h.primID];
        return;
    }
    const UserPrim& prim = leaf.user_prims[h.primID];
    hit.object = prim.object;
    switch (prim.kind) {
        case UserPrim::Kind::plane:
            // Embree hands t back in float: at a distance t the point may miss the plane by
            // t x 6e-8, more than the offset of a scene whose only geometry is an infinite plane
            // (extent 1), and its shadow rays would then start behind the plane. Put the point
            // back on the plane.
            hit.point = hit.point - (dot(prim.normal, hit.point) - prim.distance) * prim.normal;
            hit.normal = prim.normal;
            break;
        case UserPrim::Kind::sphere:
            hit.normal = unit_or_up(
                prim.world_to_local.transpose_vector(prim.world_to_local.point(hit.point)));
            break;
        case UserPrim::Kind::shape: hit.normal = unit_or_up({h.Ng_x, h.Ng_y, h.Ng_z}); break;
        case UserPrim::Kind::solid:
            hit.normal = unit_or_up({h.Ng_x, h.Ng_y, h.Ng_z});
            hit.part = int(h.u);  // user_geometry.cpp keeps the part there
            break;
    }
    hit.shading_normal = hit.normal;
}

}  // namespace rayset::tracer
