#include "TrianglePattern.h"

#include "PointWriter.h"
#include "RowStitcher.h"

#include <array>
#include <cassert>
#include <vector>

namespace tessera::tessellator::detail {
namespace {

constexpr int kEdges = 3;

// One ring as three rows of point indices, each from its edge's first corner
// to the next edge's first corner (so consecutive rows share a corner).
using Ring = std::array<std::vector<uint32_t>, kEdges>;

// Closes a ring whose points were added edge after edge, `start[e]` being
// the first point of edge e and `count[e]` its points without the end corner.
Ring closeRing(const std::array<uint32_t, kEdges>& start, const std::array<int, kEdges>& count) {
    Ring ring;
    for (int e = 0; e < kEdges; ++e) {
        auto& row = ring[static_cast<size_t>(e)];
        for (int k = 0; k < count[static_cast<size_t>(e)]; ++k)
            row.push_back(start[static_cast<size_t>(e)] + uint32_t(k));
        row.push_back(start[static_cast<size_t>((e + 1) % kEdges)]);
    }
    return ring;
}

} // namespace

TessellatedPatch TrianglePattern::build(const PatchFactors& factors, bool reverseWinding) {
    assert(!factors.culled());
    TessellatedPatch patch;
    PointWriter points(patch.uv);
    RowStitcher stitch(patch.indices, reverseWinding);

    if (factors.minimal()) {
        const uint32_t v = points.add(0, kFxpOne); // start of the u = 0 edge
        const uint32_t w = points.add(0, 0);       // start of the v = 0 edge
        const uint32_t u = points.add(kFxpOne, 0); // start of the w = 0 edge
        stitch.triangle(v, w, u);
        return patch;
    }

    // Outer ring, starting at v = 1 and running round through w = 1 and u = 1.
    // Edge 0 (u = 0) and edge 2 (w = 0) read their spacing backwards.
    std::array<uint32_t, kEdges> start{};
    std::array<int, kEdges> count{};
    for (int e = 0; e < kEdges; ++e) {
        const EdgeSpacing& spacing = factors.outer(e);
        const int last = spacing.pointCount() - 1;
        start[static_cast<size_t>(e)] = points.next();
        count[static_cast<size_t>(e)] = last;
        for (int p = 0; p < last; ++p) {
            const Fxp t = spacing.place(e == 1 ? p : last - p);
            if (e == 0)
                points.add(0, t);
            else if (e == 1)
                points.add(t, 0);
            else
                points.add(t, kFxpOne - t);
        }
    }
    const Ring outer = closeRing(start, count);

    // Inner rings. Ring r lies where the inner spacing's point r would be,
    // moved in by 2/3 of that distance along the perpendicular (barycentric
    // scaling), and takes the inner spacing's points r .. N-1-r along it.
    const EdgeSpacing& inner = factors.inner(0);
    const int n = factors.innerPoints(0);
    const int generatedRings = n >> 1;
    std::vector<Ring> rings(1); // rings[0] unused: the outer ring is separate
    for (int r = 1; r < generatedRings; ++r) {
        const int first = r, last = n - 1 - r;
        Fxp perp = inner.place(first) * kFxpTwoThirds;
        perp = (perp + kFxpHalf) >> kFractionBits;
        const Fxp shift = (perp + 1) / 2;
        for (int e = 0; e < kEdges; ++e) {
            start[static_cast<size_t>(e)] = points.next();
            count[static_cast<size_t>(e)] = last - first;
            for (int p = first; p < last; ++p) {
                const Fxp t = inner.place(e == 1 ? p : last - (p - first)) - shift;
                if (e == 0)
                    points.add(perp, t);
                else if (e == 1)
                    points.add(t, perp);
                else
                    points.add(t, kFxpOne - t - perp);
            }
        }
        rings.push_back(closeRing(start, count));
    }
    if (!inner.odd()) {
        // Even spacing ends in a centre point, a ring that is one point.
        const uint32_t centre = points.add(kFxpOneThird, kFxpOneThird);
        rings.push_back(Ring{std::vector<uint32_t>{centre}, {centre}, {centre}});
    }

    const int connectedRings = (n + 1) >> 1;
    assert(static_cast<int>(rings.size()) == connectedRings);
    for (int r = 1; r < connectedRings; ++r) {
        for (int e = 0; e < kEdges; ++e) {
            const auto& insideRow = rings[static_cast<size_t>(r)][static_cast<size_t>(e)];
            if (r == 1)
                stitch.transition(outer[static_cast<size_t>(e)], factors.outer(e), insideRow, inner);
            else
                stitch.regular(rings[static_cast<size_t>(r - 1)][static_cast<size_t>(e)], insideRow, true,
                               RowStitcher::Diagonals::Mirrored);
        }
    }
    if (inner.odd()) {
        // Odd spacing ends in a ring of three points: one triangle.
        const auto& last = rings.back();
        stitch.triangle(last[0][0], last[1][0], last[2][0]);
    }
    return patch;
}

uint32_t TrianglePattern::countTriangles(const PatchFactors& factors) {
    if (factors.culled()) return 0;
    if (factors.minimal()) return 1;
    const int n = factors.innerPoints(0);
    // Each edge strip between two rows has (points in both rows - 2) triangles.
    int triangles = 0;
    for (int e = 0; e < kEdges; ++e) triangles += factors.outer(e).pointCount() + (n - 2) - 2;
    const int connectedRings = (n + 1) >> 1;
    for (int r = 2; r < connectedRings; ++r) triangles += kEdges * 2 * (n - 2 * r);
    if (factors.inner(0).odd()) triangles += 1;
    return static_cast<uint32_t>(triangles);
}

uint32_t TrianglePattern::countPoints(const PatchFactors& factors) {
    if (factors.culled()) return 0;
    if (factors.minimal()) return 3;
    int points = 0;
    for (int e = 0; e < kEdges; ++e) points += factors.outer(e).pointCount() - 1;
    const int rings = (factors.innerPoints(0) >> 1) - 1;
    if (factors.inner(0).odd())
        points += kEdges * rings * rings;
    else
        points += kEdges * rings * (rings + 1) + 1;
    return static_cast<uint32_t>(points);
}

} // namespace tessera::tessellator::detail
