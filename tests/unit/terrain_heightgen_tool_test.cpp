// The tessera-heightgen command line, run as a process: byte-identical output
// for the same flags, and exit status 2 with a message naming the bad flag.
// Skipped when the tool has not been built next to the tests.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

class TerrainHeightgenTool : public ::testing::Test {
protected:
    void SetUp() override {
        mTool = fs::path(TESSERA_BINARY_DIR) / "bin" / "tessera-heightgen";
        if (!fs::exists(mTool)) GTEST_SKIP() << mTool << " not built";
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDir = fs::path(::testing::TempDir()) /
               ("tessera_heightgen_" + std::string(info->name()) + "_" + std::to_string(getpid()));
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override {
        if (!mDir.empty()) fs::remove_all(mDir);
    }

    /// Runs the tool with `arguments`; returns its exit status, stderr in mStderr.
    int run(const std::string& arguments) {
        const fs::path errors = mDir / "stderr.txt";
        const std::string command = "'" + mTool.string() + "' " + arguments + " 2>'" + errors.string() + "'";
        int status = std::system(command.c_str());
        std::ifstream in(errors);
        mStderr.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    static std::string read(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

    fs::path mTool, mDir;
    std::string mStderr;
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
