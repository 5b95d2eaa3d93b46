// A disk that fills up while raytrace writes its image and checkpoint: an error naming the file
// and the reason, no partial file, and the image and checkpoint the user had kept as they were.
#include "support/test_support.h"
#include "tracer/tracer_support.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rayset::test {
namespace {

TEST(FullDisk, RenderFailsAndKeepsThePreviousImageAndCheckpoint) {
    // Three pages: two for the files there before, one free (less than the image needs).
    SmallDisk disk(12 << 10);
    if (!disk.mounted()) GTEST_SKIP() << disk.why();
    write_file(disk.file("out.exr"), "previous image");
    write_file(disk.file("out.checkpoint"), "previous checkpoint");
    const CommandResult r = run_command(std::string(RAYSET_BINARY_DIR) + "/tracer/raytrace " +
                                        tracer_scene("cornell.pov") + " +W48 +H36 --passes 2 -q " +
                                        "--checkpoint-interval 0 -o " + disk.file("out.exr"));
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(disk.file("out.")), std::string::npos) << r.output;
    EXPECT_EQ(read_file(disk.file("out.exr")), "previous image");
    EXPECT_EQ(read_file(disk.file("out.checkpoint")), "previous checkpoint");
    EXPECT_EQ(disk.names(), (std::vector<std::string>{"out.checkpoint", "out.exr"}));
}

}  // namespace
}  // namespace rayset::test
