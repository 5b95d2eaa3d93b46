// POV-Ray 3.7's own sample scenes (Debian package povray-examples), as their authors wrote them,
// seen through both renderers: the flat-colour copy of each scene (flat_colour_scene.h: every
// object statement one self-lit colour, nothing else) rendered by POV-Ray and by the renderer,
// one ray through each pixel's centre, shows the same object on at least 99% of the pixels.
// Together the scenes use every shape, CSG operation and camera of the sample scenes that the
// renderer draws (checked below); two frames of an animated one show the shapes no still scene
// has. scripts/pov_geometry.sh runs the same comparison over every sample scene that renders.
// Skipped, saying so, without povray or the sample scenes.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_support.h"
#include "tracer/flat_colour_scene.h"

namespace rayset::test {
namespace {

const std::string kExamples = "/usr/share/doc/povray/examples/";

// Chosen for what they use (the coverage test below) among the scenes that agree, and for
// rendering in a second or two each.
// A sample scene, or a frame of an animated one with the shape it shows.
struct Sample {
    Sample(std::string path, SampleFrame frame = {}, std::string shows = {})
        : path(std::move(path)), frame(frame), shows(std::move(shows)) {}
    std::string path;
    SampleFrame frame;
    std::string shows;  // a frame's shape (its file names them all)
};

const std::vector<Sample> kScenes = {
    {"advanced/blocks/stackergold.pov"},
    {"advanced/drums2/drums.pov"},
    {"advanced/woodbox.pov"},
    {"bsp/Tango.pov"},
    {"camera/cylinder3.pov"},
    {"camera/fisheye.pov"},
    {"camera/mesh_camera/ess/ess-persp-camera.pov"},
    {"camera/omnimax.pov"},
    {"camera/orthographic.pov"},
    {"camera/panoramic.pov"},
    {"camera/spherical.pov"},
    {"camera/ultra_wide_angle.pov"},
    {"incdemo/metals/chromes.pov"},
    {"incdemo/sundial.pov"},
    {"incdemo/woods/wood_15.pov"},
    {"incdemo/woods/wood_4.pov"},
    {"interior/atten1.pov"},
    {"interior/media/media3.pov"},
    {"language/arrays/array2.pov"},
    {"language/macros/macro3.pov"},
    {"lights/circular.pov"},
    {"lights/glassthing.pov"},
    {"objects/blob.pov"},
    {"objects/fractal3.pov"},
    {"objects/lathe2.pov"},
    {"objects/primitiv.pov"},
    {"objects/prism3a.pov"},
    {"objects/quartic/bicube.pov"},
    {"objects/quartic/piriform.pov"},
    {"objects/quartic/steiner.pov"},
    {"objects/quartic/torus.pov"},
    {"objects/sor1.pov"},
    {"objects/superel1.pov"},
    {"radiosity/patio-radio_36.pov"},
    {"templates/Basic_Scenes/Checkered_plane.pov"},
    {"templates/Basic_Scenes/Sea_moon_partly_cloudy.pov"},
    {"textures/noise_generator.pov"},
    {"textures/patterns/crackle1.pov"},
    {"textures/patterns/fractals3.pov"},
    {"textures/pigments/skies/s_cloud3.pov"},
    // portfolio/allobjects.pov shows one shape a frame, of 27.
    {"portfolio/allobjects.pov", {13, 27}, "parametric"},
    {"portfolio/allobjects.pov", {22, 27}, "sphere_sweep"},
};

std::string test_name(const testing::TestParamInfo<Sample>& info) {
    std::string name;
    for (const char c : info.param.path.substr(0, info.param.path.rfind('.')))
        name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    if (info.param.frame.frames > 0) name += "_frame" + std::to_string(info.param.frame.number);
    return name;
}

class PovSamples : public testing::TestWithParam<Sample> {};

TEST_P(PovSamples, SeeTheSameObjectsAsPovRay) {
    if (!std::filesystem::is_directory(kExamples))
        GTEST_SKIP() << kExamples << " missing (Debian package povray-examples)";
    const int width = 160, height = 120;
    GeometryAgreement a;
    std::string message;
    const Sample& sample = GetParam();
    if (!geometry_agreement(kExamples + sample.path, width, height, a, message, sample.frame))
        GTEST_SKIP() << message;
    std::printf(
        "%s: %d object statements, POV-Ray sees an object on %d pixels; the object "
        "agrees on %d of %d pixels (%.4f)\n",
        (sample.path +
         (sample.frame.frames ? ", frame " + std::to_string(sample.frame.number) : std::string()))
            .c_str(),
        a.statements, a.seeing, a.agreeing, a.pixels, a.fraction());
    RecordProperty("agreement", std::to_string(a.fraction()));
    // Something to agree on: black in both cannot carry the agreement.
    EXPECT_GT(a.seeing, a.pixels / 5);
    EXPECT_GE(a.fraction(), 0.99);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PovSamples, testing::ValuesIn(kScenes), test_name);

// The words of the scenes (and their own include files) name every shape, CSG operation and
// camera projection that some sample scene the renderer draws uses.
TEST(PovSampleCoverage, TheScenesUseEveryShapeCsgOperationAndCamera) {
    if (!std::filesystem::is_directory(kExamples))
        GTEST_SKIP() << kExamples << " missing (Debian package povray-examples)";
    std::set<std::string> words, camera_words;
    for (const Sample& sample : kScenes) {
        if (!sample.shows.empty()) {
            words.insert(sample.shows);
            continue;
        }
        ScratchDir dir;
        const FlatColourCopy copy =
            write_flat_colour_copy(kExamples + sample.path, dir.path().string());
        words.insert(copy.words.begin(), copy.words.end());
        camera_words.insert(copy.camera_words.begin(), copy.camera_words.end());
    }
    for (const char* shape :
         {"sphere",    "box",     "plane",      "triangle",       "mesh",
          "cylinder",  "cone",    "disc",       "torus",          "polygon",
          "prism",     "lathe",   "sor",        "superellipsoid", "height_field",
          "text",      "blob",    "isosurface", "bicubic_patch",  "quadric",
          "cubic",     "quartic", "poly",       "julia_fractal",  "sphere_sweep",
          "parametric"})
        EXPECT_TRUE(words.count(shape)) << shape;
    for (const char* csg :
         {"union", "merge", "intersection", "difference", "inverse", "clipped_by", "bounded_by"})
        EXPECT_TRUE(words.count(csg)) << csg;
    for (const char* camera : {"perspective", "orthographic", "fisheye", "ultra_wide_angle",
                               "omnimax", "panoramic", "cylinder", "spherical", "mesh_camera"})
        EXPECT_TRUE(camera_words.count(camera)) << camera;
}

// The copy's rules on a small scene: what is given is removed (uv_mapping too), what is declared
// kept (a layered texture with its layers, a macro's texture argument, an array's textures), each
// top-level object statement coloured (in a macro body too), the objects inside a CSG left to
// inherit.
TEST(FlatColourCopy, RewritesAsDocumented) {
    ScratchDir source, target;
    write_file(source.file("scene.pov"), R"(#include "parts.inc"
#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbt 0.5 } }
/* a comment { with a brace */ light_source { <0, 9, 0> rgb 1 }
#declare S = sky_sphere { pigment { rgb 1 } } sky_sphere { S }
union { sphere { 0, 1 texture { T } } box { 0, 1 pigment { rgb x } } finish { phong 1 } uv_mapping }
#macro M(Tex) cone { 0, 1, y, 0 texture { Tex } } #end
M(texture { T })
#declare Looks = array[2] { texture { T }, pigment { rgb 1 } }
#declare Things = array[1][1] { { sphere { 0, 1 pigment { rgb 1 } } } }
global_settings { assumed_gamma 2.2 }
)");
    write_file(source.file("parts.inc"), "plane { y, 0 pigment { checker } }\n");
    const FlatColourCopy copy =
        write_flat_colour_copy(source.file("scene.pov"), target.path().string());
    EXPECT_EQ(copy.statements, 3);
    const std::string colour =
        " texture { pigment { rgb <%s> } finish { emission 1 ambient 0 "
        "diffuse 0 } } ";
    auto texture = [&](const char* rgb) {
        char text[200];
        std::snprintf(text, sizeof text, colour.c_str(), rgb);
        return std::string(text);
    };
    EXPECT_EQ(read_file(target.file("scene.pov")),
              "#include \"parts.inc\"\n"
              "#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbt 0.5 } }\n"
              "/* a comment { with a brace */ \n"
              "#declare S = sky_sphere { pigment { rgb 1 } } \n"
              "union { sphere { 0, 1  } box { 0, 1  }   " +
                  texture("0.00392156863, 0, 0") +
                  "}\n"
                  "#macro M(Tex) cone { 0, 1, y, 0  " +
                  texture("0.00784313725, 0, 0") +
                  "} #end\n"
                  "M(texture { T })\n"
                  "#declare Looks = array[2] { texture { T }, pigment { rgb 1 } }\n"
                  "#declare Things = array[1][1] { { sphere { 0, 1  } } }\n\n"
                  "\nglobal_settings { assumed_gamma 1 }\nbackground { rgb 0 }\n");
    EXPECT_EQ(read_file(target.file("parts.inc")),
              "plane { y, 0  " + texture("0.0117647059, 0, 0") + "}\n");
    EXPECT_TRUE(copy.words.count("cone") && copy.words.count("plane"));
}

TEST(FlatColourCopy, ColoursNameTheirStatements) {
    for (const int index : {1, 255, 256, 4095, 65535, 65536, 1000000, kMaxFlatColour}) {
        const Rgb c = flat_colour(index);
        EXPECT_EQ(flat_colour_index(c), index);
        // As POV-Ray writes it in 8 bits, and back.
        EXPECT_EQ(flat_colour_index({std::round(255 * c.red) / 255, std::round(255 * c.green) / 255,
                                     std::round(255 * c.blue) / 255}),
                  index);
    }
    EXPECT_EQ(flat_colour_index({0, 0, 0}), 0);
    EXPECT_THROW(flat_colour(kMaxFlatColour + 1), std::runtime_error);
}

}  // namespace
}  // namespace rayset::test
