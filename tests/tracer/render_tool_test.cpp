// End-to-end tests of the `raytrace` tool: POV-Ray switches and .ini files, the files it
// writes (OpenEXR channels and units, PNG, receiver maps), and errors that name
// file:line:column, exit non-zero and leave no file behind.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace rayset::tracer {
namespace {

namespace fs = std::filesystem;

const std::string kRaytrace = std::string(RAYSET_BINARY_DIR) + "/tracer/raytrace";
const std::string kCornell = (fs::path(__FILE__).parent_path() / "scenes" / "cornell.pov").string();

test::CommandResult raytrace(const std::string& arguments, const std::string& folder) {
    if (!fs::exists(kRaytrace))
        ADD_FAILURE() << kRaytrace << " is missing: build the raytrace target";
    return test::run_command("cd '" + folder + "' && '" + kRaytrace + "' " + arguments + " 2>&1");
}

std::vector<float> read_channel(const std::string& path, const char* name, int& width,
                                int& height) {
    Imf::InputFile file(path.c_str());
    const auto window = file.header().dataWindow();
    width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    std::vector<float> values(size_t(width) * height);
    Imf::FrameBuffer frame;
    frame.insert(
        name, Imf::Slice(Imf::FLOAT, (char*)values.data(), sizeof(float), sizeof(float) * width));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return values;
}

TEST(RaytraceTool, PovRaySwitchesWriteExrWithLuminanceAndPng) {
    test::ScratchDir dir;
    const auto r =
        raytrace("'" + kCornell + "' +W32 +H24 +Oout.exr --passes 2 -q", dir.path().string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(test::read_file(dir.file("out.png")).substr(0, 8),
              std::string("\x89PNG\r\n\x1a\n", 8));
    int w = 0, h = 0;
    const auto red = read_channel(dir.file("out.exr"), "R", w, h);
    const auto green = read_channel(dir.file("out.exr"), "G", w, h);
    const auto blue = read_channel(dir.file("out.exr"), "B", w, h);
    const auto y = read_channel(dir.file("out.exr"), "Y", w, h);
    ASSERT_EQ(w, 32);
    ASSERT_EQ(h, 24);
    double total = 0;
    for (size_t i = 0; i < y.size(); ++i) {
        const double expected = 683 * (0.2126 * red[i] + 0.7152 * green[i] + 0.0722 * blue[i]);
        EXPECT_NEAR(y[i], expected, 1e-6 * expected + 1e-30);
        total += y[i];
    }
    EXPECT_GT(total, 0);
}

TEST(RaytraceTool, IniFileAndReceiverMaps) {
    test::ScratchDir dir;
    test::write_file(dir.file("scene.pov"), R"(
        light_source { <0, 1000, 0> color rgb 1 }
        plane { y, 0 pigment { rgb 0.5 } finish { diffuse 1 } }
        illuminance_receiver { <-500, 0, -500>, <0, 0, 1000>, <1000, 0, 0>
            resolution <4, 3> name "floor" }
    )");
    test::write_file(dir.file("render.ini"),
                     "; a POV-Ray style ini file\nWidth=20\nHeight=10\nInput_File_Name=scene.pov\n"
                     "Output_File_Name=result.exr\n");
    const auto r = raytrace("render.ini --passes 1 -q --no-png", dir.path().string());
    ASSERT_EQ(r.status, 0) << r.output;
    int w = 0, h = 0;
    read_channel(dir.file("result.exr"), "Y", w, h);
    EXPECT_EQ(w, 20);
    EXPECT_EQ(h, 10);
    EXPECT_FALSE(fs::exists(dir.file("result.png")));
    const std::string csv = test::read_file(dir.file("result.floor.csv"));
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 4 * 3);
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "i,j,x,y,z,illuminance_lx,standard_error_lx,irradiance_red_W_m2,irradiance_green_W_"
              "m2,irradiance_blue_W_m2");
    // Cell (1, 1) centre: x = 1000 * 1.5/3 - 500 = 0, z = 1000 * 1.5/4 - 500 = -125.
    const auto lux = read_channel(dir.file("result.floor.exr"), "Y", w, h);
    ASSERT_EQ(w, 4);
    ASSERT_EQ(h, 3);
    const double d2 = 1.0 + 0.125 * 0.125, cos_theta = 1 / std::sqrt(d2);
    EXPECT_NEAR(lux[1 * 4 + 1], 683 * cos_theta / d2, 1e-4 * 683);
}

