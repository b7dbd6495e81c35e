// The impostor atlases of the content build (docs/CROWD.md 6.9): the build's
// froblin_1.impostor is exactly a fresh bake of froblin_1.glb (the content
// build is deterministic, and the runtime may take the file in place of a
// bake), and tessera-impostorgen, run as a process, writes that bake for a
// small exported character and refuses bad flags and files in one line.
#include "GlbTestCharacter.h"
#include "ToolTest.h"
#include "creature/GlbExporter.h"

#include "tessera/assets/GltfLoader.h"
#include "tessera/character/ImpostorBaker.h"
#include "tessera/character/ImpostorFile.h"
#include "tessera/shaders/CrowdImpostor.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace tessera;

TEST(ImpostorContent, TheBuildsFroblinAtlasIsAFreshBakeOfItsGlb) {
    const fs::path dir = fs::path(TESSERA_BINARY_DIR) / "content" / "characters";
    if (!fs::exists(dir / "froblin_1.impostor")) GTEST_SKIP() << "content not built (target tessera_impostors)";
    auto creature = assets::loadCharacter(dir / "froblin_1.glb");
    ASSERT_TRUE(creature) << creature.error().message;
    const auto start = std::chrono::steady_clock::now();
    const character::ImpostorAtlas baked = character::bakeImpostors(creature.value());
    std::cout << "froblin_1 (" << creature->cage.triangleCount() << " cage triangles, " << creature->clips.size()
              << " clips): baked in " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s, " << baked.bytes() << " bytes\n";
    auto stored = character::readImpostorFile(dir / "froblin_1.impostor");
    ASSERT_TRUE(stored) << stored.error().message;
    EXPECT_EQ(stored->layers, uint32_t(creature->clips.size()) * TS_IMPOSTOR_PHASES);
    EXPECT_EQ(stored->centreY, baked.centreY);
    EXPECT_EQ(stored->radius, baked.radius);
    EXPECT_TRUE(stored->albedo == baked.albedo) << "the build's albedo differs from a fresh bake";
    EXPECT_TRUE(stored->normal == baked.normal) << "the build's normals differ from a fresh bake";
}

namespace {

class ImpostorGenTool : public test::ToolTest {
protected:
    void SetUp() override { useTool("tessera-impostorgen"); }
};

} // namespace

TEST_F(ImpostorGenTool, WritesTheBakeOfTheCharacterBesideIt) {
    character::CharacterAsset tube = test::makeTestCharacter();
    tube.clips.resize(1);
    const fs::path glb = mDir / "tube.glb";
    ASSERT_TRUE(creature::exportGlb(tube, glb));
    ASSERT_EQ(run("--in '" + glb.string() + "' --threads 1"), 0) << mStderr;
    EXPECT_NE(mStderr.find("tube.impostor (8 layers"), std::string::npos) << mStderr;
    ASSERT_EQ(run("--quiet --in '" + glb.string() + "' --out '" + (mDir / "b.impostor").string() + "'"), 0) << mStderr;
    EXPECT_TRUE(mStderr.empty()) << mStderr;
    EXPECT_EQ(read(mDir / "tube.impostor"), read(mDir / "b.impostor"));
    auto loaded = assets::loadCharacter(glb);
    ASSERT_TRUE(loaded) << loaded.error().message;
    const std::vector<uint8_t> expected = character::encodeImpostorAtlas(character::bakeImpostors(loaded.value()));
    EXPECT_TRUE(read(mDir / "b.impostor") == std::string(expected.begin(), expected.end()));
}

TEST_F(ImpostorGenTool, BadFlagsAndFilesExitNamingThem) {
    EXPECT_EQ(run("--out x.impostor"), 2);
    EXPECT_NE(mStderr.find("--in"), std::string::npos) << mStderr;
    EXPECT_NE(mStderr.find("usage:"), std::string::npos) << mStderr;
    EXPECT_EQ(run("--in a.glb --threads -1"), 2);
    EXPECT_EQ(run("--in a.glb --frobnicate"), 2);
    EXPECT_NE(mStderr.find("--frobnicate"), std::string::npos) << mStderr;
    const fs::path missing = mDir / "missing.glb";
    EXPECT_EQ(run("--in '" + missing.string() + "'"), 1);
    EXPECT_NE(mStderr.find(missing.string()), std::string::npos) << mStderr;
    EXPECT_FALSE(fs::exists(mDir / "missing.impostor"));
}
