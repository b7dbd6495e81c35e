#pragma once
// The base colour map (internal header).

#include "CreatureSdf.h"
#include "SkinDetail.h"
#include "tessera/character/CageMesh.h"
#include "tessera/character/TextureImage.h"

#include <cstdint>

namespace tessera::creature {

/// Rasterises the cage's triangles into its UV atlas (size x size, Rgba8,
/// sRGB) and colours each texel from the skin at the matching point of the
/// shape: an olive to grey-green goblin palette with blotches, darker
/// wrinkle creases and brownish warts. Texels outside every chart take the
/// colour of the nearest chart texel (gutter dilation), so filtering never
/// bleeds black into the skin.
character::TextureImage paintBaseColor(const character::CageMesh& cage, const CreatureSdf& sdf,
                                       const SkinDetail& skin, const CreatureParams& params, uint32_t size);

} // namespace tessera::creature
