#pragma once
/// @file MeshPatternLibrary.h
/// The connectivity of every piece of every quad patch the mesh-shader
/// tessellation can produce (fractional_odd spacing, levels 1 to 64), as the
/// key and triangle tables the meshshader backend uploads: built once from
/// the same stitching code as Tessellator, so a patch assembled from its
/// pieces (TessMeshPattern.h) is Tessellator's pattern exactly.

#include "tessera/shaders/TessMeshPattern.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::tessellator {

class MeshPatternLibrary {
public:
    /// The library (built on first use, then shared).
    static const MeshPatternLibrary& quadFractionalOdd();

    /// One entry per key (TS_MESH_KEY_COUNT): first triangle, triangle
    /// count, points of row A and of row B.
    std::span<const shader::TsMeshKey> keys() const { return mKeys; }
    /// Triangles of all keys back to back: three 8-bit local point indices.
    std::span<const uint32_t> triangles() const { return mTriangles; }

private:
    MeshPatternLibrary();

    std::vector<shader::TsMeshKey> mKeys;
    std::vector<uint32_t> mTriangles;
};

} // namespace tessera::tessellator
