// rayset's public API: a POV-Ray 3.7 scene file read and rendered as `raytrace` reads and
// renders it (path tracer, or the bidirectional integrator that renders ray-file sources through
// their models), and the image and illuminance maps written as raytrace writes them.
// Link rayset::tracer. docs/api.md has the whole public API and examples.
//
// Units: scene lengths in the scene's unit (global_settings { length_unit }, mm by default).
// The image holds linear-sRGB radiance in W/(m^2 sr) per channel, receivers irradiance in W/m^2
// per channel; photometric() gives their luminous value (cd/m^2, lux). tracer/render/README.md
// says how POV-Ray's lights, textures and finishes become physical quantities. Errors:
// rayset::Error (rays.h); the scene language throws SceneError, an Error whose message ends
// with "at FILE:LINE:COLUMN", and refuses what the renderer cannot render yet with
// "not supported: FEATURE".
#pragma once

#include "tracer/film/film.h"
#include "tracer/film/render_output.h"
#include "tracer/render/renderer.h"
#include "tracer/render/rgb.h"
#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/scene_language.h"

#include <rayset/model.h>

namespace rayset {

// ---- Reading a scene (tracer/scene_language/scene_language.h) -----------------------------------

// SceneDescription parse_scene_file(const std::string& path, const ParseOptions& options = {});
//   Reads a scene file whole (macros, #include, arrays, functions, every object, texture,
//   camera and atmosphere statement) into a plain description with POV-Ray's rules applied.
//   Throws SceneError for a scene it cannot read or render.
// SceneDescription parse_scene_text(const std::string& text, const std::string& virtual_path,
//                                   const ParseOptions& options = {});
//   The same for text in memory; virtual_path names it in messages and its folder is where
//   relative #include and file names start.
// std::vector<std::string> default_include_paths();
//   POV-Ray's include folder (colors.inc, ...) when it is installed, else nothing; the parser
//   searches it after ParseOptions::include_paths.
//
// struct ParseOptions
//   include_paths    folders searched for #include and data files (meshes, ray files, images)
//                    after the folder of the file naming them
//   allowed_roots    more folders files may be read from; anything else is refused
//   write_roots      folders #fopen may write to (none: writing is refused)
//   animation        AnimationSettings: clock, clock_on, frame_number, image_width,
//                    image_height, ... (POV-Ray's +K, +KFI, +W, +H)
//   declarations     float identifiers declared first (POV-Ray's Declare=NAME=VALUE)
//   on_message       where #debug and #warning text goes (standard error when empty)
//   max_*            limits against runaway scenes (include depth, loop iterations, objects,
//                    memory, ...), each error naming the limit that stopped it
//
// struct SceneDescription
//   The scene read: camera, objects, lights, ray_sources, receivers (IlluminanceReceiver:
//   name, corner, edge1, edge2, nx, ny), global (GlobalSettings: length_unit, integrator,
//   spectral, passes, time_limit, ...), files (every file read).
// class SceneError : public Error
//   where(): the SourceLocation (file, line, column) of the error.

// ---- Rendering (tracer/render/renderer.h) -------------------------------------------------------

// RenderScene(const SceneDescription& scene)
//   The scene as the renderer queries it (Embree geometry, materials); notes() lists what is
//   rendered as POV-Ray renders it rather than physically (shadowless lights, ...), one
//   sentence each. Throws Error for a scene it cannot build.
//
// RenderResult render(const RenderScene& scene, const RenderSettings& settings,
//                     RenderResult start = {}, const RenderControl& control = {});
//   Renders with the scene's integrator (global_settings { integrator "bidirectional" } for
//   the paper's), building each ray_source's model first (or reading its .vdb). The image
//   depends on the seed and the number of passes only, not on threads or timing. In a program
//   that an MPI launcher did not start, it renders in this process alone. Throws Error (a ray
//   file or model that cannot be read, ...).
//
// struct RenderSettings
//   width, height      pixels (320 x 240)
//   passes             0: until time_limit, or 16 without one; raytrace takes the scene's
//                      global.passes when it is not given
//   time_limit         seconds, checked between passes; 0: none
//   seed, threads      threads 0: every core
//   render_image       false: receivers only
//   progress           a progress bar on stderr (when it is a terminal)
//   photons_per_pass, photon_radius, naive_sources, spectral
//                      the bidirectional integrator's: photons a pass (0: as many as camera
//                      samples, at least 65536), the first gather radius in scene units (0:
//                      chosen), ray sources as their stored rays (the paper's Figure 1),
//                      spectral transport
// struct RenderControl
//   after_pass         called after each pass with the state so far (for checkpoints)
//   wants_state        whether after_pass is due; unset: always
//   stop               const std::atomic<bool>*: once true, render returns the completed passes
//
// struct RenderResult
//   film               Film: the image
//   receivers          std::vector<ReceiverMap>: the illuminance receivers
//   layers             bidirectional only, RenderLayer{name, film, receivers}:
//                      direct_visibility, primary, secondary light
//   passes, samples_per_pass, seconds, rays (every ray cast), photons, photon_radius
//
// class SampleGrid (Film is the same type)
//   The per-pixel (or per-cell) means of a render: nx(), ny(), samples(),
//   mean(x, y)                    Rgb, W/(m^2 sr) for the image, W/m^2 for a receiver
//   photometric_mean(x, y)        cd/m^2 or lux
//   photometric_standard_error(x, y)
//                                 its standard error from the spread of the passes
//   Pixel (0, 0) is the top left.
// struct ReceiverMap
//   receiver (IlluminanceReceiver), irradiance (SampleGrid), cell_centre(i, j) (scene units),
//   front_normal() (the side it records light from)
//
// double photometric(Rgb value);
//   The luminous value of a radiometric triple: kLumensPerWatt (683) x (0.2126 red + 0.7152
//   green + 0.0722 blue).

// ---- Writing the outputs (tracer/film/render_output.h) ------------------------------------------

// std::vector<std::string> write_render_outputs(const Film* film,
//                                               const std::vector<ReceiverMap>& receivers,
//                                               const OutputRequest& request);
//   What raytrace writes: the image as OpenEXR (R, G, B radiance in W/(m^2 sr), Y luminance in
//   cd/m^2), its PNG preview, and per receiver an OpenEXR and a CSV map (W/m^2, lux). Returns
//   the paths written. Throws Error, leaving no file behind, when any write fails.
// struct OutputRequest
//   exr                the image's path; empty: no image files
//   png                the preview's; empty: none
//   exposure           the preview's; <= 0: automatic
//   receiver_prefix    receiver maps go to PREFIX.NAME.exr and PREFIX.NAME.csv

using tracer::AnimationSettings;
using tracer::default_include_paths;
using tracer::Film;
using tracer::GlobalSettings;
using tracer::IlluminanceReceiver;
using tracer::kLumensPerWatt;
using tracer::OutputRequest;
using tracer::parse_scene_file;
using tracer::parse_scene_text;
using tracer::ParseOptions;
using tracer::photometric;
using tracer::ReceiverMap;
using tracer::render;
using tracer::RenderControl;
using tracer::RenderLayer;
using tracer::RenderResult;
using tracer::RenderScene;
using tracer::RenderSettings;
using tracer::SampleGrid;
using tracer::SceneDescription;
using tracer::SceneError;
using tracer::write_render_outputs;

}  // namespace rayset
