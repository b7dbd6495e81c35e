#pragma once
// TextureDecoder: the images a character's material uses, decoded by the
// core's one decoder (tessera/core/ImageFile.h, decodeImage):
// base colour and normal map to Rgba8, the displacement map (a 16-bit
// grayscale PNG named by extras.tessera_displacement) to R16.

#include "GltfTinyGltf.h"
#include "tessera/character/CharacterAsset.h"

namespace tessera::assets {

/// Fills baseColor, normalMap and displacement from material `material` (-1: none).
void decodeMaterialTextures(const tinygltf::Model& model, const nlohmann::json& json, int material,
                            character::CharacterAsset& asset);

} // namespace tessera::assets
