// Editing (a sculpt brush): an edit rederives only the tiles that can
// change, the result is bit-identical to rederiving everything, texels of
// tiles it does not report stay untouched, and every invariant holds after.
#include "TileTestSupport.h"

#include <cstdio>
#include <set>

namespace tessera::subdiv::test {
namespace {

// Texels of every tile outside `rewritten` are unchanged.
void expectUntouched(const DisplacementTiles& before, const DisplacementTiles& after,
                     const std::vector<uint32_t>& rewritten, const std::string& name) {
    const std::set<uint32_t> written(rewritten.begin(), rewritten.end());
    for (uint32_t t = 0; t < after.tileCount(); ++t) {
        if (written.count(t)) continue;
        for (uint32_t level = 0; level < after.levelCount(t); ++level) {
            const uint32_t n = after.tileSize(t) >> level;
            for (uint32_t y = 0; y <= n + 1; ++y)
                for (uint32_t x = 0; x <= n + 1; ++x)
                    ASSERT_EQ(after.texel(t, level, x, y), before.texel(t, level, x, y))
                        << name << ": tile " << t << " changed but was not reported";
        }
    }
}

// A circular brush of radius r texels around (cx, cy) of one tile, clipped
// to it; a stroke is a few of them on random tiles, some on tile corners.
std::vector<CoefficientEdit> brush(const DisplacementTiles& tiles, Random& random) {
    std::vector<CoefficientEdit> edits;
    for (int dab = 0; dab < 3; ++dab) {
        const uint32_t tile = random.below(tiles.tileCount()), n = tiles.tileSize(tile);
        const bool corner = random.below(2) == 0;
        const double cx = corner ? 0.0 : random.nextDouble() * n, cy = corner ? 0.0 : random.nextDouble() * n;
        const double r = 1.0 + random.nextDouble() * 3.0, height = random.nextDouble() - 0.5;
        const auto values = tiles.coefficients(tile);
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
                if (d < r) edits.push_back({tile, x, y, float(values[y * n + x] + height * (1.0 - d / r))});
            }
    }
    return edits;
}

TEST(DisplacementEdit, MatchesAFullRebuildAndReportsWhatChanged) {
    Random random(42);
    for (TileSet& set : tileSets()) {
        DisplacementTiles& tiles = set.tiles;
        size_t rewritten = 0, strokes = 0;
        for (int stroke = 0; stroke < 4; ++stroke) {
            const DisplacementTiles before = tiles;
            const TileUpdate update = tiles.edit(brush(tiles, random));
            expectUntouched(before, tiles, update.rewritten, set.name);
            DisplacementTiles full = tiles;
            full.rebuild();
            ASSERT_TRUE(std::equal(full.texels().begin(), full.texels().end(), tiles.texels().begin()))
                << set.name << ": the edit differs from a full rebuild";
            for (uint32_t t : update.edited)
                EXPECT_TRUE(std::binary_search(update.rewritten.begin(), update.rewritten.end(), t));
            rewritten += update.rewritten.size();
            ++strokes;
        }
        // Invariants after editing.
        const EdgeAgreement edges = compareEdges(tiles);
        EXPECT_LT(edges.value, 1e-6) << set.name;
        EXPECT_LT(edges.across, 1e-5) << set.name;
        if (set.name.find("smoothtris0") != std::string::npos || set.name.find("single_crease") != std::string::npos)
            std::printf("[ edit ] %-36s %u tiles, %.1f rewritten per 3-dab stroke\n", set.name.c_str(),
                        tiles.tileCount(), double(rewritten) / double(strokes));
    }
}

// One texel in the middle of a tile: the tile and its 8 neighbours on a
// regular surface; on the cube (every corner extraordinary) the averages
// reach the four side faces, and their overlaps the last one.
TEST(DisplacementEdit, RewritesTheNeighbourhoodOnly) {
    const PtexTopology torus8 = topologyOf(torus(8, 6, 0.0f, "torus"));
    DisplacementTiles tiles = makeTiles(torus8, DisplacementTiles::uniformLog2Sizes(torus8, 3));
    TileUpdate update = tiles.edit(std::vector<CoefficientEdit>{{10, 3, 4, 1.0f}});
    EXPECT_EQ(update.edited, std::vector<uint32_t>{10});
    EXPECT_EQ(update.rewritten.size(), 9u);
    // Setting a coefficient to its value changes nothing.
    update = tiles.edit(std::vector<CoefficientEdit>{{10, 3, 4, 1.0f}});
    EXPECT_TRUE(update.edited.empty() && update.rewritten.empty());

    const PtexTopology box = topologyOf(cube());
    DisplacementTiles cubeTiles = makeTiles(box, DisplacementTiles::uniformLog2Sizes(box, 3));
    update = cubeTiles.setCoefficients(0, {3, 3}, {2, 2}, std::vector<float>{1.0f, 2.0f, 3.0f, 4.0f});
    EXPECT_EQ(update.edited, std::vector<uint32_t>{0});
    EXPECT_EQ(update.rewritten.size(), 6u);
    EXPECT_EQ(cubeTiles.coefficients(0)[4 * 8 + 4], 4.0f);
}

} // namespace
} // namespace tessera::subdiv::test
