// The baker's BVH must return exactly the brute-force answer: same triangle,
// same t, same barycentrics, for closest hits and for two-sided "nearest to
// the surface" queries.

#include "creature/Bvh.h"
#include "tessera/assets/GltfLoader.h"
#include "tessera/core/Random.h"

#include <gtest/gtest.h>

using tessera::Random;
using tessera::creature::Bvh;
using tessera::creature::BvhHit;

namespace {

struct Soup {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
};

glm::vec3 randomPoint(Random& rng, float extent) {
    return {rng.range(-extent, extent), rng.range(-extent, extent), rng.range(-extent, extent)};
}

/// Small triangles scattered in a cube, plus a few large ones crossing it.
Soup makeSoup(uint64_t seed, uint32_t count) {
    Random rng(seed);
    Soup soup;
    for (uint32_t i = 0; i < count; ++i) {
        float size = (i % 50 == 0) ? 1.5f : 0.08f;
        glm::vec3 c = randomPoint(rng, 1.0f);
        for (int k = 0; k < 3; ++k) {
            soup.indices.push_back(static_cast<uint32_t>(soup.positions.size()));
            soup.positions.push_back(c + randomPoint(rng, size));
        }
    }
    return soup;
}

void expectSame(const std::optional<BvhHit>& a, const std::optional<BvhHit>& b) {
    ASSERT_EQ(a.has_value(), b.has_value());
    if (!a) return;
    EXPECT_EQ(a->triangle, b->triangle);
    EXPECT_EQ(a->t, b->t);
    EXPECT_EQ(a->u, b->u);
    EXPECT_EQ(a->v, b->v);
}

} // namespace

TEST(Bvh, ClosestHitMatchesBruteForce) {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
        Soup soup = makeSoup(seed, 3000);
        Bvh bvh(soup.positions, soup.indices);
        Random rng(seed + 100);
        int hits = 0;
        for (int r = 0; r < 2000; ++r) {
            glm::vec3 origin = randomPoint(rng, 1.5f);
            glm::vec3 dir = glm::normalize(randomPoint(rng, 1.0f) + glm::vec3(1e-3f));
            auto fast = bvh.nearestHit(origin, dir, 0.0f, 10.0f, 0.0f);
            auto slow = bvh.nearestHitBruteForce(origin, dir, 0.0f, 10.0f, 0.0f);
            expectSame(fast, slow);
            hits += fast ? 1 : 0;
        }
        EXPECT_GT(hits, 500);  // the soup is dense enough that most rays hit
    }
}

TEST(Bvh, TwoSidedNearestToTargetMatchesBruteForce) {
    Soup soup = makeSoup(7, 4000);
    Bvh bvh(soup.positions, soup.indices);
    Random rng(77);
    int hits = 0;
    for (int r = 0; r < 3000; ++r) {
        glm::vec3 origin = randomPoint(rng, 1.2f);
        glm::vec3 dir = glm::normalize(randomPoint(rng, 1.0f) + glm::vec3(0.0f, 0.0f, 1e-3f));
        float span = rng.range(0.05f, 0.6f);
        auto fast = bvh.nearestHit(origin - span * dir, dir, 0.0f, 2.0f * span, span);
        auto slow = bvh.nearestHitBruteForce(origin - span * dir, dir, 0.0f, 2.0f * span, span);
        expectSame(fast, slow);
        hits += fast ? 1 : 0;
    }
    EXPECT_GT(hits, 300);
}

TEST(Bvh, AxisAlignedRaysAndCoincidentTriangles) {
    // A grid of coplanar quads, each duplicated: ties must go to the lower index.
    Soup soup;
    for (int y = 0; y < 20; ++y) {
        for (int x = 0; x < 20; ++x) {
            for (int copy = 0; copy < 2; ++copy) {
                uint32_t base = static_cast<uint32_t>(soup.positions.size());
                soup.positions.push_back({x * 0.1f, y * 0.1f, 0.0f});
                soup.positions.push_back({x * 0.1f + 0.1f, y * 0.1f, 0.0f});
                soup.positions.push_back({x * 0.1f, y * 0.1f + 0.1f, 0.0f});
                soup.indices.insert(soup.indices.end(), {base, base + 1, base + 2});
            }
        }
    }
    Bvh bvh(soup.positions, soup.indices);
    Random rng(5);
    for (int r = 0; r < 500; ++r) {
        glm::vec3 origin{rng.range(0.0f, 2.0f), rng.range(0.0f, 2.0f), 1.0f};
        auto fast = bvh.nearestHit(origin, {0, 0, -1}, 0.0f, 5.0f, 0.0f);
        expectSame(fast, bvh.nearestHitBruteForce(origin, {0, 0, -1}, 0.0f, 5.0f, 0.0f));
        if (fast) {
            EXPECT_EQ(fast->triangle % 2u, 0u);
        }
    }
}

TEST(Bvh, EmptyMeshNeverHits) {
    Bvh bvh({}, {});
    EXPECT_FALSE(bvh.nearestHit({0, 0, 0}, {0, 0, 1}, 0.0f, 1.0f, 0.0f));
}

TEST(Bvh, RealMeshMatchesBruteForce) {
    // Khronos' Duck: a real, irregular mesh (4.2K triangles, ~100 units across).
    auto asset = tessera::assets::loadCharacter(std::string(TESSERA_SOURCE_DIR) +
                                                "/../shared/testdata/gltf/Duck/glTF-Binary/Duck.glb");
    ASSERT_TRUE(asset.ok()) << asset.error().message;
    std::vector<glm::vec3> positions;
    for (const auto& v : asset->cage.vertices) positions.push_back(v.position);
    Bvh bvh(positions, asset->cage.indices);
    Random rng(11);
    int hits = 0;
    for (int r = 0; r < 2000; ++r) {
        // Rays from points on the surface along the vertex normal, two-sided.
        const auto& v = asset->cage.vertices[rng.below(static_cast<uint32_t>(asset->cage.vertices.size()))];
        glm::vec3 origin = v.position + v.normal * rng.range(-5.0f, 5.0f);
        auto fast = bvh.nearestHit(origin, v.normal, -20.0f, 20.0f, 0.0f);
        expectSame(fast, bvh.nearestHitBruteForce(origin, v.normal, -20.0f, 20.0f, 0.0f));
        hits += fast ? 1 : 0;
    }
    EXPECT_GT(hits, 1900);
}
