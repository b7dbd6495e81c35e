// PtexTopology: tiles numbered as OpenSubdiv numbers ptex faces, links that
// are mutual and meet on the limit surface (the orientation of every ptex
// face against its neighbours, checked against Far's own patches), fans
// around one point each, and their kinds on known shapes.
#include "TileTestSupport.h"

#include <cstdio>
#include <map>

namespace tessera::subdiv::test {
namespace {

TEST(PtexTopology, NumbersTilesAsOpenSubdivNumbersPtexFaces) {
    for (const ObjShape& shape : allShapes()) {
        const PtexTopology topology = topologyOf(shape);
        const SubdivSurface surface = build(shape);
        ASSERT_EQ(topology.tileCount(), surface.ptexFaceCount()) << shape.name;
        for (uint32_t f = 0; f < shape.faceCount(); ++f)
            EXPECT_EQ(topology.firstTile(f), surface.firstPtexFace(f)) << shape.name << " face " << f;
    }
}

TEST(PtexTopology, LinksAreMutual) {
    for (const ObjShape& shape : allShapes()) {
        const PtexTopology topology = topologyOf(shape);
        for (uint32_t a = 0; a < topology.tileCount(); ++a)
            for (uint32_t e = 0; e < 4; ++e) {
                const TileEdge& edge = topology.tile(a).edges[e];
                for (uint32_t l = 0; l < edge.count; ++l) {
                    const TileLink& link = edge.links[l];
                    const TileEdge& back = topology.tile(link.tile).edges[link.edge];
                    bool found = false;
                    for (uint32_t m = 0; m < back.count; ++m) {
                        const TileLink& r = back.links[m];
                        if (r.tile != a || r.edge != e) continue;
                        // The two maps are inverse on the shared part.
                        for (double t : {0.5 * link.lo, 0.5 * (link.lo + link.hi) / 2.0 + 0.125, 0.5 * link.hi})
                            if (r.lo <= 2.0 * link.theirT(t) && 2.0 * link.theirT(t) <= r.hi) {
                                EXPECT_EQ(r.theirT(link.theirT(t)), t) << shape.name;
                                found = true;
                            }
                    }
                    EXPECT_TRUE(found) << shape.name << ": tile " << a << " edge " << e;
                    EXPECT_EQ(topology.tile(a).hole || topology.tile(link.tile).hole, false) << shape.name;
                }
            }
    }
}

// Every link's two sides at 9 points, each evaluated by Far on its own ptex
// face: the same limit point only if the tile orientations (ours, from the
// control mesh) agree with OpenSubdiv's ptex faces.
TEST(PtexTopology, LinkedEdgesMeetOnTheLimitSurface) {
    for (const ObjShape& shape : allShapes()) {
        const PtexTopology topology = topologyOf(shape);
        const SubdivSurface surface = build(shape);
        double worst = 0.0;
        size_t points = 0;
        for (uint32_t a = 0; a < topology.tileCount(); ++a)
            for (uint32_t e = 0; e < 4; ++e)
                for (uint32_t l = 0; l < topology.tile(a).edges[e].count; ++l) {
                    const TileLink& link = topology.tile(a).edges[e].links[l];
                    for (int i = 0; i <= 8; ++i) {
                        const double t = 0.5 * link.lo + 0.5 * (link.hi - link.lo) * i / 8.0;
                        const auto pa = surface.evaluatePtex(a, PtexTopology::edgePoint(e, t, 0.0));
                        const auto pb =
                            surface.evaluatePtex(link.tile, PtexTopology::edgePoint(link.edge, link.theirT(t), 0.0));
                        ASSERT_TRUE(pa && pb) << shape.name;
                        worst = std::max(worst, glm::length(pa->position - pb->position) / surface.boundsDiagonal());
                        ++points;
                    }
                }
        EXPECT_LT(worst, 1e-6) << shape.name;
        std::printf("[ topology ] %-32s %5u tiles %6zu edge points, worst gap %.1e of the diagonal\n",
                    shape.name.c_str(), topology.tileCount(), points, worst);
    }
}

// The corners of a fan are one point of the limit surface.
TEST(PtexTopology, FansMeetAtOnePoint) {
    for (const ObjShape& shape : allShapes()) {
        const PtexTopology topology = topologyOf(shape);
        const SubdivSurface surface = build(shape);
        size_t corners = 0;
        for (uint32_t f = 0; f < topology.fanCount(); ++f) {
            const auto fan = topology.fanCorners(f);
            corners += fan.size();
            if (topology.tile(fan[0].tile).hole) continue;
            const auto p0 = surface.evaluatePtex(fan[0].tile, PtexTopology::cornerUV(fan[0].corner));
            ASSERT_TRUE(p0) << shape.name;
            for (const TileCorner& c : fan) {
                const auto p = surface.evaluatePtex(c.tile, PtexTopology::cornerUV(c.corner));
                ASSERT_TRUE(p) << shape.name;
                EXPECT_LT(glm::length(p->position - p0->position), 1e-6 * surface.boundsDiagonal())
                    << shape.name << " fan " << f;
            }
        }
        EXPECT_EQ(corners, 4u * topology.tileCount()) << shape.name << ": every corner in one fan";
    }
}

std::map<FanKind, std::map<uint32_t, uint32_t>> fanCensus(const PtexTopology& topology) {
    std::map<FanKind, std::map<uint32_t, uint32_t>> census; // kind -> corners -> fans
    for (const Fan& fan : topology.fans()) ++census[fan.kind][fan.cornerCount];
    return census;
}

TEST(PtexTopology, FanKindsOnKnownShapes) {
    using Census = std::map<FanKind, std::map<uint32_t, uint32_t>>;
    EXPECT_EQ(fanCensus(topologyOf(cube())), (Census{{FanKind::Extraordinary, {{3, 8}}}}));
    EXPECT_EQ(fanCensus(topologyOf(torus(8, 6, 0.0f, "torus"))), (Census{{FanKind::Regular, {{4, 48}}}}));
    const Census grid4 = {{FanKind::Regular, {{4, 9}}}, {FanKind::Boundary, {{2, 12}}}, {FanKind::Corner, {{1, 4}}}};
    EXPECT_EQ(fanCensus(topologyOf(grid(4, BoundaryInterpolation::EdgeAndCorner, "grid"))), grid4);
    // The pyramid: 5 base vertices (valence 3), the apex (valence 5), the
    // pentagon's and the triangles' centres, and 10 edge midpoints with four
    // sub-faces each.
    const Census pyramid = {{FanKind::Extraordinary, {{3, 10}, {5, 2}}}, {FanKind::Regular, {{4, 10}}}};
    EXPECT_EQ(fanCensus(topologyOf(pentagonPyramid(false))), pyramid);
    // A triangle on a quad strip: its two shared edges are T-junctions.
    ObjShape mixed = grid(2, BoundaryInterpolation::EdgeAndCorner, "mixed");
    mixed.positions.push_back({0.0f, 2.0f, 0.0f});
    addFace(mixed, {6, 7, 9});
    addFace(mixed, {7, 8, 9});
    const Census census = fanCensus(topologyOf(mixed));
    EXPECT_EQ(census.at(FanKind::TJunction).at(2), 2u);
}

// At a regular fan the diagonal tile is reached by crossing either edge
// first: the same tile, the same point.
TEST(PtexTopology, DiagonalsAgreeEitherWay) {
    for (const ObjShape& shape : allShapes()) {
        const PtexTopology topology = topologyOf(shape);
        size_t checked = 0;
        for (uint32_t t = 0; t < topology.tileCount(); ++t)
            for (uint32_t c = 0; c < 4; ++c) {
                if (topology.fan(topology.tile(t).fans[c]).kind != FanKind::Regular) continue;
                const glm::dvec2 uv = PtexTopology::cornerUV(c) * (1.0 + 1.0 / 8.0) - 1.0 / 16.0;
                std::optional<TilePoint> via[2];
                for (uint32_t w = 0; w < 2; ++w) {
                    const uint32_t first = w == 0 ? c : (c + 3) % 4;
                    const std::optional<TilePoint> p = topology.acrossEdge(t, first, uv);
                    ASSERT_TRUE(p) << shape.name;
                    for (uint32_t e = 0; e < 4 && !via[w]; ++e) {
                        const glm::dvec2 q = PtexTopology::edgeCoords(e, p->uv);
                        if (q.y < 0.0 && q.x > 0.0 && q.x < 1.0) via[w] = topology.acrossEdge(p->tile, e, p->uv);
                    }
                    ASSERT_TRUE(via[w]) << shape.name;
                }
                EXPECT_EQ(via[0]->tile, via[1]->tile) << shape.name << " tile " << t << " corner " << c;
                EXPECT_EQ(via[0]->uv, via[1]->uv) << shape.name << " tile " << t << " corner " << c;
                const std::optional<TilePoint> resolved = topology.resolve(t, uv);
                ASSERT_TRUE(resolved);
                EXPECT_EQ(resolved->tile, via[0]->tile);
                ++checked;
            }
        if (shape.name == "torus_sharp_ring") {
            EXPECT_EQ(checked, 4u * topology.tileCount());
        }
    }
}

TEST(PtexTopology, RefusesNonManifoldEdges) {
    ObjShape s = cube();
    addFace(s, {0, 1, 5, 4}); // the cube's face 2 a second time
    const Result<PtexTopology> topology = PtexTopology::create(s);
    ASSERT_FALSE(topology.ok());
    EXPECT_NE(topology.error().message.find("walked the same way"), std::string::npos) << topology.error().message;
}

} // namespace
} // namespace tessera::subdiv::test
