// pov_parse FILE [+LDIR ...]: parses a scene file as raytrace would and prints what it holds,
// or the error. A development tool for the scene language (and the compatibility scan).
#include <cstdio>
#include <string>

#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/scene_language.h"

int main(int argc, char** argv) {
    using namespace rayset::tracer;
    if (argc < 2) {
        std::fprintf(stderr, "usage: pov_parse FILE [+LDIR ...]\n");
        return 2;
    }
    ParseOptions options;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a.rfind("+L", 0) == 0) options.include_paths.push_back(a.substr(2));
    }
    try {
        const SceneDescription scene = parse_scene_file(argv[1], options);
        std::printf("parsed: %zu objects, %zu lights, camera %s, %zu files\n", scene.objects.size(),
                    scene.lights.size(), scene.has_camera ? "yes" : "no", scene.files.size());
        return 0;
    } catch (const rayset::Error& e) {
        std::printf("error: %s\n", e.what());
        return 1;
    }
}
