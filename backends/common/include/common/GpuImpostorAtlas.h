#pragma once
/// @file GpuImpostorAtlas.h
/// A crowd's impostor tier images on the GPU (layout in CrowdImpostor.h):
/// every creature's layers (character::ImpostorAtlas, one per clip and
/// phase) one creature after another, an instance's first layer in its
/// global baked clip's record (firstLayers(), BakedClip::timing.w on the
/// GPU), in two 2D-array images of TS_IMPOSTOR_MIPS levels:
/// base colour and coverage (R8G8B8A8_SRGB, so filtering blends linear
/// colour) and the model-space normal (R8G8B8A8_UNORM); with the sampler
/// the cards read both through (linear between texels and mips, clamped).
/// Bound at TS_BINDING_CROWD_IMPOSTOR_ALBEDO and _NORMAL (CrowdDescriptors).

#include "tessera/backend/CrowdDesc.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Sampler.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tessera::backends {

class GpuImpostorAtlas {
public:
    GpuImpostorAtlas() = default;
    /// Uploads the atlases of `desc`. An atlas holding a clip per baked clip
    /// (the rest pose first) maps clip for clip; one holding its asset's
    /// clips only (the rest pose not baked) shows its first clip for the
    /// rest pose, with no layers of its own. A creature without a usable
    /// atlas has no layers and empty cards (bounds() 0: no pixel); a crowd
    /// with none at all gets one small clear clip.
    static GpuImpostorAtlas create(gpu::Device& device, const backend::CrowdDesc& desc);

    VkDescriptorImageInfo albedo() const;
    VkDescriptorImageInfo normal() const;
    /// The images themselves (for the tests' readback).
    const gpu::Image& albedoImage() const { return mAlbedo; }
    const gpu::Image& normalImage() const { return mNormal; }
    /// Device bytes of both images, every mip.
    uint64_t bytes() const { return mBytes; }
    /// Per creature and view cell (tsCrowdImpostorBoundsWord) the rectangle
    /// its layers cover there (tsImpostorPackBounds), with a texel to spare
    /// for filtering; 0 (an empty card) where it covers nothing or has no
    /// atlas. Goes to CrowdUniforms::impostorBounds.
    const std::array<uint32_t, TS_CROWD_MAX_CHARACTERS * TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_VIEWS>& bounds() const {
        return mBounds;
    }
    /// Per global baked clip, its first layer (the GPU's BakedClip::timing.w):
    /// the rest pose, which the baker does not bake, its creature's first
    /// clip's.
    const std::vector<uint32_t>& firstLayers() const { return mFirstLayers; }

private:
    gpu::Image mAlbedo, mNormal;
    gpu::Sampler mSampler;
    uint64_t mBytes = 0;
    std::array<uint32_t, TS_CROWD_MAX_CHARACTERS * TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_VIEWS> mBounds{};
    std::vector<uint32_t> mFirstLayers;
};

} // namespace tessera::backends
