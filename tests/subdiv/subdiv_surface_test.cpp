// SubdivSurface's data for a GPU (control points, indices, patch ranges,
// packed patch parameters), coverage of every ptex face, holes, derivatives
// against finite differences, bounds, and animation by updateControlPoints.
#include "SubdivTestSupport.h"

#include "tessera/subdiv/BfrReference.h"
#include "tessera/subdiv/FaceParameterization.h"

#include <opensubdiv/far/patchParam.h>

#include <algorithm>
#include <cstdio>

namespace tessera::subdiv::test {
namespace {

TEST(SubdivSurface, PatchArraysAreConsistentForAGpu) {
    for (const ObjShape& shape : allShapes()) {
        const SubdivSurface s = build(shape);
        SCOPED_TRACE(s.name());
        ASSERT_FALSE(s.patches().empty());
        EXPECT_EQ(s.controlPoints().size(), size_t(s.refinedVertexCount()) + s.localPointCount());
        // The base vertices come first, unchanged.
        for (uint32_t v = 0; v < s.baseVertexCount(); ++v) EXPECT_EQ(s.controlPoints()[v], shape.positions[v]);
        size_t indices = 0;
        uint32_t nextPatch = 0;
        for (const PatchRange& range : s.patchRanges()) {
            EXPECT_EQ(range.firstPatch, nextPatch);
            EXPECT_EQ(range.firstIndex, indices);
            for (uint32_t p = range.firstPatch; p < range.firstPatch + range.patchCount; ++p) {
                const Patch& patch = s.patches()[p];
                EXPECT_EQ(patch.type, range.type);
                EXPECT_EQ(patch.firstIndex, indices);
                EXPECT_EQ(s.patchPoints(p).size(), controlPointsOf(patch.type));
                // Gregory patches are end caps, and B-spline patches at an
                // isolation level's end may be end caps too.
                if (patch.type == PatchType::GregoryBasis) {
                    EXPECT_FALSE(patch.param.isRegular());
                }
                EXPECT_LT(patch.param.ptexFace(), s.ptexFaceCount());
                EXPECT_LE(patch.param.depth(), s.maxDepth());
                indices += controlPointsOf(patch.type);
            }
            nextPatch += range.patchCount;
        }
        EXPECT_EQ(nextPatch, s.patches().size());
        EXPECT_EQ(indices, s.patchPointIndices().size());
        for (uint32_t index : s.patchPointIndices()) EXPECT_LT(index, s.controlPoints().size());
    }
}

TEST(SubdivSurface, BSplineEndCapsMakeOnlyRegularPatches) {
    SubdivSettings settings;
    settings.endCap = EndCap::BSplineBasis;
    for (const ObjShape& shape : {cube(), pentagonPyramid(false), extraordinaryDisk()}) {
        const SubdivSurface s = build(shape, settings);
        ASSERT_EQ(s.patchRanges().size(), 1u) << s.name();
        EXPECT_EQ(s.patchRanges()[0].type, PatchType::Regular);
        EXPECT_TRUE(
            std::any_of(s.patches().begin(), s.patches().end(), [](const Patch& p) { return !p.param.isRegular(); }))
            << s.name() << ": its extraordinary vertices need end caps";
    }
}

// The accessors decode the words exactly as Far::PatchParam does.
TEST(SubdivSurface, PatchParamDecodesAsOpenSubdiv) {
    for (const ObjShape& shape : allShapes()) {
        const SubdivSurface s = build(shape);
        for (const Patch& patch : s.patches()) {
            OpenSubdiv::Far::PatchParam far;
            far.field0 = patch.param.field0;
            far.field1 = patch.param.field1;
            ASSERT_EQ(patch.param.ptexFace(), uint32_t(far.GetFaceId()));
            ASSERT_EQ(patch.param.u(), far.GetU());
            ASSERT_EQ(patch.param.v(), far.GetV());
            ASSERT_EQ(patch.param.depth(), far.GetDepth());
            ASSERT_EQ(patch.param.nonQuadRoot(), far.NonQuadRoot());
            ASSERT_EQ(patch.param.boundaryMask(), far.GetBoundary());
            ASSERT_EQ(patch.param.transitionMask(), far.GetTransition());
            ASSERT_EQ(patch.param.isRegular(), far.IsRegular());
            ASSERT_EQ(patch.param.paramFraction(), double(far.GetParamFraction()));
            ASSERT_EQ(patch.param.sharpness, 0.0f);
        }
    }
}

// Every ptex face of a face with a limit surface is tiled by its patches
// exactly once (areas add up to 1, PatchMap finds a patch everywhere), and
// holes have none.
TEST(SubdivSurface, PatchesTileEveryPtexFaceAndNoHole) {
    for (const ObjShape& shape : allShapes()) {
        const SubdivSurface s = build(shape);
        const BfrReference bfr(s);
        std::vector<double> area(s.ptexFaceCount(), 0.0);
        for (const Patch& patch : s.patches()) area[patch.param.ptexFace()] += std::pow(patch.param.paramFraction(), 2);
        const std::vector<PtexOwner> owners = ptexOwners(s);
        for (uint32_t ptex = 0; ptex < s.ptexFaceCount(); ++ptex) {
            const uint32_t face = owners[ptex].face;
            SCOPED_TRACE(s.name() + ": face " + std::to_string(face));
            EXPECT_EQ(s.isHole(face), std::find(shape.holes.begin(), shape.holes.end(), face) != shape.holes.end());
            if (!bfr.hasLimitSurface(face)) {
                EXPECT_EQ(area[ptex], 0.0);
                EXPECT_FALSE(s.evaluatePtex(ptex, {0.5, 0.5}).has_value());
                EXPECT_FALSE(s.evaluateFace(face, {0.25, 0.25}).has_value());
                continue;
            }
            EXPECT_DOUBLE_EQ(area[ptex], 1.0);
            for (double u : {0.0, 0.3, 0.5, 1.0})
                for (double v : {0.0, 0.7, 1.0}) EXPECT_TRUE(s.findPatch(ptex, {u, v}).has_value());
        }
    }
}

TEST(SubdivSurface, HoleFacesHaveNoPatches) {
    const SubdivSurface s = build(cubeWithHole());
    EXPECT_TRUE(s.isHole(1));
    EXPECT_FALSE(s.isHole(0));
    for (const Patch& patch : s.patches()) EXPECT_NE(patch.param.ptexFace(), s.firstPtexFace(1));
    EXPECT_FALSE(s.evaluateFace(1, {0.5, 0.5}).has_value());
    EXPECT_TRUE(s.evaluateFace(0, {0.5, 0.5}).has_value());
    EXPECT_FALSE(BfrReference(s).hasLimitSurface(1));
}

// Central differences of positions (and of first derivatives) against the
// derivatives each call returns: ptex coordinates for evaluatePtex, Bfr's
// for evaluateFace, non-quads included. Exact for B-spline patches. For
// Gregory end caps OpenSubdiv (Far, Bfr and its GLSL alike) differentiates
// the Bezier patch whose interior points are the face points blended at
// (u, v), not the rational patch itself (Loop et al.'s approximation, kept
// for the GPU's sake): there the figures are reported, within a few percent.
TEST(SubdivSurface, DerivativesMatchFiniteDifferences) {
    const double h = 1e-4;
    for (const ObjShape& shape : {cube(), pentagonPyramid(false), extraordinaryDisk(), creasedCube(2.0f)}) {
        const SubdivSurface s = build(shape);
        double worstFirst[2] = {0.0, 0.0}, worstSecond[2] = {0.0, 0.0}; // regular, Gregory
        for (uint32_t f = 0; f < s.baseFaceCount(); ++f) {
            const FaceParameterization param(s.baseFaceSize(f));
            for (uint32_t k = 0; k < (param.hasSubFaces() ? param.faceSize() : 1); ++k)
                for (glm::dvec2 st : {glm::dvec2(0.3, 0.4), glm::dvec2(0.61, 0.17), glm::dvec2(0.52, 0.77),
                                      glm::dvec2(0.1, 0.1), glm::dvec2(0.9, 0.85)}) {
                    const uint32_t ptex = s.firstPtexFace(f) + k;
                    const auto at = [&](glm::dvec2 d) { return *s.evaluatePtex(ptex, st + d); };
                    const LimitPoint p = at({0, 0});
                    const glm::dvec3 du = (at({h, 0}).position - at({-h, 0}).position) / (2 * h);
                    const glm::dvec3 dv = (at({0, h}).position - at({0, -h}).position) / (2 * h);
                    const glm::dvec3 duu = (at({h, 0}).du - at({-h, 0}).du) / (2 * h);
                    const glm::dvec3 duv = (at({0, h}).du - at({0, -h}).du) / (2 * h);
                    const glm::dvec3 dvv = (at({0, h}).dv - at({0, -h}).dv) / (2 * h);
                    const double scale = std::max(glm::length(p.du), glm::length(p.dv));
                    const int gregory = s.patches()[*s.findPatch(ptex, st)].type == PatchType::GregoryBasis;
                    worstFirst[gregory] =
                        std::max({worstFirst[gregory], glm::length(du - p.du) / scale, glm::length(dv - p.dv) / scale});
                    worstSecond[gregory] =
                        std::max({worstSecond[gregory], glm::length(duu - p.duu) / scale,
                                  glm::length(duv - p.duv) / scale, glm::length(dvv - p.dvv) / scale});
                    // evaluateFace: the same derivatives scaled to Bfr's (u, v).
                    const LimitPoint q = *s.evaluateFace(f, param.fromSubFace({k, st}));
                    const double c = param.derivativeScale();
                    EXPECT_NEAR(glm::length(q.du - c * p.du), 0.0, 1e-12 * scale);
                    EXPECT_NEAR(glm::length(q.dvv - c * c * p.dvv), 0.0, 1e-12 * scale);
                }
        }
        std::printf("derivatives %-22s vs finite differences: B-spline first %.1e second %.1e, Gregory first %.1e "
                    "second %.1e (relative)\n",
                    s.name().c_str(), worstFirst[0], worstSecond[0], worstFirst[1], worstSecond[1]);
        EXPECT_LE(worstFirst[0], 1e-5) << s.name();
        EXPECT_LE(worstSecond[0], 1e-3) << s.name();
        EXPECT_LE(worstFirst[1], 0.05) << s.name();
    }
}

TEST(SubdivSurface, BoundsHoldTheLimitSurface) {
    for (const ObjShape& shape : allShapes()) {
        const SubdivSurface s = build(shape);
        const scene::Aabb box = s.bounds();
        ASSERT_GT(s.boundsDiagonal(), 0.0) << s.name();
        const glm::dvec3 slack(1e-6 * s.boundsDiagonal());
        for (uint32_t p = 0; p < s.patches().size(); ++p)
            for (glm::dvec2 st : {glm::dvec2(0, 0), glm::dvec2(0.5, 0.5), glm::dvec2(1, 0.25)}) {
                const glm::dvec3 x = s.evaluatePatch(p, st).position;
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(x, glm::dvec3(box.min) - slack)) &&
                            glm::all(glm::lessThanEqual(x, glm::dvec3(box.max) + slack)))
                    << s.name() << ": patch " << p;
            }
    }
}

