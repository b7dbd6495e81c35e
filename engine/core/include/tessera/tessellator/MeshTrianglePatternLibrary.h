#pragma once
/// @file MeshTrianglePatternLibrary.h
/// The connectivity of every piece of every uniform-level triangle patch the
/// mesh-shader tessellation can produce (fractional_odd spacing, levels 1 to
/// 64: characters and a crowd's near tier), as the key and triangle tables
/// the meshshader backend uploads. Built once from the same stitching code
/// as Tessellator's triangle rings, so a patch assembled from its pieces
/// (TessMeshTrianglePattern.h) is Tessellator's pattern exactly.

#include "tessera/shaders/TessMeshTrianglePattern.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::tessellator {

class MeshTrianglePatternLibrary {
public:
    /// The library (built on first use, then shared).
    static const MeshTrianglePatternLibrary& uniformFractionalOdd();

    /// One entry per key (TS_MESH_TRI_KEY_COUNT): first triangle, triangle
    /// count, points of row A and of row B.
    std::span<const shader::TsMeshKey> keys() const { return mKeys; }
    /// Triangles of all keys back to back: three 8-bit local point indices
    /// (a | b << 8 | c << 16), in Tessellator's order and winding.
    std::span<const uint32_t> triangles() const { return mTriangles; }

private:
    MeshTrianglePatternLibrary();
    // Stitches rows A = 0 .. rowA - 1 and B = rowA .. rowA + rowB - 1 with
    // `stitch` and stores the triangles under `key`.
    template <typename Stitch> void add(uint32_t key, uint32_t rowA, uint32_t rowB, Stitch&& stitch);

    std::vector<shader::TsMeshKey> mKeys;
    std::vector<uint32_t> mTriangles;
};

} // namespace tessera::tessellator
