#pragma once
/// @file TileAtlas.h
/// Places tiles (each with its levels, tsTileFootprint texels) in one 2D
/// texture: shelves of tiles sorted by height, so tiles of one size sit
/// side by side and little space is lost between shelves.

#include "tessera/core/Result.h"

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv::detail {

struct TileAtlas {
    uint32_t width = 0, height = 0;
    std::vector<glm::uvec2> origins; ///< per footprint, in the order given

    /// Packs `footprints` into a texture about as wide as it is high (the
    /// width a power of two, at least the widest footprint). Error: more
    /// than `maxSide` texels a side (records address 16 bits).
    static Result<TileAtlas> pack(std::span<const glm::uvec2> footprints, uint32_t maxSide = 65535);
};

} // namespace tessera::subdiv::detail
