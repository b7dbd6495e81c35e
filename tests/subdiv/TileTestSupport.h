#pragma once
// Helpers shared by the displacement tile tests: tile sets over the test
// shapes (uniform and mixed sizes), random coefficients, and the edge check
// that evaluates D from both sides of every tile edge.

#include "SubdivTestSupport.h"

#include "tessera/core/Random.h"
#include "tessera/subdiv/DisplacementTiles.h"
#include "tessera/subdiv/PtexTopology.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace tessera::subdiv::test {

inline PtexTopology topologyOf(const ObjShape& shape) {
    Result<PtexTopology> topology = PtexTopology::create(shape);
    if (!topology.ok()) throw std::runtime_error(topology.error().message);
    return std::move(topology).value();
}

inline DisplacementTiles makeTiles(const PtexTopology& topology, std::vector<uint8_t> sizes) {
    Result<DisplacementTiles> tiles = DisplacementTiles::create(topology, std::move(sizes));
    if (!tiles.ok()) throw std::runtime_error(tiles.error().message);
    return std::move(tiles).value();
}

/// Random sizes 1 .. maxLog2 per tile, made legal.
inline std::vector<uint8_t> mixedSizes(const PtexTopology& topology, uint32_t maxLog2, uint64_t seed) {
    Random random(seed);
    std::vector<uint8_t> sizes(topology.tileCount());
    for (uint8_t& k : sizes) k = uint8_t(1 + random.below(maxLog2));
    return DisplacementTiles::legalLog2Sizes(topology, std::move(sizes));
}

/// Uniform random coefficients in [-1, 1] on every tile.
inline void randomCoefficients(DisplacementTiles& tiles, uint64_t seed) {
    Random random(seed);
    std::vector<float> values(tiles.allCoefficients().size());
    for (float& v : values) v = float(2.0 * random.nextDouble() - 1.0);
    tiles.assign(values);
}

/// A tile set over a test shape.
struct TileSet {
    std::string name;
    DisplacementTiles tiles;
};

/// Every test shape twice: uniform (quads 8x8, sub-faces 4x4) and mixed
/// (random 2x2 .. 16x16, made legal), random coefficients.
inline std::vector<TileSet> tileSets() {
    std::vector<TileSet> sets;
    uint64_t seed = 7;
    for (const ObjShape& shape : allShapes()) {
        const PtexTopology topology = topologyOf(shape);
        for (bool mixed : {false, true}) {
            DisplacementTiles tiles = makeTiles(topology, mixed ? mixedSizes(topology, 4, ++seed)
                                                                : DisplacementTiles::uniformLog2Sizes(topology, 3));
            randomCoefficients(tiles, ++seed);
            sets.push_back({shape.name + (mixed ? " (mixed)" : ""), std::move(tiles)});
        }
    }
    return sets;
}

/// The level of `tile` at a shared resolution, or -1.
inline int levelAt(const DisplacementTiles& tiles, uint32_t tile, uint32_t resolution) {
    const int level = int(tiles.resolutionOf(tile, 0)) - int(resolution);
    return level >= 0 && level < int(tiles.levelCount(tile)) ? level : -1;
}

/// (dD/dt, dD/d depth) in an edge's frame from (dD/du, dD/dv).
inline glm::dvec2 edgeGradient(uint32_t edge, double du, double dv) {
    switch (edge) {
    case 0:
        return {du, dv};
    case 1:
        return {dv, -du};
    case 2:
        return {-du, -dv};
    default:
        return {-dv, du};
    }
}

/// Worst disagreement of D between the two sides of tile edges.
struct EdgeAgreement {
    size_t links = 0, points = 0, bitEqual = 0;
    size_t unmatchedLevels = 0; ///< (link, level) pairs the neighbour lacks
    double value = 0.0;         ///< |D_A - D_B| / largest |coefficient|
    double across = 0.0;        ///< derivative across the edge, / (largest |coefficient| * level size)
    double along = 0.0;         ///< derivative along it, same scale
};

inline double largestTexel(const DisplacementTiles& tiles) {
    double m = 1e-30;
    for (float v : tiles.texels()) m = std::max(m, double(std::abs(v)));
    return m;
}

/// Adds one edge point evaluated from both sides: tile A's edge e at `sa`,
/// across `link` at `sb`; `n` the level size scaling the derivatives.
inline void accumulate(EdgeAgreement& worst, const shader::TileSample& sa, const shader::TileSample& sb, uint32_t e,
                       const TileLink& link, double scale, double n) {
    const glm::dvec2 ga = edgeGradient(e, sa.value.y, sa.value.z);
    // Charts meet reversed and scaled: d(t', depth')/d(t, depth) = -scale.
    const glm::dvec2 gb = -link.scale() * edgeGradient(link.edge, sb.value.y, sb.value.z);
    ++worst.points;
    if (sa.value.x == sb.value.x) ++worst.bitEqual;
    worst.value = std::max(worst.value, std::abs(double(sa.value.x) - sb.value.x) / scale);
    worst.along = std::max(worst.along, std::abs(ga.x - gb.x) / (scale * n));
    worst.across = std::max(worst.across, std::abs(ga.y - gb.y) / (scale * n));
}

/// The edge parameter of point i of 17 along a link (ends included).
inline double linkPoint(const TileLink& link, int i) {
    return 0.5 * link.lo + (0.5 * (link.hi - link.lo)) * i / 16.0;
}

/// Every linked edge, every level both tiles have at one resolution, at 17
/// points of the link (ends included), through evaluateLevel.
inline EdgeAgreement compareEdges(const DisplacementTiles& tiles) {
    const PtexTopology& topology = tiles.topology();
    const double scale = largestTexel(tiles);
    EdgeAgreement worst;
    for (uint32_t a = 0; a < tiles.tileCount(); ++a)
        for (uint32_t e = 0; e < 4; ++e) {
            const TileEdge& edge = topology.tile(a).edges[e];
            for (uint32_t l = 0; l < edge.count; ++l) {
                const TileLink& link = edge.links[l];
                ++worst.links;
                for (uint32_t levelA = 0; levelA < tiles.levelCount(a); ++levelA) {
                    const int levelB = levelAt(tiles, link.tile, tiles.resolutionOf(a, levelA));
                    if (levelB < 0) {
                        ++worst.unmatchedLevels;
                        continue;
                    }
                    const double n = tiles.tileSize(a) >> levelA;
                    for (int i = 0; i <= 16; ++i) {
                        const double t = linkPoint(link, i);
                        const glm::dvec2 uvA = PtexTopology::edgePoint(e, t, 0.0);
                        const glm::dvec2 uvB = PtexTopology::edgePoint(link.edge, link.theirT(t), 0.0);
                        accumulate(worst, tiles.evaluateLevel(a, levelA, glm::vec2(uvA)),
                                   tiles.evaluateLevel(link.tile, uint32_t(levelB), glm::vec2(uvB)), e, link, scale, n);
                    }
                }
            }
        }
    return worst;
}

} // namespace tessera::subdiv::test
