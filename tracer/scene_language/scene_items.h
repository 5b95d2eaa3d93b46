// What a scene holds besides its objects: camera, lights, global settings, and our extensions
// (ray-file sources and illuminance receivers). Plain data; the grammar that fills it is
// grammar_scene.cpp (lights: grammar_objects.cpp, since a light is an object in POV-Ray).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "tracer/scene_language/appearance.h"
#include "tracer/scene_language/shapes.h"
#include "tracer/scene_language/source_location.h"

namespace rayset::tracer {

// A light_source in world coordinates. Its type is the last of spotlight, cylinder and
// shadowless written (each resets radius, falloff and tightness to its defaults); none of them:
// a point light. `parallel` goes with any type.
struct LightSource {
    Vec3 position;
    Rgb colour{1, 1, 1};
    bool spotlight = false;
    bool cylinder = false;  // cylindrical: the spot's cone becomes a cylinder about point_at
    Vec3 point_at{0, 0, 1};
    // Degrees, POV-Ray's spotlight defaults; a cylinder light's are 0.75, 1 and 0.
    double radius = 30, falloff = 45, tightness = 0;
    bool parallel = false;  // rays parallel to position -> point_at
    bool area_light = false;
    Vec3 axis1, axis2;          // full edge vectors of the area light
    int size1 = 1, size2 = 1;   // lights along each axis
    int adaptive = 0;
    bool jitter = false, circular = false, orient = false;
    bool area_illumination = false;  // area lights also light surfaces as areas, not as points
    double fade_distance = 0, fade_power = 0;  // 0: no fading
    bool shadowless = false;
    bool media_interaction = true;    // scattering media see it
    bool media_attenuation = false;   // fog and media dim its light
    // photons { }: whether it shoots photons that reflect, refract; per area-light point.
    bool photons_reflection = true, photons_refraction = true, photons_area_light = false;
    // projected_through { OBJECT }: only its light that passes through these reaches the scene
    // (world coordinates, textures stripped). Its looks_like object is in the scene's objects
    // (ObjectInstance::looks_like_of).
    std::vector<ObjectInstance> projected_through;
    std::shared_ptr<const LightGroup> light_group;  // null: a scene light; else lights its group only
    SourceLocation location;
};

// Perspective camera, resolved as POV-Ray 3.7 does (angle, then look_at, then transforms):
// the ray through image coordinates (s, t) in [0, 1]^2, s to the right and t downward, has the
// direction `direction + (s - 0.5) * right + (0.5 - t) * up` from `location`. The lengths of
// right and up set the aspect ratio and field of view; a right vector toward -x mirrors the
// image as in POV-Ray.
struct Camera {
    Vec3 location{0, 0, 0};
    Vec3 direction{0, 0, 1};
    Vec3 up{0, 1, 0};
    Vec3 right{1.33, 0, 0};
    Vec3 sky{0, 1, 0};
    double angle = 0;  // horizontal field of view in degrees when given, else 0
};

// Extension: an illuminance map on a parallelogram.
struct IlluminanceReceiver {
    std::string name;  // from `name "..."`, else "receiver<N>"
    Vec3 corner, edge1, edge2;  // world coordinates; cells run along edge1 (nx) and edge2 (ny)
    int nx = 1, ny = 1;
    SourceLocation location;
};

// Extension: a measured ray file placed in the scene.
struct RaySource {
    std::string path;         // absolute, canonical
    Matrix4 source_to_world;  // ray-file coordinates to scene coordinates
    SourceLocation location;
};

struct GlobalSettings {
    double assumed_gamma = 1.0;
    bool assumed_gamma_set = false;
    Rgb ambient_light{1, 1, 1};
    int max_trace_level = 5;
    // POV-Ray's radiosity block, recorded key by key (a path tracer computes indirect light
    // itself; the renderer decides what, if anything, to take from it).
    bool radiosity = false;
    std::map<std::string, std::vector<double>> radiosity_settings;
    // Our keys.
    std::string length_unit = "mm";  // mm, cm, m, in, ft
    double millimetres_per_unit = 1.0;
    std::string integrator = "path";  // "path" or "bidirectional"
    bool spectral = false;            // bidirectional: spectral transport (`spectral on`)
    int passes = 0;                   // 0: the renderer's default
    double time_limit = 0;            // seconds; 0: no limit
};

}  // namespace rayset::tracer
