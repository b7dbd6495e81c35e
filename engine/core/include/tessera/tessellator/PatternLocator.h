#pragma once
/// @file PatternLocator.h
/// Which triangle of a tessellated pattern holds a domain point, and where in
/// it: what a renderer needs to evaluate the surface it drew (a linear
/// interpolation over that triangle) at a point that is not a vertex.
///
/// Used by terrain::DrawnSurface to stand characters on the terrain the GPU
/// drew, whose triangles are Tessellator's (bit for bit on every backend).

#include "tessera/tessellator/TessellationTypes.h"

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tessera::tessellator {

class PatternLocator {
public:
    /// A domain point's triangle: its three corners (indices into the
    /// pattern's points) and the point's barycentric weights on them (each in
    /// [0, 1], summing to 1).
    struct Hit {
        std::array<uint32_t, 3> corners{};
        glm::vec3 weights{1.0f, 0.0f, 0.0f};
    };

    /// Indexes `patch` (any domain: points are (u, v) in the unit square) on
    /// a uniform grid of cells, each listing the triangles whose bounds touch
    /// it. Zero-area triangles (fractional levels make a few) cover nothing
    /// and are left out. An empty pattern locates nothing.
    explicit PatternLocator(TessellatedPatch patch);

    const TessellatedPatch& patch() const { return mPatch; }
    bool empty() const { return mTriangles.empty(); }

    /// The triangle holding `uv` (clamped to the unit square). A point on a
    /// shared edge belongs to either triangle (both give the same linear
    /// interpolation there); a point that float rounding puts a hair outside
    /// every triangle of its cell gets the nearest, its weights clamped.
    /// Must not be called on an empty locator.
    Hit locate(glm::vec2 uv) const;

private:
    /// A triangle ready for barycentric tests without a division: its first
    /// corner and the inverse of the matrix of its two edges from there.
    struct Triangle {
        glm::vec2 origin{0.0f};
        glm::vec2 inverseRow0{0.0f}, inverseRow1{0.0f};
        std::array<uint32_t, 3> corners{};
    };

    /// The cell row or column of coordinate `t` (clamped to the square).
    uint32_t cellOf(float t) const {
        const float cell = t * float(mCells);
        return cell <= 0.0f ? 0u : cell >= float(mCells - 1) ? mCells - 1 : uint32_t(cell);
    }

    TessellatedPatch mPatch;
    std::vector<Triangle> mTriangles;     ///< the pattern's triangles of non-zero area
    uint32_t mCells = 1;                  ///< cells per side
    std::vector<uint32_t> mCellStart;     ///< per cell, its first entry in mCellTriangles (one more at the end)
    std::vector<uint32_t> mCellTriangles; ///< indices into mTriangles, cell by cell
};

} // namespace tessera::tessellator
