// rayconv killed (SIGKILL) at moments drawn at random while it converts: the output's name
// holds either what was there before or the whole conversion, never part of one.
#include "core/random.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>

namespace rayset::test {
namespace {

TEST(Interruptions, AKilledConversionLeavesThePreviousOutputOrTheWholeOne) {
    ScratchDir dir;
    const std::string rays = dir.file("disk.tm25ray"), reference = dir.file("reference.csv"),
                      target = dir.file("out.csv");
    const std::string rayconv = RAYCONV_EXE;
    ASSERT_EQ(run_command(rayconv + " synth disk --rays 300000 --seed 1 -o " + rays).status, 0);
    const auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(run_command(rayconv + " convert " + rays + " " + reference).status, 0);
    const double whole =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string expected = read_file(reference);
    Pcg32 rng(7);  // the moments of the kills: uniform over 1.2 times an uninterrupted run
    int killed = 0, finished = 0;
    for (int round = 0; round < 12; ++round) {
        write_file(target, "previous");
        if (killed_after({rayconv, "convert", rays, target}, 1.2 * whole * rng.uniform()))
            ++killed;
        else
            ++finished;
        const std::string now = read_file(target);
        EXPECT_TRUE(now == "previous" || now == expected)
            << "round " << round << ": " << now.size() << " bytes under the name";
    }
    // Kills during the conversion happened, or the test would not show what it claims.
    EXPECT_GT(killed, 0) << finished << " conversions ended before their kill";
}

}  // namespace
}  // namespace rayset::test
