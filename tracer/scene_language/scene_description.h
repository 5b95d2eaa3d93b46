// The scene as the parser hands it to the renderer: a plain description with every POV-Ray
// rule already applied (camera vectors resolved, transforms composed into one object-to-world
// matrix per instance, textures inherited through unions, lights in world coordinates).
//
// Frame: POV-Ray's own (left-handed, y up), coordinates as the file writes them. Lengths in
// the scene's unit (GlobalSettings::length_unit, mm by default). Colours are POV-Ray's
// numbers as written (assumed_gamma is recorded; the renderer decodes them with it).
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "tracer/scene_language/appearance.h"
#include "tracer/scene_language/scene_items.h"
#include "tracer/scene_language/shapes.h"

namespace rayset::tracer {

struct SceneDescription {
    double version = 3.7;  // from #version, last seen
    bool has_camera = false;
    Camera camera;
    std::deque<ObjectInstance> objects;  // a deque: millions are added without moving them
    std::vector<LightSource> lights;
    std::vector<IlluminanceReceiver> receivers;
    std::vector<RaySource> ray_sources;
    GlobalSettings global;
    Colour background;               // black unless `background { ... }`
    Atmosphere atmosphere;           // fogs, rainbows, sky sphere, atmospheric media
    std::vector<std::string> files;  // every file read, main file first
};

}  // namespace rayset::tracer
