// Shared by the tracer tests: the closed box with a receiver on each of its six inner walls,
// the scene of the energy-balance tests (primary and secondary light against closed forms),
// and the wall average read from its receivers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "converters/analytic/analytic_sources.h"
#include "support/test_support.h"
#include "tracer/film/film.h"
#include "tracer/render/renderer.h"

namespace rayset::test {

// A closed cube (side 100 mm, centred on the origin) of `pigment` (a POV-Ray colour: "1",
// "<0.2, 0.4, 0.9>") and finish diffuse `diffuse`, an illuminance receiver of cells x cells on
// each inner wall, facing in, and the ray sources at its centre turned to emit toward -y
// (rotate <90, 0, 0>), then `more` (lights); the integrator `integrator`, spectral transport if
// `spectral`.
// Every unit of light at wavelength l lands on a wall once (primary) and a / (1 - a) times more
// after reflections (secondary), a = the walls' reflectance at l: the wall-averaged
// irradiances are Phi / A and the sum over the light of Phi a / ((1 - a) A), A = kClosedBoxArea.
struct ClosedBox {
    std::string pigment = "1";
    double diffuse = 0.5;
    int cells = 20;  // receiver cells along each edge of a wall
    bool spectral = false;
    std::vector<std::string> sources;  // ray files or light models
    std::string more;
    std::string integrator = "bidirectional";
};
std::string closed_box_scene(const ClosedBox& box);

constexpr double kClosedBoxArea = 6 * 0.01;  // m^2 of wall

// Mean over every cell of the maps of the luminance weight (lx / 683, W/m^2 for a grey light),
// and its standard error from the cells' own.
struct WallAverage {
    double mean = 0, standard_error = 0;
};
WallAverage wall_average(const std::vector<tracer::ReceiverMap>& maps);

// A Lambertian disk (radius 1 mm, 1 W at 555 nm, facing +z), and it as `rays` rays of a TM-25
// file (seed 7).
analytic::LambertianDisk disk_source();
void write_disk_rays(const std::string& path, uint64_t rays);
// That disk at 10^6 rays and its model (test::synthesised_model: made once per build of the
// tests), in a scratch folder of this process where scenes naming them are parsed.
struct DiskFiles {
    ScratchDir scratch;
    std::string rays, model;
};
const DiskFiles& disk_files();
// A closed grey box (side 100 mm, diffuse 0.5) seen from inside, a faint point light, a 3 x 3
// receiver on its floor and the ray source `source` (a ray file or model, as the scene names
// it) 20 mm above the centre emitting down; the bidirectional integrator. Primary and
// secondary light of both lights and direct visibility of the disk all enter it.
std::string disk_in_box_scene(const std::string& source);

// The disk source `source` 20 mm above a black floor, facing down (rotate 90 x: its +z to -y, so
// a floor point (x, 0, z) is the disk-frame point (x, z, 20)), with a 4 x 4 receiver over the
// floor's 80 x 80 mm middle; the integrator `integrator`.
std::string disk_over_black_floor(const std::string& source, const std::string& integrator);

// tests/tracer/scenes/cornell.pov (the path tracer, POV-Ray's area lights) with a 4 x 3
// illuminance receiver on its floor, facing up.
std::string cornell_with_receiver();

// POV-Ray's own render of `scene` (no anti-aliasing, output encoded with `file_gamma`: 1 is
// linear; the scene's folder, then `library_path` if given, on its library path, where files it
// names are found; `more_options` added to the command line: an animation's frame, say), read back
// as 8-bit RGB rows from the top. False with `message` set when povray is not installed (the test
// skips, saying so); std::runtime_error when it fails.
bool povray_render(const std::string& scene, int width, int height, std::vector<uint8_t>& rgb,
                   std::string& message, double file_gamma = 1,
                   const std::string& library_path = "", const std::string& more_options = "");
// Whether our colour (POV-Ray's colour scale, 1 = white) agrees with POV-Ray's 8-bit pixel
// `pov` (three bytes): every channel within 2% of the value and half an 8-bit step.
bool agrees_with_povray(Rgb ours, const uint8_t* pov);
// Each pixel's colour as POV-Ray shows `scene_file` (objects of diffuse finishes under one
// distant light at `light`, colour 1, no shadows) and as computed here from the hit its centre
// ray makes, shaded as POV-Ray shades it: the pigment times N'.L, N' the BSDF's tilted
// shading normal. False (with a note printed) when povray is not installed.
struct LitTiles {
    std::vector<uint8_t> povray;
    std::vector<Rgb> ours;
    std::vector<int> object;  // what each pixel's centre ray sees (-1: none)
};
bool render_lit_tiles(const std::string& scene_file, Vec3 light, int width, int height,
                      LitTiles& out);
// A scene written in the test ("test.pov"), rendered with `settings`.
tracer::RenderResult render_text(const std::string& text, const tracer::RenderSettings& settings);
// The error rendering a scene written in the test (4 x 3 pixels, one pass) throws, or "no error".
std::string render_error(const std::string& text);
// The path of a scene of tests/tracer/scenes/.
std::string tracer_scene(const std::string& name);

}  // namespace rayset::test
