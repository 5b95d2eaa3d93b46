// rayconv as a user meets it: bad inputs give a message naming the file and the place, a
// non-zero exit, and leave no output (and whatever was at the output path untouched).
#include <gtest/gtest.h>

#include "support/test_support.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <vector>

namespace {

using rayset::test::read_file;
using rayset::test::run_command;
using rayset::test::ScratchDir;
using rayset::test::write_file;

// A minimal TM-25 file made byte by byte (independent of our encoder): radiant flux column only.
std::string tm25_bytes(const std::vector<std::array<float, 7>>& rays, float stated_watts,
                       uint64_t count_in_header) {
    std::string b(256 + 32 + 9 * 4000, '\0');
    std::memcpy(&b[0], "TM25", 4);
    int32_t version = 2013;
    std::memcpy(&b[4], &version, 4);
    float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&b[12], &nan, 4);           // luminous total unknown
    std::memcpy(&b[16], &stated_watts, 4);  // radiant total
    std::memcpy(&b[20], &count_in_header, 8);
    float wavelengths[3] = {nan, nan, nan};
    std::memcpy(&b[64], wavelengths, 12);
    int32_t flags[8] = {1, 1, 1, 0, 0, 0, 0, 0};
    std::memcpy(&b[256], flags, 32);
    for (const auto& r : rays) b.append(reinterpret_cast<const char*>(r.data()), 28);
    return b;
}

const uint64_t kRaysStart = 256 + 32 + 9 * 4000;

std::string rayconv(const std::string& args) { return std::string(RAYCONV_EXE) + " " + args; }

class RayconvCli : public ::testing::Test {
protected:
    ScratchDir dir;
    std::vector<std::array<float, 7>> good{{0, 0, 0, 0, 0, 1, 0.5f},
                                           {1, 0, 0, 0, 0.6f, 0.8f, 0.5f}};

    // Runs a conversion expected to fail; checks the message mentions every `expected` piece and
    // that an output file that existed before is byte-identical afterwards.
    void expect_failure(const std::string& input, const std::vector<std::string>& expected,
                        const std::string& extra = "") {
        const std::string out = dir.file("out.csv");
        write_file(out, "precious user data");
        auto result = run_command(rayconv("convert " + input + " " + out + " " + extra));
        EXPECT_EQ(result.status, 1) << result.output;
        for (const auto& piece : expected)
            EXPECT_NE(result.output.find(piece), std::string::npos)
                << "missing '" << piece << "' in: " << result.output;
        EXPECT_EQ(read_file(out), "precious user data");
        int leftovers = 0;  // no temporary file left beside it
        for (const auto& e : std::filesystem::directory_iterator(dir.path()))
            if (e.path().filename().string().find(".tmp") != std::string::npos) ++leftovers;
        EXPECT_EQ(leftovers, 0);
    }
};

