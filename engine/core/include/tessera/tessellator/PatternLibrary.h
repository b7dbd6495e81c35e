#pragma once
/// @file PatternLibrary.h
/// The emulated tessellator's pattern library: every piece of every quad
/// patch the D3D10-era emulation can produce (fractional_odd spacing, levels
/// 1 to 14.99), as lists of point references, built once from the same
/// stitching code as Tessellator. The r2vb and streamout backends upload it
/// as their pattern buffer and key table; their shaders select a piece per
/// patch edge and place its points (engine/core/include/tessera/shaders/TessPattern.h
/// defines the keys and references, shared with the shaders).

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::tessellator {

class PatternLibrary {
public:
    /// Where one key's triangles lie in vertices(): 3 references per triangle.
    struct Piece {
        uint32_t firstVertex = 0;
        uint32_t vertexCount = 0;
    };

    /// The library for quad patches, fractional_odd spacing, levels up to
    /// TS_EMU_MAX_LEVEL (built on first use, then shared).
    static const PatternLibrary& quadFractionalOdd();

    /// Packed point references (TS_EMU_REF_*), all pieces back to back.
    std::span<const uint32_t> vertices() const { return mVertices; }
    /// One entry per key (TS_EMU_KEY_COUNT).
    std::span<const Piece> pieces() const { return mPieces; }

private:
    PatternLibrary();
    void addStrip(uint32_t outerPoints, uint32_t innerPoints);
    void addInterior(uint32_t pointsU, uint32_t pointsV);
    void addMinimal();

    std::vector<uint32_t> mVertices;
    std::vector<Piece> mPieces;
};

} // namespace tessera::tessellator
