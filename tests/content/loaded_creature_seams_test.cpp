// The crack test's CPU half, on the files the build ships: the generated
// creatures, loaded back through the engine's loader (Draco and the 16-bit
// PNG included), must be watertight when displaced. The cage must be closed
// once welded by position, and across every UV seam the renderer's bilinear
// fetch of the displacement must agree on both sides (the paper's Figure 17),
// measured in metres at 16 points per texel of edge length.
#include "creature/SeamFixer.h"
#include "tessera/assets/GltfLoader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <tuple>
#include <vector>

namespace {

std::filesystem::path shippedCreature(int seed) {
    return std::filesystem::path(TESSERA_BINARY_DIR) / "content" / "characters" /
           ("froblin_" + std::to_string(seed) + ".glb");
}

// Directed edges of the cage with its vertices welded by position, and how
// many of them have no reverse (an open edge: a crack in the cage itself).
size_t openEdges(const tessera::character::CageMesh& cage) {
    std::map<std::tuple<float, float, float>, uint32_t> weld;
    std::vector<uint32_t> id(cage.vertices.size());
    for (size_t i = 0; i < cage.vertices.size(); ++i) {
        const glm::vec3& p = cage.vertices[i].position;
        id[i] = weld.emplace(std::make_tuple(p.x, p.y, p.z), uint32_t(weld.size())).first->second;
    }
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    for (size_t t = 0; t + 2 < cage.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) ++edges[{id[cage.indices[t + e]], id[cage.indices[t + (e + 1) % 3]]}];
    size_t open = 0;
    for (const auto& [edge, count] : edges) open += !edges.count({edge.second, edge.first}) || count != 1;
    return open;
}

} // namespace

TEST(LoadedCreatureSeams, ShippedCreaturesAreWatertightWhenDisplaced) {
    for (int seed = 1; seed <= 3; ++seed) {
        const auto file = shippedCreature(seed);
        if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not built";
        auto loaded = tessera::assets::loadCharacter(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        const auto& asset = loaded.value();
        ASSERT_TRUE(asset.displacement);
        EXPECT_EQ(openEdges(asset.cage), 0u) << file;

        const auto& map = *asset.displacement;
        std::vector<float> metres(size_t(map.image.width) * map.image.height);
        for (size_t i = 0; i < metres.size(); ++i) {
            uint16_t texel;
            std::memcpy(&texel, &map.image.bytes[i * 2], 2);
            metres[i] = float(texel) / 65535.0f * map.scale + map.bias;
        }
        const tessera::creature::SeamFixer seams(asset.cage, map.image.width);
        const float worst = seams.maxMismatch(metres, 16.0f);
        std::printf("%s: %llu seam edges, %llu seam vertices, worst displacement mismatch %.3g mm (%.2g%% of the "
                    "range)\n",
                    file.filename().c_str(), (unsigned long long)seams.seamEdgeCount(),
                    (unsigned long long)seams.seamVertexCount(), worst * 1e3, 100.0 * worst / map.scale);
        EXPECT_GT(seams.seamEdgeCount(), 100u);
        // A tenth of a millimetre: far below a pixel at any distance the
        // demo's level choice tessellates finely (a pixel is 1 to 7 mm there).
        EXPECT_LT(worst, 1e-4f) << file;
    }
}
