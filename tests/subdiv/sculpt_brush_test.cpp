// The sculpt brush (SculptBrush): a dab moves exactly the coefficients
// within its radius on the limit surface, by the falloff; what the edit
// rederives equals a full rebuild (so every overlap still equals its
// neighbour's texels and every corner average holds); the rectangles to
// re-upload cover every rewritten tile and nothing else; holes are never
// edited.
#include "SubdivTestSupport.h"
#include "TileTestSupport.h"

#include "tessera/subdiv/SculptBrush.h"

#include <algorithm>

namespace tessera::subdiv::test {
namespace {

struct Sculptable {
    ObjShape shape;
    SubdivSurface surface;
    DisplacementTiles tiles;
};

Sculptable sculptable(const ObjShape& shape, bool mixed) {
    SubdivSurface surface = build(shape);
    const PtexTopology topology = topologyOf(shape);
    DisplacementTiles tiles = makeTiles(topology, mixed ? mixedSizes(topology, 4, 11)
                                                        : DisplacementTiles::uniformLog2Sizes(topology, 3));
    randomCoefficients(tiles, 5);
    return {shape, std::move(surface), std::move(tiles)};
}

/// The box of the shape's control points.
std::pair<glm::vec3, glm::vec3> boxOf(const ObjShape& shape) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : shape.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return {lo, hi};
}

} // namespace

TEST(SculptBrush, StrokesMatchAFullRebuildOnEveryShape) {
    for (const ObjShape& shape : fileShapes())
        for (bool mixed : {false, true}) {
            SCOPED_TRACE(shape.name + (mixed ? " (mixed sizes)" : ""));
            Sculptable s = sculptable(shape, mixed);
            const SculptBrush brush(s.surface, s.tiles);
            const auto [lo, hi] = boxOf(shape);
            const float size = glm::length(hi - lo);
            size_t rewritten = 0;
            for (int dab = 0; dab < 6; ++dab) {
                // Dabs on the surface, some straddling tile edges by chance.
                const glm::vec3 target = glm::mix(lo, hi, glm::vec3(0.2f + 0.12f * dab, 0.5f, 0.8f - 0.1f * dab));
                SculptDab d;
                d.centre = brush.nearestSurfacePoint(target);
                d.radius = 0.15f * size;
                d.amount = (dab % 2 ? -0.02f : 0.03f) * size;
                const TileUpdate update = brush.apply(s.tiles, d);
                rewritten += update.rewritten.size();
                // The rectangles: one per rewritten tile, inside the texture.
                const std::vector<glm::uvec4> rects = SculptBrush::uploadRects(s.tiles, update);
                ASSERT_EQ(rects.size(), update.rewritten.size());
                for (const glm::uvec4& r : rects) {
                    EXPECT_LE(r.x + r.z, s.tiles.textureWidth());
                    EXPECT_LE(r.y + r.w, s.tiles.textureHeight());
                }
            }
            EXPECT_GT(rewritten, 0u);
            DisplacementTiles full = s.tiles;
            full.rebuild();
            EXPECT_TRUE(std::equal(full.texels().begin(), full.texels().end(), s.tiles.texels().begin()))
                << "the brush's incremental update differs from a full rebuild";
            // Overlaps and corners, checked the same way as after a full build.
            const EdgeAgreement worst = compareEdges(s.tiles);
            EXPECT_LT(worst.value, 1e-6); // relative to the largest coefficient, as ContinuousAcrossEveryEdge
        }
}

TEST(SculptBrush, ADabMovesOnlyCoefficientsWithinItsRadiusByTheFalloff) {
    const ObjShape shape = fileShapes().front();
    Sculptable s = sculptable(shape, false);
    const SculptBrush brush(s.surface, s.tiles);
    const std::vector<float> before(s.tiles.allCoefficients().begin(), s.tiles.allCoefficients().end());
    const auto [lo, hi] = boxOf(shape);
    SculptDab dab;
    dab.centre = brush.nearestSurfacePoint(glm::vec3(hi.x * 2.0f, (lo.y + hi.y) * 0.5f, (lo.z + hi.z) * 0.5f));
    dab.radius = 0.2f * glm::length(hi - lo);
    dab.amount = 0.5f;
    brush.apply(s.tiles, dab);
    const std::span<const float> after = s.tiles.allCoefficients();
    size_t moved = 0;
    float largest = 0.0f;
    for (size_t i = 0; i < before.size(); ++i) {
        const float delta = after[i] - before[i];
        EXPECT_GE(delta, 0.0f);
        EXPECT_LE(delta, dab.amount * 1.0001f);
        largest = std::max(largest, delta);
        moved += delta != 0.0f;
    }
    EXPECT_GT(moved, 0u);
    EXPECT_LT(moved, before.size() / 2) << "a dab of a fifth of the size touched half the surface";
    // The coefficient nearest the centre sits at the centre: the full amount.
    EXPECT_NEAR(largest, dab.amount, 1e-6f);
}

TEST(SculptBrush, HolesAreNeverEdited) {
    for (const ObjShape& shape : fileShapes()) {
        if (shape.name != "catmark_hole_test1.obj") continue;
        Sculptable s = sculptable(shape, false);
        const SculptBrush brush(s.surface, s.tiles);
        const std::vector<float> before(s.tiles.allCoefficients().begin(), s.tiles.allCoefficients().end());
        const auto [lo, hi] = boxOf(shape);
        SculptDab dab;
        dab.centre = (lo + hi) * 0.5f;
        dab.radius = glm::length(hi - lo); // everything
        dab.amount = 1.0f;
        brush.apply(s.tiles, dab);
        size_t holeTiles = 0;
        for (uint32_t t = 0; t < s.tiles.tileCount(); ++t) {
            if (s.surface.evaluatePtex(t, glm::dvec2(0.5)).has_value()) continue;
            ++holeTiles;
            const size_t first = s.tiles.firstCoefficient(t), n = size_t(s.tiles.tileSize(t)) * s.tiles.tileSize(t);
            for (size_t i = first; i < first + n; ++i)
                EXPECT_EQ(s.tiles.allCoefficients()[i], before[i]) << "hole tile " << t << " was edited";
        }
        EXPECT_GT(holeTiles, 0u);
        return;
    }
    FAIL() << "catmark_hole_test1.obj not among the shapes";
}

} // namespace tessera::subdiv::test
