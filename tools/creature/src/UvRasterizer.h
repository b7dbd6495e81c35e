#pragma once
/// @file UvRasterizer.h
/// Which cage triangle, and which point on it, each texel of a map stands for.

#include "tessera/character/CageMesh.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// How a texel relates to the cage's UV layout.
enum class TexelKind : uint8_t {
    Empty,    ///< no triangle's bilinear footprint reaches it (gutter or unused)
    Inside,   ///< its centre lies inside a triangle's UVs
    Dilated,  ///< outside every triangle, but a bilinear fetch inside the nearest one reads it
};

/// One texel's surface point: a cage triangle and the barycentric weights of
/// its second and third vertices. For a Dilated texel the point is the
/// triangle point nearest the texel centre (see DilatedTexel).
struct TexelSample {
    int32_t triangle = -1;
    float b1 = 0.0f;
    float b2 = 0.0f;
    TexelKind kind = TexelKind::Empty;
};

/// How a Dilated texel extrapolates: its centre P lies outside its
/// triangle, Q (the TexelSample's point) is the nearest triangle point and M
/// a point inside on the line from P through Q. The texel holds
/// value(Q) + (value(Q) - value(M)) * ratio, the linear extrapolation that a
/// bilinear fetch across the edge expects. (Casting a ray from P itself
/// would leave the surface at a crease and hit whatever lies beyond.)
struct DilatedTexel {
    uint32_t index = 0;  ///< texel, row-major
    float m1 = 0.0f;     ///< M's barycentric weights (second, third vertex)
    float m2 = 0.0f;
    float ratio = 0.0f;  ///< |P - Q| / |Q - M|, at most 2; 0 (flat extension) where the triangle is too thin
};

/// Rasterises every cage triangle's UVs over a square map. Texel centres
/// inside a triangle go to the first such triangle in index order; texels
/// within sqrt(2) texels of some triangle (a superset of the texels its
/// bilinear fetches touch) go to the nearest, ties to the lower index.
class UvRasterizer {
public:
    UvRasterizer(const character::CageMesh& cage, uint32_t size);

    uint32_t size() const { return mSize; }
    const TexelSample& at(uint32_t index) const { return mTexels[index]; }
    const std::vector<TexelSample>& texels() const { return mTexels; }
    uint64_t insideCount() const { return mInside; }
    uint64_t dilatedCount() const { return mDilatedTexels.size(); }
    /// The Dilated texels in index order.
    const std::vector<DilatedTexel>& dilatedTexels() const { return mDilatedTexels; }

private:
    uint32_t mSize;
    std::vector<TexelSample> mTexels;
    uint64_t mInside = 0;
    std::vector<DilatedTexel> mDilatedTexels;
};

} // namespace tessera::creature
