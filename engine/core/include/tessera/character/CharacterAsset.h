#pragma once
/// @file CharacterAsset.h
/// Everything the engine needs to animate and render one character: the
/// skinned cage, its skeleton and clips, and its maps. Made by the creature
/// generator (tools/creature) or loaded from any glTF 2.0 file
/// (assets::loadCharacter); rendered by every backend.

#include "tessera/character/AnimationClip.h"
#include "tessera/character/CageMesh.h"
#include "tessera/character/Skeleton.h"
#include "tessera/character/TextureImage.h"

#include <optional>
#include <string>
#include <vector>

namespace tessera::character {

/// A scalar displacement map and the exact numbers the shader needs: the
/// displacement at a surface point is `sample * scale + bias` model-space
/// units along the normalised, interpolated cage normal (sample in [0, 1],
/// the paper's fDisplacementScale and fDisplacementBias).
struct DisplacementMap {
    TextureImage image;  ///< TextureFormat::R16
    float scale = 0.0f;
    float bias = 0.0f;
};

/// One renderable, animatable character.
struct CharacterAsset {
    std::string name;    ///< for debug names and messages
    std::string source;  ///< the file it came from, for messages ("" if generated)
    CageMesh cage;
    Skeleton skeleton;
    std::vector<AnimationClip> clips;
    std::optional<TextureImage> baseColor;  ///< Rgba8, sRGB
    std::optional<TextureImage> normalMap;  ///< Rgba8, tangent space of the cage, same frame as the displacement
    std::optional<DisplacementMap> displacement;
    /// The far LOD tier's simplified mesh (a few hundred triangles, see
    /// FarMesh.h), drawn by the crowd's far tier without tessellation. It has
    /// the same `bindings` as `cage`, so the cage's skinning palette poses it.
    /// Every loaded character has one (read from the file's MSFT_lod level,
    /// else made at load time).
    std::optional<CageMesh> farMesh;
};

} // namespace tessera::character
