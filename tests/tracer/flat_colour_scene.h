// What each pixel sees, POV-Ray's render against ours, on scenes written for POV-Ray: a copy of
// the scene in which every appearance is replaced by one flat, self-lit colour per object
// statement, so that a pixel's colour names the object its centre ray meets.
//
// The copy (the scene file and the include files beside it, rewritten token by token):
// - removes every texture, pigment, finish, normal, material, interior, interior_texture,
//   texture_list and photons block and uv_mapping given to an object, and the scene's lights,
//   light groups, sky, background, fog, rainbow, atmospheric media, #default and
//   global_settings;
// - keeps what is declared (`#declare T = texture { ... }`, colour and texture maps, functions),
//   so that the scene still reads;
// - gives each object statement at the top level of a file (a union, a sphere, `object { X }`,
//   also inside a macro body or a loop) the texture `pigment { rgb C } finish { emission 1
//   ambient 0 diffuse 0 }`, C a colour of its own (flat_colour below); the objects inside it
//   inherit it, as POV-Ray's objects inherit their parent's texture;
// - ends with `global_settings { assumed_gamma 1 }` and a black background.
// Both renderers then show C where the object is seen, black where nothing is.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "core/colour.h"

namespace rayset::test {

// The flat colour of the object statement number `index` (1, 2, ..., kMaxFlatColour): channel
// values k / 255, the digits of `index` in base 256, exact in 8-bit output.
constexpr int kMaxFlatColour = 256 * 256 * 256 - 1;
Rgb flat_colour(int index);
// The statement number of a colour (each channel rounded to the nearest k / 255); 0 is black.
int flat_colour_index(Rgb colour);

struct FlatColourCopy {
    std::string scene;   // the rewritten scene file
    int statements = 0;  // object statements given a colour
    // Every word of the scene and its local includes, and the words inside its camera blocks:
    // which shapes, CSG operations and camera types it uses.
    std::set<std::string> words, camera_words;
};
// Writes the flat-colour copy of `scene` (and of the files it includes from its own folder)
// into `folder`. Throws std::runtime_error when a file cannot be read or written.
FlatColourCopy write_flat_colour_copy(const std::string& scene, const std::string& folder);

// The agreement of the two renders of a scene's flat-colour copy, width x height, one ray
// through each pixel's centre: the fraction of the pixels where POV-Ray and the renderer see the
// same object statement (or both nothing).
struct GeometryAgreement {
    int pixels = 0, agreeing = 0, seeing = 0;  // seeing: pixels where POV-Ray sees an object
    int statements = 0;
    std::set<std::string> words, camera_words;
    double fraction() const { return pixels ? double(agreeing) / pixels : 0; }
};
// A frame of an animated scene: number 1 .. frames, the clock from 0 to 1 (frames 0: a still).
struct SampleFrame {
    int number = 0, frames = 0;
};
// False with `message` set when povray is not installed; throws (rayset::Error from the
// renderer's parser, std::runtime_error from POV-Ray) when a side cannot render the copy.
bool geometry_agreement(const std::string& scene, int width, int height, GeometryAgreement& out,
                        std::string& message, const SampleFrame& frame = {});

}  // namespace rayset::test