TEST_F(RayconvCli, ConvertsAGoodFileAndTheOutputReadsBack) {
    const std::string in = dir.file("good.tm25ray");
    write_file(in, tm25_bytes(good, 1.0f, 2));
    auto result = run_command(rayconv("convert " + in + " " + dir.file("good.csv")));
    ASSERT_EQ(result.status, 0) << result.output;
    auto info = run_command(rayconv("info --json " + dir.file("good.csv")));
    ASSERT_EQ(info.status, 0) << info.output;
    EXPECT_NE(info.output.find("\"rays\": 2"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("\"radiant_W\": 1.0"), std::string::npos) << info.output;
}

TEST_F(RayconvCli, WrongMagicIsNotARayFile) {
    const std::string in = dir.file("junk.ray");
    write_file(in, std::string("JUNK") + std::string(500, 'x'));
    expect_failure(in, {in, "not a ray file of a known format", "--from"});
}

TEST_F(RayconvCli, TruncatedRaysNameTheFileSize) {
    const std::string in = dir.file("truncated.tm25ray");
    std::string bytes = tm25_bytes(good, 1.0f, 2);
    bytes.resize(bytes.size() - 10);
    write_file(in, bytes);
    expect_failure(in, {in, "byte"});
}

TEST_F(RayconvCli, CountLargerThanTheFile) {
    const std::string in = dir.file("count.tm25ray");
    write_file(in, tm25_bytes(good, 1.0f, 1000000));
    expect_failure(in, {in, "byte"});
}

TEST_F(RayconvCli, NanOriginNamesTheRaysByteOffset) {
    auto rays = good;
    rays[1][1] = std::numeric_limits<float>::quiet_NaN();
    const std::string in = dir.file("nan.tm25ray");
    write_file(in, tm25_bytes(rays, 1.0f, 2));
    expect_failure(in, {in, "byte " + std::to_string(kRaysStart + 28), "ray 2", "origin"});
}

TEST_F(RayconvCli, InfiniteFluxIsRejected) {
    auto rays = good;
    rays[0][6] = std::numeric_limits<float>::infinity();
    const std::string in = dir.file("inf.tm25ray");
    write_file(in, tm25_bytes(rays, 1.0f, 2));
    expect_failure(in, {in, "byte " + std::to_string(kRaysStart), "ray 1", "radiant flux"});
}

TEST_F(RayconvCli, NegativeFluxIsRejected) {
    auto rays = good;
    rays[1][6] = -0.5f;
    const std::string in = dir.file("negative.tm25ray");
    write_file(in, tm25_bytes(rays, 0.0f, 2));
    expect_failure(in, {in, "ray 2", "radiant flux -0.5"});
}

TEST_F(RayconvCli, ZeroFluxEverywhereCarriesNoLight) {
    auto rays = good;
    rays[0][6] = rays[1][6] = 0;
    const std::string in = dir.file("zero.tm25ray");
    write_file(in, tm25_bytes(rays, 0.0f, 2));
    expect_failure(in, {in, "zero flux"});
}

TEST_F(RayconvCli, NonUnitDirectionFailsUnlessNormaliseIsAsked) {
    auto rays = good;
    rays[1][3] = 0, rays[1][4] = 0, rays[1][5] = 2;
    const std::string in = dir.file("long.tm25ray");
    write_file(in, tm25_bytes(rays, 1.0f, 2));
    expect_failure(in, {in, "ray 2", "length 2", "--normalise"});
    auto result = run_command(rayconv("convert --normalise " + in + " " + dir.file("fixed.csv")));
    EXPECT_EQ(result.status, 0) << result.output;
}

TEST_F(RayconvCli, UnknownOutputFormatSaysWhatToDo) {
    const std::string in = dir.file("good.tm25ray");
    write_file(in, tm25_bytes(good, 1.0f, 2));
    auto result = run_command(rayconv("convert " + in + " " + dir.file("out.ray")));
    EXPECT_EQ(result.status, 1);
    EXPECT_NE(result.output.find("--to"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.ray")));
}

TEST_F(RayconvCli, StatedTotalThatDisagreesIsReported) {
    const std::string in = dir.file("disagree.tm25ray");
    write_file(in, tm25_bytes(good, 5.0f, 2));  // rays sum to 1 W
    auto kept = run_command(rayconv("info --json " + in));
    ASSERT_EQ(kept.status, 0) << kept.output;
    EXPECT_NE(kept.output.find("header states 5"), std::string::npos) << kept.output;
    auto scaled = run_command(rayconv("info --json --trust header " + in));
    ASSERT_EQ(scaled.status, 0) << scaled.output;
    EXPECT_NE(scaled.output.find("\"radiant\": 5.0"), std::string::npos)
        << scaled.output;  // flux_scale
}

TEST_F(RayconvCli, MissingInputAndHelp) {
    auto missing = run_command(rayconv("info " + dir.file("nope.tm25ray")));
    EXPECT_NE(missing.status, 0);
    EXPECT_NE(missing.output.find("nope.tm25ray"), std::string::npos);
    EXPECT_EQ(missing.status, 2);  // a usage error (docs/architecture.md)
    EXPECT_EQ(run_command(rayconv("info --no-such-option x")).status, 2);
    auto help = run_command(rayconv("--help"));
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.output.find("convert"), std::string::npos);
}

}  // namespace
