// FaceParameterization (Tessera's own statement of how Bfr lays out a
// face's sub-faces) against Bfr::Parameterization itself, for every face
// size a shape may have; the limit-surface tests check the same mapping
// geometrically.
#include "tessera/subdiv/FaceParameterization.h"
#include "tessera/subdiv/ObjShape.h"

#include <opensubdiv/bfr/parameterization.h>

#include <gtest/gtest.h>

namespace tessera::subdiv {
namespace {

namespace Bfr = OpenSubdiv::Bfr;
namespace Sdc = OpenSubdiv::Sdc;

TEST(FaceParameterization, QuadIsItsOwnPtexFace) {
    const FaceParameterization quad(4);
    EXPECT_FALSE(quad.hasSubFaces());
    EXPECT_EQ(quad.derivativeScale(), 1.0);
    const SubFaceCoord c = quad.toSubFace({0.25, 0.75});
    EXPECT_EQ(c.subFace, 0u);
    EXPECT_EQ(c.st, glm::dvec2(0.25, 0.75));
    EXPECT_EQ(quad.vertexCoord(2), glm::dvec2(1.0, 1.0));
}

TEST(FaceParameterization, MatchesBfrForEveryFaceSize) {
    for (uint32_t n = 3; n <= kMaxFaceVertices; ++n) {
        const Bfr::Parameterization bfr(Sdc::SCHEME_CATMARK, int(n));
        const FaceParameterization ours(n);
        ASSERT_TRUE(bfr.IsValid()) << n;
        EXPECT_EQ(bfr.HasSubFaces(), ours.hasSubFaces()) << n;
        double centre[2];
        bfr.GetCenterCoord(centre);
        EXPECT_EQ(ours.centerCoord(), glm::dvec2(centre[0], centre[1])) << n;
        for (uint32_t k = 0; k < n; ++k) {
            double vertex[2];
            bfr.GetVertexCoord(int(k), vertex);
            EXPECT_EQ(ours.vertexCoord(k), glm::dvec2(vertex[0], vertex[1])) << n << " vertex " << k;
            if (!ours.hasSubFaces()) continue;
            for (double s : {0.0, 0.125, 0.5, 0.875, 1.0})
                for (double t : {0.0, 0.25, 0.625, 1.0}) {
                    const double st[2] = {s, t};
                    double uv[2], back[2];
                    bfr.ConvertNormalizedSubFaceToCoord(int(k), st, uv);
                    EXPECT_EQ(ours.fromSubFace({k, {s, t}}), glm::dvec2(uv[0], uv[1])) << n << " sub-face " << k;
                    const int subFace = bfr.ConvertCoordToNormalizedSubFace(uv, back);
                    const SubFaceCoord coord = ours.toSubFace({uv[0], uv[1]});
                    EXPECT_EQ(coord.subFace, uint32_t(subFace)) << n << " at " << uv[0] << ", " << uv[1];
                    EXPECT_EQ(coord.st, glm::dvec2(back[0], back[1])) << n << " at " << uv[0] << ", " << uv[1];
                }
        }
        // Bfr's edge coordinates: edge k's first half is sub-face k's
        // t = 0 edge, its second half sub-face k+1's s = 0 edge.
        for (uint32_t k = 0; ours.hasSubFaces() && k < n; ++k) {
            double uv[2];
            bfr.GetEdgeCoord(int(k), 0.25, uv);
            EXPECT_EQ(ours.fromSubFace({k, {0.5, 0.0}}), glm::dvec2(uv[0], uv[1])) << n << " edge " << k;
            bfr.GetEdgeCoord(int(k), 0.75, uv);
            EXPECT_EQ(ours.fromSubFace({(k + 1) % n, {0.0, 0.5}}), glm::dvec2(uv[0], uv[1])) << n << " edge " << k;
        }
    }
}

} // namespace
} // namespace tessera::subdiv
