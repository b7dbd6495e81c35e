// backend::checkCrowdDesc, what every backend's createCrowd refuses first:
// the per-tier index lists given over a creature's meshes (the middle tier's
// over the cage, the far casters' over the far mesh) must be whole
// triangles of vertices the mesh has, and its impostor atlas must be
// complete with a layer per phase of each of its clips, named in one line.
#include "tessera/backend/CrowdChecks.h"
#include "tessera/character/BakedAnimation.h"
#include "tessera/character/CageMesh.h"

#include "SyntheticImpostorAtlas.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace tessera;

namespace {

/// A one-triangle mesh of three vertices and one binding.
character::CageMesh triangle() {
    character::CageMesh mesh;
    mesh.vertices.resize(3);
    mesh.indices = {0, 1, 2};
    mesh.bindings.resize(1);
    return mesh;
}

struct Fixture {
    character::CageMesh cage = triangle(), far = triangle();
    character::BakedAnimation baked;
    character::ImpostorAtlas impostor = test::syntheticImpostorAtlas(0, 1);
    std::vector<uint32_t> middle, farCasters;
    backend::CrowdCharacterDesc character;
    backend::CrowdDesc desc;

    Fixture() {
        baked.characterClipBase = {0};
        character.character.id = 0;
        character.cage = &cage;
        character.farMesh = &far;
        character.impostor = &impostor;
        desc.animation = &baked;
        desc.maxInstances = desc.maxIds = 1;
    }
    Status check() {
        character.middleIndices = middle;
        character.farCasterIndices = farCasters;
        desc.characters = std::span<const backend::CrowdCharacterDesc>(&character, 1);
        return backend::checkCrowdDesc(desc);
    }
};

void expectRefused(Fixture& f, const std::string& text) {
    const Status ok = f.check();
    ASSERT_FALSE(ok) << "accepted; expected: " << text;
    EXPECT_NE(ok.error().message.find(text), std::string::npos) << ok.error().message;
}

} // namespace

TEST(CrowdChecks, AcceptsIndexListsOverTheirMeshes) {
    Fixture f;
    EXPECT_TRUE(f.check());
    f.middle = {2, 1, 0};
    f.farCasters = {0, 2, 1};
    EXPECT_TRUE(f.check());
}

TEST(CrowdChecks, RefusesTheMiddleTiersIndicesOutsideTheCage) {
    Fixture f;
    f.middle = {0, 1};
    expectRefused(f, "character 0: its middle tier's index count (2) is not a multiple of 3");
    f.middle = {0, 1, 3};
    expectRefused(f, "character 0: its middle tier's index 3 is past its cage's 3 vertices");
}

TEST(CrowdChecks, RefusesTheFarCastersIndicesOutsideTheFarMesh) {
    Fixture f;
    f.farCasters = {0, 1, 2, 0};
    expectRefused(f, "character 0: its far casters' index count (4) is not a multiple of 3");
    f.farCasters = {0, 1, 7};
    expectRefused(f, "character 0: its far casters' index 7 is past its far mesh's 3 vertices");
}

TEST(CrowdChecks, RefusesACreatureWithoutACompleteImpostorAtlas) {
    Fixture f;
    f.character.impostor = nullptr;
    expectRefused(f, "character 0 has no impostor atlas (character::bakeImpostors)");
    character::ImpostorAtlas empty;
    f.character.impostor = &empty;
    expectRefused(f, "character 0 has no impostor atlas");
    f.character.impostor = &f.impostor;
    f.impostor.albedo[2].pop_back();
    expectRefused(f, "character 0: its impostor atlas's mip 2 holds");
    f.impostor = test::syntheticImpostorAtlas(0, 1);
    f.impostor.radius = 0.0f;
    expectRefused(f, "character 0: its impostor atlas's sphere");
}

TEST(CrowdChecks, RefusesAnImpostorAtlasWithoutALayerPerPhaseOfEveryClip) {
    Fixture f;
    // The creature's baked clips: the rest pose and two clips, then a second
    // creature's rest pose.
    f.baked.clips.resize(4);
    f.baked.characterClipBase = {0, 3};
    backend::CrowdCharacterDesc characters[2] = {f.character, f.character};
    f.desc.characters = characters;
    character::ImpostorAtlas two = test::syntheticImpostorAtlas(0, 2);
    characters[0].impostor = &two;
    EXPECT_TRUE(backend::checkCrowdDesc(f.desc));
    characters[0].impostor = &f.impostor;
    Status ok = backend::checkCrowdDesc(f.desc);
    ASSERT_FALSE(ok);
    EXPECT_NE(ok.error().message.find("character 0: its impostor atlas has 8 layers, its 2 clips need 16 (8 phases "
                                      "each)"),
              std::string::npos)
        << ok.error().message;
    characters[0].impostor = &two;
    characters[1].impostor = &two;
    ok = backend::checkCrowdDesc(f.desc);
    ASSERT_FALSE(ok);
    EXPECT_NE(ok.error().message.find("character 1: its impostor atlas has 16 layers, its 0 clips need 8"),
              std::string::npos)
        << ok.error().message;
}