ObjShape moved(ObjShape shape, double t) {
    for (size_t v = 0; v < shape.positions.size(); ++v) {
        const double phase = 0.7 * double(v) + t;
        shape.positions[v] += glm::vec3(float(0.2 * std::sin(phase)), float(0.15 * std::cos(1.3 * phase)),
                                        float(0.1 * std::sin(2.1 * phase)));
    }
    return shape;
}

// Animation: updating with moved base vertices gives the surface built from
// the moved shape (the update's factorized stencils against create's
// level-by-level refinement: both in float, so within rounding).
TEST(SubdivSurface, UpdateControlPointsEqualsRebuilding) {
    for (const ObjShape& shape : allShapes()) {
        SubdivSurface animated = build(shape);
        const ObjShape pose = moved(shape, 0.5);
        ASSERT_TRUE(animated.updateControlPoints(pose.positions).ok());
        const SubdivSurface rebuilt = build(pose);
        ASSERT_EQ(animated.controlPoints().size(), rebuilt.controlPoints().size());
        ASSERT_EQ(animated.patchPointIndices().size(), rebuilt.patchPointIndices().size());
        const double diagonal = rebuilt.boundsDiagonal();
        double worstPoint = 0.0, worstSurface = 0.0;
        for (size_t i = 0; i < rebuilt.controlPoints().size(); ++i)
            worstPoint =
                std::max(worstPoint, double(glm::length(animated.controlPoints()[i] - rebuilt.controlPoints()[i])));
        for (uint32_t p = 0; p < rebuilt.patches().size(); ++p)
            for (int j = 0; j <= 4; ++j)
                for (int i = 0; i <= 4; ++i) {
                    const glm::dvec2 st(i / 4.0, j / 4.0);
                    worstSurface = std::max(worstSurface, glm::length(animated.evaluatePatch(p, st).position -
                                                                      rebuilt.evaluatePatch(p, st).position));
                }
        std::printf("update %-28s control points %.2e diag, surface %.2e diag\n", shape.name.c_str(),
                    worstPoint / diagonal, worstSurface / diagonal);
        EXPECT_LE(worstPoint / diagonal, 1e-6) << shape.name;
        EXPECT_LE(worstSurface / diagonal, 1e-6) << shape.name;
        EXPECT_EQ(animated.basePositions()[0], pose.positions[0]);
        // And back: the original pose again.
        const SubdivSurface original = build(shape);
        ASSERT_TRUE(animated.updateControlPoints(shape.positions).ok());
        for (size_t i = 0; i < original.controlPoints().size(); ++i)
            ASSERT_LE(glm::length(animated.controlPoints()[i] - original.controlPoints()[i]), 1e-6 * diagonal);
    }
}

TEST(SubdivSurface, UpdateRejectsWrongInput) {
    SubdivSurface s = build(cube());
    std::vector<glm::vec3> positions = cube().positions;
    positions.pop_back();
    Status fewer = s.updateControlPoints(positions);
    ASSERT_FALSE(fewer.ok());
    EXPECT_EQ(fewer.error().message, "cube: 7 base positions given for 8 vertices");
    positions = cube().positions;
    positions[3].y = std::nanf("");
    Status nan = s.updateControlPoints(positions);
    ASSERT_FALSE(nan.ok());
    EXPECT_EQ(nan.error().message, "cube: base vertex 3 is not finite");
    EXPECT_EQ(s.basePositions()[3], cube().positions[3]); // unchanged by a refused update
}

} // namespace
} // namespace tessera::subdiv::test
