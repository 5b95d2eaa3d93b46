// What a scene holds besides its objects: camera, lights, atmosphere (background, fogs,
// rainbows, sky sphere, atmospheric media), global settings, and our extensions (ray-file
// sources and illuminance receivers). Plain data with POV-Ray's defaults; the grammar that
// fills it is grammar_scene.cpp (lights: grammar_objects.cpp, since a light is an object in
// POV-Ray).
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
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
    Vec3 axis1, axis2;         // full edge vectors of the area light
    int size1 = 1, size2 = 1;  // lights along each axis
    int adaptive = 0;
    bool jitter = false, circular = false, orient = false;
    bool area_illumination = false;  // area lights also light surfaces as areas, not as points
    double fade_distance = 0, fade_power = 0;  // 0: no fading
    bool shadowless = false;
    bool media_interaction = true;   // scattering media see it
    bool media_attenuation = false;  // fog and media dim its light
    // photons { }: whether it shoots photons that reflect, refract; per area-light point.
    bool photons_reflection = true, photons_refraction = true, photons_area_light = false;
    // projected_through { OBJECT }: only its light that passes through these reaches the scene
    // (world coordinates, textures stripped). Its looks_like object is in the scene's objects
    // (ObjectInstance::looks_like_of).
    std::vector<ObjectInstance> projected_through;
    std::shared_ptr<const LightGroup>
        light_group;  // null: a scene light; else lights its group only
    SourceLocation location;
};

enum class CameraProjection {
    perspective,
    orthographic,
    mesh,  // mesh_camera
    fisheye,
    ultra_wide_angle,
    omnimax,
    panoramic,
    cylinder,  // Camera::cylinder_type says which of the four
    spherical,
};

// POV-Ray's focal blur: on when the aperture is not 0.
struct FocalBlur {
    double aperture = 0;        // size of the lens; 0: no focal blur
    int min_samples = 0;        // blur_samples MIN, MAX; POV-Ray's minimum when not given:
    int max_samples = 0;        // 4 if MAX < 7, else 7
    Vec3 focal_point{0, 0, 0};  // a point of the plane in focus (world coordinates)
    double confidence = 0.9;    // adaptive sampling: probability that the estimate is close enough
    double variance = 1.0 / 128;  // adaptive sampling: tolerated variance of the samples
    PigmentRef bokeh;  // bokeh { pigment }: the lens shape over <0,0,0>..<1,1,0>; null: round
};

// mesh_camera { rays_per_pixel distribution [max_distance] mesh {...} ... [smooth] }: each pixel's
// rays start on mesh faces (see POV-Ray's manual, "Mesh projection").
struct MeshCamera {
    int rays_per_pixel = 1;
    int distribution = 0;           // 0..3: how pixels map to faces
    double max_distance = 0;        // longest ray; 0: unlimited
    std::vector<ObjectRef> meshes;  // mesh or mesh2 objects, with their transforms
    bool smooth = false;            // distribution 3: interpolate vertex normals
};

// The camera, resolved as POV-Ray 3.5+ does (type first; then angle, look_at, transforms).
// Perspective: the ray through image coordinates (s, t) in [0, 1]^2, s to the right and t
// downward, has the direction `direction + (s - 0.5) * right + (0.5 - t) * up` from `location`.
// The lengths of right and up set the aspect ratio and field of view; a right vector toward -x
// mirrors the image as in POV-Ray. Orthographic: parallel rays along `direction` from
// `location + (s - 0.5) * right + (0.5 - t) * up`; without up or right in the block, or with an
// angle, right and up are scaled to the area a perspective camera sees at the look_at point
// (POV-Ray's default look_at is the point <0,0,1>). The other projections use these vectors and
// `angle` as POV-Ray's manual describes each.
struct Camera {
    CameraProjection projection = CameraProjection::perspective;
    int cylinder_type = 0;  // cylinder: 1..4 (vertical/horizontal, fixed or moving viewpoint)
    Vec3 location{0, 0, 0};
    Vec3 direction{0, 0, 1};
    Vec3 up{0, 1, 0};
    Vec3 right{1.33, 0, 0};
    Vec3 sky{0, 1, 0};
    // Degrees. Perspective and orthographic: the horizontal field of view when given, else 0
    // (the field of view then follows from direction, right and up). The other projections: the
    // horizontal angle they cover, 90 unless given (spherical: 360).
    double angle = 0;
    double vertical_angle = 0;  // spherical: degrees, half the horizontal angle unless given
    FocalBlur focal_blur;
    NormalRef normal;          // normal { }: perturbs every camera ray; null: none
    Matrix4 transform;         // the camera's transforms, already applied to the vectors above
    MeshCamera mesh;           // projection == mesh
    SourceLocation statement;  // the camera keyword (of the declaration, for a declared camera)
    SourceLocation projection_location;  // the projection keyword; empty for the default
    SourceLocation focal_blur_location;  // the aperture keyword
    SourceLocation normal_location;      // the normal keyword
};

