#pragma once
// Triangulates the strip between two rows of points, the way the reference
// tessellator does: transition stitching (outer edge to first ring), regular
// ring-to-ring stitching, and the strips at the centre of a quad.
//
// Rows are lists of point indices running the same way along the strip.
// Triangles are handed to the sink in the reference's "clockwise" order,
// which the caller turns into the requested winding.

#include "EdgeSpacing.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::tessellator::detail {

class RowStitcher {
public:
    /// How the diagonals of a row of quads run.
    enum class Diagonals {
        InsideToOutside,             ///< every diagonal from inside point i to outside point i + 1
        InsideToOutsideExceptMiddle, ///< the same, but the middle quad is split the other way
        Mirrored,                    ///< mirrored about the middle of the row
    };

    explicit RowStitcher(std::vector<uint32_t>& indices, bool reverseWinding)
        : mIndices(indices), mReverse(reverseWinding) {}

    /// Stitches an outer edge to the matching edge of the first ring. Points
    /// are consumed from both ends towards the middle, inside and outside
    /// interleaved in ruler-function order of their half-level point counts,
    /// so the pattern only changes locally as either level moves.
    void transition(std::span<const uint32_t> outside, const EdgeSpacing& outsideSpacing,
                    std::span<const uint32_t> inside, const EdgeSpacing& insideSpacing);

    /// Stitches two rows. A trapezoid has one more point at each end of the
    /// outside row than of the inside row (consecutive rings); otherwise both
    /// rows have the same length (the strip at the centre of a quad).
    void regular(std::span<const uint32_t> outside, std::span<const uint32_t> inside, bool trapezoid,
                 Diagonals diagonals);

    /// One triangle, given clockwise in the reference's sense.
    void triangle(uint32_t a, uint32_t b, uint32_t c);

private:
    std::vector<uint32_t>& mIndices;
    bool mReverse;
};

} // namespace tessera::tessellator::detail