TEST(RaytraceTool, SceneErrorNamesTheLocationAndWritesNothing) {
    test::ScratchDir dir;
    test::write_file(dir.file("bad.pov"), "sphere { <0,0,0>, 1 }\nsphere { <0,0,0>, oops }\n");
    const auto r = raytrace("bad.pov -o bad.exr -q", dir.path().string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("bad.pov:2:"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir.file("bad.exr")));
    for (const auto& entry : fs::directory_iterator(dir.path()))
        EXPECT_TRUE(entry.path().extension() == ".pov") << "left behind: " << entry.path();
}

TEST(RaytraceTool, BadIniAndSwitchesAreReported) {
    test::ScratchDir dir;
    // POV-Ray's antialiasing, quality and bounding options are read and have no effect (as
    // benchmark.ini writes them); an unknown option is refused.
    test::write_file(
        dir.file("x.ini"),
        "Width=20\nAntialias=on\nQuality=9\nBounding_Threshold=3\nField_Render=Off\n"
        "Pre_Scene_Command=\nStart_Column=0\nEnd_Column=1\nVersion=3.7\nFrobnicate=2\n");
    auto r = raytrace("x.ini '" + kCornell + "'", dir.path().string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("x.ini:10: not supported: .ini option 'Frobnicate'"), std::string::npos)
        << r.output;
    // What would change the render is refused when asked for.
    const std::pair<const char*, const char*> refused[] = {
        {"Field_Render=On", "not supported: Field_Render=On (only off)"},
        {"Odd_Field=maybe",
         "Odd_Field must be on or off (or true/false, yes/no, 1/0), got 'maybe'"},
        {"Post_Scene_Command=rm x", "not supported: Post_Scene_Command=rm x (raytrace runs no"},
        {"End_Row=0.5", "not supported: End_Row=0.5 (only the whole image: render it and crop)"},
        {"Version=3.5", "not supported: Version=3.5 (the language of POV-Ray 3.7 only)"}};
    for (const auto& [line, message] : refused) {
        test::write_file(dir.file("y.ini"), std::string("Width=20\n") + line + "\n");
        r = raytrace("y.ini '" + kCornell + "' --parse-only", dir.path().string());
        EXPECT_NE(r.status, 0) << line;
        EXPECT_NE(r.output.find(std::string("y.ini:2: ") + message), std::string::npos) << r.output;
    }
    r = raytrace("'" + kCornell + "' --no-such-option", dir.path().string());
    EXPECT_EQ(r.status, 2) << r.output;  // a usage error (docs/architecture.md)
    r = raytrace("'" + kCornell + "' +Q9", dir.path().string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("'+Q9' is not supported"), std::string::npos) << r.output;
    r = raytrace("", dir.path().string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("no scene file given"), std::string::npos) << r.output;
    r = raytrace("--help", dir.path().string());
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("+Wn width"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("cd/m^2"), std::string::npos) << r.output;
}

// A small scene that prints the animation built-ins (#debug goes to standard error).
constexpr const char* kAnimationScene = R"(#version 3.7;
#debug concat("clock ", str(clock,0,6), " delta ", str(clock_delta,0,6), " on ",
              str(clock_on,0,0), " frame ", str(frame_number,0,0), "\n")
#debug concat("if ", str(initial_frame,0,0), " ff ", str(final_frame,0,0), " ic ",
              str(initial_clock,0,6), " fc ", str(final_clock,0,6), " w ", str(image_width,0,0),
              " h ", str(image_height,0,0), "\n")
camera { location -5*z }
light_source { <0, 5, -5> rgb 1 }
sphere { 0, 1 pigment { rgb 0.5 } }
)";

