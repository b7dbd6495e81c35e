#pragma once
/// @file ToolTest.h
/// A test fixture that runs one of the build's command-line tools
/// (tessera-heightgen, tessera-texgen) as a process, in a fresh temporary
/// directory, keeping its stderr apart from its stdout: the tools' tests
/// read progress and error messages from stderr alone.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace tessera::test {

class ToolTest : public ::testing::Test {
protected:
    /// Finds `tool` in the build's bin/ (the test is skipped when it was
    /// not built) and makes the test's directory. Call from SetUp.
    void useTool(const std::string& tool) {
        mTool = std::filesystem::path(TESSERA_BINARY_DIR) / "bin" / tool;
        if (!std::filesystem::exists(mTool)) GTEST_SKIP() << mTool << " not built";
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDir = std::filesystem::path(::testing::TempDir()) /
               (tool + "_" + std::string(info->name()) + "_" + std::to_string(getpid()));
        std::filesystem::remove_all(mDir);
        std::filesystem::create_directories(mDir);
    }
    void TearDown() override {
        if (!mDir.empty()) std::filesystem::remove_all(mDir);
    }

    /// Runs the tool with `arguments` (shell words); returns its exit status
    /// (-1 when it did not exit normally), its stderr in mStderr.
    int run(const std::string& arguments) {
        const std::filesystem::path errors = mDir / "stderr.txt";
        // Appended piece by piece: GCC 12 misreads `"'" + std::string&&` as
        // an overlapping copy (-Wrestrict).
        std::string command = "'";
        command += mTool.string();
        command += "' ";
        command += arguments;
        command += " 2>'";
        command += errors.string();
        command += "'";
        const int status = std::system(command.c_str());
        std::ifstream in(errors);
        mStderr.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    /// The whole of a file's bytes (empty when it cannot be read).
    static std::string read(const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

    std::filesystem::path mTool, mDir;
    std::string mStderr;
};

} // namespace tessera::test
