// RenderScene: Embree device and scene, materials, and the three ray queries.
#include "tracer/render/render_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/render/camera.h"
#include "tracer/render/povray_lights.h"
#include "tracer/render/scene_geometry.h"

namespace rayset::tracer {

namespace {

uint8_t skip_flags(RayKind kind) {
    switch (kind) {
        case RayKind::camera: return kNoImage;
        case RayKind::indirect: return kNoReflection;
        case RayKind::shadow: return kNoShadow;
    }
    return 0;
}

RTCRayHit make_ray(Vec3 o, Vec3 d, double t_near, double t_far) {
    RTCRayHit rh;
    rh.ray.org_x = float(o.x), rh.ray.org_y = float(o.y), rh.ray.org_z = float(o.z);
    rh.ray.dir_x = float(d.x), rh.ray.dir_y = float(d.y), rh.ray.dir_z = float(d.z);
    rh.ray.tnear = float(t_near);
    rh.ray.tfar = t_far >= double(std::numeric_limits<float>::max())
                      ? std::numeric_limits<float>::infinity()
                      : float(t_far);
    rh.ray.time = 0;
    rh.ray.mask = ~0u;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

RecordedRay record_of(const RTCRay& ray, uint8_t skip, bool shadow) {
    return {{ray.org_x, ray.org_y, ray.org_z},
            {ray.dir_x, ray.dir_y, ray.dir_z},
            ray.tnear,
            ray.tfar,
            skip,
            shadow};
}

void check_device(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw Error(fmt::format("Embree failed while {} (error code {})", what, int(error)));
}

[[noreturn]] void refuse(const std::string& feature, const SourceLocation& where) {
    throw Error(fmt::format("not supported: {} at {}", feature, where.str()));
}

// The light features the renderer does not render (povray_lights.cpp refuses its own: shadowless
// area lights, fade powers other than 2). media_interaction,
// media_attenuation and photon flags matter only with media (both earn notes,
// note_media_attenuation) and photon mapping, which a path tracer does not use;
// area_illumination is what its area lights always do.
void refuse_unrendered(const LightSource& light) {
    if (light.cylinder) refuse("cylinder light_source", light.location);
    if (light.parallel) refuse("parallel light_source", light.location);
    if (!light.projected_through.empty()) refuse("projected_through", light.location);
    if (light.light_group)
        refuse(fmt::format("light_group (at {})", light.light_group->location.str()),
               light.location);
}

// What the renderer does not render is refused, never ignored (README.md, "Scene items"). The
// global settings left out here are hints of POV-Ray's own algorithms or affect only features
// refused elsewhere.
void refuse_what_is_not_rendered(const SceneDescription& scene) {
    check_camera_renderable(scene.camera);
    for (const LightSource& light : scene.lights) refuse_unrendered(light);
    const Atmosphere& atmosphere = scene.atmosphere;
    if (!atmosphere.rainbows.empty()) refuse("rainbow", atmosphere.rainbows.front().location);
}

SceneUnits units_of(const SceneDescription& scene) {
    SceneUnits units;
    units.metres_per_unit = scene.global.millimetres_per_unit / 1000;
    return units;
}

}  // namespace

// interior { caustics C } brightens the shadows of transparent objects with POV-Ray's fake
// caustics, a stand-in for the light they focus; the renderer renders that light as it goes
// (the bidirectional integrator finds its caustics), so the hint only earns a note.
void RenderScene::note_fake_caustics(const SceneDescription& scene) {
    for (const ObjectInstance& o : scene.objects) {
        const InteriorRef& interior = o.appearance.interior;
        if (!interior || interior->caustics == 0) continue;
        notes_.push_back(fmt::format(
            "interior caustics at {}: POV-Ray's fake caustics are not drawn; the light through "
            "the object is rendered as it goes (the bidirectional integrator renders caustics)",
            interior->location.str()));
        return;  // one note says it for every object
    }
}

// POV-Ray does not dim a light by the media on its way unless it says media_attenuation on
// (the default is off); the renderer always does, as light is dimmed. A light with
// media_interaction off is not scattered by media, as POV-Ray renders it (not physical).
void RenderScene::note_media_attenuation(const SceneDescription& scene) {
    if (!interiors_.any()) return;
    for (const LightSource& light : scene.lights) {
        if (light.media_attenuation) continue;
        notes_.push_back(fmt::format(
            "the light_source at {} is dimmed by the media its light crosses, as every light is "
            "here (POV-Ray dims only lights with media_attenuation on)",
            light.location.str()));
        break;  // one note says it for every light
    }
    if (!interiors_.participating()) return;
    for (const LightSource& light : scene.lights)
        if (!light.media_interaction)
            notes_.push_back(fmt::format(
                "the light_source at {} has media_interaction off: media do not scatter its "
                "light, as POV-Ray renders it (not physical)",
                light.location.str()));
}

RenderScene::RenderScene(const SceneDescription& scene)
    : description_(scene),
      units_(units_of(scene)),
      sky_(scene, 1 / units_.per_square_metre()),
      fog_(scene, 1 / units_.per_square_metre()),
      interiors_(scene, 1 / units_.per_square_metre()) {
    refuse_what_is_not_rendered(scene);
    const double to_internal = 1 / units_.per_square_metre();
    // Refuses, at load, what has no physical reading.
    const ColourDecoding decoding(scene.global);
    read_povray_lights(scene.lights, units_, decoding);
    for (const LightSource& light : scene.lights)
        if (light.shadowless)
            notes_.push_back(fmt::format(
                "the shadowless light_source at {} lights what it faces through every object, as "
                "POV-Ray renders it (not physical)",
                light.location.str()));
    for (const ObjectInstance& o : scene.objects) {
        materials_.emplace_back(o, to_internal, decoding);
        no_shadow_.push_back(o.no_shadow);
    }
    note_fake_caustics(scene);
    note_media_attenuation(scene);

    device_ = rtcNewDevice(nullptr);
    if (!device_) throw Error("cannot create the Embree device");
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    tables_ = build_geometry(device_, scene_, description_);
    rtcCommitScene(scene_);
    check_device(device_, "building the scene");
    epsilon_ = 1e-5 * tables_->extent;
    add_part_materials(to_internal);
}

void RenderScene::add_part_materials(double emission_scale) {
    const ColourDecoding decoding(description_.global);
    part_material_.resize(description_.objects.size());
    for (const auto& [object, parts] : tables_->solid_parts) {
        const ObjectAppearance& whole = description_.objects[size_t(object)].appearance;
        std::vector<int>& own = part_material_[size_t(object)];
        own.assign(parts.size(), -1);
        for (size_t node = 0; node < parts.size(); ++node) {
            const ObjectInstance* part = parts[node];
            if (!part || (part->appearance.texture == whole.texture &&
                          part->appearance.interior == whole.interior &&
                          part->appearance.interior_texture == whole.interior_texture))
                continue;
            own[node] = int(part_materials_.size());
            part_materials_.emplace_back(*part, emission_scale, decoding);
        }
    }
}

bool RenderScene::emits(int object) const {
    if (materials_[size_t(object)].emits()) return true;
    for (int index : part_material_[size_t(object)])
        if (index >= 0 && part_materials_[size_t(index)].emits()) return true;
    return false;
}

bool RenderScene::has_varying_colours() const {
    auto patterned = [](const ObjectMaterial& m) { return m.patterned(); };
    return !sky_.uniform() || fog_.present() ||
           std::any_of(materials_.begin(), materials_.end(), patterned) ||
           std::any_of(part_materials_.begin(), part_materials_.end(), patterned);
}

RenderScene::~RenderScene() {
    if (tables_)
        for (RTCScene prototype : tables_->prototypes) rtcReleaseScene(prototype);
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

bool RenderScene::clear_within(const Bounds3& box) const {
    return !fog_.present() && !interiors_.any() && !surfaces_may_reach(*tables_, scene_, box);
}

Vec3 RenderScene::offset(Vec3 point, Vec3 normal, Vec3 direction) const {
    const double e = offset_distance(point);
    return point + (dot(direction, normal) >= 0 ? e : -e) * normal;
}

bool RenderScene::intersect(Vec3 origin, Vec3 direction, double t_near, double t_far, RayKind kind,
                            SurfaceHit& hit) const {
    TraceContext context;
    rtcInitIntersectContext(&context.embree);
    context.skip = skip_flags(kind);
    RTCRayHit rh = make_ray(origin, direction, t_near, t_far);
    if (recorder_) recorder_->push_back(record_of(rh.ray, context.skip, false));
    rtcIntersect1(scene_, &context.embree, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit.t = rh.ray.tfar;
    hit.point = origin + hit.t * direction;
    resolve_hit(*tables_, rh.hit, hit);
    return true;
}

double RenderScene::nearest_shadow_caster(Vec3 origin, Vec3 direction, double t_near,
                                          double t_far) const {
    SurfaceHit hit;
    return intersect(origin, direction, t_near, t_far, RayKind::shadow, hit) ? hit.t : t_far;
}

bool RenderScene::occluded(Vec3 origin, Vec3 direction, double t_near, double t_far) const {
    TraceContext context;
    rtcInitIntersectContext(&context.embree);
    context.skip = kNoShadow;
    RTCRayHit rh = make_ray(origin, direction, t_near, t_far);
    if (recorder_) recorder_->push_back(record_of(rh.ray, context.skip, true));
    rtcOccluded1(scene_, &context.embree, &rh.ray);
    return rh.ray.tfar < 0;
}

}  // namespace rayset::tracer
