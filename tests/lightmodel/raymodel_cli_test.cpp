// The raymodel tool end to end: build from a synthetic file, read the summary back, and refuse
// bad input with a message that names the file, a non-zero exit and no model file left behind.
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace rayset::test {
namespace {

TEST(RaymodelCli, BuildsAModelWhoseInfoGivesTheRayFilesFlux) {
    ScratchDir dir;
    const std::string rays = dir.file("disk.tm25ray"), model = dir.file("disk.vdb");
    ASSERT_EQ(run_command(std::string(RAYCONV_EXE) +
                          " synth disk radius=1 flux=2 --rays 200000 --seed 3 -o " + rays)
                  .status,
              0);
    const CommandResult build =
        run_command(std::string(RAYMODEL_EXE) + " build " + rays + " -o " + model + " --threads 2");
    ASSERT_EQ(build.status, 0) << build.output;
    const CommandResult info =
        run_command(std::string(RAYMODEL_EXE) + " info " + model + " --json");
    ASSERT_EQ(info.status, 0) << info.output;
    const auto j = nlohmann::json::parse(info.output);
    EXPECT_NEAR(j["total_flux"].get<double>(), 2, 2e-6);  // the rays' float fluxes sum to 2 W
    EXPECT_EQ(j["source"]["rays"].get<uint64_t>(), 200000u);
    EXPECT_EQ(j["density_lattice"]["resolution"].get<int>(), 56);  // round(sqrt(200000 / 64))
    EXPECT_GT(j["spheres"].get<size_t>(), 0u);
}

TEST(RaymodelCli, RefusesWhatIsNotARayFileAndLeavesNoModel) {
    ScratchDir dir;
    const std::string bad = dir.file("bad.tm25ray"), model = dir.file("bad.vdb");
    write_file(bad, "this is not a ray file\n");
    const CommandResult r =
        run_command(std::string(RAYMODEL_EXE) + " build " + bad + " -o " + model);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("bad.tm25ray"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(model));
    for (const auto& entry :
         std::filesystem::directory_iterator(dir.path()))  // no hidden temporary left
        EXPECT_NE(entry.path().filename().string().rfind('.', 0), 0u) << entry.path();
}

TEST(RaymodelCli, RefusesAFileThatIsNotAModel) {
    ScratchDir dir;
    const std::string bad = dir.file("bad.vdb");
    write_file(bad, "not openvdb");
    const CommandResult r = run_command(std::string(RAYMODEL_EXE) + " info " + bad);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("bad.vdb"), std::string::npos) << r.output;
}

// Exit codes as docs/architecture.md gives them: 2 for a usage error (here a value outside an
// option's choices, which the option table's diagram_smoothing has), nothing written.
TEST(RaymodelCli, AUsageErrorExitsWith2) {
    ScratchDir dir;
    write_file(dir.file("x.tm25ray"), "the options are read before the file");
    const CommandResult r =
        run_command(std::string(RAYMODEL_EXE) + " build " + dir.file("x.tm25ray") + " -o " +
                    dir.file("m.vdb") + " --diagram-smoothing maybe");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--diagram-smoothing"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("m.vdb")));
    EXPECT_EQ(run_command(std::string(RAYMODEL_EXE) + " build --help").status, 0);
}

}  // namespace
}  // namespace rayset::test
