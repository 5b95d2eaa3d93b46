// Every include file of POV-Ray 3.7 (package povray-includes) loads: a scene that includes it
// and has a camera and a light parses and renders one pass. Skips, saying so, when POV-Ray's
// include folder is not installed.
#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "support/test_support.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

namespace fs = std::filesystem;

// Include files that cannot stand alone, with what each needs first: they use identifiers of
// colors.inc or shapes.inc without including it. POV-Ray 3.7.0.10 fails the same way without it
// and loads them with it (checked).
const std::map<std::string, std::string> kNeedsFirst = {
    {"stdcam.inc", "colors.inc"},  {"skies.inc", "colors.inc"},   {"stones.inc", "colors.inc"},
    {"stones1.inc", "colors.inc"}, {"stones2.inc", "colors.inc"}, {"stoneold.inc", "colors.inc"},
    {"shapes2.inc", "shapes.inc"}, {"shapesq.inc", "shapes.inc"},
};

std::vector<std::string> include_files() {
    std::vector<std::string> names;
    for (const std::string& folder : default_include_paths())
        for (const auto& entry : fs::directory_iterator(folder))
            if (entry.path().extension() == ".inc")
                names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(PovRayIncludes, EachLoadsInASceneThatRendersOnePass) {
    const std::vector<std::string> names = include_files();
    if (names.empty())
        GTEST_SKIP() << "POV-Ray's include folder is not installed (scripts/install-deps.sh)";
    EXPECT_GE(names.size(), 39u);  // POV-Ray 3.7's 39
    test::ScratchDir dir;
    int rendered = 0;
    for (const std::string& name : names) {
        const auto first = kNeedsFirst.find(name);
        const std::string text =
            "#version 3.7;\n" +
            (first == kNeedsFirst.end() ? "" : "#include \"" + first->second + "\"\n") +
            "#include \"" + name + "\"\n" +
            "camera { location <0, 1, -3> look_at 0 }\n"
            "light_source { <2, 4, -3> rgb 1 }\n";
        test::write_file(dir.file("scene.pov"), text);
        SceneDescription description;
        try {
            description = parse_scene_file(dir.file("scene.pov"));
        } catch (const Error& e) {
            ADD_FAILURE() << name << " does not load: " << e.what();
            continue;
        }
        try {
            const RenderScene scene(description);
            RenderSettings settings;
            settings.width = 8;
            settings.height = 6;
            settings.passes = 1;
            settings.progress = false;
            render(scene, settings);
            ++rendered;
        } catch (const Error& e) {
            ADD_FAILURE() << name << ": " << e.what();
        }
    }
    std::printf("%zu include files load; %d render\n", names.size(), rendered);
    EXPECT_EQ(rendered, int(names.size()));
}

}  // namespace
}  // namespace rayset::tracer
