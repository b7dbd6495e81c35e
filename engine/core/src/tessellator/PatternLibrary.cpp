#include "tessera/tessellator/PatternLibrary.h"

#include "EdgeSpacing.h"
#include "RowStitcher.h"
#include "tessera/shaders/TessPattern.h"

#include <algorithm>
#include <array>
#include <cassert>

namespace tessera::tessellator {
namespace {

using shader::tsEmuRef;

// Triangles go in the order Tessellator emits them (the reference's reversed,
// Vulkan's ccw), so the pieces of a patch are its pattern exactly.
constexpr bool kReverseWinding = true;

// An odd-spacing edge with `points` points. Only the point count and parity
// shape a stitch (EdgeSpacing::halfPoints, odd); the level's fraction only
// moves points, which the shaders do.
detail::EdgeSpacing oddSpacing(uint32_t points) {
    return detail::EdgeSpacing(detail::toFixed(float(points - 1)), detail::Parity::Odd);
}

using Row = std::vector<uint32_t>;
// A ring of the inner grid as four rows of grid references, each from its
// edge's first corner to the next edge's first corner (QuadPattern's order).
using Ring = std::array<Row, 4>;

Ring gridRing(uint32_t r, const std::array<uint32_t, 2>& n) {
    Ring ring;
    const std::array<uint32_t, 2> last{n[0] - 1 - r, n[1] - 1 - r};
    for (uint32_t e = 0; e < 4; ++e) {
        const uint32_t along = (e + 1) & 1, across = 1 - along;
        const uint32_t perp = e < 2 ? r : last[across];
        const uint32_t end = last[along];
        for (uint32_t p = r; p <= end; ++p) {
            // The row's last point is the next edge's first corner.
            const uint32_t index = e == 1 || e == 2 ? p : end - (p - r);
            ring[e].push_back(along == 0 ? tsEmuRef(TS_EMU_REF_GRID, index, perp) : tsEmuRef(TS_EMU_REF_GRID, perp, index));
        }
    }
    return ring;
}

Row reversed(Row row) {
    std::reverse(row.begin(), row.end());
    return row;
}

} // namespace

const PatternLibrary& PatternLibrary::quadFractionalOdd() {
    static const PatternLibrary library;
    return library;
}

PatternLibrary::PatternLibrary() {
    mPieces.resize(TS_EMU_KEY_COUNT);
    for (uint32_t o = 0; o < TS_EMU_OUTER_CLASSES; ++o)
        for (uint32_t i = 0; i < TS_EMU_INNER_CLASSES; ++i) addStrip(2 * (o + 1), 2 * (i + 2));
    for (uint32_t u = 0; u < TS_EMU_INNER_CLASSES; ++u)
        for (uint32_t v = 0; v < TS_EMU_INNER_CLASSES; ++v) addInterior(2 * (u + 2), 2 * (v + 2));
    addMinimal();
}

void PatternLibrary::addStrip(uint32_t outerPoints, uint32_t innerPoints) {
    const uint32_t key = (outerPoints / 2 - 1) * TS_EMU_INNER_CLASSES + (innerPoints / 2 - 2);
    // The outer row has every point of the edge; the first ring's row spans
    // the inner axis without its two outermost points.
    Row outside, inside;
    for (uint32_t k = 0; k < outerPoints; ++k) outside.push_back(tsEmuRef(TS_EMU_REF_OUTER, k, 0));
    for (uint32_t k = 0; k + 2 < innerPoints; ++k) inside.push_back(tsEmuRef(TS_EMU_REF_RING, k, 0));
    const auto first = static_cast<uint32_t>(mVertices.size());
    detail::RowStitcher stitch(mVertices, kReverseWinding);
    stitch.transition(outside, oddSpacing(outerPoints), inside, oddSpacing(innerPoints));
    mPieces[key] = {first, static_cast<uint32_t>(mVertices.size()) - first};
}

void PatternLibrary::addInterior(uint32_t pointsU, uint32_t pointsV) {
    const uint32_t key = TS_EMU_STRIP_KEYS + (pointsU / 2 - 2) * TS_EMU_INNER_CLASSES + (pointsV / 2 - 2);
    const std::array<uint32_t, 2> n{pointsU, pointsV};
    // Odd spacing has no centre row of points: the rings end in a two-row
    // strip across the narrower axis (QuadPattern's rules, for odd axes).
    const uint32_t rings = std::min(n[0], n[1]) / 2;
    std::vector<Ring> ring;
    for (uint32_t r = 1; r < rings; ++r) ring.push_back(gridRing(r, n));
    const auto first = static_cast<uint32_t>(mVertices.size());
    detail::RowStitcher stitch(mVertices, kReverseWinding);
    for (size_t r = 1; r < ring.size(); ++r)
        for (size_t e = 0; e < 4; ++e)
            stitch.regular(ring[r - 1][e], ring[r][e], true, detail::RowStitcher::Diagonals::Mirrored);
    const Ring& last = ring.back();
    if (n[0] > n[1])
        stitch.regular(last[1], reversed(last[3]), false, detail::RowStitcher::Diagonals::InsideToOutside);
    else
        stitch.regular(last[0], reversed(last[2]), false, detail::RowStitcher::Diagonals::InsideToOutsideExceptMiddle);
    mPieces[key] = {first, static_cast<uint32_t>(mVertices.size()) - first};
}

void PatternLibrary::addMinimal() {
    const auto first = static_cast<uint32_t>(mVertices.size());
    const uint32_t a = tsEmuRef(TS_EMU_REF_CORNER, 0, 0), b = tsEmuRef(TS_EMU_REF_CORNER, 1, 0);
    const uint32_t c = tsEmuRef(TS_EMU_REF_CORNER, 3, 0), d = tsEmuRef(TS_EMU_REF_CORNER, 2, 0);
    detail::RowStitcher stitch(mVertices, kReverseWinding);
    stitch.triangle(a, b, d);
    stitch.triangle(b, c, d);
    mPieces[TS_EMU_KEY_MINIMAL] = {first, static_cast<uint32_t>(mVertices.size()) - first};
}

} // namespace tessera::tessellator
