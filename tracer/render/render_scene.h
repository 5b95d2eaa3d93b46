// The scene as the renderer queries it: the SceneDescription's objects in Embree 3 (world
// triangles for triangles and boxes, instanced prototypes for meshes, user geometry for spheres,
// ellipsoids and planes), their materials and the unit conventions. The lights are the
// integrators' (light.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include <embree3/rtcore.h>

#include "core/bounds.h"
#include "tracer/render/fog.h"
#include "tracer/render/interior_media.h"
#include "tracer/render/material.h"
#include "tracer/render/rgb_upsampling.h"
#include "tracer/render/sky.h"
#include "tracer/render/units.h"

namespace rayset::tracer {

struct SurfaceHit {
    double t = 0;
    Vec3 point;
    Vec3 normal;          // unit geometric normal (outward for closed shapes)
    Vec3 shading_normal;  // unit; interpolated for meshes with normals, else `normal`
    int object = -1;      // index into SceneDescription::objects
    int part = -1;        // a solid's part (solids.h), for its material; -1 otherwise
};

// Which objects a ray ignores, after POV-Ray's object modifiers.
enum class RayKind {
    camera,    // skips no_image objects
    indirect,  // skips no_reflection objects
    shadow,    // skips no_shadow objects
};

struct GeometryTables;

// A ray as the renderer handed it to Embree (for the benchmark's bare replay).
struct RecordedRay {
    float origin[3], direction[3];
    float t_near, t_far;
    uint8_t skip;  // ObjectFlag bits the ray ignored
    bool shadow;   // an occlusion query
};

class RenderScene {
public:
    explicit RenderScene(const SceneDescription& scene);
    ~RenderScene();
    RenderScene(const RenderScene&) = delete;
    RenderScene& operator=(const RenderScene&) = delete;

    const SceneDescription& description() const { return description_; }
    // The material at a point of an object's surface, or of a part of a solid, where the
    // outward geometric normal is `normal` (ObjectMaterial::at).
    const Material& material(int object, int part, Vec3 point, Vec3 normal,
                             std::optional<Material>& scratch) const {
        return object_material(object, part).at(point, normal, scratch);
    }
    const Material& material(const SurfaceHit& hit, std::optional<Material>& scratch) const {
        return material(hit.object, hit.part, hit.point, hit.normal, scratch);
    }
    // Whether some point of the object emits light.
    bool emits(int object) const;
    // Whether some colour is made point by point: a patterned pigment, a sky_sphere or fog.
    bool has_varying_colours() const;
    const SceneUnits& units() const { return units_; }
    // What the scene asks for that is rendered as POV-Ray renders it rather than physically
    // (shadowless lights), one sentence each, for the tools to show.
    const std::vector<std::string>& notes() const { return notes_; }
    // What rays that leave the scene see (background, sky_sphere), renderer units.
    const Sky& sky() const { return sky_; }
    // What eye paths see through between their vertices (fog.h).
    const FogMedium& fog() const { return fog_; }
    // What fills the objects' insides (interior_media.h).
    const Interiors& interiors() const { return interiors_; }
    // Offset that moves a ray origin off the surface it starts on (scene units).
    double epsilon() const { return epsilon_; }
    // How far offset() moves `point`: epsilon plus the float rounding of Embree's hit points
    // there (relative to its largest coordinate).
    double offset_distance(Vec3 point) const {
        return epsilon_ +
               1e-6 * std::max({std::abs(point.x), std::abs(point.y), std::abs(point.z)});
    }
    // Whether nothing a ray can meet or pass through lies within `box`: no surface (tested
    // conservatively: false when unsure), no fog, no medium, no fade.
    bool clear_within(const Bounds3& box) const;

    // Nearest surface along (origin, unit direction) in (t_near, t_far) that this kind of ray sees.
    bool intersect(Vec3 origin, Vec3 direction, double t_near, double t_far, RayKind kind,
                   SurfaceHit& hit) const;
    // Distance to the nearest shadow-casting surface (t_far when none).
    double nearest_shadow_caster(Vec3 origin, Vec3 direction, double t_near, double t_far) const;
    bool occluded(Vec3 origin, Vec3 direction, double t_near, double t_far) const;
    // Where a ray (origin, unit direction) stops collecting light bodies, given the first
    // surface it sees (`found`, `hit`): that surface, or the first one behind it that casts
    // shadows (what light sampling's shadow rays test). Counts the extra ray in `rays`.
    double light_horizon(Vec3 origin, Vec3 direction, bool found, const SurfaceHit& hit,
                         uint64_t& rays) const {
        if (!found) return std::numeric_limits<double>::infinity();
        if (!no_shadow_[size_t(hit.object)]) return hit.t;
        ++rays;
        return nearest_shadow_caster(origin, direction, 0, std::numeric_limits<double>::infinity());
    }

    // Benchmark support: while `sink` is set, every query appends its ray to it (single
    // thread only); bare_embree_rays_per_second() replays such rays through rtcIntersect1 /
    // rtcOccluded1 alone on `threads` threads and returns the rate.
    void record_rays(std::vector<RecordedRay>* sink) { recorder_ = sink; }
    double bare_embree_rays_per_second(const std::vector<RecordedRay>& rays, int threads,
                                       int repeats) const;
    // Offsets a point off a surface along its normal, toward the side `direction` leaves to.
    Vec3 offset(Vec3 point, Vec3 normal, Vec3 direction) const;

private:
    SceneDescription description_;
    SceneUnits units_;
    const ObjectMaterial& object_material(int object, int part) const {
        if (part >= 0) {
            const std::vector<int>& own = part_material_[size_t(object)];
            if (size_t(part) < own.size() && own[size_t(part)] >= 0)
                return part_materials_[size_t(own[size_t(part)])];
        }
        return materials_[size_t(object)];
    }
    // The materials of solids' parts that have an appearance of their own.
    void add_part_materials(double emission_scale);
    void note_fake_caustics(const SceneDescription& scene);
    void note_media_attenuation(const SceneDescription& scene);

    std::vector<ObjectMaterial> materials_;
    std::vector<ObjectMaterial> part_materials_;
    std::vector<std::vector<int>> part_material_;  // by object, by part: index or -1
    std::vector<uint8_t> no_shadow_;  // per object: read on every hit, apart from the big objects
    Sky sky_;
    FogMedium fog_;
    Interiors interiors_;
    std::vector<std::string> notes_;
    double epsilon_ = 1e-6;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::unique_ptr<GeometryTables> tables_;
    std::vector<RecordedRay>* recorder_ = nullptr;
};

}  // namespace rayset::tracer
