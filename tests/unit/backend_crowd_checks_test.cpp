// backend::checkCrowdDesc, what every backend's createCrowd refuses first:
// the per-tier index lists given over a creature's meshes (the middle tier's
// over the cage, the far casters' over the far mesh) must be whole
// triangles of vertices the mesh has, named in one line.
#include "tessera/backend/CrowdChecks.h"
#include "tessera/character/BakedAnimation.h"
#include "tessera/character/CageMesh.h"

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
    std::vector<uint32_t> middle, farCasters;
    backend::CrowdCharacterDesc character;
    backend::CrowdDesc desc;

    Fixture() {
        baked.characterClipBase = {0};
        character.character.id = 0;
        character.cage = &cage;
        character.farMesh = &far;
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
