// Non-uniform tile sizes (section 4.4) and level selection (section 6.2):
// the level limit tsTileMaxResolution reaches the same value from both
// sides of every tile edge (in resolutions shared across edges), while the
// paper's wording (the highest resolution around a vertex as its base
// value) does not; and tsTileEvaluate, which blends two levels clamped to
// that limit, gives the same D and first derivatives from both sides.
#include "TileTestSupport.h"

#include <cstdio>

namespace tessera::subdiv::test {
namespace {

double bilinear(const double corner[4], glm::dvec2 uv) {
    const double bottom = corner[0] + (corner[1] - corner[0]) * uv.x;
    const double top = corner[3] + (corner[2] - corner[3]) * uv.x;
    return bottom + (top - bottom) * uv.y;
}

double scaleOf(const DisplacementTiles& tiles, uint32_t tile) {
    return tiles.topology().tile(tile).isSubFace ? 1.0 : 0.0;
}

// The paper's words taken literally: a vertex's base value is the highest
// resolution of its tiles, each corner stores base - k, and a tile's limit
// is its k minus the interpolated difference.
double literalLimit(const DisplacementTiles& tiles, uint32_t tile, glm::dvec2 uv) {
    const PtexTopology& topology = tiles.topology();
    double difference[4];
    for (uint32_t c = 0; c < 4; ++c) {
        uint32_t base = 0;
        for (const TileCorner& corner : topology.fanCorners(topology.tile(tile).fans[c]))
            base = std::max(base, tiles.resolutionOf(corner.tile, 0));
        difference[c] = double(base) - tiles.resolutionOf(tile, 0);
    }
    return tiles.resolutionOf(tile, 0) - bilinear(difference, uv);
}

TEST(TileLevels, LimitsAgreeAlongEveryEdge) {
    size_t literalMismatches = 0, literalPoints = 0;
    for (const TileSet& set : tileSets()) {
        const DisplacementTiles& tiles = set.tiles;
        const PtexTopology& topology = tiles.topology();
        size_t points = 0, mismatches = 0, literalBad = 0;
        for (uint32_t a = 0; a < tiles.tileCount(); ++a)
            for (uint32_t e = 0; e < 4; ++e)
                for (uint32_t l = 0; l < topology.tile(a).edges[e].count; ++l) {
                    const TileLink& link = topology.tile(a).edges[e].links[l];
                    const uint32_t b = link.tile;
                    for (int i = 0; i <= 16; ++i) {
                        const double t = linkPoint(link, i);
                        const glm::dvec2 uvA = PtexTopology::edgePoint(e, t, 0.0);
                        const glm::dvec2 uvB = PtexTopology::edgePoint(link.edge, link.theirT(t), 0.0);
                        const float ours = shader::tsTileMaxResolution(tiles.tileRecords()[a], glm::vec2(uvA));
                        const float theirs = shader::tsTileMaxResolution(tiles.tileRecords()[b], glm::vec2(uvB));
                        // Shared units: a sub-face's resolution r is a quad's r + 1.
                        if (ours + scaleOf(tiles, a) != theirs + scaleOf(tiles, b)) ++mismatches;
                        // Never past the tile's finest level, never below its coarsest.
                        EXPECT_LE(ours, float(tiles.log2Size(a))) << set.name;
                        EXPECT_GE(ours, 1.0f) << set.name;
                        if (std::abs(literalLimit(tiles, a, uvA) - literalLimit(tiles, b, uvB)) > 1e-9) ++literalBad;
                        ++points;
                    }
                }
        EXPECT_EQ(mismatches, 0u) << set.name << ": of " << points;
        literalMismatches += literalBad;
        literalPoints += points;
        if (set.name.find("mixed") != std::string::npos && literalBad > 0)
            std::printf("[ limits ] %-36s %6zu edge points: smallest-k rule equal at all, highest-k rule differs at "
                        "%zu\n",
                        set.name.c_str(), points, literalBad);
    }
    // The highest-resolution reading fails somewhere on mixed sizes.
    EXPECT_GT(literalMismatches, 0u);
    std::printf("[ limits ] highest-k rule: %zu of %zu edge points differ across the edge\n", literalMismatches,
                literalPoints);
}

// Both sides sample one density (samples per base-edge length; a sub-face
// gets half as many per unit of its own (u, v)) and blend their two levels.
TEST(TileLevels, SelectionAndBlendingAgreeAlongEveryEdge) {
    for (const TileSet& set : tileSets()) {
        const DisplacementTiles& tiles = set.tiles;
        const PtexTopology& topology = tiles.topology();
        const double scale = largestTexel(tiles);
        EdgeAgreement worst;
        double resolution = 0.0;
        for (double density : {1.0, 2.5, 5.7, 12.0, 40.0, 1e4})
            for (uint32_t a = 0; a < tiles.tileCount(); ++a)
                for (uint32_t e = 0; e < 4; ++e)
                    for (uint32_t l = 0; l < topology.tile(a).edges[e].count; ++l) {
                        const TileLink& link = topology.tile(a).edges[e].links[l];
                        const uint32_t b = link.tile;
                        const float densityA = float(density / (1.0 + scaleOf(tiles, a)));
                        const float densityB = float(density / (1.0 + scaleOf(tiles, b)));
                        for (int i = 0; i <= 16; ++i) {
                            const double t = linkPoint(link, i);
                            const glm::vec2 uvA(PtexTopology::edgePoint(e, t, 0.0));
                            const glm::vec2 uvB(PtexTopology::edgePoint(link.edge, link.theirT(t), 0.0));
                            const float ra = shader::tsTileResolution(tiles.tileRecords()[a], uvA, densityA);
                            const float rb = shader::tsTileResolution(tiles.tileRecords()[b], uvB, densityB);
                            resolution =
                                std::max(resolution, std::abs(ra + scaleOf(tiles, a) - rb - scaleOf(tiles, b)));
                            accumulate(worst, tiles.evaluate(a, uvA, densityA), tiles.evaluate(b, uvB, densityB), e,
                                       link, scale, double(tiles.tileSize(a)));
                        }
                    }
        // log2 of a density and of half of it differ by 1 up to rounding;
        // the blend weights by as much.
        EXPECT_LT(resolution, 1e-6) << set.name;
        EXPECT_LT(worst.value, 1e-6) << set.name;
        EXPECT_LT(worst.across, 1e-5) << set.name;
        EXPECT_LT(worst.along, 1e-5) << set.name;
        std::printf("[ blended ] %-36s %7zu points (%4.1f%% bit-equal) resolution %.1e D %.1e across %.1e along %.1e\n",
                    set.name.c_str(), worst.points, 100.0 * double(worst.bitEqual) / double(worst.points), resolution,
                    worst.value, worst.across, worst.along);
    }
}

// Inside a tile the selection follows the density and the limit: a tile
// between a large and a small neighbour uses its own finest level only
// away from the small one.
TEST(TileLevels, ClampFollowsTheCornerLimits) {
    const ObjShape shape = grid(3, BoundaryInterpolation::EdgeAndCorner, "grid3");
    const PtexTopology topology = topologyOf(shape);
    std::vector<uint8_t> sizes(topology.tileCount(), 4);
    sizes[0] = 1; // a 2x2 tile in the corner of 16x16 ones
    const DisplacementTiles tiles = makeTiles(topology, sizes);
    const shader::TileRecord far = tiles.tileRecords()[8], centre = tiles.tileRecords()[4];
    const shader::TileRecord next = tiles.tileRecords()[1];
    EXPECT_EQ(shader::tsTileMaxResolution(far, glm::vec2(0.5f)), 4.0f);
    // The centre tile touches tile 0 at its corner 0 only: 4 - 3/4 there.
    EXPECT_EQ(shader::tsTileMaxResolution(centre, glm::vec2(0.5f)), 3.25f);
    EXPECT_EQ(shader::tsTileMaxResolution(centre, glm::vec2(0.0f)), 1.0f);
    // Tile 1 touches tile 0 along its u = 0 edge: limit 1 there, 4 at u = 1.
    EXPECT_EQ(shader::tsTileMaxResolution(next, glm::vec2(0.0f, 0.5f)), 1.0f);
    EXPECT_EQ(shader::tsTileMaxResolution(next, glm::vec2(1.0f, 0.5f)), 4.0f);
    EXPECT_EQ(shader::tsTileResolution(next, glm::vec2(0.5f, 0.5f), 1e6f), 2.5f);
    EXPECT_EQ(shader::tsTileResolution(next, glm::vec2(0.5f, 0.5f), 4.0f), 2.0f);
    EXPECT_EQ(shader::tsTileResolution(next, glm::vec2(0.5f, 0.5f), 0.25f), 1.0f);
}

} // namespace
} // namespace tessera::subdiv::test
