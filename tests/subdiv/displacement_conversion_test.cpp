// Conversion from sampled displacement (section 4.1) and the procedural
// displacement: converted tiles reproduce the samples at every texel centre
// but the pinned extraordinary corners, take the vertex's sample at
// extraordinary vertices, stay continuous, and a constant converts exactly.
#include "TileTestSupport.h"

#include "tessera/subdiv/DisplacementConversion.h"
#include "tessera/subdiv/ProceduralDisplacement.h"

#include <cstdio>

namespace tessera::subdiv::test {
namespace {

TEST(ProceduralDisplacement, IsContinuousAcrossTiles) {
    for (const ObjShape& shape : allShapes()) {
        const SubdivSurface surface = build(shape);
        const PtexTopology topology = topologyOf(shape);
        const ProceduralDisplacement field(surface);
        const double amplitude = 0.02 * surface.boundsDiagonal();
        double worst = 0.0, largest = 0.0;
        for (uint32_t a = 0; a < topology.tileCount(); ++a)
            for (uint32_t e = 0; e < 4; ++e)
                for (uint32_t l = 0; l < topology.tile(a).edges[e].count; ++l) {
                    const TileLink& link = topology.tile(a).edges[e].links[l];
                    for (int i = 0; i <= 16; ++i) {
                        const double t = linkPoint(link, i);
                        const double da = field(a, PtexTopology::edgePoint(e, t, 0.0));
                        const double db = field(link.tile, PtexTopology::edgePoint(link.edge, link.theirT(t), 0.0));
                        worst = std::max(worst, std::abs(da - db));
                        largest = std::max(largest, std::abs(da));
                    }
                }
        EXPECT_LT(worst, 1e-5 * amplitude) << shape.name;
        EXPECT_LE(largest, amplitude * (1.0 + 1e-12)) << shape.name;
        EXPECT_GT(largest, 0.1 * amplitude) << shape.name;
    }
}

TEST(DisplacementConversion, ConstantConvertsExactly) {
    const PtexTopology topology = topologyOf(pentagonPyramid(false));
    DisplacementTiles tiles = makeTiles(topology, mixedSizes(topology, 4, 3));
    const ConversionReport report = convertDisplacement(tiles, [](uint32_t, glm::dvec2) { return 0.375; });
    EXPECT_TRUE(report.converged);
    for (float v : tiles.allCoefficients()) EXPECT_EQ(v, 0.375f);
    for (uint32_t t = 0; t < tiles.tileCount(); ++t)
        for (uint32_t level = 0; level < tiles.levelCount(t); ++level) {
            const uint32_t n = tiles.tileSize(t) >> level;
            for (uint32_t y = 0; y <= n + 1; ++y)
                for (uint32_t x = 0; x <= n + 1; ++x) EXPECT_EQ(tiles.texel(t, level, x, y), 0.375f);
        }
}

TEST(DisplacementConversion, ReproducesTheSamples) {
    uint64_t seed = 11;
    for (const ObjShape& shape : allShapes()) {
        const SubdivSurface surface = build(shape);
        const PtexTopology topology = topologyOf(shape);
        const ProceduralDisplacement field(surface);
        for (bool mixed : {false, true}) {
            DisplacementTiles tiles = makeTiles(topology, mixed ? mixedSizes(topology, 4, ++seed)
                                                                : DisplacementTiles::uniformLog2Sizes(topology, 3));
            const ConversionReport report = convertDisplacement(tiles, field.sampler());
            const std::string name = shape.name + (mixed ? " (mixed)" : "");
            EXPECT_TRUE(report.converged) << name;
            // Float coefficients and a float lookup: a few ulps.
            EXPECT_LT(report.maxResidual, 2e-6 * report.sampleScale) << name;
            const EdgeAgreement edges = compareEdges(tiles);
            EXPECT_LT(edges.value, 1e-6) << name;
            EXPECT_LT(edges.across, 1e-5) << name;
            std::printf("[ convert ] %-36s %6zu samples, %2u rounds, residual %.1e; %4zu pinned corner samples off "
                        "by up to %.1e (of the largest sample)\n",
                        name.c_str(), report.samples, report.rounds, report.maxResidual / report.sampleScale,
                        report.pinnedSamples, report.maxPinnedResidual / report.sampleScale);
        }
    }
}

// Where every tile around an extraordinary vertex has the same resolution,
// D there is the mean of the tiles' samples at the vertex.
TEST(DisplacementConversion, ExtraordinaryVerticesTakeTheVertexSample) {
    for (const ObjShape& shape : {cube(), extraordinaryDisk(), pentagonPyramid(false)}) {
        const SubdivSurface surface = build(shape);
        const PtexTopology topology = topologyOf(shape);
        const ProceduralDisplacement field(surface);
        DisplacementTiles tiles = makeTiles(topology, DisplacementTiles::uniformLog2Sizes(topology, 3));
        convertDisplacement(tiles, field.sampler());
        for (uint32_t f = 0; f < topology.fanCount(); ++f) {
            if (topology.fan(f).kind != FanKind::Extraordinary) continue;
            double mean = 0.0;
            for (const TileCorner& c : topology.fanCorners(f)) mean += field(c.tile, PtexTopology::cornerUV(c.corner));
            mean /= topology.fan(f).cornerCount;
            for (const TileCorner& c : topology.fanCorners(f)) {
                const float d = tiles.evaluateLevel(c.tile, 0, glm::vec2(PtexTopology::cornerUV(c.corner))).value.x;
                EXPECT_NEAR(d, mean, 1e-6 * surface.boundsDiagonal()) << shape.name << " fan " << f;
            }
        }
    }
}

} // namespace
} // namespace tessera::subdiv::test
