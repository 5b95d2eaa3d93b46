// A disk that fills up while raymodel writes a model: an error naming the file and the reason,
// no partial model, and the model the user had under the name kept.
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rayset::test {
namespace {

TEST(FullDisk, ModelBuildFailsAndKeepsThePreviousModel) {
    SmallDisk disk(64 << 10);
    if (!disk.mounted()) GTEST_SKIP() << disk.why();
    ScratchDir dir;
    const std::string rays = dir.file("disk.tm25ray");
    ASSERT_EQ(run_command(std::string(RAYCONV_EXE) + " synth disk --rays 20000 --seed 1 -o " + rays)
                  .status,
              0);
    // The model of these rays is larger than the disk (checked on a disk with room).
    const CommandResult roomy =
        run_command(std::string(RAYMODEL_EXE) + " build " + rays + " -o " + dir.file("m.vdb"));
    ASSERT_EQ(roomy.status, 0) << roomy.output;
    ASSERT_GT(std::filesystem::file_size(dir.file("m.vdb")), 64u << 10);

    write_file(disk.file("m.vdb"), "previous");
    const CommandResult full =
        run_command(std::string(RAYMODEL_EXE) + " build " + rays + " -o " + disk.file("m.vdb"));
    EXPECT_NE(full.status, 0);
    EXPECT_NE(full.output.find(disk.file("m.vdb") + ": cannot write: No space left on device"),
              std::string::npos)
        << full.output;
    EXPECT_EQ(read_file(disk.file("m.vdb")), "previous");
    EXPECT_EQ(disk.names(), std::vector<std::string>{"m.vdb"});
}

}  // namespace
}  // namespace rayset::test
