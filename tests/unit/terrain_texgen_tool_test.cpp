// The tessera-texgen command line, run as a process: byte-identical textures
// for the same flags, different ones for another seed, and exit status 2 with
// a message naming the bad flag. Skipped when the tool has not been built.

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

const char* const kMaterials[] = {"grass", "dirt", "rock", "snow"};

class TerrainTexgenTool : public ::testing::Test {
protected:
    void SetUp() override {
        mTool = fs::path(TESSERA_BINARY_DIR) / "bin" / "tessera-texgen";
        if (!fs::exists(mTool)) GTEST_SKIP() << mTool << " not built";
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDir = fs::path(::testing::TempDir()) /
               ("tessera_texgen_" + std::string(info->name()) + "_" + std::to_string(getpid()));
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override {
        if (!mDir.empty()) fs::remove_all(mDir);
    }

    /// Runs the tool with `arguments`; returns its exit status, stderr in mStderr.
    int run(const std::string& arguments) {
        const fs::path errors = mDir / "stderr.txt";
        // Appended piece by piece: GCC 12 misreads `"'" + std::string&&` here
        // as an overlapping copy (-Wrestrict).
        std::string command = "'";
        command += mTool.string();
        command += "' ";
        command += arguments;
        command += " 2>'";
        command += errors.string();
        command += "'";
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
