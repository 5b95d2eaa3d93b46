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
    if (!fs::exists(kRaytrace)) ADD_FAILURE() << kRaytrace << " is missing: build the raytrace target";
    return test::run_command("cd '" + folder + "' && '" + kRaytrace + "' " + arguments + " 2>&1");
}

std::vector<float> read_channel(const std::string& path, const char* name, int& width, int& height) {
    Imf::InputFile file(path.c_str());
    const auto window = file.header().dataWindow();
    width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    std::vector<float> values(size_t(width) * height);
    Imf::FrameBuffer frame;
    frame.insert(name, Imf::Slice(Imf::FLOAT, (char*)values.data(), sizeof(float), sizeof(float) * width));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return values;
}

TEST(RaytraceTool, PovRaySwitchesWriteExrWithLuminanceAndPng) {
    test::ScratchDir dir;
    const auto r = raytrace("'" + kCornell + "' +W32 +H24 +Oout.exr --passes 2 -q", dir.path().string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(test::read_file(dir.file("out.png")).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
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
        illuminance_receiver { <-500, 0, -500>, <0, 0, 1000>, <1000, 0, 0> resolution <4, 3> name "floor" }
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
              "i,j,x,y,z,illuminance_lx,standard_error_lx,irradiance_red_W_m2,irradiance_green_W_m2,irradiance_blue_W_m2");
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
    test::write_file(dir.file("x.ini"), "Width=20\nAntialias=on\n");
    auto r = raytrace("x.ini '" + kCornell + "'", dir.path().string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("x.ini:2: not supported: .ini option 'Antialias'"), std::string::npos) << r.output;
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

}  // namespace
}  // namespace rayset::tracer
