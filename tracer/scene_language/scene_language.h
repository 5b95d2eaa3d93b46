// Entry points of the scene-language front end: POV-Ray 3.7's scene description language (see
// README.md beside this file) interpreted into a SceneDescription.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

// The values of POV-Ray's animation and image built-ins (clock, frame_number, image_width, ...),
// as its animation options (+K, +KFI, +KFF, +KI, +KF, +SF, Clock=, Initial_Frame= ...) set them.
struct AnimationSettings {
    double clock = 0;
    double clock_delta = 0;
    bool clock_on = false;
    int frame_number = 0;
    int initial_frame = 0, final_frame = 0;
    double initial_clock = 0, final_clock = 0;
    int image_width = 320, image_height = 240;
};

enum class MessageStream { debug, warning };

struct ParseOptions {
    // Folders searched for #include files and data files (mesh_file, ray_source, image files)
    // after the folder of the file that names them. POV-Ray's own include folder is appended
    // when it is installed (default_include_paths()).
    std::vector<std::string> include_paths;
    // Folders files may be read from besides the main file's folder and the include paths;
    // anything resolving (after symlinks) outside all of them is refused.
    std::vector<std::string> allowed_roots;
    // Folders #fopen may write or append to; none by default (writing is refused).
    std::vector<std::string> write_roots;
    AnimationSettings animation;
    // Float identifiers declared before the scene is read (POV-Ray's Declare=NAME=VALUE).
    std::vector<std::pair<std::string, double>> declarations;
    // Where #debug and #warning text and the parser's warnings go; standard error when empty.
    std::function<void(MessageStream, const std::string&)> on_message;

    // Limits against hostile or runaway scenes; each error names the limit that stopped it.
    int max_include_depth = 64;            // nested #include levels
    int max_nesting = 1000;                // macro calls, include files and {} blocks in progress
    long max_loop_iterations = 100000000;  // #while and #for iterations in total
    long max_macro_calls = 100000000;      // macro calls in total (a recursion may branch)
    long max_array_elements = 100000000;   // elements of one array
    long max_string_length = 100000000;    // bytes of one string
    // Objects and light sources placed in the scene (a union counts its parts, a mesh one): far
    // above real scenes, they stop a loop that never ends long before memory runs out.
    long max_objects = 10000000;
    long max_lights = 100000;
    long max_memory_megabytes = 0;  // growth of the process while parsing; 0: half the RAM
};

// POV-Ray's include folder when the package is installed (/usr/share/povray-3.7/include), as
// its configuration puts it on the library path; empty otherwise.
std::vector<std::string> default_include_paths();

// Throws SceneError (a rayset::Error) whose message ends with "at FILE:LINE:COLUMN".
SceneDescription parse_scene_file(const std::string& path, const ParseOptions& options = {});
// `virtual_path` names the text in messages; its folder is where relative includes start.
SceneDescription parse_scene_text(const std::string& text, const std::string& virtual_path,
                                  const ParseOptions& options = {});

}  // namespace rayset::tracer
