// The tessera-texgen command line, run as a process: byte-identical textures
// for the same flags, different ones for another seed, and exit status 2 with
// a message naming the bad flag. Skipped when the tool has not been built.

#include "ToolTest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;

namespace {

const char* const kMaterials[] = {"grass", "dirt", "rock", "snow"};

class TerrainTexgenTool : public tessera::test::ToolTest {
protected:
    void SetUp() override { useTool("tessera-texgen"); }
};

} // namespace

TEST_F(TerrainTexgenTool, SameFlagsGiveByteIdenticalFiles) {
    const fs::path a = mDir / "a", b = mDir / "nested" / "b", c = mDir / "c";
    ASSERT_EQ(run("--size 64 --seed 9 --quiet --out-dir '" + a.string() + "'"), 0) << mStderr;
    ASSERT_EQ(run("--size=64 --seed=9 --out-dir '" + b.string() + "'"), 0) << mStderr;
    ASSERT_EQ(run("--size 64 --seed 10 --quiet --out-dir '" + c.string() + "'"), 0) << mStderr;
    for (const char* material : kMaterials) {
        const std::string file = std::string("detail_") + material + ".png";
        SCOPED_TRACE(file);
        EXPECT_FALSE(read(a / file).empty());
        EXPECT_TRUE(read(a / file) == read(b / file));
        EXPECT_FALSE(read(a / file) == read(c / file)) << "the seed changes nothing";
    }
}

TEST_F(TerrainTexgenTool, BadFlagsExitWithStatus2NamingTheFlag) {
    const std::string out = " --out-dir '" + (mDir / "x").string() + "'";
    EXPECT_EQ(run("--size 100" + out), 2);
    EXPECT_NE(mStderr.find("--size"), std::string::npos) << mStderr;
    EXPECT_NE(mStderr.find("usage:"), std::string::npos) << mStderr;
    EXPECT_EQ(run("--size 8" + out), 2);
    EXPECT_EQ(run("--size abc" + out), 2);
    EXPECT_EQ(run("--seed -1" + out), 2);
    EXPECT_EQ(run("--frobnicate" + out), 2);
    EXPECT_NE(mStderr.find("--frobnicate"), std::string::npos) << mStderr;
    EXPECT_EQ(run("--size 64"), 2);
    EXPECT_NE(mStderr.find("--out-dir"), std::string::npos) << mStderr;
    EXPECT_FALSE(fs::exists(mDir / "x"));
}
