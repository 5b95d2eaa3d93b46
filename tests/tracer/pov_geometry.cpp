// pov_geometry [--width W] [--height H] SCENE...: for each scene, the fraction of pixels where
// POV-Ray and the renderer see the same object in its flat-colour copy (flat_colour_scene.h),
// as one tab-separated line: the fraction, the pixels, the pixels POV-Ray sees an object in, the
// object statements, the scene, then the words it uses ("camera:" before its camera's words); or
// "error" and the first line of the error. pov_geometry --copy FOLDER SCENE writes the copy only
// (to render it by hand). A development tool for scripts/pov_geometry.sh.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "tracer/flat_colour_scene.h"

int main(int argc, char** argv) {
    int width = 160, height = 120;
    std::vector<std::string> scenes;
    std::string copy_folder;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--copy" && i + 1 < argc)
            copy_folder = argv[++i];
        else if (a == "--width" && i + 1 < argc)
            width = std::atoi(argv[++i]);
        else if (a == "--height" && i + 1 < argc)
            height = std::atoi(argv[++i]);
        else
            scenes.push_back(a);
    }
    if (scenes.empty() || width < 1 || height < 1) {
        std::fprintf(stderr, "usage: pov_geometry [--width W] [--height H] SCENE...\n");
        return 2;
    }
    if (!copy_folder.empty()) {
        for (const std::string& scene : scenes)
            std::printf("%s\n",
                        rayset::test::write_flat_colour_copy(scene, copy_folder).scene.c_str());
        return 0;
    }
    for (const std::string& scene : scenes) {
        try {
            rayset::test::GeometryAgreement a;
            std::string message;
            if (!rayset::test::geometry_agreement(scene, width, height, a, message)) {
                std::fprintf(stderr, "pov_geometry: %s\n", message.c_str());
                return 2;
            }
            std::printf("%.4f\t%d\t%d\t%d\t%s\t", a.fraction(), a.pixels, a.seeing, a.statements,
                        scene.c_str());
            for (const std::string& w : a.words) std::printf(" %s", w.c_str());
            for (const std::string& w : a.camera_words) std::printf(" camera:%s", w.c_str());
            std::printf("\n");
        } catch (const std::exception& e) {
            std::string what = e.what();
            what = what.substr(0, what.find('\n'));
            std::printf("error\t0\t0\t0\t%s\t%s\n", scene.c_str(), what.c_str());
        }
        std::fflush(stdout);
    }
    return 0;
}
