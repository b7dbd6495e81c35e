// The tessera-heightgen command line, run as a process: byte-identical output
// for the same flags, and exit status 2 with a message naming the bad flag.
// Skipped when the tool has not been built next to the tests.

#include "ToolTest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;

namespace {

class TerrainHeightgenTool : public tessera::test::ToolTest {
protected:
    void SetUp() override { useTool("tessera-heightgen"); }
};

} // namespace

TEST_F(TerrainHeightgenTool, SameFlagsGiveByteIdenticalFiles) {
    const fs::path a = mDir / "a.png", b = mDir / "nested" / "b.png";
    ASSERT_EQ(run("--size 128 --seed 9 --quiet --out '" + a.string() + "'"), 0) << mStderr;
    ASSERT_EQ(run("--size=128 --seed=9 --threads 1 --out '" + b.string() + "'"), 0) << mStderr;
    EXPECT_FALSE(read(a).empty());
    EXPECT_TRUE(read(a) == read(b));
}

TEST_F(TerrainHeightgenTool, ProgressWithoutATerminalIsLineBased) {
    ASSERT_EQ(run("--size 64 --out '" + (mDir / "p.png").string() + "'"), 0) << mStderr;
    EXPECT_EQ(mStderr.find('\r'), std::string::npos);
    EXPECT_NE(mStderr.find("hydraulic erosion"), std::string::npos) << mStderr;
    EXPECT_NE(mStderr.find("100%"), std::string::npos) << mStderr;
}

TEST_F(TerrainHeightgenTool, BadSizeExitsWithStatus2) {
    EXPECT_EQ(run("--size 1000 --out x.png"), 2);
    EXPECT_NE(mStderr.find("--size"), std::string::npos) << mStderr;
    EXPECT_NE(mStderr.find("usage:"), std::string::npos) << mStderr;
    EXPECT_EQ(run("--size 16384 --out x.png"), 2);
    EXPECT_EQ(run("--size abc --out x.png"), 2);
}

TEST_F(TerrainHeightgenTool, UnknownFlagAndMissingValuesExitWithStatus2) {
    EXPECT_EQ(run("--frobnicate --out x.png"), 2);
    EXPECT_NE(mStderr.find("--frobnicate"), std::string::npos) << mStderr;
    EXPECT_EQ(run("--size 64"), 2);
    EXPECT_NE(mStderr.find("--out"), std::string::npos) << mStderr;
    EXPECT_EQ(run("--out"), 2);
    EXPECT_NE(mStderr.find("--out"), std::string::npos) << mStderr;
}

TEST_F(TerrainHeightgenTool, HelpExitsWithStatus0) {
    EXPECT_EQ(run("--help >/dev/null"), 0);
}
