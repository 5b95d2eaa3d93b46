// A disk that fills up while rayconv writes: the conversion fails with an error naming the file
// and the reason, no partial file is left, and what the user had under the name is kept.
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rayset::test {
namespace {

std::string rayconv(const std::string& args) { return std::string(RAYCONV_EXE) + " " + args; }

TEST(FullDisk, ConversionFailsAndKeepsThePreviousOutput) {
    SmallDisk disk(256 << 10);
    if (!disk.mounted()) GTEST_SKIP() << disk.why();
    ScratchDir dir;
    const std::string rays = dir.file("disk.tm25ray");  // 100000 rays: 3.2 MB of TM-25
    ASSERT_EQ(run_command(rayconv("synth disk --rays 100000 --seed 1 -o " + rays)).status, 0);
    write_file(disk.file("out.csv"), "previous");
    for (const std::string target : {"out.csv", "new.zmx.dat"}) {
        const CommandResult r =
            run_command(rayconv("convert " + rays + " " + disk.file(target) +
                                (target == "new.zmx.dat" ? " --to zemax" : "")));
        EXPECT_NE(r.status, 0) << target;
        EXPECT_NE(r.output.find(disk.file(target) + ": write failed: No space left on device"),
                  std::string::npos)
            << r.output;
        EXPECT_EQ(read_file(disk.file("out.csv")), "previous");
        EXPECT_EQ(disk.names(), std::vector<std::string>{"out.csv"});
    }
}

}  // namespace
}  // namespace rayset::test
