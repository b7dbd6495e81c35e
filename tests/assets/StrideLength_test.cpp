// Stride length (character::measureStride) on a model nobody here made:
// Khronos' CesiumMan, whose joints are not named like feet ("leg_joint_L_5")
// and sit under a Z-up to Y-up node and a rotated armature. Its variants must
// agree and the figures must be plausible for its legs.
#include "tessera/assets/GltfLoader.h"
#include "tessera/character/Pose.h"
#include "tessera/character/StrideLength.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using tessera::character::CharacterAsset;
using tessera::character::StrideMeasure;

namespace {

const fs::path kCesiumMan = fs::path(TESSERA_TESTDATA_DIR) / "gltf" / "CesiumMan";

// The rest-pose bone lengths from `foot` up to its ancestor `hips`, and the
// height of `hips` above it.
struct Leg {
    float length = 0.0f;
    float hipHeight = 0.0f;
};

Leg legOf(const CharacterAsset& asset, uint32_t foot, int32_t hips) {
    const tessera::character::Pose rest(asset.skeleton);
    auto at = [&](int32_t node) { return glm::vec3(rest.globals()[static_cast<size_t>(node)][3]); };
    Leg leg;
    for (int32_t i = static_cast<int32_t>(foot); i != hips;) {
        const int32_t parent = asset.skeleton.nodes[static_cast<size_t>(i)].parent;
        if (parent < 0) break;
        leg.length += glm::distance(at(i), at(parent));
        i = parent;
    }
    leg.hipHeight = at(hips).y - at(static_cast<int32_t>(foot)).y;
    return leg;
}

int32_t findNode(const CharacterAsset& asset, const std::string& name) {
    for (size_t i = 0; i < asset.skeleton.nodes.size(); ++i)
        if (asset.skeleton.nodes[i].name == name) return static_cast<int32_t>(i);
    return -1;
}

} // namespace

TEST(StrideLength, CesiumManWalksAPlausibleStride) {
    float firstStride = -1.0f;
    for (const char* variant : {"glTF/CesiumMan.gltf", "glTF-Binary/CesiumMan.glb", "glTF-Draco/CesiumMan.gltf"}) {
        const fs::path file = kCesiumMan / variant;
        if (!fs::exists(file)) GTEST_SKIP() << file << " not found";
        auto loaded = tessera::assets::loadCharacter(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        const CharacterAsset& asset = loaded.value();
        ASSERT_EQ(asset.clips.size(), 1u);

        const StrideMeasure m = tessera::character::measureStride(asset, 0);
        ASSERT_EQ(m.feet.size(), 2u) << variant;
        std::string feet = asset.skeleton.nodes[m.feet[0]].name + ", " + asset.skeleton.nodes[m.feet[1]].name;
        // The toe ends: the lowest leaf joints, one on each leg.
        EXPECT_EQ(feet, "leg_joint_L_5, leg_joint_R_5") << variant;

        // Both legs hang from the pelvis joint.
        const int32_t hips = findNode(asset, "Skeleton_torso_joint_1");
        ASSERT_GE(hips, 0);
        const Leg left = legOf(asset, m.feet[0], hips), right = legOf(asset, m.feet[1], hips);
        const float leg = 0.5f * (left.length + right.length);
        const float duration = asset.clips[0].duration();
        std::printf("%s: clip %.3f s, feet %s, leg %.3f (hips %.3f above the toes): stride %.3f (%.2f legs), "
                    "natural speed %.3f per s\n",
                    variant, duration, feet.c_str(), leg, left.hipHeight, m.strideLength, m.strideLength / leg,
                    m.naturalSpeed);
        // CesiumMan is in metres after its node transforms: hips about 0.7 m up.
        EXPECT_GT(left.hipHeight, 0.5f);
        EXPECT_LT(left.hipHeight, 1.2f);
        // A walk covers between half a leg and three legs per cycle.
        EXPECT_GT(m.strideLength, 0.5f * leg);
        EXPECT_LT(m.strideLength, 3.0f * leg);
        EXPECT_NEAR(m.naturalSpeed * duration, m.strideLength, 1e-5f);
        // The variants hold the same skeleton and clip.
        if (firstStride < 0.0f) firstStride = m.strideLength;
        EXPECT_NEAR(m.strideLength, firstStride, 1e-4f * firstStride) << variant;
    }
}
