#pragma once
// Builds the mesh-shader pattern libraries' tables (MeshPatternLibrary,
// MeshTrianglePatternLibrary): each piece is two rows of local points,
// A = 0 .. rowA - 1 and B = rowA .. rowA + rowB - 1, stitched with the
// tessellator's own RowStitcher and stored as one key entry and packed
// triangles (three 8-bit local indices).

#include "EdgeSpacing.h"
#include "RowStitcher.h"
#include "tessera/shaders/TessMeshPattern.h"

#include <cassert>
#include <numeric>
#include <vector>

namespace tessera::tessellator::detail {

class MeshPieceStitcher {
public:
    using Rows = const std::vector<uint32_t>&;

    MeshPieceStitcher(std::vector<shader::TsMeshKey>& keys, std::vector<uint32_t>& triangles)
        : mKeys(keys), mTriangles(triangles) {}

    /// An odd-spacing edge with `points` points: only the count and parity
    /// shape a stitch; the level's fraction only moves points, which the
    /// shaders do.
    static EdgeSpacing oddSpacing(uint32_t points) {
        return EdgeSpacing(toFixed(float(points - 1)), Parity::Odd);
    }

    /// Stitches rows A and B with `stitch(RowStitcher&, Rows a, Rows b)` and
    /// stores the triangles under `key`, in the order and winding Tessellator
    /// emits them (the reference's reversed: Vulkan's counter-clockwise).
    template <typename Stitch>
    void add(uint32_t key, uint32_t rowA, uint32_t rowB, Stitch&& stitch) {
        assert(rowA + rowB <= TS_MESH_MAX_VERTICES);
        std::vector<uint32_t> indices;
        RowStitcher stitcher(indices, /*reverseWinding=*/true);
        stitch(stitcher, row(0, rowA), row(rowA, rowB));
        const auto first = static_cast<uint32_t>(mTriangles.size());
        for (size_t i = 0; i < indices.size(); i += 3)
            mTriangles.push_back(indices[i] | indices[i + 1] << 8 | indices[i + 2] << 16);
        const auto count = static_cast<uint32_t>(mTriangles.size()) - first;
        assert(count <= TS_MESH_MAX_TRIANGLES);
        mKeys[key].entry = {first, count, rowA, rowB};
    }

private:
    static std::vector<uint32_t> row(uint32_t first, uint32_t count) {
        std::vector<uint32_t> indices(count);
        std::iota(indices.begin(), indices.end(), first);
        return indices;
    }

    std::vector<shader::TsMeshKey>& mKeys;
    std::vector<uint32_t>& mTriangles;
};

} // namespace tessera::tessellator::detail
