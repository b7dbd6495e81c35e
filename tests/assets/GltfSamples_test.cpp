// Khronos sample models: every variant loads; CesiumMan agrees across its
// uncompressed, binary and Draco variants.
#include "tessera/assets/GltfLoader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace fs = std::filesystem;
using tessera::assets::loadCharacter;
using tessera::character::CharacterAsset;

namespace {

const fs::path kSamples = fs::path(TESSERA_TESTDATA_DIR) / "gltf";

CharacterAsset loadOrFail(const fs::path& file) {
    auto result = loadCharacter(file);
    EXPECT_TRUE(result.ok()) << (result ? "" : result.error().message);
    return result ? std::move(result).value() : CharacterAsset{};
}

std::vector<float> sortedTriangleAreas(const CharacterAsset& a) {
    std::vector<float> areas;
    const auto& v = a.cage.vertices;
    const auto& i = a.cage.indices;
    for (size_t t = 0; t + 2 < i.size(); t += 3)
        areas.push_back(0.5f * glm::length(glm::cross(v[i[t + 1]].position - v[i[t]].position,
                                                      v[i[t + 2]].position - v[i[t]].position)));
    std::sort(areas.begin(), areas.end());
    return areas;
}

} // namespace

TEST(GltfSamples, EveryVariantLoads) {
    size_t loaded = 0;
    for (const auto& model : fs::directory_iterator(kSamples)) {
        if (!model.is_directory()) continue;
        for (const auto& variant : fs::directory_iterator(model.path())) {
            if (!variant.is_directory()) continue;
            for (const auto& file : fs::directory_iterator(variant.path())) {
                std::string ext = file.path().extension().string();
                if (ext != ".gltf" && ext != ".glb") continue;
                CharacterAsset asset = loadOrFail(file.path());
                EXPECT_GT(asset.cage.triangleCount(), 0u) << file.path();
                EXPECT_TRUE(asset.skeleton.isParentFirst()) << file.path();
                for (const auto& vertex : asset.cage.vertices) {
                    ASSERT_NEAR(glm::length(vertex.normal), 1.0f, 1e-3f) << file.path();
                    ASSERT_NEAR(vertex.weights.x + vertex.weights.y + vertex.weights.z + vertex.weights.w, 1.0f, 1e-3f);
                    for (int c = 0; c < 4; ++c) ASSERT_LT(vertex.joints[c], std::max<size_t>(asset.cage.bindings.size(), 1));
                }
                ++loaded;
            }
        }
    }
    EXPECT_GE(loaded, 30u);
}

TEST(GltfSamples, CesiumManVariantsAgree) {
    CharacterAsset plain = loadOrFail(kSamples / "CesiumMan/glTF/CesiumMan.gltf");
    CharacterAsset binary = loadOrFail(kSamples / "CesiumMan/glTF-Binary/CesiumMan.glb");
    CharacterAsset draco = loadOrFail(kSamples / "CesiumMan/glTF-Draco/CesiumMan.gltf");
    std::vector<const CharacterAsset*> variants = {&plain, &binary, &draco};
    if (fs::exists(kSamples / "CesiumMan/glTF-Embedded/CesiumMan.gltf"))
        variants.push_back(new CharacterAsset(loadOrFail(kSamples / "CesiumMan/glTF-Embedded/CesiumMan.gltf")));
    for (const CharacterAsset* a : variants) {
        EXPECT_EQ(a->cage.triangleCount(), plain.cage.triangleCount());
        EXPECT_EQ(a->cage.bindings.size(), 19u);
        ASSERT_EQ(a->clips.size(), 1u);
        ASSERT_TRUE(a->baseColor.has_value());
        EXPECT_EQ(a->baseColor->width, 1024u);
        EXPECT_EQ(a->baseColor->height, 1024u);
        EXPECT_EQ(a->baseColor->bytes.size(), 1024u * 1024u * 4u);
    }
    // Draco reorders and quantises: compare bounds and the sorted triangle areas.
    glm::vec3 lo(1e9f), hi(-1e9f), dlo(1e9f), dhi(-1e9f);
    for (const auto& v : plain.cage.vertices) { lo = glm::min(lo, v.position); hi = glm::max(hi, v.position); }
    for (const auto& v : draco.cage.vertices) { dlo = glm::min(dlo, v.position); dhi = glm::max(dhi, v.position); }
    float tolerance = glm::length(hi - lo) * 2e-3f;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(lo[c], dlo[c], tolerance);
        EXPECT_NEAR(hi[c], dhi[c], tolerance);
    }
    std::vector<float> a = sortedTriangleAreas(plain), b = sortedTriangleAreas(draco);
    ASSERT_EQ(a.size(), b.size());
    float maxArea = a.back();
    for (size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(a[i], b[i], maxArea * 0.02f) << i;
    // The walk cycle: finite unit rotations and a positive duration.
    const auto& clip = plain.clips[0];
    EXPECT_GT(clip.duration(), 0.5f);
    EXPECT_LT(clip.duration(), 10.0f);
    for (const auto& channel : clip.channels) {
        EXPECT_LT(channel.node, plain.skeleton.nodes.size());
        for (size_t k = 1; k < channel.times.size(); ++k) EXPECT_GT(channel.times[k], channel.times[k - 1]);
        for (const auto& v : channel.values) {
            EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w));
            if (channel.path == tessera::character::AnimationPath::Rotation) {
                EXPECT_NEAR(glm::length(v), 1.0f, 1e-3f);
            }
        }
    }
    for (size_t i = 3; i < variants.size(); ++i) delete variants[i];
}
