// Creases and corners behave as Catmull-Clark's sharp rules say: an
// infinitely sharp crease loop's limit curve is the uniform cubic B-spline
// of its cage vertices (regular crease vertices on the torus: B-spline
// boundary patches, exact; the cube's top loop of valence-3 crease
// vertices: isolated with end caps, within tolerance), semi-sharp creases
// lie between smooth and sharp and approach sharp as sharpness grows, and
// sharp corners interpolate their vertex.
#include "SubdivTestSupport.h"

#include <cstdio>

namespace tessera::subdiv::test {
namespace {

// Point t in [0, 1] of the uniform cubic B-spline segment between p1 and p2.
glm::dvec3 bspline(glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 p2, glm::dvec3 p3, double t) {
    const double s = 1.0 - t;
    return (s * s * s * p0 + (3 * t * t * t - 6 * t * t + 4) * p1 + (-3 * t * t * t + 3 * t * t + 3 * t + 1) * p2 +
            t * t * t * p3) /
           6.0;
}

// (u, v) of quad face `face` at fraction t from its vertex `a` to its
// vertex `b` along their shared edge (edge k runs from face vertex k to k+1:
// (t, 0), (1, t), (1 - t, 1), (0, 1 - t)).
glm::dvec2 quadEdgePoint(const ObjShape& shape, uint32_t face, uint32_t a, uint32_t b, double t) {
    const uint32_t* fv = &shape.faceVertices[4 * face]; // the crease shapes are all-quad
    for (uint32_t k = 0; k < 4; ++k) {
        const uint32_t from = fv[k], to = fv[(k + 1) % 4];
        if (from != a && from != b) continue;
        if (to != a && to != b) continue;
        const double x = from == a ? t : 1.0 - t;
        const glm::dvec2 points[4] = {{x, 0.0}, {1.0, x}, {1.0 - x, 1.0}, {0.0, 1.0 - x}};
        return points[k];
    }
    ADD_FAILURE() << "face " << face << " has no edge " << a << "-" << b;
    return {};
}

// Worst distance (relative to the diagonal) between the limit surface along
// the creased loop `loop` (closed, of cage vertices) and the loop's B-spline,
// evaluated on face `faces[i]` along its edge from loop[i] to loop[i+1].
double creaseCurveError(const SubdivSurface& s, const ObjShape& shape, const std::vector<uint32_t>& loop,
                        const std::vector<uint32_t>& faces) {
    const size_t n = loop.size();
    const auto cage = [&](size_t i) { return glm::dvec3(shape.positions[loop[(i + n) % n]]); };
    double worst = 0.0;
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k <= 16; ++k) {
            const double t = k / 16.0;
            const glm::dvec2 uv = quadEdgePoint(shape, faces[i], loop[i], loop[(i + 1) % n], t);
            const glm::dvec3 expected = bspline(cage(i - 1), cage(i), cage(i + 1), cage(i + 2), t);
            worst = std::max(worst, glm::length(s.evaluateFace(faces[i], uv)->position - expected));
        }
    return worst / s.boundsDiagonal();
}

// The torus's ring 0 and the faces on either side of each of its edges.
struct TorusRing {
    std::vector<uint32_t> loop, facesAbove, facesBelow;
    TorusRing(uint32_t around, uint32_t across) {
        for (uint32_t i = 0; i < around; ++i) {
            loop.push_back(i);
            facesAbove.push_back(i);
            facesBelow.push_back((across - 1) * around + i);
        }
    }
};

TEST(Creases, SharpRingOnTheTorusIsItsCageBSpline) {
    const ObjShape shape = torus(8, 6, 10.0f, "torus_sharp_ring");
    const SubdivSurface s = build(shape);
    const TorusRing ring(8, 6);
    const double above = creaseCurveError(s, shape, ring.loop, ring.facesAbove);
    const double below = creaseCurveError(s, shape, ring.loop, ring.facesBelow);
    std::printf("crease torus sharp ring: limit curve vs cage B-spline %.2e / %.2e diag (either side)\n", above, below);
    EXPECT_LE(above, 1e-6);
    EXPECT_LE(below, 1e-6);
    // Regular crease vertices: every patch a B-spline, no end cap.
    for (const Patch& p : s.patches()) EXPECT_EQ(p.type, PatchType::Regular);
}

TEST(Creases, SharpLoopOnTheCubeIsItsCageBSpline) {
    const ObjShape shape = creasedCube(10.0f);
    // The loop around the top face 1 = (4, 5, 6, 7), from the top face and
    // from the side faces 2 .. 5 below it.
    const SubdivSurface s = build(shape);
    const double top = creaseCurveError(s, shape, {4, 5, 6, 7}, {1, 1, 1, 1});
    const double side = creaseCurveError(s, shape, {4, 5, 6, 7}, {2, 3, 4, 5});
    std::printf("crease cube sharp loop (valence-3 crease vertices): limit curve vs cage B-spline %.2e / %.2e diag\n",
                top, side);
    EXPECT_LE(top, 1e-5);
    EXPECT_LE(side, 1e-5);
}

// How far the limit surface is from the sharp crease curve at the middle of
// each creased edge, for a crease of `sharpness` on the torus ring.
double distanceFromSharp(float sharpness) {
    const ObjShape shape = torus(8, 6, sharpness, "torus");
    const SubdivSurface s = build(shape, {4, 2});
    const TorusRing ring(8, 6);
    double worst = 0.0;
    for (size_t i = 0; i < 8; ++i) {
        const auto cage = [&](size_t k) { return glm::dvec3(shape.positions[(k + 8) % 8]); };
        const glm::dvec3 sharp = bspline(cage(i - 1), cage(i), cage(i + 1), cage(i + 2), 0.5);
        const glm::dvec2 uv = quadEdgePoint(shape, ring.facesAbove[i], ring.loop[i], ring.loop[(i + 1) % 8], 0.5);
        worst = std::max(worst, glm::length(s.evaluateFace(ring.facesAbove[i], uv)->position - sharp));
    }
    return worst / s.boundsDiagonal();
}

TEST(Creases, SemiSharpCreasesLieBetweenSmoothAndSharp) {
    double previous = 1.0;
    for (float sharpness : {0.0f, 0.5f, 1.0f, 2.0f, 3.0f, 10.0f}) {
        const double d = distanceFromSharp(sharpness);
        std::printf("crease torus ring sharpness %4.1f: %.3e diag from the sharp crease curve\n", sharpness, d);
        EXPECT_LT(d, previous) << "sharpness " << sharpness;
        previous = d;
    }
    EXPECT_GT(distanceFromSharp(0.0f), 1e-2);  // smooth is visibly different
    EXPECT_GT(distanceFromSharp(1.0f), 1e-3);  // and so is semi-sharp
    EXPECT_LT(distanceFromSharp(10.0f), 1e-6); // infinitely sharp is on the curve
}

TEST(Creases, SemiSharpDiffersFromSmoothOnTheRegressionShape) {
    for (const ObjShape& shape : fileShapes()) {
        if (shape.name != "catmark_cube_creases1.obj") continue;
        ObjShape smooth = shape;
        smooth.creases.clear();
        const SubdivSurface creased = build(shape), plain = build(smooth);
        double largest = 0.0;
        for (uint32_t f = 0; f < creased.baseFaceCount(); ++f)
            for (glm::dvec2 uv : {glm::dvec2(0, 0), glm::dvec2(0.5, 0), glm::dvec2(0.5, 0.5)})
                largest = std::max(
                    largest, glm::length(creased.evaluateFace(f, uv)->position - plain.evaluateFace(f, uv)->position));
        EXPECT_GT(largest / plain.boundsDiagonal(), 1e-2);
    }
}

// Sharp corners interpolate their cage vertex: the boundary corners of an
// EdgeAndCorner grid, and the explicitly sharp corner of an EdgeOnly one;
// the smooth corner of an EdgeOnly grid does not.
TEST(Creases, SharpCornersInterpolateTheirVertex) {
    const ObjShape edgeAndCorner = grid(4, BoundaryInterpolation::EdgeAndCorner, "grid");
    const SubdivSurface a = build(edgeAndCorner);
    EXPECT_LE(glm::length(a.evaluateFace(0, {0, 0})->position - glm::dvec3(edgeAndCorner.positions[0])),
              1e-6 * a.boundsDiagonal());
    const ObjShape corners = gridWithCorners(); // vertex 0 sharp (10), vertex 3 smooth
    const SubdivSurface b = build(corners);
    EXPECT_LE(glm::length(b.evaluateFace(0, {0, 0})->position - glm::dvec3(corners.positions[0])),
              1e-6 * b.boundsDiagonal());
    EXPECT_GT(glm::length(b.evaluateFace(2, {1, 0})->position - glm::dvec3(corners.positions[3])),
              1e-3 * b.boundsDiagonal());
}

} // namespace
} // namespace tessera::subdiv::test
