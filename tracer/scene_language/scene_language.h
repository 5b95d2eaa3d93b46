// Entry points of the scene-language front end: a subset of POV-Ray 3.7's scene description
// language (see README.md beside this file) parsed into a SceneDescription.
#pragma once

#include <string>
#include <vector>

#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

struct ParseOptions {
    // Folders searched for #include files and data files (mesh_file, ray_source) after the
    // folder of the file that names them.
    std::vector<std::string> include_paths;
    // Folders files may be read from besides the main file's folder and the include paths;
    // anything resolving (after symlinks) outside all of them is refused.
    std::vector<std::string> allowed_roots;
    int max_include_depth = 16;          // nested #include levels
    long max_loop_iterations = 10000000; // #while iterations in total, against runaway loops
};

// Throws SceneError (a rayset::Error) whose message ends with "at FILE:LINE:COLUMN".
SceneDescription parse_scene_file(const std::string& path, const ParseOptions& options = {});
// `virtual_path` names the text in messages; its folder is where relative includes start.
SceneDescription parse_scene_text(const std::string& text, const std::string& virtual_path,
                                  const ParseOptions& options = {});

}  // namespace rayset::tracer
