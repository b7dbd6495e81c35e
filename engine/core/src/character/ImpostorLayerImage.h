#pragma once
// ImpostorLayerImage: one impostor layer's texels at mip 0 in float while
// the baker fills them (private to the baker), then the dilation into each
// cell's uncovered texels, the mip chain and the bytes of the atlas.

#include "tessera/character/ImpostorAtlas.h"
#include "tessera/shaders/CrowdImpostor.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::character {

/// One texel while baking.
struct ImpostorTexel {
    glm::vec3 colour{0.0f}; ///< 0..255, the base colour's stored sRGB values
    float coverage = 0.0f;  ///< 0..1
    glm::vec3 normal{0.0f}; ///< unit length once filled
};

class ImpostorLayerImage {
public:
    /// Texels a side of a layer at mip 0.
    static constexpr uint32_t kSize = TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL;
    /// Texels the colour and normal are carried into a cell's uncovered
    /// texels from its covered ones (at mip 0); beyond them the cell's mean.
    static constexpr uint32_t kDilationTexels = 4;

    ImpostorLayerImage() : mTexels(size_t(kSize) * kSize) {}

    ImpostorTexel& at(uint32_t x, uint32_t y) { return mTexels[size_t(y) * kSize + x]; }
    const ImpostorTexel& at(uint32_t x, uint32_t y) const { return mTexels[size_t(y) * kSize + x]; }

    /// Fills cell `cell`'s uncovered texels (coverage stays 0): kDilationTexels
    /// passes, each giving a texel next to a filled one (8-neighbourhood,
    /// inside the cell) its filled neighbours' mean colour and normal; then
    /// the rest the coverage-weighted mean of the cell's covered texels
    /// (`emptyColour` and `emptyNormal` in a cell nothing covers).
    void dilateCell(glm::uvec2 cell, const glm::vec3& emptyColour, const glm::vec3& emptyNormal);

    /// Writes this layer and its TS_IMPOSTOR_MIPS - 1 mips, as bytes, into
    /// layer `layer` of `atlas`, whose images are already sized.
    void store(ImpostorAtlas& atlas, uint32_t layer) const;

private:
    std::vector<ImpostorTexel> mTexels;
};

} // namespace tessera::character
