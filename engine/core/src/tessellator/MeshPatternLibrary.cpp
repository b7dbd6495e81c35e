#include "tessera/tessellator/MeshPatternLibrary.h"

#include "MeshPieceStitcher.h"

#include <cassert>

namespace tessera::tessellator {

const MeshPatternLibrary& MeshPatternLibrary::quadFractionalOdd() {
    static const MeshPatternLibrary library;
    return library;
}

MeshPatternLibrary::MeshPatternLibrary() {
    using Rows = detail::MeshPieceStitcher::Rows;
    detail::MeshPieceStitcher pieces(mKeys, mTriangles);
    const auto oddSpacing = detail::MeshPieceStitcher::oddSpacing;
    using Diagonals = detail::RowStitcher::Diagonals;
    mKeys.resize(TS_MESH_KEY_COUNT);
    // Transition strips: the outer edge's points to the first ring's row,
    // which spans the inner axis without its two outermost points.
    for (uint32_t o = 0; o < TS_MESH_OUTER_CLASSES; ++o)
        for (uint32_t i = 0; i < TS_MESH_INNER_CLASSES; ++i) {
            const uint32_t outer = 2 * (o + 1), inner = 2 * (i + 2);
            pieces.add(o * TS_MESH_INNER_CLASSES + i, outer, inner - 2, [&](detail::RowStitcher& s, Rows a, Rows b) {
                s.transition(a, oddSpacing(outer), b, oddSpacing(inner));
            });
        }
    // One side of a ring pair: a trapezoid, diagonals mirrored.
    for (uint32_t k = 0; k < TS_MESH_RING_KEYS; ++k) {
        const uint32_t outside = 2 * (k + 2);
        pieces.add(TS_MESH_KEY_RING + k, outside, outside - 2, [](detail::RowStitcher& s, Rows a, Rows b) {
            s.regular(a, b, true, Diagonals::Mirrored);
        });
    }
    // The centre strip, two rows of equal length; the diagonal rule depends
    // on whether u is the wider axis (QuadPattern's rules for odd axes).
    for (uint32_t k = 0; k < TS_MESH_CENTRE_KEYS; ++k) {
        const uint32_t length = 2 * (k + 1);
        pieces.add(TS_MESH_KEY_CENTRE + k, length, length, [](detail::RowStitcher& s, Rows a, Rows b) {
            s.regular(a, b, false, Diagonals::InsideToOutside);
        });
        pieces.add(TS_MESH_KEY_CENTRE + TS_MESH_CENTRE_KEYS + k, length, length, [](detail::RowStitcher& s, Rows a, Rows b) {
            s.regular(a, b, false, Diagonals::InsideToOutsideExceptMiddle);
        });
    }
    // All levels 1: rows v = 0 and v = 1, two triangles.
    pieces.add(TS_MESH_KEY_MINIMAL, 2, 2, [](detail::RowStitcher& s, Rows a, Rows b) {
        s.triangle(a[0], a[1], b[0]);
        s.triangle(a[1], b[1], b[0]);
    });
}

} // namespace tessera::tessellator
