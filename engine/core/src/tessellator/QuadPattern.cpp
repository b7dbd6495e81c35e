#include "QuadPattern.h"

#include "PointWriter.h"
#include "RowStitcher.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <vector>

namespace tessera::tessellator::detail {
namespace {

constexpr int kEdges = 4;

// One ring as four rows of point indices, each from its edge's first corner
// to the next edge's first corner. Edges run u = 0 (v falling), v = 0 (u
// rising), u = 1 (v rising), v = 1 (u falling).
using Ring = std::array<std::vector<uint32_t>, kEdges>;

// The inner axis whose spacing runs along edge e: v for the u = const edges.
int alongAxis(int edge) {
    return (edge + 1) & 1;
}

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

std::vector<uint32_t> reversed(std::vector<uint32_t> row) {
    std::reverse(row.begin(), row.end());
    return row;
}

// Ring counts of the inner grid with n[0] x n[1] points.
struct RingCounts {
    int generated; ///< rings with four proper edges, the outer ring counting as 0
    int connected; ///< rings to stitch, including a degenerate centre row or point
};

RingCounts ringCounts(const std::array<int, 2>& n) {
    return {std::min(n[0], n[1]) >> 1, std::min((n[0] + 1) >> 1, (n[1] + 1) >> 1)};
}

} // namespace

TessellatedPatch QuadPattern::build(const PatchFactors& factors, bool reverseWinding) {
    assert(!factors.culled());
    TessellatedPatch patch;
    PointWriter points(patch.uv);
    RowStitcher stitch(patch.indices, reverseWinding);

    if (factors.minimal()) {
        const uint32_t a = points.add(0, 0), b = points.add(kFxpOne, 0);
        const uint32_t c = points.add(kFxpOne, kFxpOne), d = points.add(0, kFxpOne);
        stitch.triangle(a, b, d);
        stitch.triangle(b, c, d);
        return patch;
    }

    // Outer ring from (0, 1) round through (0, 0), (1, 0) and (1, 1).
    std::array<uint32_t, kEdges> start{};
    std::array<int, kEdges> count{};
    for (int e = 0; e < kEdges; ++e) {
        const EdgeSpacing& spacing = factors.outer(e);
        const int last = spacing.pointCount() - 1;
        start[static_cast<size_t>(e)] = points.next();
        count[static_cast<size_t>(e)] = last;
        for (int p = 0; p < last; ++p) {
            const Fxp t = spacing.place(e == 1 || e == 2 ? p : last - p);
            switch (e) {
            case 0:
                points.add(0, t);
                break;
            case 1:
                points.add(t, 0);
                break;
            case 2:
                points.add(kFxpOne, t);
                break;
            default:
                points.add(t, kFxpOne);
                break;
            }
        }
    }
    const Ring outer = closeRing(start, count);

    // Inner rectangles: ring r takes the inner spacings' points r .. N-1-r.
    const std::array<int, 2> n{factors.innerPoints(0), factors.innerPoints(1)};
    const RingCounts rc = ringCounts(n);
    std::vector<Ring> rings(1);
    for (int r = 1; r < rc.generated; ++r) {
        const std::array<int, 2> last{n[0] - 1 - r, n[1] - 1 - r};
        for (int e = 0; e < kEdges; ++e) {
            const int along = alongAxis(e), across = 1 - along;
            const Fxp perp = factors.inner(across).place(e < 2 ? r : last[static_cast<size_t>(across)]);
            const EdgeSpacing& spacing = factors.inner(along);
            const int end = last[static_cast<size_t>(along)];
            start[static_cast<size_t>(e)] = points.next();
            count[static_cast<size_t>(e)] = end - r;
            for (int p = r; p < end; ++p) {
                const Fxp t = spacing.place(e == 1 || e == 2 ? p : end - (p - r));
                if (along == 1)
                    points.add(perp, t);
                else
                    points.add(t, perp);
            }
        }
        rings.push_back(closeRing(start, count));
    }

    // Even spacing across the narrower axis ends the rings in a row of points
    // on its midline (a single point when both axes match): a ring whose two
    // long edges are the row, one each way, and whose short edges are its ends.
    const bool rowAlongU = n[0] > n[1] && !factors.inner(1).odd();
    const bool rowAlongV = !rowAlongU && n[1] >= n[0] && !factors.inner(0).odd();
    if (rowAlongU) {
        std::vector<uint32_t> row;
        for (int p = rc.generated; p <= n[0] - 1 - rc.generated; ++p)
            row.push_back(points.add(factors.inner(0).place(p), kFxpHalf));
        rings.push_back(Ring{std::vector<uint32_t>{row.front()}, row, {row.back()}, reversed(row)});
    } else if (rowAlongV) {
        std::vector<uint32_t> row; // v falling, like the u = 0 edge
        for (int p = n[1] - 1 - rc.generated; p >= rc.generated; --p)
            row.push_back(points.add(kFxpHalf, factors.inner(1).place(p)));
        rings.push_back(Ring{row, {row.back()}, reversed(row), {row.front()}});
    }

    assert(static_cast<int>(rings.size()) == rc.connected);
    for (int r = 1; r < rc.connected; ++r) {
        for (int e = 0; e < kEdges; ++e) {
            const auto& insideRow = rings[static_cast<size_t>(r)][static_cast<size_t>(e)];
            if (r == 1)
                stitch.transition(outer[static_cast<size_t>(e)], factors.outer(e), insideRow,
                                  factors.inner(alongAxis(e)));
            else
                stitch.regular(rings[static_cast<size_t>(r - 1)][static_cast<size_t>(e)], insideRow, true,
                               RowStitcher::Diagonals::Mirrored);
        }
    }

    // Odd spacing across the narrower axis ends the rings in a two-row strip:
    // stitch its long sides to each other.
    const Ring& last = rings.back();
    if (n[0] > n[1] && factors.inner(1).odd()) {
        stitch.regular(last[1], reversed(last[3]), false, RowStitcher::Diagonals::InsideToOutside);
    } else if (n[1] >= n[0] && factors.inner(0).odd()) {
        stitch.regular(last[0], reversed(last[2]), false,
                       factors.inner(1).odd() ? RowStitcher::Diagonals::InsideToOutsideExceptMiddle
                                              : RowStitcher::Diagonals::InsideToOutside);
    }
    return patch;
}

uint32_t QuadPattern::countTriangles(const PatchFactors& factors) {
    if (factors.culled()) return 0;
    if (factors.minimal()) return 2;
    const std::array<int, 2> n{factors.innerPoints(0), factors.innerPoints(1)};
    const RingCounts rc = ringCounts(n);
    // Each edge strip between two rows has (points in both rows - 2) triangles.
    int triangles = 0;
    for (int e = 0; e < kEdges; ++e) triangles += factors.outer(e).pointCount() + (n[size_t(alongAxis(e))] - 2) - 2;
    for (int r = 2; r < rc.connected; ++r)
        for (int e = 0; e < kEdges; ++e) triangles += 2 * (n[size_t(alongAxis(e))] - 2 * r);
    // The centre strip: its long rows have N - 2r points along the long axis.
    const int lastRing = rc.connected - 1;
    if (n[0] > n[1] && factors.inner(1).odd())
        triangles += 2 * (n[0] - 2 * lastRing - 1);
    else if (n[1] >= n[0] && factors.inner(0).odd())
        triangles += 2 * (n[1] - 2 * lastRing - 1);
    return static_cast<uint32_t>(triangles);
}

uint32_t QuadPattern::countPoints(const PatchFactors& factors) {
    if (factors.culled()) return 0;
    if (factors.minimal()) return 4;
    int points = 0;
    for (int e = 0; e < kEdges; ++e) points += factors.outer(e).pointCount() - 1;
    return static_cast<uint32_t>(points + (factors.innerPoints(0) - 2) * (factors.innerPoints(1) - 2));
}

} // namespace tessera::tessellator::detail
