#pragma once
/// @file TrianglePatternLibrary.h
/// The emulated tessellator's triangle patterns for one uniform level per
/// draw instance: what the r2vb and streamout backends draw a crowd's near
/// tier with, where the GPU gives every instance its own continuous level.
/// Fractional-odd spacing at levels 1 to 14.99 has eight connectivity
/// classes (TessTrianglePattern.h); each class is a list of point codes and
/// the triangles over them, built once from Tessellator's own output, and
/// the evaluation vertex shader places each code at the instance's level.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tessera::tessellator {

class TrianglePatternLibrary {
public:
    /// Where one class lies in codes() and indices().
    struct Class {
        uint32_t firstCode = 0; ///< the class's first point code (an indexed draw's vertexOffset)
        uint32_t codeCount = 0;
        uint32_t firstIndex = 0; ///< the class's first index (3 per triangle, local to its codes)
        uint32_t indexCount = 0;
    };

    /// The library of TS_EMU_TRIANGLE_CLASSES classes (built on first use, then shared).
    static const TrianglePatternLibrary& fractionalOdd();

    /// Point codes (tsEmuTriangleCode), every class back to back.
    std::span<const uint32_t> codes() const { return mCodes; }
    /// Triangles of every class, in Tessellator's order and winding.
    std::span<const uint32_t> indices() const { return mIndices; }
    std::span<const Class> classes() const { return mClasses; }

private:
    TrianglePatternLibrary();

    std::vector<uint32_t> mCodes;
    std::vector<uint32_t> mIndices;
    std::vector<Class> mClasses;
};

} // namespace tessera::tessellator