// The most pixels of an image, or cells of a receiver, along one side.
constexpr int kMaxImageSide = 65536;

// Extension: an illuminance map on a parallelogram.
struct IlluminanceReceiver {
    std::string name;           // from `name "..."`, else "receiver<N>"
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

// global_settings { radiosity { } }: POV-Ray's radiosity, on when the block is present.
struct RadiositySettings {
    double adc_bailout = 0.01;      // radiosity rays' adaptive depth control
    bool always_sample = false;     // gather new samples in the final pass too
    double brightness = 1.0;        // factor on the gathered light
    int count = 35;                 // rays per new sample
    int direction_pool = 0;         // count's second value: directions drawn from; 0: count
    double error_bound = 1.8;       // tolerated error before a new sample
    double gray_threshold = 0.0;    // 0..1: how far gathered light is greyed
    double low_error_factor = 0.5;  // error_bound's factor in the pretrace
    double max_sample = -1;         // brightest sample kept; non-positive: no limit
    double maximum_reuse = 0.2;     // fractions of the distance from the eye bounding sample reuse
    double minimum_reuse = 0.015;
    int nearest_count = 5;             // 1..20: samples blended into one value
    int adaptive_nearest_count = 0;    // nearest_count's second value (adaptive pretrace); 0: none
    bool normal = false;               // honour normal perturbation
    bool media = false;                // honour media
    bool subsurface = false;           // honour subsurface light transport
    double pretrace_start = 0.08;      // (0, 1]: mosaic block sizes of the pretrace, fractions of
    double pretrace_end = 0.04;        // the image
    int recursion_limit = 2;           // 1..20: diffuse bounces
    std::string save_file, load_file;  // radiosity data files as written; empty: none
};

// global_settings { photons { } }: POV-Ray's photon mapping, on when the block is present.
struct PhotonSettings {
    double spacing = 0;  // average distance between surface photons; 0: not given
    int count = 0;       // photons to shoot; 0: not given (spacing decides)
    int gather_min = 20, gather_max = 100;  // photons gathered at each point
    int media_max_steps = 0;                // media photons deposited per ray interval; 0: none
    double media_factor = 1;                // media photon spacing relative to surface spacing
    double jitter = 0.4;                    // jitter of the photon directions
    std::optional<int> max_trace_level;     // unset: the global max_trace_level
    std::optional<double> adc_bailout;      // unset: the global adc_bailout
    std::string save_file, load_file;       // photon map files as written; empty: none
    std::optional<double> autostop;  // 0..1 of the target's bounding box; unset: POV-Ray's own
    double expand_increase = 0.2;    // expand_thresholds: density increase that discards an
    int expand_min = 40;             // expanded search, unless it found fewer photons than this
    double radius = 0;               // gather radius for surface photons; 0: POV-Ray's estimate
    double radius_multiplier = 1;
    double media_radius = 0;  // the same for media photons
    double media_radius_multiplier = 1;
};

// global_settings { subsurface { } }: subsurface light transport, on when the block is present.
struct SubsurfaceSettings {
    int diffuse_samples = 50;  // samples { diffuse, single }
    int single_samples = 50;
    bool radiosity = false;  // apply to radiosity's diffuse light too
};

enum class Charset { ascii, utf8, sys };

// The integrators a scene may name (global_settings { integrator "..." }), the default first.
// The renderer has one of each name (tracer/render/integrator.cpp).
inline constexpr std::array<std::string_view, 3> kIntegratorNames = {"path", "bidirectional",
                                                                     "vcm"};
// The names for a message: "path", "bidirectional" or "vcm".
inline std::string integrator_names_text() {
    std::string text;
    for (size_t i = 0; i < kIntegratorNames.size(); ++i) {
        if (i > 0) text += i + 1 < kIntegratorNames.size() ? ", " : " or ";
        text += '"';
        text += kIntegratorNames[i];
        text += '"';
    }
    return text;
}

struct GlobalSettings {
    double adc_bailout = 1.0 / 255;   // adaptive depth control: smallest ray contribution traced
    Rgb ambient_light{1, 1, 1};       // factor on every finish's ambient
    double assumed_gamma = 1.0;       // the gamma colour literals are encoded with
    bool assumed_gamma_srgb = false;  // `assumed_gamma srgb`: the sRGB curve instead
    bool assumed_gamma_set = false;
    SourceLocation assumed_gamma_location;  // the last assumed_gamma keyword
    Charset charset = Charset::ascii;       // of strings (text objects)
    Rgb irid_wavelength{0.25, 0.18, 0.14};  // iridescence: relative wavelengths of r, g, b
    int max_intersections = 64;             // POV-Ray's intersection stack size
    int max_trace_level = 5;                // recursion limit of reflected and refracted rays
    double mm_per_unit = 10;   // subsurface light transport's scale (POV-Ray's; not ours)
    int number_of_waves = 10;  // waves and ripples patterns
    int noise_generator = 2;   // 1..3: the noise function of patterns
    std::optional<RadiositySettings> radiosity;
    std::optional<PhotonSettings> photons;
    std::optional<SubsurfaceSettings> subsurface;
    // Our keys.
    std::string length_unit = "mm";  // mm, cm, m, in, ft
    double millimetres_per_unit = 1.0;
    std::string integrator{kIntegratorNames[0]};  // one of kIntegratorNames
    bool spectral = false;  // bidirectional: spectral transport (`spectral on`)
    int passes = 0;         // 0: the renderer's default
    double time_limit = 0;  // seconds; 0: no limit
};

// fog { }: a colour blended in with the distance a ray travels.
struct Fog {
    int fog_type = 1;          // 1: constant density; 2: ground fog, thinning above fog_offset
    double distance = 0;       // distance at which 63% of the fog colour is reached; <= 0: no fog
    Colour colour;             // filter and transmit: how much light always passes
    Vec3 turbulence{0, 0, 0};  // turbulence and its parameters (as a pattern's)
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
    double turb_depth = 0.5;  // turbulence scale along the ray
    double fog_offset = 0;    // ground fog: height below which the density is 1
    double fog_alt = 0;       // ground fog: at fog_offset + fog_alt the density is 25%
    Vec3 up{0, 1, 0};         // unit vector heights are measured along (transforms rotate it)
    Matrix4 transform;        // the fog's transforms, for the turbulence
    SourceLocation location;  // the fog keyword
};

// rainbow { }: a fog-like arc at an angle around a direction.
struct Rainbow {
    Vec3 direction{0, 0, 0};     // toward the (virtual) light; required
    double angle = 0;            // degrees: centre of the bow around -direction
    double width = 0;            // degrees
    double distance = 0;         // fog distance of the bow; 0: not given (POV-Ray's large default)
    double jitter = 0;           // noise on the colour map index
    Vec3 up{0, 1, 0};            // where the arc's zero angle is
    double arc_angle = 180;      // degrees, 0..360: size of the arc
    double falloff_angle = 180;  // degrees, 0..arc_angle: where the arc starts to fade
    ColourMapRef colour_map;     // index 0 at the inner edge, 1 at the outer; null when not given
    SourceLocation location;     // the rainbow keyword
};

// sky_sphere { }: pigments evaluated on the direction of rays that leave the scene.
struct SkySphere {
    std::vector<PigmentRef> pigments;  // layers, first at the bottom
    Rgb emission{1, 1, 1};             // brightness factor
    Matrix4 transform;                 // applied to the whole sky, wherever it is written
    SourceLocation location;           // the sky_sphere keyword
};

// Atmospheric media: media { } at the top level.
struct AtmosphericMedia {
    MediaRef media;
    SourceLocation location;  // the media keyword
};

// Everything rays meet outside objects.
struct Atmosphere {
    std::vector<Fog> fogs;  // layered
    std::vector<Rainbow> rainbows;
    SkySphereRef sky_sphere;  // the last one; null: none
    std::vector<AtmosphericMedia> media;
};

}  // namespace rayset::tracer
