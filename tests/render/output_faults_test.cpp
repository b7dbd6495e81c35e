// Faults around the demo's files (docs/RELIABILITY.md, "Faults"): a full
// disk (/dev/full) or a path that cannot be created for every output, and
// truncated content. Each is one error line naming the path, exit 1, no
// validation message, and nothing of the user's deleted.
#include "CharacterDemo.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using namespace tessera::test;
namespace fs = std::filesystem;

namespace {

// Under --validation: a message would be a second error line.
void expectFailure(std::vector<std::string> args, const std::string& path) {
    args.insert(args.end(), {"--validation"});
    std::cout << "[faults] " << expectOneLineError(args, 1, path) << "\n";
}

bool isCharacterDevice(const char* path) {
    struct stat s {};
    return stat(path, &s) == 0 && S_ISCHR(s.st_mode);
}

/// The first `keep` bytes of `from`, written to the test output folder.
std::string truncatedCopy(const fs::path& from, size_t keep, const std::string& name) {
    std::ifstream in(from, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    bytes.resize(std::min(keep, bytes.size()));
    const fs::path out = testOutputDir("faults") / name;
    std::ofstream(out, std::ios::binary) << bytes;
    return out.string();
}

const std::vector<std::string> kSmallRun = {"--backend", "r2vb", "--scene", "terrain", "--width", "64",
                                            "--height",  "64",   "--frames", "2"};

std::vector<std::string> smallRunWith(std::initializer_list<std::string> extra) {
    std::vector<std::string> args = kSmallRun;
    args.insert(args.end(), extra);
    return args;
}

} // namespace

TEST(OutputFaults, AFullDiskFailsEveryOutputAndDeletesNothing) {
    if (!isCharacterDevice("/dev/full")) GTEST_SKIP() << "no /dev/full on this machine";
    for (const char* flag : {"--screenshot", "--capture", "--benchmark"})
        expectFailure(smallRunWith({flag, "/dev/full"}), "/dev/full");
    expectFailure({"--bench", "terrain", "--backend", "r2vb", "--frames", "2", "--width", "64", "--height", "64",
                   "--out", "/dev/full"},
                  "/dev/full");
    // The failed write did not remove the device it could not write to.
    EXPECT_TRUE(isCharacterDevice("/dev/full"));
}

TEST(OutputFaults, PathsThatCannotBeCreatedFail) {
    // /proc takes no new files, not even from root.
    for (const char* flag : {"--capture", "--benchmark", "--screenshot"})
        expectFailure(smallRunWith({flag, "/proc/tessera/out.file"}), "/proc/tessera/out.file");
    expectFailure(smallRunWith({"--record", "/proc/tessera-frames"}), "/proc/tessera-frames");
}

TEST(OutputFaults, TruncatedContentNamesTheFile) {
    const std::string heights = truncatedCopy(buildContentDir() / "terrain" / "height.png", 4000, "height_cut.png");
    expectFailure(smallRunWith({"--heightmap", heights}), heights);
    const std::string creature = truncatedCopy(froblinFile(1), 20000, "froblin_cut.glb");
    expectFailure({"--backend", "r2vb", "--scene", "characters", "--crowd", "0", "--model", creature, "--width", "64",
                   "--height", "64", "--frames", "1"},
                  creature);
}

// Out of device memory as a user meets it: --device-memory-cap smaller than
// the scene. One line naming the allocation and the cap, exit 1, and the
// validation layer's object tracking clean (every object released as the
// error unwound). The walk over every allocation is in
// tests/runtime/device_memory_exhaustion_test.cpp.
TEST(OutputFaults, ADeviceTooSmallEndsTheRunCleanly) {
    for (const char* backend : {"hulldomain", "r2vb", "streamout", "meshshader"}) {
        if (!deviceRunsBackend(backend)) continue;
        expectFailure({"--backend", backend, "--scene", "terrain", "--width", "64", "--height", "64", "--frames", "2",
                       "--device-memory-cap", "16"},
                      "of the 16.00 MiB cap in use");
    }
    // Enough for the terrain but not for a crowd: it fails later, in the crowd's upload.
    const std::string line = expectOneLineError(
        {"--backend", "hulldomain", "--agents", "64", "--width", "64", "--height", "64", "--frames", "2",
         "--device-memory-cap", "64", "--validation"},
        1, "of the 64.00 MiB cap in use");
    EXPECT_NE(line.find("raise it (--device-memory-cap)"), std::string::npos) << line;
}