// The animation switches and .ini keys set the built-ins as POV-Ray 3.7 does: each expected
// pair of lines is what /tmp/pv/pov.sh (POV-Ray 3.7.0.10) printed for the same options.
TEST(RaytraceTool, AnimationSwitchesSetTheBuiltInsAsPovRay) {
    test::ScratchDir dir;
    test::write_file(dir.file("anim.pov"), kAnimationScene);
    auto builtins = [&](const std::string& arguments) {
        const auto r =
            raytrace("anim.pov +W4 +H3 --passes 1 -q --no-png " + arguments, dir.path().string());
        EXPECT_EQ(r.status, 0) << r.output;
        return r.output;
    };
    EXPECT_EQ(builtins(""),
              "clock 0.000000 delta 0.000000 on 0 frame 0\n"
              "if 0 ff 0 ic 0.000000 fc 0.000000 w 4 h 3\n");
    EXPECT_EQ(builtins("+K0.3"),
              "clock 0.300000 delta 0.000000 on 1 frame 0\n"
              "if 0 ff 0 ic 0.000000 fc 0.000000 w 4 h 3\n");
    EXPECT_EQ(builtins("+KFI1 +KFF5 +SF3 +EF3"),
              "clock 0.500000 delta 0.250000 on 1 frame 3\n"
              "if 1 ff 5 ic 0.000000 fc 1.000000 w 4 h 3\n");
    // A subset start below the initial frame is raised to it; +K is ignored in an animation.
    EXPECT_EQ(builtins("+KFI3 +KFF10 +SF2 +EF2 +K0.7"),
              "clock 0.000000 delta 0.142857 on 1 frame 3\n"
              "if 3 ff 10 ic 0.000000 fc 1.000000 w 4 h 3\n");
    // A final frame not above the initial one is no animation (POV-Ray: +KFI1 +KFF1).
    EXPECT_EQ(builtins("+KFI1 +KFF1"),
              "clock 0.000000 delta 0.000000 on 0 frame 0\n"
              "if 0 ff 0 ic 0.000000 fc 0.000000 w 4 h 3\n");
    // .ini keys; a subset fraction 0.35 of the 11 frames 0..10 is frame 3.
    test::write_file(dir.file("anim.ini"),
                     "Initial_Frame=0\nFinal_Frame=10\nSubset_Start_Frame=0.35\n"
                     "Subset_End_Frame=0.35\nInitial_Clock=2\nFinal_Clock=4\nWidth=8\nHeight=6\n");
    const auto r = raytrace("anim.ini anim.pov --passes 1 -q --no-png", dir.path().string());
    EXPECT_EQ(r.output,
              "clock 2.600000 delta 0.200000 on 1 frame 3\n"
              "if 0 ff 10 ic 2.000000 fc 4.000000 w 8 h 6\n");
}

TEST(RaytraceTool, AnimationRendersTheFirstFrameOfTheSubsetAndSaysSo) {
    test::ScratchDir dir;
    test::write_file(dir.file("anim.pov"), kAnimationScene);
    auto r = raytrace("anim.pov +W4 +H3 --passes 1 --no-png +KFF10 +SF4", dir.path().string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("raytrace: note: rendering frame 4 only of frames 4 to 10 (one frame "
                            "per run; +SF chooses it)"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("clock 0.333333 delta 0.111111 on 1 frame 4"), std::string::npos)
        << r.output;
    EXPECT_TRUE(fs::exists(dir.file("anim.exr")));
    // Cyclic: frames 1 to 4 stop a step short of the final clock, and POV-Ray reports final
    // frame 5 (povray 3.7.0.10 +KFI1 +KFF4 +KC +SF4 +EF4: clock 0.75, delta 0.25, final 5).
    r = raytrace("anim.pov +W4 +H3 --passes 1 --no-png +KC +KFF4 +SF4", dir.path().string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("clock 0.750000 delta 0.250000 on 1 frame 4\nif 1 ff 5"),
              std::string::npos)
        << r.output;
    // Declare=NAME=VALUE on the command line or in an .ini file, several switches to a line.
    test::write_file(dir.file("declare.pov"), "#debug concat(\"fp \", str(Fp, 0, 2), \"\\n\")\n");
    test::write_file(dir.file("declare.ini"), "+W4 +H3 Declare=Fp=2.5\n");
    r = raytrace("declare.ini declare.pov --parse-only", dir.path().string());
    EXPECT_NE(r.output.find("fp 2.50"), std::string::npos) << r.output;
    r = raytrace("declare.pov --parse-only Declare=Fp=-1", dir.path().string());
    EXPECT_NE(r.output.find("fp -1.00"), std::string::npos) << r.output;
    r = raytrace("anim.pov +KFI1.5", dir.path().string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("command line: Initial_Frame (+KFI) must be a whole frame number, got "
                            "'1.5'"),
              std::string::npos)
        << r.output;
    // A checkpoint made at another clock is of another scene: refused.
    ASSERT_EQ(raytrace("anim.pov +W4 +H3 --passes 1 -q --no-png +K0.3 --keep-checkpoint",
                       dir.path().string())
                  .status,
              0);
    r = raytrace("anim.pov +W4 +H3 --passes 2 -q --no-png +K0.5 --resume", dir.path().string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("anim.pov at clock 0.3 (frame 0) with content hash"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("(this render: "), std::string::npos) << r.output;
    EXPECT_EQ(
        raytrace("anim.pov +W4 +H3 --passes 2 -q --no-png +K0.3 --resume", dir.path().string())
            .status,
        0);
    test::write_file(dir.file("bad.ini"), "Clock=soon\n");
    r = raytrace("bad.ini anim.pov", dir.path().string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("bad.ini:1: Clock (+K) must be a number, got 'soon'"),
              std::string::npos)
        << r.output;
}

}  // namespace
}  // namespace rayset::tracer
