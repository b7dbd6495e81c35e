// Stride length (character::measureStride) of the generated creatures' walk:
// made in memory by the generator, and as the build ships them (loaded back
// through the engine's loader, Draco and all). The figures must agree, pick
// the foot joints, and be plausible for the creature's legs; the idle must
// not walk.
#include "creature/CreatureGenerator.h"
#include "tessera/assets/GltfLoader.h"
#include "tessera/character/Pose.h"
#include "tessera/character/StrideLength.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace {

using tessera::character::CharacterAsset;
using tessera::character::StrideMeasure;

std::filesystem::path shippedCreature(int seed) {
    return std::filesystem::path(TESSERA_BINARY_DIR) / "content" / "characters" /
           ("froblin_" + std::to_string(seed) + ".glb");
}

size_t clipNamed(const CharacterAsset& asset, const std::string& name) {
    for (size_t i = 0; i < asset.clips.size(); ++i)
        if (asset.clips[i].name == name) return i;
    ADD_FAILURE() << asset.name << " has no clip " << name;
    return asset.clips.size();
}

// The rest-pose bone lengths from `foot` up to `hips`.
float legLength(const CharacterAsset& asset, uint32_t foot, uint32_t hips) {
    const tessera::character::Pose rest(asset.skeleton);
    float length = 0.0f;
    for (int32_t i = static_cast<int32_t>(foot); i > 0 && i != static_cast<int32_t>(hips);) {
        const int32_t parent = asset.skeleton.nodes[static_cast<size_t>(i)].parent;
        length += glm::distance(glm::vec3(rest.globals()[static_cast<size_t>(i)][3]),
                                glm::vec3(rest.globals()[static_cast<size_t>(parent)][3]));
        i = parent;
    }
    return length;
}

// Checks one creature's walk and idle; returns the walk's measure.
StrideMeasure checkCreature(const CharacterAsset& asset, const std::string& label) {
    const StrideMeasure walk = tessera::character::measureStride(asset, clipNamed(asset, "walk"));
    const StrideMeasure idle = tessera::character::measureStride(asset, clipNamed(asset, "idle"));
    EXPECT_EQ(idle.strideLength, 0.0f) << label;

    std::string feet;
    for (uint32_t f : walk.feet) feet += (feet.empty() ? "" : ", ") + asset.skeleton.nodes[f].name;
    EXPECT_EQ(feet, "foot_l, foot_r") << label;
    if (walk.feet.size() != 2) return walk;

    const uint32_t hips = 1; // "hips": the feet's common ancestor
    EXPECT_EQ(asset.skeleton.nodes[hips].name, "hips");
    const float leg = 0.5f * (legLength(asset, walk.feet[0], hips) + legLength(asset, walk.feet[1], hips));
    const float duration = asset.clips[clipNamed(asset, "walk")].duration();
    std::printf("%s: walk %.3f s, feet %s, leg %.3f m: stride %.3f m (%.2f legs), natural speed %.3f m/s; "
                "idle stride %.3f\n",
                label.c_str(), duration, feet.c_str(), leg, walk.strideLength, walk.strideLength / leg,
                walk.naturalSpeed, idle.strideLength);
    // A walk covers between half a leg and three legs per cycle (a person at
    // a comfortable walk: about 1.5 to 2 leg lengths).
    EXPECT_GT(walk.strideLength, 0.5f * leg) << label;
    EXPECT_LT(walk.strideLength, 3.0f * leg) << label;
    EXPECT_NEAR(walk.naturalSpeed * duration, walk.strideLength, 1e-5f) << label;
    return walk;
}

} // namespace

TEST(CreatureStrideLength, GeneratedAndShippedCreaturesAgree) {
    tessera::creature::CreatureOptions options;
    options.seed = 1;
    // The skeleton and clips do not depend on the mesh's resolution.
    options.sculptTriangles = 50'000;
    options.cageTriangles = 1'000;
    options.baseColorSize = 64;
    const tessera::creature::Creature generated = tessera::creature::generateCreature(options);
    const StrideMeasure fresh = checkCreature(generated.asset, "froblin seed 1 (generated)");

    for (int seed = 1; seed <= 3; ++seed) {
        const auto file = shippedCreature(seed);
        if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not built";
        auto loaded = tessera::assets::loadCharacter(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        const StrideMeasure shipped = checkCreature(loaded.value(), file.filename().string());
        // The file keys the same clip at the same times.
        if (seed == 1) {
            EXPECT_NEAR(shipped.strideLength, fresh.strideLength, 1e-3f * fresh.strideLength);
        }
    }
}
