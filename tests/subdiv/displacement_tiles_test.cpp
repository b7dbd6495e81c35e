// DisplacementTiles: the memory per tile, the packing, the records, and the
// format's invariants on every test shape with uniform and mixed tile
// sizes and random coefficients: overlaps equal to the neighbours' texels
// at every shared level, D continuous with its first derivatives across
// every tile edge, extraordinary corners shared and flat, levels the Haar
// averages, level limits and level selection equal from both sides.
#include "TileTestSupport.h"

#include <cstdio>

namespace tessera::subdiv::test {
namespace {

using shader::TileSample;

glm::uvec2 texelAt(glm::dvec2 uv, uint32_t n) {
    return glm::uvec2(glm::floor(uv * double(n) + 0.5));
}

TEST(DisplacementTiles, FootprintIsThePapersFigure) {
    for (uint32_t k = 1; k <= TS_TILE_MAX_LOG2_SIZE; ++k) {
        const uint32_t n = 1u << k;
        const glm::uvec2 f = shader::tsTileFootprint(k);
        if (k >= 2)
            EXPECT_EQ(f.x * f.y, (3 * n / 2 + 4) * (n + 2)) << k; // (1.5 tileSize + 4)(tileSize + 2)
        else
            EXPECT_EQ(f.x * f.y, 16u); // 2x2 has no further level: 4x4, not the formula's 28
        // Levels 0 .. k-1 lie inside the footprint and apart.
        for (uint32_t a = 0; a < k; ++a) {
            const glm::uvec2 pa = shader::tsTileMipOffset(k, a), sa = glm::uvec2((n >> a) + 2);
            EXPECT_LE(pa.x + sa.x, f.x) << k << " level " << a;
            EXPECT_LE(pa.y + sa.y, f.y) << k << " level " << a;
            for (uint32_t b = 0; b < a; ++b) {
                const glm::uvec2 pb = shader::tsTileMipOffset(k, b), sb = glm::uvec2((n >> b) + 2);
                const bool apart =
                    pa.x >= pb.x + sb.x || pb.x >= pa.x + sa.x || pa.y >= pb.y + sb.y || pb.y >= pa.y + sa.y;
                EXPECT_TRUE(apart) << k << ": levels " << a << " and " << b;
            }
        }
    }
}

TEST(DisplacementTiles, TilesPackApartInOneTexture) {
    double leastUsed = 1.0, mostUsed = 0.0;
    for (const TileSet& set : tileSets()) {
        const DisplacementTiles& tiles = set.tiles;
        std::vector<uint8_t> owner(size_t(tiles.textureWidth()) * tiles.textureHeight(), 0);
        size_t used = 0;
        for (uint32_t t = 0; t < tiles.tileCount(); ++t) {
            const glm::uvec2 o = tiles.tileOrigin(t), f = shader::tsTileFootprint(tiles.log2Size(t));
            ASSERT_LE(o.x + f.x, tiles.textureWidth()) << set.name;
            ASSERT_LE(o.y + f.y, tiles.textureHeight()) << set.name;
            for (uint32_t y = 0; y < f.y; ++y)
                for (uint32_t x = 0; x < f.x; ++x) ++owner[size_t(o.y + y) * tiles.textureWidth() + o.x + x];
            used += size_t(f.x) * f.y;
        }
        EXPECT_EQ(std::count_if(owner.begin(), owner.end(), [](uint8_t c) { return c > 1; }), 0) << set.name;
        const double fraction = double(used) / (double(tiles.textureWidth()) * tiles.textureHeight());
        leastUsed = std::min(leastUsed, fraction);
        mostUsed = std::max(mostUsed, fraction);
        if (set.name.find("smoothtris0") != std::string::npos)
            std::printf("[ atlas ] %-36s %4u x %4u texels, %.0f%% used by %u tiles\n", set.name.c_str(),
                        tiles.textureWidth(), tiles.textureHeight(), 100.0 * fraction, tiles.tileCount());
    }
    std::printf("[ atlas ] every set: %.0f .. %.0f%% of the texture used\n", 100.0 * leastUsed, 100.0 * mostUsed);
}

TEST(DisplacementTiles, RecordsDescribeTheTiles) {
    for (const TileSet& set : tileSets()) {
        const DisplacementTiles& tiles = set.tiles;
        for (uint32_t t = 0; t < tiles.tileCount(); ++t) {
            const shader::TileRecord r = tiles.tileRecords()[t];
            EXPECT_EQ(shader::tsTileOrigin(r), tiles.tileOrigin(t));
            EXPECT_EQ(shader::tsTileSize(r), tiles.tileSize(t));
            EXPECT_EQ(shader::tsTileLog2Size(r), tiles.log2Size(t));
            EXPECT_EQ(shader::tsTileDomainLevel(r), 0u);
            for (uint32_t c = 0; c < 4; ++c) {
                const uint32_t fan = tiles.topology().tile(t).fans[c];
                EXPECT_EQ(shader::tsTileCornerDifference(r, c),
                          float(tiles.resolutionOf(t, 0) - tiles.fanResolution(fan)));
            }
        }
    }
}

// OpenSubdiv 3.5 patches are never rotated in their ptex face: the record's
// tile (u, v), built from PatchParam's offset and depth alone, is where Far
// evaluates the patch (far_vs_bfr_test checks the same against Bfr).
TEST(DisplacementTiles, PatchRecordsAddressPatchDomains) {
    for (const ObjShape& shape : allShapes()) {
        const SubdivSurface surface = build(shape);
        const DisplacementTiles tiles =
            makeTiles(topologyOf(shape), DisplacementTiles::uniformLog2Sizes(topologyOf(shape), 2));
        const std::vector<shader::TileRecord> records = tiles.patchRecords(surface.patches());
        ASSERT_EQ(records.size(), surface.patches().size());
        for (uint32_t p = 0; p < records.size(); ++p) {
            const PatchParam& param = surface.patches()[p].param;
            for (glm::dvec2 st : {glm::dvec2(0.0), glm::dvec2(1.0), glm::dvec2(0.25, 0.75)}) {
                const glm::vec2 uv = shader::tsTilePatchUV(records[p], glm::vec2(st));
                EXPECT_EQ(glm::dvec2(uv), ptexCoord(param, st)) << shape.name << " patch " << p;
                // Far finds this patch again from the tile (u, v) (at a
                // corner it may answer from a neighbour: exact only inside).
                if (st.x > 0.0 && st.x < 1.0) {
                    const std::optional<uint32_t> found = surface.findPatch(param.ptexFace(), glm::dvec2(uv));
                    ASSERT_TRUE(found);
                    EXPECT_EQ(*found, p) << shape.name;
                }
            }
            EXPECT_EQ(shader::tsTileOrigin(records[p]), tiles.tileOrigin(param.ptexFace()));
        }
    }
}

// Every overlap texel against the texel the topology maps it to, when the
// neighbour has the level: bit-equal. Edge texels across links, corner
// texels at regular fans and T-junctions by resolving.
TEST(DisplacementTiles, OverlapsEqualNeighbourTexels) {
    for (const TileSet& set : tileSets()) {
        const DisplacementTiles& tiles = set.tiles;
        const PtexTopology& topology = tiles.topology();
        size_t matched = 0, unmatched = 0;
        const auto check = [&](uint32_t t, uint32_t level, glm::dvec2 uv, const std::optional<TilePoint>& p) {
            if (!p) return;
            const int theirs = levelAt(tiles, p->tile, tiles.resolutionOf(t, level));
            if (theirs < 0) {
                ++unmatched;
                return;
            }
            ++matched;
            const glm::uvec2 mine = texelAt(uv, tiles.tileSize(t) >> level);
            const glm::uvec2 other = texelAt(p->uv, tiles.tileSize(p->tile) >> theirs);
            const uint32_t m = tiles.tileSize(p->tile) >> theirs;
            ASSERT_TRUE(other.x >= 1 && other.x <= m && other.y >= 1 && other.y <= m) << set.name;
            EXPECT_EQ(tiles.texel(t, level, mine.x, mine.y), tiles.texel(p->tile, theirs, other.x, other.y))
                << set.name << ": tile " << t << " level " << level;
        };
        for (uint32_t t = 0; t < tiles.tileCount(); ++t)
            for (uint32_t level = 0; level < tiles.levelCount(t); ++level) {
                const uint32_t n = tiles.tileSize(t) >> level;
                const double h = 0.5 / n;
                for (uint32_t e = 0; e < 4; ++e)
                    for (uint32_t i = 1; i <= n; ++i) {
                        const glm::dvec2 uv = PtexTopology::edgePoint(e, (i - 0.5) / n, -h);
                        check(t, level, uv, topology.acrossEdge(t, e, uv));
                    }
                for (uint32_t c = 0; c < 4; ++c) {
                    const FanKind kind = topology.fan(topology.tile(t).fans[c]).kind;
                    if (kind != FanKind::Regular && kind != FanKind::TJunction) continue;
                    const glm::dvec2 uv = PtexTopology::cornerUV(c) * (1.0 + 2.0 * h) - h;
                    check(t, level, uv, topology.resolve(t, uv));
                }
            }
        EXPECT_GT(matched, 0u) << set.name;
        // Unmatched texels (the neighbour lacks the level; a virtual one is
        // read) are checked by their effect: ContinuousAcrossEveryEdge.
        if (set.name == "catmark_nonquads.obj" || set.name == "catmark_nonquads.obj (mixed)")
            std::printf("[ overlaps ] %-30s %zu texels matched, %zu from virtual levels\n", set.name.c_str(), matched,
                        unmatched);
    }
}

TEST(DisplacementTiles, LevelsAreHaarAverages) {
    for (const TileSet& set : tileSets()) {
        const DisplacementTiles& tiles = set.tiles;
        const PtexTopology& topology = tiles.topology();
        for (uint32_t t = 0; t < tiles.tileCount(); ++t)
            for (uint32_t level = 1; level < tiles.levelCount(t); ++level) {
                const uint32_t n = tiles.tileSize(t) >> level;
                for (uint32_t y = 1; y <= n; ++y)
                    for (uint32_t x = 1; x <= n; ++x) {
                        // Corner texels at extraordinary fans are averaged afterwards.
                        const uint32_t corner = (x == 1 ? (y == 1 ? 0 : 3) : (y == 1 ? 1 : 2));
                        const bool atCorner = (x == 1 || x == n) && (y == 1 || y == n);
                        if (atCorner && topology.fan(topology.tile(t).fans[corner]).kind == FanKind::Extraordinary)
                            continue;
                        const auto a = [&](uint32_t i, uint32_t j) { return tiles.texel(t, level - 1, i, j); };
                        const float mean = 0.25f * ((a(2 * x - 1, 2 * y - 1) + a(2 * x, 2 * y - 1)) +
                                                    (a(2 * x - 1, 2 * y) + a(2 * x, 2 * y)));
                        EXPECT_EQ(tiles.texel(t, level, x, y), mean) << set.name;
                    }
            }
    }
}

TEST(DisplacementTiles, ContinuousAcrossEveryEdgeAtEveryLevel) {
    for (const TileSet& set : tileSets()) {
        const EdgeAgreement a = compareEdges(set.tiles);
        // Float rounding of the 9-term sums (the two sides sum in different
        // orders): a few ulps of the largest coefficient.
        EXPECT_LT(a.value, 1e-6) << set.name;
        EXPECT_LT(a.across, 1e-5) << set.name;
        EXPECT_LT(a.along, 1e-5) << set.name;
        std::printf("[ C0/C1 ] %-36s %5zu links %7zu points (%4.1f%% bit-equal) D %.1e across %.1e along %.1e, "
                    "%zu link levels unmatched\n",
                    set.name.c_str(), a.links, a.points, 100.0 * double(a.bitEqual) / double(a.points), a.value,
                    a.across, a.along, a.unmatchedLevels);
    }
}

TEST(DisplacementTiles, ExtraordinaryCornersAreSharedAndFlat) {
    for (const TileSet& set : tileSets()) {
        const DisplacementTiles& tiles = set.tiles;
        const PtexTopology& topology = tiles.topology();
        size_t corners = 0;
        for (uint32_t f = 0; f < topology.fanCount(); ++f) {
            if (topology.fan(f).kind != FanKind::Extraordinary) continue;
            for (uint32_t r = 1; r <= 13; ++r) {
                std::optional<float> shared;
                for (const TileCorner& c : topology.fanCorners(f)) {
                    const int level = levelAt(tiles, c.tile, r);
                    if (level < 0) continue;
                    const TileSample s =
                        tiles.evaluateLevel(c.tile, uint32_t(level), glm::vec2(PtexTopology::cornerUV(c.corner)));
                    EXPECT_EQ(s.value.y, 0.0f) << set.name << " fan " << f;
                    EXPECT_EQ(s.value.z, 0.0f) << set.name << " fan " << f;
                    if (!shared) shared = s.value.x;
                    EXPECT_EQ(s.value.x, *shared) << set.name << " fan " << f;
                    ++corners;
                }
            }
        }
        if (set.name == "cube") {
            EXPECT_EQ(corners, 24u * 3u);
        } // 8 fans x 3 tiles x levels 0..2
    }
}

TEST(DisplacementTiles, RefusesBadSizes) {
    const PtexTopology topology = topologyOf(pentagonPyramid(false));
    EXPECT_FALSE(DisplacementTiles::create(topology, std::vector<uint8_t>(3, 2)).ok());
    EXPECT_FALSE(DisplacementTiles::create(topology, std::vector<uint8_t>(topology.tileCount(), 13)).ok());
    // A quad of k = 1 next to a triangle.
    ObjShape mixed = grid(1, BoundaryInterpolation::EdgeAndCorner, "quad_and_triangle");
    mixed.positions.push_back({0.0f, 2.0f, 0.0f});
    addFace(mixed, {2, 3, 4});
    const PtexTopology t2 = topologyOf(mixed);
    const Result<DisplacementTiles> bad = DisplacementTiles::create(t2, std::vector<uint8_t>(t2.tileCount(), 1));
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("need 2 or more"), std::string::npos) << bad.error().message;
    EXPECT_TRUE(DisplacementTiles::create(t2, DisplacementTiles::legalLog2Sizes(t2, std::vector<uint8_t>(4, 1))).ok());
}

} // namespace
} // namespace tessera::subdiv::test
