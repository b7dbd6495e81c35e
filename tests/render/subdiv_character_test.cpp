// The generated Froblin as a Catmull-Clark surface (issue 14, item 5;
// docs/SUBDIV.md, "The Froblin as a Catmull-Clark surface"): the same
// creature drawn by the first paper's planar method and by the second's
// (--character-surface both) on a magenta background, both in view and
// validation-clean; bad values and bad or missing .cctiles files get a
// clear message and a non-zero exit, never a crash.
#include "CharacterDemo.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

namespace fs = std::filesystem;

void expectFailure(const std::vector<std::string>& args, int exitCode, const std::string& expected) {
    const ProcessResult run = runDemo(args);
    EXPECT_EQ(run.exitCode, exitCode) << demoCommandLine(args) << ": crashed or wrong exit code: " << run.output;
    EXPECT_NE(run.output.find(expected), std::string::npos)
        << demoCommandLine(args) << ": expected \"" << expected << "\" in: " << run.output;
}

std::string tilesOf(const std::string& glb) {
    return fs::path(glb).replace_extension(".cctiles").string();
}

/// Copies froblin_1.glb into the test's folder under `name`, without its tiles.
std::string copiedFroblin(const std::string& name) {
    const fs::path dir = testOutputDir("subdiv_character");
    const fs::path glb = dir / (name + ".glb");
    fs::copy_file(froblinFile(1), glb, fs::copy_options::overwrite_existing);
    fs::remove(tilesOf(glb.string()));
    return glb.string();
}

} // namespace

TEST(SubdivCharacter, BothSurfacesStandSideBySide) {
    constexpr int kWidth = 320, kHeight = 240;
    std::vector<std::string> args = soloCharacterArgs("hulldomain", froblinFile(1), "1,0,1", "3", kWidth, kHeight);
    args.insert(args.end(), {"--character-surface", "both", "--frames", "2"});
    const DemoShot shot = runDemoShot(args, testOutputDir("subdiv_character") / "both.png");
    ASSERT_EQ(shot.result.exitCode, 0) << shot.command << "\n" << shot.result.output;
    EXPECT_TRUE(validationClean(shot.result)) << shot.command << "\n" << shot.result.output;
    ASSERT_TRUE(shot.image) << shot.command << ": " << shot.readError;
    const Rgba8Image& image = *shot.image;
    // Creature pixels per column, then runs of occupied columns (gaps of up
    // to 3 columns bridged): the planar creature and the Catmull-Clark one
    // to its right must be two separate figures, each well in view.
    std::vector<size_t> columns(image.width, 0);
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const uint8_t* p = &image.pixels[(size_t(y) * image.width + x) * 4];
            const bool background = p[0] > 240 && p[1] < 15 && p[2] > 240;
            columns[x] += background ? 0 : 1;
        }
    struct Run {
        uint32_t first, last;
        size_t pixels;
    };
    std::vector<Run> runs;
    for (uint32_t x = 0; x < image.width; ++x) {
        if (!columns[x]) continue;
        if (!runs.empty() && x - runs.back().last <= 3) {
            runs.back().last = x;
            runs.back().pixels += columns[x];
        } else {
            runs.push_back({x, x, columns[x]});
        }
    }
    std::cout << "[subdiv character] " << shot.screenshot << ":";
    for (const Run& r : runs) std::cout << " columns " << r.first << ".." << r.last << " " << r.pixels << " px;";
    std::cout << "\n";
    ASSERT_EQ(runs.size(), 2u) << "expected two creatures side by side\n  " << shot.command;
    // A creature here covers about 2,000 pixels, drawn either way.
    EXPECT_GT(runs[0].pixels, 1500u) << "the planar creature\n  " << shot.command;
    EXPECT_GT(runs[1].pixels, 1500u) << "the Catmull-Clark creature\n  " << shot.command;
    EXPECT_LT(runs[0].last, runs[1].first);
}

TEST(SubdivCharacter, CatmullClarkAloneRunsOnTheNullBackend) {
    const std::vector<std::string> args = {"--backend", "null", "--crowd", "0", "--model", froblinFile(1),
                                           "--character-surface", "catmull-clark", "--frames", "2"};
    const ProcessResult run = runDemo(args);
    EXPECT_EQ(run.exitCode, 0) << demoCommandLine(args) << "\n" << run.output;
}

TEST(SubdivCharacter, BadValuesAreRefused) {
    expectFailure({"--character-surface", "nurbs"}, 2,
                  "--character-surface expects planar, catmull-clark or both, got \"nurbs\"");
    expectFailure({"--character-surface", "both"}, 2, "--character-surface both draws the --model .glb files");
}

// Every backend draws the Catmull-Clark creature (the emulated ones at
// their tessellator's levels, up to 14.99).
TEST(SubdivCharacter, EveryBackendDrawsBoth) {
    for (const char* backend : {"streamout", "r2vb"}) {
        const std::vector<std::string> args = {"--backend", backend, "--crowd", "0", "--model", froblinFile(1),
                                               "--character-surface", "both", "--frames", "1", "--width", "320",
                                               "--height", "240", "--validation"};
        const ProcessResult run = runDemo(args);
        EXPECT_EQ(run.exitCode, 0) << demoCommandLine(args) << "\n" << run.output;
        EXPECT_TRUE(validationClean(run)) << demoCommandLine(args) << "\n" << run.output;
    }
}

TEST(SubdivCharacter, MissingCorruptedOrForeignTilesNameTheFile) {
    auto run = [](const std::string& glb) {
        return std::vector<std::string>{"--backend", "null", "--crowd", "0", "--model", glb,
                                        "--character-surface", "catmull-clark", "--frames", "1"};
    };
    const std::string missing = copiedFroblin("missing");
    expectFailure(run(missing), 1, tilesOf(missing) + ": cannot open the tile file");

    const std::string truncated = copiedFroblin("truncated");
    fs::copy_file(tilesOf(froblinFile(1)), tilesOf(truncated));
    fs::resize_file(tilesOf(truncated), fs::file_size(tilesOf(truncated)) - 100);
    expectFailure(run(truncated), 1, tilesOf(truncated) + ": truncated");

    const std::string flipped = copiedFroblin("flipped");
    fs::copy_file(tilesOf(froblinFile(1)), tilesOf(flipped));
    {
        // A byte among the coefficients (the tile sizes come first and are
        // range-checked on their own): only the checksum can tell.
        const std::streamoff at = std::streamoff(fs::file_size(tilesOf(flipped))) - 1000;
        std::fstream f(tilesOf(flipped), std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(at);
        const char byte = char(f.get() ^ 0x5a);
        f.seekp(at);
        f.put(byte);
    }
    expectFailure(run(flipped), 1, tilesOf(flipped) + ": checksum mismatch");

    const std::string foreign = copiedFroblin("foreign");
    fs::copy_file(tilesOf(froblinFile(2)), tilesOf(foreign));
    expectFailure(run(foreign), 1, tilesOf(foreign) + ": baked for another cage");
}
