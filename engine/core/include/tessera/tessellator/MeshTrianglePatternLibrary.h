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
    /// How a draw's mesh workgroups share its patches, which all have one
    /// level, as entries of one table: first TS_MESH_TRI_CLASSES entries, one
    /// per point class (points / 2 - 1): x = its first group entry, y =
    /// groups per patch, z = patches per group (more than 1 when a whole
    /// patch is small); then each class's groups: x = the entry of its first
    /// chain, y = chains, z = points, w = triangles; then the chains: x = an
    /// edge (or TS_MESH_TRI_CHAIN_CENTRE), y = first ring pair q0, z = last
    /// q1. A chain is the pieces (q0 .. q1) along one edge, which share their
    /// rows: ring q + 1's row is the outside row of piece q + 1 and the
    /// inside row of piece q, so each row is placed and evaluated once.
    /// Chains are packed greedily up to TS_MESH_MAX_VERTICES points and
    /// TS_MESH_TRI_GROUP_MAX_TRIANGLES triangles: a level-15 patch is three
    /// chains (72 points, 112 triangles each) and the centre, 0.65 points a
    /// triangle where a piece a workgroup evaluated 1.13.
    std::span<const glm::uvec4> groups() const { return mGroups; }
    /// The same for a crowd's near tier, whose mesh stage writes two more
    /// attributes a point: its workgroups keep to TS_MESH_MAX_TRIANGLES.
    std::span<const glm::uvec4> crowdGroups() const { return mCrowdGroups; }

private:
    MeshTrianglePatternLibrary();
    std::vector<glm::uvec4> buildGroups(uint32_t maxTriangles) const;

    std::vector<shader::TsMeshKey> mKeys;
    std::vector<uint32_t> mTriangles;
    std::vector<glm::uvec4> mGroups;
    std::vector<glm::uvec4> mCrowdGroups;
};

} // namespace tessera::tessellator
