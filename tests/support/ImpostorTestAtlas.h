#pragma once
/// @file ImpostorTestAtlas.h
/// An impostor atlas of the right shape for tests that need one but not a
/// bake (crowd descriptions, the file format): every image at its size,
/// filled with a fixed pattern.

#include "tessera/character/ImpostorAtlas.h"
#include "tessera/shaders/CrowdImpostor.h"

#include <cstdint>

namespace tessera::test {

inline character::ImpostorAtlas makeTestAtlas(uint32_t layers = TS_IMPOSTOR_PHASES) {
    character::ImpostorAtlas atlas;
    atlas.size = TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL;
    atlas.layers = layers;
    atlas.centreY = 0.75f;
    atlas.radius = 1.25f;
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
        atlas.albedo.emplace_back(size_t(atlas.layerBytes(m)) * layers);
        atlas.normal.emplace_back(size_t(atlas.layerBytes(m)) * layers);
        for (size_t i = 0; i < atlas.albedo[m].size(); ++i) {
            atlas.albedo[m][i] = uint8_t(i * 7u + m);
            atlas.normal[m][i] = uint8_t(i * 13u + m + 1u);
        }
    }
    return atlas;
}

} // namespace tessera::test
