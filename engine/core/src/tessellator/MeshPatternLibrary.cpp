#include "tessera/tessellator/MeshPatternLibrary.h"

#include "EdgeSpacing.h"
#include "RowStitcher.h"

#include <cassert>
#include <numeric>

namespace tessera::tessellator {
namespace {

// Triangles go in the order and winding Tessellator emits them (the
// reference's reversed: Vulkan's counter-clockwise).
constexpr bool kReverseWinding = true;

// An odd-spacing edge with `points` points: only the count and parity shape
// a stitch; the level's fraction only moves points, which the shaders do.
detail::EdgeSpacing oddSpacing(uint32_t points) {
    return detail::EdgeSpacing(detail::toFixed(float(points - 1)), detail::Parity::Odd);
}

std::vector<uint32_t> row(uint32_t first, uint32_t count) {
    std::vector<uint32_t> indices(count);
    std::iota(indices.begin(), indices.end(), first);
    return indices;
}

} // namespace

const MeshPatternLibrary& MeshPatternLibrary::quadFractionalOdd() {
    static const MeshPatternLibrary library;
    return library;
}

template <typename Stitch>
void MeshPatternLibrary::add(uint32_t key, uint32_t rowA, uint32_t rowB, Stitch&& stitch) {
    assert(rowA + rowB <= TS_MESH_MAX_VERTICES);
    std::vector<uint32_t> indices;
    detail::RowStitcher stitcher(indices, kReverseWinding);
    stitch(stitcher, row(0, rowA), row(rowA, rowB));
    const auto first = static_cast<uint32_t>(mTriangles.size());
    for (size_t i = 0; i < indices.size(); i += 3)
        mTriangles.push_back(indices[i] | indices[i + 1] << 8 | indices[i + 2] << 16);
    const auto count = static_cast<uint32_t>(mTriangles.size()) - first;
    assert(count <= TS_MESH_MAX_TRIANGLES);
    mKeys[key].entry = {first, count, rowA, rowB};
}

MeshPatternLibrary::MeshPatternLibrary() {
    using Rows = const std::vector<uint32_t>&;
    using Diagonals = detail::RowStitcher::Diagonals;
    mKeys.resize(TS_MESH_KEY_COUNT);
    // Transition strips: the outer edge's points to the first ring's row,
    // which spans the inner axis without its two outermost points.
    for (uint32_t o = 0; o < TS_MESH_OUTER_CLASSES; ++o)
        for (uint32_t i = 0; i < TS_MESH_INNER_CLASSES; ++i) {
            const uint32_t outer = 2 * (o + 1), inner = 2 * (i + 2);
            add(o * TS_MESH_INNER_CLASSES + i, outer, inner - 2, [&](detail::RowStitcher& s, Rows a, Rows b) {
                s.transition(a, oddSpacing(outer), b, oddSpacing(inner));
            });
        }
    // One side of a ring pair: a trapezoid, diagonals mirrored.
    for (uint32_t k = 0; k < TS_MESH_RING_KEYS; ++k) {
        const uint32_t outside = 2 * (k + 2);
        add(TS_MESH_KEY_RING + k, outside, outside - 2, [](detail::RowStitcher& s, Rows a, Rows b) {
            s.regular(a, b, true, Diagonals::Mirrored);
        });
    }
    // The centre strip, two rows of equal length; the diagonal rule depends
    // on whether u is the wider axis (QuadPattern's rules for odd axes).
    for (uint32_t k = 0; k < TS_MESH_CENTRE_KEYS; ++k) {
        const uint32_t length = 2 * (k + 1);
        add(TS_MESH_KEY_CENTRE + k, length, length, [](detail::RowStitcher& s, Rows a, Rows b) {
            s.regular(a, b, false, Diagonals::InsideToOutside);
        });
        add(TS_MESH_KEY_CENTRE + TS_MESH_CENTRE_KEYS + k, length, length, [](detail::RowStitcher& s, Rows a, Rows b) {
            s.regular(a, b, false, Diagonals::InsideToOutsideExceptMiddle);
        });
    }
    // All levels 1: rows v = 0 and v = 1, two triangles.
    add(TS_MESH_KEY_MINIMAL, 2, 2, [](detail::RowStitcher& s, Rows a, Rows b) {
        s.triangle(a[0], a[1], b[0]);
        s.triangle(a[1], b[1], b[0]);
    });
}

} // namespace tessera::tessellator
