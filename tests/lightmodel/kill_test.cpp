// raymodel killed (SIGKILL) at moments drawn at random while it builds: the model's name holds
// either what was there before or a whole model that reads back, never part of one.
#include "core/random.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <string>

namespace rayset::test {
namespace {

TEST(Interruptions, AKilledModelBuildLeavesThePreviousModelOrAWholeOne) {
    ScratchDir dir;
    const std::string rays = dir.file("disk.tm25ray"), target = dir.file("m.vdb");
    const std::string raymodel = RAYMODEL_EXE;
    ASSERT_EQ(run_command(std::string(RAYCONV_EXE) + " synth disk --rays 20000 --seed 1 -o " + rays)
                  .status,
              0);
    const auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(run_command(raymodel + " build " + rays + " -o " + dir.file("whole.vdb")).status, 0);
    const double whole =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Pcg32 rng(11);  // the moments of the kills: uniform over 1.2 times an uninterrupted build
    int killed = 0;
    for (int round = 0; round < 5; ++round) {
        write_file(target, "previous");
        killed +=
            killed_after({raymodel, "build", rays, "-o", target}, 1.2 * whole * rng.uniform());
        if (read_file(target) == "previous") continue;
        const CommandResult info = run_command(raymodel + " info --json " + target);
        ASSERT_EQ(info.status, 0) << "round " << round << ": " << info.output;
        EXPECT_EQ(nlohmann::json::parse(info.output)["source"]["rays"], 20000) << round;
    }
    EXPECT_GT(killed, 0);
}

}  // namespace
}  // namespace rayset::test
