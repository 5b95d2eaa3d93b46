// The rayview tool: off-screen PNG and export from the command line, and its exit codes.
#include <gtest/gtest.h>

#include "support/test_support.h"
#include "viz/viz_support.h"

#include <fmt/format.h>
#include <filesystem>

using rayset::test::run_command;

TEST(RayviewCli, RendersAndExportsAModel) {
    rayset::test::ScratchDir dir;
    const std::string model = rayset::test::cluster_model_file();
    const auto png = run_command(fmt::format(
        "'{}' '{}' --show diagram --cell 2,2,0 --png '{}' --size 320x240 --camera 30,20,1.2",
        RAYVIEW_EXE, model, dir.file("d.png")));
    ASSERT_EQ(png.status, 0) << png.output;
    const double all[4] = {0, 1, 0, 1};
    const auto s = rayset::test::png_statistics(dir.file("d.png"), all);
    EXPECT_EQ(s.width, 320);
    EXPECT_EQ(s.height, 240);
    EXPECT_GT(s.foreground, 0.05 * 320 * 240);

    const auto exported =
        run_command(fmt::format("'{}' '{}' --export '{}'", RAYVIEW_EXE, model, dir.file("out")));
    ASSERT_EQ(exported.status, 0) << exported.output;
    for (const char* name :
         {"density.vti", "flux.vti", "spheres.vtp", "diagram_2_2_0.vtp", "cluster.vtm"})
        EXPECT_TRUE(std::filesystem::exists(dir.file(std::string("out/") + name))) << name;
}

TEST(RayviewCli, ExitCodes) {
    rayset::test::ScratchDir dir;
    const std::string model = rayset::test::cluster_model_file();
    EXPECT_EQ(run_command(fmt::format("'{}' --help", RAYVIEW_EXE)).status, 0);
    EXPECT_EQ(run_command(fmt::format("'{}' '{}'", RAYVIEW_EXE, dir.file("missing.vdb"))).status,
              2);
    const auto bad_view = run_command(
        fmt::format("'{}' '{}' --show polar --png '{}'", RAYVIEW_EXE, model, dir.file("x.png")));
    EXPECT_EQ(bad_view.status, 1);
    EXPECT_NE(bad_view.output.find("no view 'polar'"), std::string::npos) << bad_view.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
    const auto bad_cell = run_command(fmt::format(
        "'{}' '{}' --show diagram --cell 9,9,9 --png '{}'", RAYVIEW_EXE, model, dir.file("y.png")));
    EXPECT_EQ(bad_cell.status, 1);
    EXPECT_NE(bad_cell.output.find("emits nothing"), std::string::npos) << bad_cell.output;
}
