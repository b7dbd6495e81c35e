#pragma once
/// @file DetailTextureGenerator.h
/// The terrain's detail albedo textures, made procedurally: tileable (every
/// noise lattice wraps at the texture's size, so the terrain can repeat them
/// without seams) and deterministic (integer hashing, no threads, no clock:
/// the same size and seed give the same bytes on every machine).

#include "tessera/core/ImageFile.h"

#include <array>
#include <cstdint>
#include <string_view>

namespace tessera::texgen {

/// The materials, in the order of the terrain's texture array layers
/// (terrain_shading.glsl reads them by these indices).
enum class DetailMaterial : uint32_t { Grass = 0, Dirt = 1, Rock = 2, Snow = 3 };

inline constexpr std::array<DetailMaterial, 4> kDetailMaterials = {DetailMaterial::Grass, DetailMaterial::Dirt,
                                                                   DetailMaterial::Rock, DetailMaterial::Snow};

/// "grass", "dirt", "rock" or "snow": the file is detail_<name>.png.
std::string_view materialName(DetailMaterial material);

/// A `size` x `size` sRGB-encoded RGBA8 albedo texture of `material`
/// (alpha 255). `size` is a power of two of at least 16.
Rgba8Image generateDetailTexture(DetailMaterial material, uint32_t size, uint64_t seed);

} // namespace tessera::texgen
