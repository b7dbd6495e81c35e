#pragma once
/// @file ImpostorAtlas.h
/// A creature's impostor images for the crowd's impostor tier (layout in
/// shaders/CrowdImpostor.h): per clip of the character and baked phase one
/// layer of TS_IMPOSTOR_VIEWS^2 view cells, with TS_IMPOSTOR_MIPS mip
/// levels. Made by character::bakeImpostors, stored by the content build
/// next to the character (ImpostorFile.h).

#include <cstdint>
#include <vector>

namespace tessera::character {

struct ImpostorAtlas {
    /// Texels a side of a layer at mip 0 (TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL).
    uint32_t size = 0;
    /// Layers: the character's clips times TS_IMPOSTOR_PHASES, clip-major
    /// (clip c's phase k is layer c * TS_IMPOSTOR_PHASES + k); a character
    /// without clips has TS_IMPOSTOR_PHASES layers of its rest pose.
    uint32_t layers = 0;
    /// The sphere the cells frame, in model space: centre (0, centreY, 0)
    /// and radius (as the crowd's instance spheres, AnimatedBounds.h).
    float centreY = 0.0f;
    float radius = 0.0f;
    /// Per mip level m (size >> m texels a side), every layer's texels row
    /// by row from the top, layer after layer: base colour in sRGB with
    /// coverage in alpha (colour dilated into the uncovered texels), and the
    /// model-space unit normal as n * 0.5 + 0.5 with 255 in alpha.
    std::vector<std::vector<uint8_t>> albedo;
    std::vector<std::vector<uint8_t>> normal;

    bool empty() const { return size == 0 || layers == 0; }
    /// Texels a side of a layer at mip `mip`.
    uint32_t sizeAt(uint32_t mip) const { return size >> mip; }
    /// Bytes of one layer of one image (albedo or normal) at mip `mip`.
    uint64_t layerBytes(uint32_t mip) const { return uint64_t(sizeAt(mip)) * sizeAt(mip) * 4u; }
    /// Bytes of both images, every mip.
    uint64_t bytes() const;
};

} // namespace tessera::character
